// expect: 2 4
#version 3.7;
camera { location <0,1,-3> look_at 0 } light_source { <0,5,-5>, rgb 1 }
sphere { <0, 1e308 * 10 - 1e308 * 10, 0>, 1 pigment { rgb 1 } }
