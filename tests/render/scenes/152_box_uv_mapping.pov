// SPDX-License-Identifier: MIT
// 152_box_uv_mapping.pov: a box's uv coordinates under uv_mapping.
// POV-Ray's Box::UVCoord unfolds the box as a cube cross: with the hit
// point taken to [0,1] per axis over the box, the -x face gets
// u = z/4, v = 1/3 + y/3, +x u = 3/4 - z/4, -y u = 1/4 + x/4, v = z/3,
// +y v = 1 - z/3, -z u = 1 - x/4, +z u = 1/4 + x/4 (v = 1/3 + y/3 on the
// four sides). Three rotated, non-cubic boxes show three faces each: a
// checker (4 x 3 cells per face, so a face's place in the cross and its
// orientation both show), a gradient in u and one in v. The middle box's
// corners are given high first (POV-Ray orders them). Without box uv
// (every hit at uv 0, a flat colour per box) iris scored 16.65 dB here
// (inf with it).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.2, -9> look_at <0, 0, 0> right x*4/3 angle 50 }
light_source { <-20, 30, -30> color rgb 1 }
background { rgb <0.1, 0.15, 0.3> }
#declare F = finish { ambient 0.25 diffuse 0.75 }
box { <-1, -1.2, -0.8>, <1, 1.2, 0.8>
  pigment { uv_mapping checker rgb <0.9, 0.2, 0.1>, rgb <0.95, 0.95, 0.8>
            scale <1/16, 1/9, 1> }
  finish { F }
  rotate <-25, 35, 10> translate <-2.6, 0, 0>
}
box { <0.9, 1.1, 1>, <-0.9, -1.1, -1>
  pigment { uv_mapping gradient x
            color_map { [0 rgb <0.1, 0.2, 0.9>] [0.5 rgb <1, 0.9, 0.2>]
                        [1 rgb <0.1, 0.7, 0.3>] } }
  finish { F }
  rotate <30, -40, 0>
}
box { <-0.8, -1.2, -1>, <0.8, 1.2, 1>
  pigment { uv_mapping gradient y
            color_map { [0 rgb <0.9, 0.1, 0.6>] [0.5 rgb <0.95, 0.95, 0.95>]
                        [1 rgb <0.2, 0.8, 0.9>] } }
  finish { F }
  rotate <-30, 200, -15> translate <2.6, 0, 0>
}
