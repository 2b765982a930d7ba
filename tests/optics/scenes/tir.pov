// SPDX-License-Identifier: MIT
// tir.pov (tests/optics/optics.sh, check "total internal reflection"): a
// right-angle glass prism of index N (legs 2 along x and y, hypotenuse
// x + y = 2, 2 deep in z) in a horizontal round beam (a cylinder light
// along +x, radius 0.3, centred at y = 0.6). The beam enters the vertical
// leg square-on and meets the hypotenuse at 45 degrees: beyond the
// critical angle asin(1/N) (41.8 degrees for N = 1.5) it is reflected
// totally, straight down through the bottom leg onto the floor y = -1;
// below it (N < 1.414) part of it leaves through the hypotenuse towards
// the wall x = 3. VIEW 1 looks at the floor under the prism, VIEW 2 at
// the wall; both lie outside the incident beam or in the prism's shadow.
#version 3.7;
#ifndef (N) #declare N = 1.5; #end
#ifndef (VIEW) #declare VIEW = 1; #end
global_settings {
  assumed_gamma 1
  max_trace_level 20
  photons { spacing 0.001 autostop 0 }
}
#if (VIEW = 1)
  // the floor x in [1.2, 1.6], z in [-0.2, 0.2], from between it and
  // the prism
  camera { orthographic location <1.4, -0.5, 0> direction <0, -1, 0>
    right <0.4, 0, 0> up <0, 0, 0.4> }
#else
  // the wall y in [-1, 1.4], z in [-0.3, 0.3]; image rows 0.01 apart
  camera { orthographic location <2.5, 0.2, 0> direction <1, 0, 0>
    right <0, 0, 0.6> up <0, 2.4, 0> }
#end
light_source { <-5, 0.6, 0> color rgb 1
  cylinder point_at <0, 0.6, 0> radius 0.3 falloff 0.3 tightness 0
  photons { refraction on reflection on }
}
plane { y, -1 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
plane { -x, -3 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
prism { linear_sweep linear_spline -1, 1, 4, <0, 0>, <2, 0>, <0, 2>, <0, 0>
  rotate -90 * x
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior N }
  photons { target refraction on reflection on collect off }
}
