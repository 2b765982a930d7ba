// Constant fog.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
fog { distance 8 color rgb <0.7, 0.7, 0.75> }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 } }
sphere { <-1, 1, 2>, 1 pigment { rgb <1, 0.3, 0.2> } }
sphere { <1.5, 1, 8>, 1 pigment { rgb <0.2, 1, 0.3> } }
