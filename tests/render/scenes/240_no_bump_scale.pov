// SPDX-License-Identifier: MIT
// 240_no_bump_scale.pov: 'no_bump_scale' in a normal keeps the normal
// unnormalised on its way into and out of pattern space (POV-Ray's
// Warp_Normal / UnWarp_Normal with DONT_SCALE_BUMPS_FLAG), so a pattern
// scaled by s has its bumps made 1/s times stronger; a normal_map hands
// the flag to its entries. Left: bumps scaled 0.2 inside an object
// scaled 1.2; middle: a normal_map (entries inherit the flag) under a
// non-uniform scale; right: a slope_map pattern normal (tetrahedron
// differences); the floor's texture holds the flag, which POV-Ray's
// Post_Textures hands to the texture's normal (POV-Ray also takes it,
// to no effect, in a pigment: left). iris dropped the keyword in a
// normal and refused it in a texture and a pigment (a scene error); with
// all taken out, 80x60 +A0.3: 18.8 dB before, identical after.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 texture { pigment { rgb 0.8 } normal { bumps 0.5 scale 0.3 }
  scale 0.5 no_bump_scale } }
sphere { <-1.5, 1, 0>, 0.75
  pigment { granite no_bump_scale color_map { [0 rgb 1] [1 rgb <1, 0.8, 0.6>] } }
  normal { bumps -1 scale 0.2 no_bump_scale } scale 1.2 }
sphere { <0, 1, 0>, 0.9 pigment { rgb <1, 0.8, 0.6> }
  normal { gradient y normal_map { [0 bumps 0.3 scale 0.5] [1 dents 0.6 scale 0.7] }
    no_bump_scale scale <0.3, 0.5, 0.4> } }
sphere { <1.5, 1, 0>, 0.9 pigment { rgb <0.6, 0.8, 1> }
  normal { marble 0.4 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] }
    turbulence 0.3 scale <0.25, 0.4, 0.25> no_bump_scale }
  finish { phong 0.6 } }
