// Normal perturbation: bumps and dents.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { rgb 0.8 } normal { dents 0.8 scale 0.3 } }
sphere { <-1.1, 1, 0>, 1 pigment { rgb <0.9, 0.5, 0.2> } normal { bumps 0.6 scale 0.2 } finish { phong 0.7 } }
sphere { <1.1, 1, 0>, 1 pigment { rgb <0.3, 0.6, 0.9> } normal { wrinkles 0.7 scale 0.5 } finish { specular 0.5 } }
