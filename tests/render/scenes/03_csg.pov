// CSG: difference, intersection and union.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <4, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.8, 0.7> } }
difference {
  box { <-1, 0, -1>, <1, 2, 1> }
  sphere { <0, 2, 0>, 1.3 }
  pigment { rgb <0.9, 0.4, 0.1> } translate x*-1.6
}
intersection {
  sphere { <0, 1, 0>, 1 } cylinder { <0, 0, -2>, <0, 0, 2>, 0.7 translate y }
  pigment { rgb <0.2, 0.6, 0.9> } translate x*1.6
}
union { sphere { <0, 0.4, -1.8>, 0.4 } cylinder { <0, 0.4, -1.8>, <0, 1.5, -1.8>, 0.1 } pigment { rgb 1 } }
