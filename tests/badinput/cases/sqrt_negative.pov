// expect: 2 3
#version 3.7;
#declare X = sqrt(-1);
