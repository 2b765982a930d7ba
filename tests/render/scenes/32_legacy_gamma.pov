// #version 3.6 without assumed_gamma: gamma handling off, values written as computed.
#version 3.6;
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <5, 10, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> } finish { diffuse 0.8 } }
sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.8 reflection 0.2 } }
