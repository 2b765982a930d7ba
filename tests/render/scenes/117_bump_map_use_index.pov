// bump_map_use_index: a palette image's bump_map with use_index takes the
// palette index itself as the height (POV-Ray's bump_map: Amount * index,
// so index 4 stands 4 units tall, not a grey level in [0, 1]); the left
// panel uses the indices, the right one the colours' grey (use_color, the
// default). matmap_palette.png's colours run against its indices.
// Measured against POV-Ray 3.7.0: 62.5 dB at 80x60; with grey levels for
// both panels 28.9 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -5> look_at <0, 0.5, 0> right x*4/3 angle 50 }
light_source { <-3, 6, -6> color rgb 1 }
box { <0, 0, 0>, <1, 1, 0.1> pigment { rgb 0.8 }
  normal { bump_map { png "maps/matmap_palette.png" use_index bump_size 0.3 } }
  scale <2, 1.5, 1> translate <-2.1, -0.25, 0> }
box { <0, 0, 0>, <1, 1, 0.1> pigment { rgb 0.8 }
  normal { bump_map { png "maps/matmap_palette.png" use_color bump_size 3 } }
  scale <2, 1.5, 1> translate <0.1, -0.25, 0> }
