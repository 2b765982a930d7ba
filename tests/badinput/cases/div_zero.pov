// expect: 0 5
// POV-Ray 3.7 warns "Divide by zero." and goes on with HUGE_VAL (Parse_Term);
// only such a value reaching the scene is an error.
#version 3.7;
#declare X = 1 / 0;
