// SPDX-License-Identifier: MIT
// fade.pov (tests/optics/optics.sh, check "absorption"): camera rays
// through three slabs of absorbing "glass" of index 1 (no refraction, no
// reflection) onto a white background. Left to right in the image: 0.1
// thick with POV-Ray's exponential fade (fade_power >= 1000), 0.3 thick
// with it, 0.3 thick with the power law fade_power 2. Fade colour
// <0.8, 0.5, 0.2>, fade_distance 0.2.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
background { color rgb 1 }
camera { orthographic location <0, 0, -5> direction <0, 0, 1>
  right <3, 0, 0> up <0, 1, 0> }
#declare Glass = material {
  texture { pigment { color rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
}
#macro Slab(X0, D, P)
  box { <X0, -1, 0>, <X0 + 1, 1, D>
    material { Glass }
    interior { ior 1 fade_distance 0.2 fade_power P
      fade_colour <0.8, 0.5, 0.2> }
  }
#end
Slab(-1.5, 0.1, 1001)
Slab(-0.5, 0.3, 1001)
Slab(0.5, 0.3, 2)
