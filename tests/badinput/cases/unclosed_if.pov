// expect: 2 3
#version 3.7;
#if (1)
sphere { 0, 1 pigment { rgb 1 } }
