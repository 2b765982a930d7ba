// SPDX-License-Identifier: MIT
// 220_diffuse_albedo_raw.pov: 'diffuse albedo D' with brilliance B
// multiplies diffuse, and the back side's diffuse, by (B + 1) / 2 for the
// light sources; subsurface (its reduced albedo) and radiosity take the
// diffuse as written (POV-Ray 3.7's RawDiffuse). The wax sphere has
// brilliance 3, so its subsurface colour came from a diffuse twice too
// large in iris (povparse/mat.c scaled it in place); the disc, lit from
// behind, shows 'diffuse albedo 0.3, 0.5': iris left the back side
// unscaled. 80x60 +A0.3: 23.9 dB before, 49.2 dB after.
// parity-min-psnr: 45 the BSSRDF is sampled as in scene 210 (POV-Ray's
// own renders of this scene with +WT1 and +WT2 differ by 53.0 dB).
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 20
  subsurface { samples 200, 20 }
}
camera { location <0, 1.4, -4> look_at <0, 0.7, 0> angle 40 }
light_source { <-5, 8, -6> rgb 1 }
light_source { <3, 1.5, 6> rgb 0.8 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0.1 diffuse 0.7 } }
sphere {
  <-0.45, 0.7, 0>, 0.7
  pigment { rgb <0.9, 0.6, 0.3> }
  finish {
    ambient 0.05 diffuse albedo 0.5 brilliance 3
    subsurface { translucency <2, 1, 0.5> }
  }
  interior { ior 1.4 }
}
disc { <0.95, 0.8, 0.3>, <0.2, 0, -1>, 0.55
  pigment { rgb <0.3, 0.9, 0.5> }
  finish { ambient 0.05 diffuse albedo 0.3, 0.5 brilliance 2 } }
