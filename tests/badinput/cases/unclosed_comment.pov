// expect: 2 3
#version 3.7;
/* a comment that never ends
sphere { 0, 1 }
