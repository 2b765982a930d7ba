// A function cannot be declared again, not even by a #local in a macro
// (colors.inc's CH2RGB does '#local G = ...': a scene with a function G
// cannot call it). POV-Ray 3.7 stops on line 7: "Redeclaring functions
// is not allowed - #undef the function first!" (iris made a new local).
#version 3.7;
#declare G = function { x * x }
#macro Green(H) #local G = H / 60; G #end
#declare C = Green(30);
