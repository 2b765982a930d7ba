// SPDX-License-Identifier: MIT
// 135_no_radiosity.pov: no_radiosity hides an object from radiosity's
// gather rays only (POV-Ray 3.7's NoSomethingFlagRayObjectCondition:
// radiosity rays skip it as camera rays skip no_image objects); the
// camera and shadow rays still see it. A wide glowing red wall beside a
// white floor under a uniform sky: the floor gathers the whole sky, no red
// bleeding and no occlusion, while the wall shows and casts its shadow.
// parity-min-psnr: 40 both renderers estimate the sky's light with 100
// rays per cached sample from their own direction sets and caches;
// measured 50.0-51.8 dB over 3 POV-Ray runs. With the wall seen by the
// gather rays (no_radiosity ignored, before session 5) 30.3 dB
#version 3.7;
global_settings { assumed_gamma 1 radiosity { count 100 recursion_limit 1 } }
background { rgb <0.5, 0.6, 0.8> }
camera { location <0, 3, -6> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 10, -8> color rgb 0.8 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0 diffuse 0.8 } }
box { <-1.5, 0, -0.2>, <1.5, 2.5, 0.2>
  pigment { rgb <1, 0.1, 0.05> } finish { ambient 0 emission 1.5 diffuse 0.4 }
  no_radiosity }
sphere { <1.8, 0.5, -0.8>, 0.5 pigment { rgb 0.9 } finish { ambient 0 diffuse 0.8 } }
