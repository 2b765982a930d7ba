// image_map_gamma: image maps in a scene with assumed_gamma 2.2. The file's
// colours are decoded to linear light and handed to the shading in the
// working gamma space, v^(1/2.2), as POV-Ray 3.7 does (src/material
// pigment.c image_to_working), texel by texel before the interpolation;
// used as linear values instead, the maps came out darker (an sRGB texel
// of 64 rendered as 5). Measured: 41.7 dB (34.0 dB with the conversion
// after the interpolation).
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { image_map { png "maps/tile.png" interpolate 2 } rotate x*90 scale 2 } }
sphere { <-1.1, 1, 0>, 1 pigment { image_map { png "maps/tile.png" map_type 1 } } }
box { <0.3, 0, -0.5>, <2.3, 2, 0.5> pigment { image_map { png "maps/tile.png" once } scale 2 translate x*0.3 } }
