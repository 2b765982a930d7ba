// SPDX-License-Identifier: MIT
// lit_furnace.pov: a point light of colour 1 at the centre of a closed
// diffuse sphere of albedo a = 0.4, seen from inside (gather.sh), under
// radiosity with recursion_limit L. POV-Ray's radiosity sees L bounces
// after the direct light a: a + a^2 + ... + a^(L+1), 0.624 for L = 2 and
// 0.6496 for L = 3 (POV-Ray 3.7 renders 0.62401 and 0.64960). iris: the
// gather is the first bounce, the global map the L - 1 after it.
#version 3.7;
#ifndef (L) #declare L = 2; #end
global_settings { assumed_gamma 1 radiosity { recursion_limit L } }
camera { location <0, 0, -0.5> look_at <0, 0, 1> angle 70 }
light_source { <0, 0, 0> color rgb 1 }
sphere { 0, 2 pigment { color rgb 0.4 } finish { ambient 0 diffuse 1 } }
