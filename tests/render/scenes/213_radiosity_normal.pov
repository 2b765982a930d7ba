// SPDX-License-Identifier: MIT
// 213_radiosity_normal.pov: radiosity { normal on } (rad_def.inc's
// Rad_Settings; the examples balcony and benchmark): a bumpy floor and a
// wavy sphere lit only by a sky that is bright on one side (no light
// source), so all their light is radiosity's. With 'normal on' each
// point gathers about its perturbed normal (cut off at the surface) and
// the cache is searched under it, so the bumps show (src/render/gather.c).
// parity-min-psnr: 34 POV-Ray's own images with +WT1 and +WT2 differ by
// 40.2 dB; iris's is 35.9 dB from either. The same scene without the
// normals shows the same gap (iris 39.8 dB, POV-Ray against itself
// 45.2 dB): the gather's cache and direction set, not the normal. With
// 'normal on' ignored (the gather about the raw normal: a flat floor)
// it was 22.4 dB.
#version 3.7;
global_settings { assumed_gamma 1.0
  radiosity { count 100 error_bound 0.3 recursion_limit 1 normal on } }
camera { location <0, 2.2, -4> look_at <0, 0.3, 0> angle 45 }
sky_sphere { pigment { gradient x
  color_map { [0 rgb 0.02] [0.5 rgb 0.2] [1 rgb <1.6, 1.5, 1.3>] }
  scale 2 translate -x } }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 }
  normal { bumps 1.2 scale 0.35 } }
sphere { <0, 0.8, 0.5>, 0.8 pigment { rgb <0.9, 0.7, 0.5> }
  finish { ambient 0 diffuse 0.8 }
  normal { waves 1.0 frequency 3 scale 0.4 } }
