// Parity scene: a height_field from a function, as POV-Ray builds it
// (parser_materials.cpp Make_Pattern_Image, heightfield.cpp
// Compute_HField): row r of the function image is F(x, r/(h-1), 0) and
// becomes the grid row z = (h-1-r)/(h-1), so the function's y runs
// against z; a pigment function gives its Greyscale() (0.297 R + 0.589 G
// + 0.114 B), not its red. The left field is a tilted ramp in y with a
// bump, so a y that ran along z would face the other way; the right one
// a pigment whose red and grey disagree. iris once ran y along z and
// took the red (advanced/landscape.pov at 6.5 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.0, -3.8> look_at <0, 0.2, 0.2> right x*4/3 angle 50 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.2, 0.25, 0.35> }
height_field {
  function 40, 30 { 0.15 + 0.6 * y + 0.25 * exp(-20 * ((x - 0.3) * (x - 0.3) + (y - 0.7) * (y - 0.7))) }
  translate <-0.5, 0, -0.5> scale <2, 1, 1.5> translate <-1.05, 0, 0>
  pigment { gradient y color_map { [0 rgb <0.1, 0.4, 0.1>] [1 rgb <1, 0.9, 0.8>] } } }
height_field {
  function 36, 28 { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0.2>] } } }
  translate <-0.5, 0, -0.5> scale <2, 0.8, 1.5> translate <1.05, 0, 0>
  pigment { rgb <0.8, 0.7, 0.5> } finish { specular 0.4 } }
