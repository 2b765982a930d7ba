// tiling: POV-Ray 3.7 truncates the number and refuses what is not
// 1..27 ("Tiling number must be between 1 and 27"); 27.9 is 27.
plane { y, 0 pigment { tiling 27.9 } }
plane { y, 0 pigment { tiling 0.5 } }
