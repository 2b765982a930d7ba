// expect: 2 4
#version 3.7;
#macro Down(N)
    Down(N + 1)
#end
Down(0)
