// A cylindrical light source.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -6> look_at <0, 0, 0> right x*4/3 }
light_source { <0, 5, 0> color rgb 1 cylinder point_at <0.5, 0, 0.5> radius 1.5 falloff 2.5 tightness 2 }
light_source { <-5, 5, -5> color rgb 0.15 }
plane { y, 0 pigment { rgb 1 } }
box { <-0.3, 0, -0.3>, <0.3, 1, 0.3> pigment { rgb <0.9, 0.5, 0.2> } }
