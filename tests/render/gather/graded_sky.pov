// SPDX-License-Identifier: MIT
// graded_sky.pov: the plane of open_sky.pov under a sky whose radiance
// is the cosine of the zenith angle (gradient y, black at the horizon,
// white at the zenith), no light (gather.sh). The irradiance the gather
// estimates is the cosine-weighted mean radiance
//   E = (1/pi) integral cos(theta) cos(theta) dw = 2/3,
// so every pixel is 0.7 x 2/3 = 0.4667: a check that the gather rays are
// cosine distributed (uniform ones would give 1/2, i.e. 0.35).
#version 3.7;
global_settings { assumed_gamma 1 radiosity { } }
sky_sphere {
  pigment { gradient y color_map { [0 rgb 0] [1 rgb 1] } }
}
camera { location <0, 5, 0> look_at <0, 0, 0> angle 30 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.7 } }
