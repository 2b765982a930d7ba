// expect: 2 3
#version 3.7;
#declare X = 1 / 0;
