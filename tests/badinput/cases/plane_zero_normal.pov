// expect: 2 3
#version 3.7;
plane { <0, 0, 0>, 1 pigment { rgb 1 } }
