// expect: 2 3
#version 3.7;
#declare A = array[1000][1000][1000];
