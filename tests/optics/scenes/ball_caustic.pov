// SPDX-License-Identifier: MIT
// ball_caustic.pov (tests/optics/optics.sh, check "ball lens"): a clear
// glass ball (radius 1, n = 1.5, no dispersion) in a parallel white light
// from straight above, a white floor 0.1 below it (y = -1.1). The ball's
// spherical aberration folds the refracted light into a bright ring (the
// caustic) around a brighter centre; the test traces the same fan of
// rays with Snell's law and Fresnel to predict the ring's radius and the
// irradiance inside it. The floor under the ball is lit only through it.
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.01 autostop 0 }
}
// between the ball and the floor, looking straight down at x, z in
// [-0.2, 0.2]: image rows run along z (top row +z)
camera { orthographic location <0, -1.05, 0> direction <0, -1, 0>
  right <0.4, 0, 0> up <0, 0, 0.4> }
light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
plane { y, -1.1 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { 0, 1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off }
}
