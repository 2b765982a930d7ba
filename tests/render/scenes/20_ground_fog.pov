// Ground fog with offset and altitude.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.1, 0.1, 0.3> }
fog { fog_type 2 distance 3 color rgb <0.9, 0.9, 0.9> fog_offset 0.3 fog_alt 0.5 }
plane { y, 0 pigment { checker rgb <0.8, 0.2, 0.2> rgb 0.9 } }
sphere { <0, 1, 2>, 1 pigment { rgb <0.2, 0.5, 1> } }
