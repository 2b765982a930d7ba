// atan2 of two zeros: POV-Ray 3.7 stops on line 6, "Domain error in
// atan2!" (both within its EPSILON, 1e-10, of zero; iris gave 0).
#version 3.7;
#declare A = atan2(0, -1);
#declare B = atan2(1e-9, 0);
#declare C = atan2(0, 1e-11);
