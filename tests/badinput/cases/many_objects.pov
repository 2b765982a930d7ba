// expect: 2 4
#version 3.7;
#for (I, 0, 1e9)
    sphere { <I, 0, 0>, 0.5 } sphere { <I, 1, 0>, 0.5 } sphere { <I, 2, 0>, 0.5 } sphere { <I, 3, 0>, 0.5 } sphere { <I, 4, 0>, 0.5 } sphere { <I, 5, 0>, 0.5 } sphere { <I, 6, 0>, 0.5 } sphere { <I, 7, 0>, 0.5 }
#end
// Eight objects an iteration: the memory runs out (at a third of the
// test's 2 GB address space, or at ASan's 1 GB soft RSS limit) well
// before the 1000000-iteration loop limit would stop the loop at line 3.
