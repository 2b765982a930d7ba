// A macro's name cannot be #declared. POV-Ray 3.7 stops on line 6:
// "Expected 'undeclared identifier', macro identifier found instead"
// (iris replaced the macro by the float).
#version 3.7;
#macro F(X) X * 2 #end
#declare F = 1;
