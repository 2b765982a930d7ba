// expect: 2 3
#version 3.7;
#declare A = array[3] { 1, 2, 3, 4 };
