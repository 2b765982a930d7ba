// assumed_gamma 2.2: POV-Ray shades in the gamma-2.2 working space.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <5, 10, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.3, 0.8> } finish { diffuse 0.8 } }
sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 0.8 reflection 0.2 } }
