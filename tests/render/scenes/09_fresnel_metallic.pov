// Fresnel reflection with an interior, metallic reflection, falloff.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.6, 0.7, 0.9> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.1 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.1, 0.1, 0.5> } finish { reflection { 0.1, 1 fresnel } } interior { ior 1.5 } }
sphere { <1.2, 1, 0>, 1 pigment { rgb <1, 0.7, 0.2> } finish { diffuse 0.3 reflection { 0.8 metallic } specular 0.6 roughness 0.02 metallic } }
