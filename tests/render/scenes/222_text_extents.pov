// SPDX-License-Identifier: MIT
// 222_text_extents.pov: text placed by its min_extent/max_extent and by
// shapes.inc's Text_Width, as scenes centre and stack words. POV-Ray's
// box of a text is the union of its glyphs' boxes: each glyph's glyf
// header box widened by all its points (off-curve ones too), an empty
// glyph (a space) its pen point. iris took the outline's tight box, so
// the leading space of " wide" was dropped and the bar under "Wavy"
// (its width from Text_Width) came out short: 19.0 dB at 80x60 +A0.3,
// now 57.5 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "shapes.inc"
camera { location <0, 0.6, -5> look_at <0, 0.6, 0> }
light_source { <-3, 6, -8> color rgb 1 }
plane { z, 0.3 pigment { rgb <0.85, 0.85, 0.8> } }
#declare T1 = text { ttf "timrom.ttf" " wide" 0.3, 0 }
#declare Lo = min_extent(T1);
#declare Hi = max_extent(T1);
object { T1 translate -(Lo + Hi) / 2 scale 1.4 / (Hi.y - Lo.y)
         translate <0, 1.3, 0> pigment { rgb <0.8, 0.2, 0.1> } }
#declare W = Text_Width("crystal.ttf", "Wavy", 1, 0);
text { ttf "crystal.ttf" "Wavy" 0.2, 0 translate <-W / 2, -0.3, 0>
       pigment { rgb <0.1, 0.3, 0.8> } }
box { <-W / 2, -0.5, -0.1>, <W / 2, -0.4, 0.1> pigment { rgb <0.1, 0.6, 0.2> } }
