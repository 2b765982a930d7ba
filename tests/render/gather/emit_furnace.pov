// SPDX-License-Identifier: MIT
// emit_furnace.pov: seen from inside, a closed sphere that glows
// (pigment p = 0.5, emission 1) and reflects diffusely (diffuse 0.8,
// albedo a = p x diffuse = 0.4); no light source, so there is no global
// photon map and every bounce is the gather's (gather.sh). POV-Ray's
// radiosity stops gathering at recursion_limit L: the deepest hits show
// their emission p alone, each level above adds a times the one below,
// so a pixel is p (1 + a + ... + a^L): 0.7, 0.78, 0.812 for L = 1, 2, 3.
// The radiance is the same everywhere: no quadrature or cache error.
#version 3.7;
#ifndef (L) #declare L = 2; #end
global_settings { assumed_gamma 1 radiosity { recursion_limit L } }
camera { location <0, 0, -0.5> look_at <0, 0, 1> angle 70 }
sphere { 0, 2 hollow pigment { rgb 0.5 }
  finish { ambient 0 emission 1 diffuse 0.8 } }
