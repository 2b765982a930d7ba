// Box, cylinder, cone and torus with plain colours and two lights.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-6, 8, -6> color rgb <1, 0.9, 0.8> }
light_source { <6, 5, -3> color rgb 0.4 }
plane { y, 0 pigment { rgb 0.7 } }
box { <-3, 0, -0.5>, <-2, 1, 0.5> pigment { rgb <0.9, 0.2, 0.2> } rotate y*20 }
cylinder { <-0.5, 0, 0>, <-0.5, 2, 0>, 0.5 pigment { rgb <0.2, 0.9, 0.2> } }
cone { <1.2, 0, 0>, 0.7, <1.2, 1.8, 0>, 0 pigment { rgb <0.2, 0.3, 0.9> } }
torus { 0.8, 0.25 pigment { rgb <0.9, 0.8, 0.1> } translate <3, 0.25, -1> }
