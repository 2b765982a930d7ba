// A glass sphere (ior 1.5) over a checker floor: refraction, TIR, phong.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -5> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.2> rgb <0.1, 0.3, 0.6> scale 0.5 } }
sphere { <0, 1, 0>, 1 pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 phong 0.9 phong_size 80 reflection 0.05 } interior { ior 1.5 } }
