// expect: 2 4
#version 3.7;
#declare A = array[3] { 1, 2, 3 };
#declare B = A[-1];
