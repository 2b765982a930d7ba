// SPDX-License-Identifier: MIT
// filter.pov (tests/optics/optics.sh, check "filter and transmit"): a
// parallel white light from above through a coloured transparent sheet
// at y = 1 onto a white floor. The sheet's pigment is rgbft <0.9, 0.5,
// 0.2, F, T>; POV-Ray passes light through such a surface multiplied by
// F·colour + T per channel (povray-3.7-semantics.md §3.6; iris: the
// spectral transmittance F·rho(lambda) + T, rho Burns' curve of the
// colour). SHAPE 1: a disc (one surface, crossed once); SHAPE 2: a box
// 0.1 thick (two surfaces: POV-Ray filters at each). Index 1, so no
// Fresnel. PH 0 renders without photons (the floor under the sheet is
// then lit by shadow rays through it).
#version 3.7;
#ifndef (SHAPE) #declare SHAPE = 1; #end
#ifndef (PH) #declare PH = 1; #end
#ifndef (F) #declare F = 0.6; #end
#ifndef (T) #declare T = 0.4; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  #if (PH) photons { spacing 0.008 autostop 0 } #end
}
// looking down at the floor, x in [-2, 2] (rows, top row x = -2: under
// the sheet first), z in [-0.1, 0.1] (columns)
camera { orthographic location <0, 0.5, 0> direction <0, -1, 0>
  right <0, 0, 0.2> up <-4, 0, 0> }
light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
#if (SHAPE = 1)
  disc { <-1.5, 1, 0>, y, 1.5
#else
  box { <-3, 1, -1.5>, <0, 1.1, 1.5>
#end
  pigment { color rgbft <0.9, 0.5, 0.2, F, T> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1 }
  photons { target refraction on reflection on collect off }
}
