// SPDX-License-Identifier: MIT
// open_sky.pov: a white diffuse plane (pigment 1, diffuse 0.7) under a
// uniform white background, no light source, radiosity{} (gather.sh).
// Every gather ray escapes and returns 1, so POV-Ray's radiosity term is
// pigment x 1 x diffuse = 0.7 at every pixel; nothing else lights it.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { } }
background { rgb 1 }
camera { location <0, 5, 0> look_at <0, 0, 0> angle 30 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.7 } }
