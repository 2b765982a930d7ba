// spiral1 without a wave keyword: POV-Ray gives spirals triangle_wave.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -4> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { rgb 0.6 } }
sphere { <0, 1, 0>, 1 pigment { spiral1 5 color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } scale 0.3 } }
