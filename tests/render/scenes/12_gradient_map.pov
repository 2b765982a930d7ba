// Gradient and onion patterns with colour maps, frequency and phase.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { gradient x color_map { [0 rgb <1, 0, 0>] [0.5 rgb <0, 1, 0>] [1 rgb <0, 0, 1>] } scale 2 } }
sphere { <-1.2, 1, 0>, 1 pigment { onion color_map { [0 rgb 1] [0.5 rgb <0.2, 0.2, 0.2>] [1 rgb 1] } frequency 3 scale 0.5 } }
box { <0.4, 0, -0.8>, <2, 1.6, 0.8> pigment { gradient y sine_wave color_map { [0 rgb <1, 1, 0>] [1 rgb <0.5, 0, 0.5>] } phase 0.25 scale 0.4 } }
