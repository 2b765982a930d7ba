// Ripples and waves normals, and a pattern normal (gradient).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0, 0> right x*4/3 }
light_source { <-3, 6, -6> color rgb 1 }
plane { y, 0 pigment { rgb <0.3, 0.5, 0.8> } normal { ripples 0.8 frequency 4 } finish { phong 0.8 } }
sphere { <-1.5, 0.8, 0>, 0.8 pigment { rgb 0.9 } normal { waves 0.6 scale 0.3 } }
box { <0.5, 0, -0.6>, <2.5, 1, 0.6> pigment { rgb <0.9, 0.9, 0.6> } normal { gradient x 0.8 scale 0.3 } }
