// SPDX-License-Identifier: MIT
// light_falloff.pov (tests/optics/optics.sh, check "light falloff"): a
// white floor lit directly by one light 1 above it, seen from above along
// a strip z in [-2, 2] (200 rows, 0.02 each, top row +z; 4 columns at
// x = +-0.01, +-0.03). LIGHT = 1: a point light with fade_distance 1, fade_power 2;
// LIGHT = 2: a spotlight pointing straight down, radius 20, falloff 40,
// tightness 5 (degrees; POV-Ray 3.7's meaning of each,
// povray-3.7-semantics.md). No photons, no antialiasing: each pixel is
// one ray through its centre.
#version 3.7;
#ifndef (LIGHT) #declare LIGHT = 1; #end
global_settings { assumed_gamma 1 max_trace_level 5 }
camera { orthographic location <0, 0.5, 0> direction <0, -1, 0>
  right <0.08, 0, 0> up <0, 0, 4> }
#if (LIGHT = 1)
  light_source { <0, 1, 0> color rgb 1 fade_distance 1 fade_power 2 }
#else
  light_source { <0, 1, 0> color rgb 1 spotlight point_at <0, 0, 0>
    radius 20 falloff 40 tightness 5 }
#end
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
