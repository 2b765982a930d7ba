// expect: 2 4
#version 3.7;
#for (I, 0, 1e9)
    sphere { <I, 0, 0>, 0.5 }
#end
