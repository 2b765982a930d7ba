// expect: 2 4
#version 3.7;
#if (1)
sphere { 0, 1 pigment { rgb 1 } }
