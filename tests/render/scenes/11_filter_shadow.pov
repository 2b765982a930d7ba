// Filtering and transmitting objects tint shadows.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <0, 8, -2> color rgb 1 }
plane { y, 0 pigment { rgb 1 } }
box { <-2.2, 0.8, -0.5>, <-0.8, 1.2, 0.5> pigment { rgbf <1, 0.2, 0.2, 0.8> } }
box { <0.8, 0.8, -0.5>, <2.2, 1.2, 0.5> pigment { rgbt <0.2, 0.2, 1, 0.6> } }
