// SPDX-License-Identifier: MIT
// An orthographic camera with an angle and no look_at: POV-Ray's
// Parse_Camera sizes right and up for the view at the look_at point even
// then, from the default look_at <0, 0, 1> (t-o-k's Icosahedron:
// 'orthographic direction +z location -24*z angle 15'). iris sized
// them only when a look_at was given: 5.3 dB before session 12.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic direction z right 4/3 * x up y location -12 * z
         angle 20 }
light_source { <-5, 8, -10> rgb 1 }
background { rgb <0.3, 0.35, 0.4> }
sphere { 0, 1.2 pigment { checker rgb <0.9, 0.4, 0.2> rgb 0.9 scale 0.4 } }
torus { 1.8, 0.15 rotate 70 * x pigment { rgb <0.2, 0.6, 0.9> } }
box { <-2.6, -2, 1>, <2.6, -1.7, 3> pigment { rgb 0.7 } }
