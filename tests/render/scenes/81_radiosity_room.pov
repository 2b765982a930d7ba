// SPDX-License-Identifier: MIT
// 81_radiosity_room.pov: a small Cornell box lit by one point light under
// radiosity{} (iris: a final gather whose rays read the global photon
// map, src/render/gather.c; POV-Ray: its radiosity with
// recursion_limit 2). The walls' colour bleeding and the light in the
// ceiling, which the light does not reach directly, come from it.
// parity-min-psnr: 40 two noisy estimators of the same light: the
// gather's cache and direction set differ from POV-Ray's, and iris's
// second bounce is a photon map estimate where POV-Ray gathers again;
// measured 45.8-46.8 dB over 3 runs (POV-Ray's threaded radiosity varies from
// run to run). Before the global map stopped at recursion_limit (it
// carried every bounce, 7% more light in a furnace of albedo 0.4):
// 33.0-33.6 dB; the global photon map alone: 29.7 dB
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 100 } }
camera { location <0, 2.5, -7.5> look_at <0, 2.5, 0> angle 45 }
light_source { <0, 4.5, 0> color rgb 1 }
#declare W = finish { ambient 0 diffuse 0.75 }
box { <-2.5, -0.1, -2.5>, <2.5, 0, 2.5> pigment { rgb 0.8 } finish { W } }
box { <-2.5, 5, -2.5>, <2.5, 5.1, 2.5> pigment { rgb 0.8 } finish { W } }
box { <-2.5, 0, 2.5>, <2.5, 5, 2.6> pigment { rgb 0.8 } finish { W } }
box { <-2.6, 0, -2.5>, <-2.5, 5, 2.5> pigment { rgb <0.8, 0.15, 0.1> } finish { W } }
box { <2.5, 0, -2.5>, <2.6, 5, 2.5> pigment { rgb <0.15, 0.7, 0.15> } finish { W } }
box { <-1.3, 0, -0.2>, <-0.1, 2.2, 1.0> rotate 20 * y pigment { rgb 0.8 } finish { W } }
sphere { <1.0, 0.8, -0.6>, 0.8 pigment { rgb 0.8 } finish { W } }
