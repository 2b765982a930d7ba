// expect: 2 3
#version 3.7;
sphere { <0, 1,