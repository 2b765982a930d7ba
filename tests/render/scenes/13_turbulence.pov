// Marble and wood with turbulence; classic noise patterns.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { wood turbulence 0.3 color_map { [0 rgb <0.8, 0.5, 0.2>] [1 rgb <0.4, 0.2, 0.05>] } scale 0.5 rotate x*90 } }
sphere { <-1.2, 1, 0>, 1 pigment { marble turbulence 1 color_map { [0 rgb 0.9] [0.8 rgb <0.6, 0.1, 0.1>] [1 rgb 0.1] } scale 0.7 } }
sphere { <1.2, 1, 0>, 1 pigment { agate } }
