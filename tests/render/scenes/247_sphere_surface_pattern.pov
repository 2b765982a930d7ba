// SPDX-License-Identifier: MIT
// 247_sphere_surface_pattern.pov: a pattern whose value jumps at the
// sphere's own surface, as textures/pigments/cantelop.pov's melon skin:
// onion is |p| mod 1, so on a unit sphere each hit point lands just below
// radius 1 (value ~1, blue here) or just above it (value ~0, orange) by
// the sign of the rounding in the ray/sphere solution. POV-Ray's speckle
// is that of its own sums (Sphere::Intersect: h^2 = r^2 - |c - o|^2 +
// tc^2 for a unit direction); iris measured the chord at the closest
// approach, as accurate but rounding the other way on about half the
// surface. Without antialiasing (its jitter would move the samples):
// 80x60 -A 9.1 dB before (e9905d9), identical after
// (geometry/sphere_span.h, accel/node.c sphere_world_crossing).
// parity-options: -A
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <-2, 3, -3> look_at <0.8, 0, 1.2> right x*4/3 angle 55 }
light_source { <-20, 30, -100> color rgb 1 }
#declare Melon = sphere { 0, 1
  pigment { onion color_map { [0 rgb <1, 0.5, 0>] [0.5 rgb <1, 0.5, 0>]
                              [0.5 rgb <0, 0, 1>] [1 rgb <0, 0, 1>] } }
  finish { ambient 0.3 diffuse 0.7 }
}
object { Melon }
// the same sphere moved, and turned and scaled: POV-Ray moves the centre
// and scales the radius, solving in world space (the pattern point is
// moved back into the pattern's space); iris solved the turned one in
// its object space until node_sphere_world_prepare()
object { Melon translate <1.6, -0.5, 2.5> }
object { Melon rotate <30, 40, 0> scale 0.8 translate <2.2, 1.2, 0.6> }
