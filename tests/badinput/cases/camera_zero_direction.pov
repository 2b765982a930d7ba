// expect: 0 3
#version 3.7;
camera { location <0, 1, -3> direction <0, 0, 0> }
light_source { <0, 5, -5>, rgb 1 }
sphere { 0, 1 pigment { rgb 1 } }
