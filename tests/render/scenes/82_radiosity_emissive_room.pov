// SPDX-License-Identifier: MIT
// 82_radiosity_emissive_room.pov: a small room lit only by a glowing
// ceiling panel, no light source (iris: no global photon map, so the
// gather's rays gather again down to recursion_limit 2, as POV-Ray's
// radiosity does; src/render/gather.c). Much of the light on the walls
// is the second bounce: with one bounce only (what iris rendered before
// it recursed) the image is 22.4-22.6 dB from POV-Ray's.
// parity-min-psnr: 28 two noisy estimators of the same light: each
// renderer's cache and direction set (iris: a golden-angle spiral and a
// pretrace grid; POV-Ray: its direction pool and octree) err by a few
// percent at different places, POV-Ray's default settings 13% brighter
// than its own converged image (count 400: iris and POV-Ray then agree to
// 42.6 dB); measured 29.9-31.4 dB over 4 runs (POV-Ray's threaded
// radiosity varies from run to run)
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 60 } }
camera { location <0, 2.5, -7.5> look_at <0, 2.2, 0> angle 45 }
#declare W = finish { ambient 0 diffuse 0.8 }
box { <-2.5, -0.1, -2.5>, <2.5, 0, 2.5> pigment { rgb 0.8 } finish { W } }
box { <-2.5, 5, -2.5>, <2.5, 5.1, 2.5> pigment { rgb 0.8 } finish { W } }
box { <-2.5, 0, 2.5>, <2.5, 5, 2.6> pigment { rgb 0.8 } finish { W } }
box { <-2.6, 0, -2.5>, <-2.5, 5, 2.5> pigment { rgb <0.8, 0.2, 0.1> } finish { W } }
box { <2.5, 0, -2.5>, <2.6, 5, 2.5> pigment { rgb <0.15, 0.7, 0.2> } finish { W } }
box { <-1, 4.95, -1>, <1, 5, 1> pigment { rgb 1 }
  finish { ambient 0 diffuse 0 emission 3 } }
box { <-1.3, 0, -0.2>, <-0.1, 2.2, 1.0> rotate 20 * y pigment { rgb 0.8 } finish { W } }
sphere { <1.0, 0.8, -0.6>, 0.8 pigment { rgb 0.8 } finish { W } }
