// expect: 2 3
#version 3.7;
#declare S = "a string that never ends;
sphere { 0, 1 }
