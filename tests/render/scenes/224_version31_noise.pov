// A #version 3.1 scene (users' older scenes): POV-Ray 3.7 picks the
// default noise generator from the version the scene ends with, 1 (the
// original Perlin noise) before 3.5 and 2 after (Parser::Parse; each
// #version also sets it, tokenize.cpp), unless global_settings gives
// noise_generator. textures.inc switches to 3.5 and back, so Jade, a
// marble with turbulence, renders with generator 1 here (iris used 2:
// 45.9 dB at 80x60 for Jade alone; this scene, patterns everywhere,
// 31.7 dB, now 72 dB; at #version 3.6 both were identical).
#version 3.1;
#include "colors.inc"
#include "textures.inc"
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <3, 8, -5> color White }
plane { y, -1 pigment { bozo turbulence 0.8 color_map { [0 color Gray80] [1 color Gray20] } scale 0.5 } }
sphere { <-1.2, 0.5, 0>, 1 texture { Jade } }
sphere { <1.2, 0.5, 0>, 1 pigment { bozo turbulence 0.5 color_map { [0 color Red] [1 color Yellow] } scale 0.3 } }
box { <-0.5, -1, 1.5>, <0.5, 0, 2.5> pigment { granite color_map { [0 color Blue] [1 color White] } } }
