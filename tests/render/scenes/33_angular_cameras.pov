// Parity scene: the angular camera types (cylinder 1, the type camera.c
// maps to angles; the unit tests cover the others) looking at coloured
// boxes around the camera, so a wrong angle mapping moves every edge.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { cylinder 1 location <0, 1, 0> look_at <0, 1, 1> angle 200 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.3, 0.4, 0.6> } }
#declare B = box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> }
object { B pigment { rgb <1, 0.3, 0.2> } translate <0, 0, 3> }
object { B pigment { rgb <0.2, 0.8, 0.3> } translate <2.5, 0, 1.5> }
object { B pigment { rgb <0.2, 0.4, 1> } translate <-2.5, 0, 1.5> }
object { B pigment { rgb <1, 0.9, 0.2> } translate <3, 0, -0.5> }
object { B pigment { rgb <0.8, 0.3, 0.9> } translate <-3, 0, -0.5> }
sphere { <0, 2.2, 2.5>, 0.4 pigment { rgb 1 } finish { phong 0.6 } }
