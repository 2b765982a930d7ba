// expect: 2 6
// radiosity importance 0: POV-Ray 3.7 refuses it ("Radiosity importance
// must be greater than 0.0 and at most 1.0"), so does iris, located.
#version 3.7;
sphere { 0, 1 pigment { rgb 1 }
  radiosity { importance 0 } }
