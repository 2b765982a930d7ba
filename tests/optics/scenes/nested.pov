// SPDX-License-Identifier: MIT
// nested.pov (tests/optics/optics.sh, check "nested interiors"): a glass
// plate (n = NG) immersed in a water layer (n = NW): a box of glass
// inside a box of water, as POV-Ray scenes build it (the ray's interior
// stack gives the indices on both sides of each surface: water | glass
// inside, povray-3.7-semantics.md §1.2). A round parallel beam (a
// cylinder light of radius 0.6) falls TILT degrees from the vertical on
// the middle of the stack, whose edges are far outside the beam (light
// entering a side face would land elsewhere on the floor); the floor
// under it is lit by photons only.
#version 3.7;
#ifndef (TILT) #declare TILT = 0; #end
#ifndef (NW) #declare NW = 1.33; #end
#ifndef (NG) #declare NG = 1.5; #end
global_settings {
  assumed_gamma 1
  max_trace_level 30
  photons { spacing 0.004 autostop 0 }
}
// looking down at x in [-0.35, 0.05], z in [-0.2, 0.2]: inside the
// beam's footprint at every tilt used (the stack shifts it by < 0.3
// towards -x; the footprint is 0.6/cos(TILT) by 0.6 in radius)
camera { orthographic location <-0.15, 0.5, 0> direction <0, -1, 0>
  right <0.4, 0, 0> up <0, 0, 0.4> }
light_source { <0, 10, 0> color rgb 1
  cylinder point_at <0, 0, 0> radius 0.6 falloff 0.6 tightness 0
  rotate TILT * z
  photons { refraction on reflection on }
}
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-3, 1, -3>, <3, 1.3, 3>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior NW }
  photons { target refraction on reflection on collect off }
}
box { <-2.8, 1.1, -2.8>, <2.8, 1.2, 2.8>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior NG }
  photons { collect off }
}
