// An orthographic camera.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <3, 4, -5> look_at <0, 0.5, 0> right x*5*4/3 up y*5 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.3, 0.3, 0.3> } }
box { <-1, 0, -1>, <1, 1, 1> pigment { rgb <0.8, 0.4, 0.1> } }
sphere { <0, 1.5, 0>, 0.5 pigment { rgb <0.1, 0.5, 0.8> } }
