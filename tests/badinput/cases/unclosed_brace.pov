// expect: 2 3
#version 3.7;
union {
    sphere { 0, 1 pigment { rgb 1 } }
