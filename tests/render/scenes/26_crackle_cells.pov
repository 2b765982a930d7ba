// crackle and cells (POV-Ray's random table).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { cells scale 0.7 } }
sphere { <-1.2, 1, 0>, 1 pigment { crackle color_map { [0 rgb 0] [0.05 rgb 0] [0.1 rgb <1, 0.8, 0.5>] [1 rgb <1, 0.8, 0.5>] } scale 0.4 } }
sphere { <1.2, 1, 0>, 1 pigment { crackle solid scale 0.4 } }
