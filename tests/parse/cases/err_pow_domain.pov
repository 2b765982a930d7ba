// pow(0, 0): POV-Ray 3.7 stops on line 5, "Domain error." (iris gave 1).
#version 3.7;
#declare A = pow(0, 2) + pow(2, 0);
#declare B = pow(0.5, 0);
#declare C = pow(0, 0);
