// SPDX-License-Identifier: MIT
// Transformed normals share their normal_map trees (session 12, after the
// pigment maps of scene 252): the transforms written after a map, the
// normal's own and the object's, must still reach every level of the
// tree, as points and as normal directions (a non-uniform scale tilts
// the bumps). Through a warp, a list pattern's normals, an average,
// no_bump_scale, a texture_map's normals, and (the uv-mapped, which keep
// the copies) a uv-mapped entry and a transformed normal made uv-mapped
// afterwards.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 6, -9> look_at <0, 0.6, 0> angle 52 }
light_source { <-4, 12, -8> rgb 1 }
light_source { <6, 3, -6> rgb 0.4 }
background { rgb <0.5, 0.6, 0.7> }

#declare Leaf = normal { gradient x
    normal_map { [0 bumps 0.8 scale 0.2] [1 waves 0.9 scale 0.3] } scale 1.5 }
#declare Mid = normal { checker
    normal { Leaf rotate 30 * y }
    normal { dents 0.9 scale 0.4 }
    warp { turbulence 0.2 } scale <1.4, 0.5, 1> }
#declare Top = normal { hexagon
    normal { Mid }
    normal { Mid scale 0.5 translate 0.3 * x }
    normal { average normal_map { [1 Leaf] [1 Mid rotate 45 * y] } }
    rotate -90 * x }
#declare Plain = pigment { rgb <0.9, 0.8, 0.6> }

plane { y, 0 pigment { Plain }
        normal { Top scale <1.6, 1, 0.7> rotate 20 * y translate <0.2, 0, 0.1> } }
box { <-1, 0, -1>, <1, 2, 1>
      pigment { Plain }
      normal { Top translate <0.5, 0.5, 0> scale 0.4 }
      rotate 25 * y scale <0.8, 1, 0.5> translate <-2.5, 0, 1> }
sphere { 0, 1
         texture { gradient y
             texture_map { [0 pigment { Plain } normal { Mid scale 0.3 }]
                           [1 pigment { rgb <0.4, 0.7, 0.9> }
                              normal { Top rotate 90 * x scale 0.2 }] } }
         scale <1, 0.7, 1> rotate 40 * z translate <0.2, 1, 0.5> }
// (its own tree: POV-Ray's no_bump_scale marks the shared map's entries
// for every user of a declared map, so Mid would change the others)
sphere { 0, 0.8
         pigment { Plain }
         normal { checker
                  normal { gradient x
                           normal_map { [0 bumps 0.8 scale 0.2]
                                        [1 waves 0.9 scale 0.3] }
                           scale 1.5 rotate 30 * y }
                  normal { dents 0.9 scale 0.4 }
                  warp { turbulence 0.2 } scale <1.4, 0.5, 1>
                  no_bump_scale scale <0.3, 1, 0.3> }
         scale <1.5, 1, 1> translate <-0.7, 0.8, -2.8> }
box { <-1, 0, -1>, <1, 2, 1>
      pigment { Plain }
      normal { checker normal { Mid }
               normal { uv_mapping gradient x
                        normal_map { [0 Leaf] [1 Mid scale 0.1] } scale 0.25 }
               scale 0.5 }
      scale 0.8 translate <2.5, 0, 1> }
box { <-1, -1, -1>, <1, 1, 1>
      texture { uv_mapping pigment { Plain } normal { Mid scale 0.3 } }
      scale 0.5 rotate 30 * y translate <1.2, 0.5, -2.5> }
