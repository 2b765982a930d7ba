// Spiral, radial, quilted and spherical patterns.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -6> look_at <0, 0.3, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { radial frequency 8 color_map { [0 rgb 1] [0.5 rgb 1] [0.5 rgb 0.3] [1 rgb 0.3] } } }
sphere { <-2, 0.8, 0>, 0.8 pigment { spiral1 5 triangle_wave color_map { [0 rgb <0, 0, 1>] [1 rgb 1] } scale 0.3 } }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> pigment { quilted color_map { [0 rgb 0.2] [1 rgb <1, 0.6, 0.2>] } scale 0.3 } }
sphere { <2, 0.8, 0>, 0.8 pigment { spherical color_map { [0 rgb 0] [1 rgb <1, 1, 0.5>] } scale 0.8 translate <2, 0.8, 0> } }
