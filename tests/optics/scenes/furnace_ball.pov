// SPDX-License-Identifier: MIT
// furnace_ball.pov (tests/optics/optics.sh, check "white furnace"): a
// point light of colour 1 at the centre of a closed diffuse sphere of
// albedo a = 0.4 (tests/progressive/furnace.pov), with a clear glass
// ball (n = 1.5, no absorption) in the view. Every surface of the
// furnace gets the same light, a/(1 - a) with every bounce counted (the
// global photon map, radiosity {}); a lossless ball in a uniform light
// field changes nothing, so it must vanish: seen through, around, or in
// the light it bends (its "shadow" on the wall).
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 20
  // recursion_limit 20: every bounce that matters (a^21 < 1e-8)
  radiosity { recursion_limit 20 }
}
camera { location <0, 0, -0.5> look_at <0, 0, 1> angle 70 }
light_source { <0, 0, 0> color rgb 1 }
sphere { 0, 2 pigment { color rgb 0.4 } finish { ambient 0 diffuse 1 } }
// about 12 degrees across, right of and above the view's centre
sphere { <0.3, 0.2, 1.2>, 0.35
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
}
