// SPDX-License-Identifier: MIT
// glow.pov: the plane of open_sky.pov under a black sky, lit only by a
// huge emissive sphere around it (emission 1, pigment 0.5: radiance
// 0.5 towards the plane), no light source (gather.sh). A photon map
// cannot carry this light (it does not start at a light source); the
// gather sees it as POV-Ray's radiosity does: 0.7 x 0.5 = 0.35.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { } }
camera { location <0, 5, 0> look_at <0, 0, 0> angle 30 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.7 } }
sphere { 0, 1000 hollow
  pigment { rgb 0.5 } finish { ambient 0 emission 1 diffuse 0 } }
