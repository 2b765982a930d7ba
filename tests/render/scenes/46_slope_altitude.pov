// Parity scene: the slope pattern as POV-Ray computes it, asin of the
// normal's angle to the slope vector mapped to [0, 1], rescaled by the
// low/high slope and mixed with the altitude in proportion to the two
// vectors' lengths (textures/patterns/slopemt_*.pov); and transforms
// written between a map's pattern and the map ('gradient y scale 2
// texture_map'), which POV-Ray's map entries see too. iris once used
// 0.5 + 0.5 n.v, ignored the ranges and the altitude, and dropped such
// a transform (19.9 dB here without the point_at sphere, which iris did
// not parse; slopemt_36 14.8 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.5, -7> look_at <0, 0.6, 0> right x*4/3 angle 48 }
light_source { <-5, 9, -6> color rgb 1 }
#declare Grass = texture { pigment { rgb <0.2, 0.5, 0.1> } }
#declare Rock = texture { pigment { rgb <0.5, 0.45, 0.4> } }
#declare Snow = texture { pigment { rgb 1 } }
#declare Low = texture { slope { -y*3, 0, 0.5 altitude y, 0.0, 0.8 }
  texture_map { [0.45 Grass] [0.55 Rock] } }
#declare High = texture { slope { -y, 0.1, 0.6 altitude y, 0.5, 1.5 }
  texture_map { [0.6 Snow] [0.6 Rock] } }
plane { y, 0 pigment { slope { x, 0.4, 0.6 } color_map { [0 rgb <0.3, 0.3, 0.8>] [1 rgb <0.8, 0.8, 0.3>] } } }
sphere { <-1.6, 1, 0>, 1
  texture { gradient y scale 2 texture_map { [0.5 Low] [0.5 High] } } }
cone { <1.4, 0, 0>, 1.2, <1.4, 2.2, 0>, 0.1
  texture { gradient y scale 2 texture_map { [0.5 Low] [0.5 High] } } }
sphere { <0, 0.5, -1.5>, 0.5
  pigment { slope { point_at <-3, 5, -4> } color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } } }
