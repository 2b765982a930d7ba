// Parity scene: images computed from functions, image_map { function W,
// H { ... } } (POV-Ray's Make_Pattern_Image: pixel j of row i is the
// function at (j / (W - 1), i / (H - 1), 0); a float function gives grey,
// a pigment function its colour with transmit as alpha), as an image_map
// on a wall, a spherical image_map on a ball and a bump_map. iris
// rejected these scenes ("image from a function is not supported"); now
// 42.9 dB (the images agree; the rest is the bump_map's edges: POV-Ray
// keeps 16 bits a pixel, iris the function's float).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 0.5, -1.3> look_at <0.5, 0.5, 0> }
light_source { <-2, 3, -6> color rgb 1 }
#declare G = function { 0.5 + 0.5 * sin(x * 12) * cos(y * 7) }
plane { z, 0
  pigment { image_map { function 64, 48 { G(x, y, z) } } }
  finish { ambient 0.3 diffuse 0.7 } }
box { <0.55, 0.55, -0.05>, <1.1, 1.1, -0.02>
  pigment { image_map { function 80, 60 { pigment { bozo
    color_map { [0 rgb <1, 0, 0>] [1 rgbt <0, 0, 1, 0.6>] } scale 0.2 } } } } }
sphere { <0.2, 0.25, -0.2>, 0.18
  pigment { image_map { function 32, 32 { 0.5 + 0.5 * sin(x * 40) } map_type 1 } } }
box { <0.1, 0.6, -0.05>, <0.45, 0.95, -0.02>
  pigment { rgb <0.9, 0.8, 0.6> }
  normal { bump_map { function 40, 40 { 0.5 + 0.5 * sin(x * 30) } bump_size 2 } } }
