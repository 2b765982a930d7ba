// SPDX-License-Identifier: MIT
// List patterns given fewer entries than they have: POV-Ray's
// Parse_Blend_List fills the rest, colours from the pattern's default map
// (checker: blue, green; hexagon: blue, green, red; brick: grey, red),
// pigments and textures with the default texture's (black here, the
// '#default' one otherwise). Users write 'checker pigment { color Green }'
// and get green and black squares; iris repeated the last entry (a plain
// green floor) before session 11.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 5, -7> look_at <0, 0, 0.5> angle 50 }
light_source { <-3, 10, -6> rgb 1 }
background { rgb <0.5, 0.6, 0.7> }
plane { y, 0 pigment { checker pigment { color rgb <0.2, 0.8, 0.3> } } }
box { <-3.5, 0, 0>, <-1.3, 1.5, 0.2>
      pigment { hexagon rgb <1, 1, 0.5> rotate -90 * x scale 0.3 } }
box { <-1, 0, 0>, <1, 1.5, 0.2>
      pigment { brick rgb <0.9, 0.9, 0.8> scale 0.1 } }
box { <1.3, 0, 0>, <3.5, 1.5, 0.2>
      texture { checker texture { pigment { rgb <1, 0.5, 0> } } scale 0.4 } }
#default { pigment { rgb <0.6, 0.2, 0.8> } }
sphere { <0, 0.6, -2>, 0.6
         pigment { checker pigment { rgb <1, 1, 1> } scale 0.3 } }
