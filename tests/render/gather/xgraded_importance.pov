// SPDX-License-Identifier: MIT
// xgraded_importance.pov: the plane of open_sky.pov under a sky whose
// radiance is (1 + x) / 2 (black towards -x, white towards +x), no light,
// and #default { radiosity { importance 0.5 } }: the sky and the plane
// take 0.5, so each sample shades 18 of its 35 rays, counted 35/18 times
// (gather.sh). The x term integrates to 0 over the hemisphere, so
// E = 1/2 and every pixel is 0.7 x 1/2 = 0.35 with or without
// importance; rays chosen from one side of the sky would miss it by up
// to 0.7 x 1/4.
#version 3.7;
global_settings { assumed_gamma 1 radiosity { } }
#default { radiosity { importance 0.5 } }
sky_sphere {
  pigment { gradient x color_map { [0 rgb 0] [1 rgb 1] } scale 2 translate -x }
}
camera { location <0, 5, 0> look_at <0, 0, 0> angle 30 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 0.7 } }
