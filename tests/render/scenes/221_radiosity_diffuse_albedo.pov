// SPDX-License-Identifier: MIT
// 221_radiosity_diffuse_albedo.pov: the radiosity term of a finish with
// 'diffuse albedo D' and brilliance B takes D as written (POV-Ray 3.7's
// RawDiffuse), while the light sources see D * (B + 1) / 2. The room of
// scene 81 with the sphere and the back wall at brilliance 4 and 3: the
// light's direct term on them is 2.5 and 2 times their diffuse, their
// indirect light is not. iris gathered with the scaled diffuse: 26.8 dB
// at 80x60 +A0.3; now 43.6-44.0 over 3 runs (scene 81: 46.1).
// parity-min-psnr: 40 two noisy estimators of the same light, as in scene
// 81 (its note gives the run-to-run spread).
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 100 } }
camera { location <0, 2.5, -7.5> look_at <0, 2.5, 0> angle 45 }
light_source { <0, 4.5, 0> color rgb 1 }
#declare W = finish { ambient 0 diffuse 0.75 }
box { <-2.5, -0.1, -2.5>, <2.5, 0, 2.5> pigment { rgb 0.8 } finish { W } }
box { <-2.5, 5, -2.5>, <2.5, 5.1, 2.5> pigment { rgb 0.8 } finish { W } }
box { <-2.5, 0, 2.5>, <2.5, 5, 2.6> pigment { rgb 0.8 }
      finish { ambient 0 diffuse albedo 0.3 brilliance 3 } }
box { <-2.6, 0, -2.5>, <-2.5, 5, 2.5> pigment { rgb <0.8, 0.15, 0.1> } finish { W } }
box { <2.5, 0, -2.5>, <2.6, 5, 2.5> pigment { rgb <0.15, 0.7, 0.15> } finish { W } }
box { <-1.3, 0, -0.2>, <-0.1, 2.2, 1.0> rotate 20 * y pigment { rgb 0.8 } finish { W } }
sphere { <1.0, 0.8, -0.6>, 0.8 pigment { rgb 0.8 }
         finish { ambient 0 diffuse albedo 0.3 brilliance 4 } }
