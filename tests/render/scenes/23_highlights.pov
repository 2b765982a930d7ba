// Brilliance, specular with roughness, phong_size, metallic highlights.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 6, -6> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.5 }
plane { y, 0 pigment { rgb 0.5 } }
sphere { <-2.2, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.3> } finish { brilliance 4 diffuse 0.9 } }
sphere { <0, 1, 0>, 1 pigment { rgb <0.3, 0.9, 0.3> } finish { specular 0.8 roughness 0.01 } }
sphere { <2.2, 1, 0>, 1 pigment { rgb <0.9, 0.7, 0.2> } finish { phong 1 phong_size 10 metallic } }
