// Transparent blocks with interior fade (absorbing glass).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-3, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.4 scale 0.5 } }
box { <-2.2, 0.01, -0.7>, <-0.6, 1.4, 0.7> pigment { rgbt <1, 1, 1, 1> } interior { ior 1.0 fade_distance 0.8 fade_power 2 fade_color rgb <0.2, 0.8, 0.3> } }
sphere { <1.4, 0.8, 0>, 0.8 pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } interior { ior 1.3 fade_distance 0.5 fade_power 1001 fade_color rgb <0.9, 0.3, 0.2> } }
