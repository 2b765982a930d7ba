// hexagon, brick and checker patterns.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -6> look_at <0, 0, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { hexagon rgb <0.9, 0.2, 0.2> rgb <0.2, 0.9, 0.2> rgb <0.2, 0.2, 0.9> scale 0.5 } }
box { <-2.5, 0, -1>, <-0.5, 2, 1> pigment { brick rgb 0.8 rgb <0.7, 0.3, 0.2> brick_size <0.5, 0.2, 0.3> mortar 0.03 } }
box { <0.5, 0, -1>, <2.5, 1, 1> pigment { checker rgb 1 rgb 0 scale 0.25 } }
