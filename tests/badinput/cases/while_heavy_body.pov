// expect: 2 7
#version 3.7;
// Found by fuzz_plan (a POV-Ray example whose loop increment was mangled):
// an endless #while whose body costs microseconds (six octaves of
// turbulence) must end with the located loop-limit error in 10 CPU s.
#declare X = 0;
#while (X < 1)
    #declare T = vturbulence(2, 0.5, 6, <X, 0, 0>) * 0.5;
#end
