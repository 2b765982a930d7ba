// SPDX-License-Identifier: MIT
// Transformed pigments share their nested pigment_map trees (session 12:
// mscharrer's tree_of_squares_v4 ran out of parser memory copying a
// 63-pigment tree per transform). The transforms written after a map,
// the pigment's own and the object's, must still reach every level of
// the tree, through a warp, a list pattern's pigments, an average, a
// texture_map's pigments, and (the uv-mapped, which the shared form
// cannot serve and which keeps the copies) a uv-mapped entry and a
// transformed pigment made uv-mapped afterwards.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -9> look_at <0, 0.6, 0> angle 52 }
light_source { <-4, 12, -8> rgb 1 }
background { rgb <0.5, 0.6, 0.7> }

#declare Leaf = pigment { gradient x
    pigment_map { [0 rgb <1, 0.9, 0.2>] [1 rgb <0.1, 0.3, 0.9>] } scale 1.5 }
#declare Mid = pigment { checker
    pigment { Leaf rotate 30 * y }
    pigment { bozo color_map { [0 rgb 0.1] [1 rgb <1, 0.4, 0.2>] } scale 0.6 }
    warp { turbulence 0.2 } scale 1.4 }
#declare Top = pigment { hexagon
    pigment { Mid }
    pigment { Mid scale 0.5 translate 0.3 * x }
    pigment { average pigment_map { [1 Leaf] [1 Mid rotate 45 * y] } }
    rotate -90 * x }

plane { y, 0 pigment { Top scale 1.6 rotate 20 * y translate <0.2, 0, 0.1> } }
box { <-1, 0, -1>, <1, 2, 1>
      pigment { Top translate <0.5, 0.5, 0> scale 0.4 }
      rotate 25 * y scale <0.8, 1, 0.8> translate <-2.5, 0, 1> }
sphere { 0, 1
         texture { gradient y
             texture_map { [0 pigment { Mid scale 0.3 }]
                           [1 pigment { Top rotate 90 * x scale 0.2 }] } }
         rotate 40 * z translate <0.2, 1, 0.5> }
box { <-1, 0, -1>, <1, 2, 1>
      pigment { checker pigment { Mid }
                pigment { uv_mapping gradient x
                          pigment_map { [0 Leaf] [1 Mid scale 0.1] } scale 0.25 }
                scale 0.5 }
      scale 0.8 translate <2.5, 0, 1> }
box { <-1, -1, -1>, <1, 1, 1>
      texture { uv_mapping pigment { Mid scale 0.3 } }
      scale 0.5 rotate 30 * y translate <0.8, 0.5, -2.5> }
