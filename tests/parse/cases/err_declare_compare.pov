// A bare comparison as a #declare value. POV-Ray 3.7 stops on line 6,
// at the '<': "All #declares of float, vector, and color require
// semi-colon ';' at end" (iris declared 1).
#version 3.7;
#declare Ok = (1 < 2);
#declare V = 1 < 2;
