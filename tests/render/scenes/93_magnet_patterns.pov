// SPDX-License-Identifier: MIT
// 93_magnet_patterns.pov: the magnet fractal patterns
// (src/material/fractal_pattern.c): magnet 1 and 2 in mandel and julia
// form with the mandel/julia colourings, and magnet 1 mandel as a normal.
// The old iris warned and drew them as plain mandel/julia: 11.1 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 0, -10> look_at <0, 0, 0>
         right x * 8 up y * 6 }
light_source { <-5, 5, -10> color rgb 1 }
#declare F = finish { ambient 0.3 diffuse 0.7 }
#declare M = color_map { [0 rgb <0.1, 0.1, 0.3>] [0.3 rgb <0.9, 0.5, 0.2>]
                         [1 rgb <1, 1, 0.8>] }
box { <-4, 0, 0>, <0, 3, 1>
      pigment { magnet 1 mandel 40 color_map { M } exterior 1, 1
                translate <-1, -1.5, 0> scale 0.8 translate <-2, 1.5, 0> }
      finish { F } }
box { <0, 0, 0>, <4, 3, 1>
      pigment { magnet 2 mandel 40 color_map { M } interior 1, 50
                exterior 5, 1
                translate <-1.2, -1.5, 0> scale 0.9 translate <2, 1.5, 0> }
      finish { F } }
box { <-4, -3, 0>, <0, 0, 1>
      pigment { magnet 1 julia <1.5, 0.4>, 40 color_map { M }
                translate <-1, 0, 0> translate <-2, -1.5, 0> }
      finish { F } }
box { <0, -3, 0>, <4, 0, 1>
      pigment { rgb <0.8, 0.7, 0.6> }
      normal { magnet 2 julia <0.9, 0.6>, 30 0.5
               translate <-1, 0, 0> translate <2, -1.5, 0> }
      finish { F } }
