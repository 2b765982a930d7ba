// expect: 0 -
#version 3.7;
#declare S = str(1/3, 0, 1000000000);
