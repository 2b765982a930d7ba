// A float has only the components it is read with: '.y' of a float where
// a float is read. POV-Ray 3.7 stops on line 7: "Bad operands for period
// operator." (iris took F.y as F). Where a vector is read, vlength(F.y),
// POV-Ray and iris take it as F (povray_period.pov).
#version 3.7;
#declare F = 2;
#declare Q = F.y;
