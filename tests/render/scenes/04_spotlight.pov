// A spotlight with radius, falloff and tightness on a plane.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0, 0> right x*4/3 }
light_source { <0, 6, 0> color rgb 1.5 spotlight point_at <1, 0, 0> radius 15 falloff 30 tightness 5 }
light_source { <-5, 5, -5> color rgb 0.2 shadowless }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <1, 0.5, 0>, 0.5 pigment { rgb <0.3, 0.9, 0.3> } }
