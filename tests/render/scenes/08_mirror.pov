// Mirror floor and a reflective sphere; reflections of reflections.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { rgb 0.2 } finish { reflection 0.7 } }
sphere { <-1, 1, 0>, 1 pigment { rgb 0.1 } finish { reflection 0.8 phong 1 } }
box { <0.8, 0, -0.5>, <2, 1.5, 0.5> pigment { checker rgb <1, 0.2, 0.2> rgb 1 scale 0.3 } }
