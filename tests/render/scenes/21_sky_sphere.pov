// sky_sphere with a gradient pigment.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at <0, 1.5, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <1, 0.9, 0.7>] [0.3 rgb <0.3, 0.5, 1>] [1 rgb <0.05, 0.1, 0.4>] } } }
plane { y, 0 pigment { rgb 0.6 } }
sphere { <0, 1, 0>, 1 pigment { rgb 1 } finish { reflection 0.5 } }
