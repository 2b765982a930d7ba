// gradient_vector: POV-Ray normalises a gradient's vector as it parses
// it, so 'gradient x+y' has stripes 1/sqrt(2) apart and 'gradient 2*y'
// is 'gradient y' (pigment, normal and texture_map alike). Measured
// against POV-Ray 3.7.0 before the backdrop was added: identical at 80x60
// (PSNR inf); with the vector as written (stripes 1/|v| apart) 14.3 dB.
// With the turbulence backdrop and the tiles floor: 127.1 dB at 80x60
// +A0.3, 125.7 dB at 320x240. Before 22 Nov 2026 iris read lambda 0 /
// omega 0 / octaves 0 as the defaults (backdrop alone: 14.1 dB at
// 320x240) and put tiles' first texture on checker value 0 (18.4 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 1, 0> right x*4/3 angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
background { rgb 0.2 }
// turbulence with lambda 0, omega 0 and octaves 0, taken literally as
// POV-Ray 3.7 does (octaves clamped to 1): the backdrop's three panels
#declare TurbMap = color_map { [0.2 rgb <0, 0, 1>] [0.5 rgb 1] [0.9 rgb <1, 0, 0>] }
box { <-4.5, -1, 3>, <-1.5, 4, 3.1> pigment { gradient y turbulence 1 lambda 0 color_map { TurbMap } scale 0.5 } }
box { <-1.5, -1, 3>, <1.5, 4, 3.1> pigment { gradient y turbulence 1 omega 0 color_map { TurbMap } scale 0.5 } }
box { <1.5, -1, 3>, <4.5, 4, 3.1> pigment { gradient y warp { turbulence 1 octaves 0 lambda 3 } color_map { TurbMap } scale 0.5 } }
// the old tiles texture: the first texture is checker value 1, tile2 is 0
plane { y, 0 texture { tiles { texture { pigment { rgb <0.9, 0.8, 0.6> } }
  tile2 texture { pigment { rgb 0.3 } } } scale 1.5 } }
box { -1, 1 pigment { gradient x+y color_map { [0.25 rgb <1, 0, 0>] [0.25 rgb 1] [0.75 rgb 1] [0.75 rgb <1, 0, 0>] } scale 0.5 }
  translate <-2.2, 1, 0> }
sphere { <0, 1, 0>, 1 pigment { gradient <1, 1, 1> color_map { [0 rgb <0, 0, 1>] [0.5 rgb <1, 1, 0>] [1 rgb <0, 0, 1>] } scale 0.7 }
  normal { gradient 3*y 0.5 scale 0.2 } }
box { -1, 1 texture { gradient <0, 2, 0> texture_map { [0.5 pigment { rgb <0, 0.6, 0> }] [0.5 pigment { rgb 0.9 }] } scale 0.5 }
  translate <2.2, 1, 0> }
