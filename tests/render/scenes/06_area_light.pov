// An area light (no jitter) and its soft shadow.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <2, 6, -2> color rgb 1 area_light <2, 0, 0>, <0, 0, 2>, 5, 5 adaptive 1 }
plane { y, 0 pigment { rgb 0.9 } }
sphere { <0, 1, 0>, 0.7 pigment { rgb <0.9, 0.2, 0.3> } }
