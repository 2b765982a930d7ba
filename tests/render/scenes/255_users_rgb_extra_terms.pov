// SPDX-License-Identifier: MIT
// 'rgb' given more terms than three: POV-Ray's Parse_Colour copies every
// term with a warning ("Suspicious expression after rgb"), so
// 'rgb <0.1, 0.1, 0.1, 1>' filters fully (2-complex's domino: a floor
// that shows only its reflection; iris dropped the fourth term, 10.8 dB
// before session 12). rgbt's fourth term is transmit and a fifth is
// lost; rgbf's fifth is transmit.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.5, 0> angle 50 }
light_source { <-3, 8, -4> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, -0.1 pigment { rgb <0.6, 0.5, 0.3> } }
plane { y, 0 pigment { rgb <0.1, 0.1, 0.1, 1> } finish { reflection 0.3 } }
box { <-1.8, 0, -0.5>, <-0.8, 1, 0.5> pigment { rgb <0.9, 0.3, 0.2> } }
sphere { <0.2, 0.6, 0>, 0.6 pigment { rgbt <0.2, 0.9, 0.3, 0.6, 0.9> } }
sphere { <1.5, 0.5, 0>, 0.5 pigment { rgbf <0.3, 0.4, 1, 0.2, 0.5> } }
