// SPDX-License-Identifier: MIT
// 212_subsurface_defaults.pov: subsurface {} with POV-Ray 3.7's defaults
// (samples 50, 50; mm_per_unit 10) under an area light and a spotlight,
// on two objects of different ior (one albedo table each) and a CSG
// piece, with a layered texture whose top layer is half transparent
// (src/render/subsurface.c).
// parity-min-psnr: 38 50 samples each are noisy on both sides: POV-Ray's
// own images with +WT1 and +WT2 differ by 40.9 dB, iris's is 41.0-41.2 dB
// from either. Without subsurface (the diffuse term) it was 30.8 dB.
#version 3.7;
global_settings { assumed_gamma 1.0 subsurface {} }
camera { location <0, 2, -5> look_at <0, 0.6, 0> angle 40 }
light_source { <-4, 6, -5> rgb 0.8 area_light x, y, 3, 3 adaptive 0 }
light_source { <4, 5, -2> rgb 0.7 spotlight point_at <0.8, 0.5, 0> radius 15 falloff 25 }
background { rgb <0.3, 0.35, 0.45> }
plane { y, 0 pigment { rgb 0.4 } }
sphere {
  <-1, 0.6, 0>, 0.6
  pigment { rgb <0.7, 0.85, 0.6> }
  finish { diffuse 0.9 subsurface { translucency 0.8 } }
  interior { ior 1.5 }
}
difference {
  box { <-0.5, 0, -0.5>, <0.5, 1, 0.5> }
  cylinder { <0, 0.5, -1>, <0, 0.5, 1>, 0.25 }
  texture {
    pigment { rgb <0.9, 0.5, 0.4> }
    finish { diffuse 0.8 specular 0.4 subsurface { translucency <1.5, 0.8, 0.4> } }
  }
  texture { pigment { checker rgbt <1, 1, 1, 1> rgbt <0.2, 0.2, 0.6, 0.5> scale 0.2 } }
  interior { ior 1.3 }
  rotate y * 30
  translate <0.9, 0, 0.2>
}
