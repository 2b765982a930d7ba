// SPDX-License-Identifier: MIT
// pipe.pov (tests/optics/optics.sh, check "light pipe"): total internal
// reflection inside a light pipe. A clear glass bar (index N, 0.5 high,
// axis along x) in a parallel white light that rises at ANGLE degrees
// from the axis and enters only its left end face x = 0 (an opaque shield
// a little below the bar keeps it off the bottom face). Inside, the
// light rises at r = asin(sin(ANGLE)/N) and bounces between the top and
// bottom faces, beyond their critical angle whenever N >= sqrt(2). The
// bar's length L = 4 H / tan(r) makes the light fold exactly four times:
// at the far end x = L it again fills the end face, all rising, so it
// leaves as a uniform beam at ANGLE onto the white screen x = L + 0.05,
// which only photons light (the bar and the shield shadow it).
#version 3.7;
#ifndef (ANGLE) #declare ANGLE = 40; #end
#ifndef (N) #declare N = 1.5; #end
#declare H = 0.5;
#declare R = asin(sin(radians(ANGLE)) / N);
#declare L = 4 * H / tan(R);
global_settings {
  assumed_gamma 1
  max_trace_level 30
  photons { spacing 0.004 autostop 0 }
}
// looking at the screen (+x) from between it and the bar: y in
// [-0.05, 0.55] (image rows, top row +y), z in [-0.3, 0.3]
camera { orthographic location <L + 0.025, 0.25, 0> direction <1, 0, 0>
  right <0, 0, -0.6> up <0, 0.6, 0> }
light_source { <-10, 0, 0> color rgb 1 parallel point_at <0, 0, 0>
  rotate ANGLE * z
  photons { refraction on reflection on }
}
// the screen, facing the bar
box { <L + 0.05, -2, -2>, <L + 0.1, 2, 2>
  pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
// the shield: no light reaches the bar's bottom face within 2 of its far
// end (light entering there would leave through the top, or by the end
// face after a reflection, and reach the screen)
box { <L - 2, -0.2, -1>, <L + 0.04, -0.01, 1>
  pigment { color rgb 0 } finish { ambient 0 diffuse 0 } }
// the bar: 1 wide in z, so its side faces are far from the window and
// parallel to the light
box { <0, 0, -0.5>, <L, H, 0.5>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior N }
  photons { target refraction on reflection on collect off }
}
