// SPDX-License-Identifier: MIT
// ambient_sky.pov: a diffuse plane (pigment 0.7, ambient 0.5, diffuse
// 0.8) under a uniform white background, no light source, radiosity{}
// (gather.sh). POV-Ray 3.7 counts ambient only where radiosity runs not:
// at +Q9 the pixel is the radiosity term 0.7 x 1 x 0.8 = 0.56 and
// ambient is dropped; at +Q8 (no radiosity) it is the ambient term
// 0.7 x 0.5 x ambient_light 1 = 0.35. POV-Ray 3.7 renders 0.56 and 0.35.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { } }
background { rgb 1 }
camera { location <0, 5, 0> look_at <0, 0, 0> angle 30 }
plane { y, 0 pigment { rgb 0.7 } finish { ambient 0.5 diffuse 0.8 } }
