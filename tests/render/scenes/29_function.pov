// A function pattern and a pigment_map.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { function { abs(sin(x * 2) * cos(z * 3)) } color_map { [0 rgb <0.1, 0.2, 0.5>] [1 rgb <1, 0.9, 0.6>] } } }
sphere { <0, 1, 0>, 1 pigment { bozo pigment_map { [0.3 checker rgb 1 rgb 0 scale 0.2] [0.7 rgb <0.8, 0.2, 0.1>] } scale 0.5 } }
