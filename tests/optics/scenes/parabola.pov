// SPDX-License-Identifier: MIT
// parabola.pov (tests/optics/optics.sh, check "parabolic mirror"): a
// parabolic trough mirror y = A x^2 (a quadric cut by clipped_by planes
// at its rim y = 0.5 and at z = +-1, as users write a paraboloid mirror)
// under parallel light from straight above. Every reflected ray passes
// through the focal line x = 0, y = 1/(4A): a white screen, the plane
// x = 0 (parallel to the light: no direct light on it, and it shades
// nothing), catches them there. The camera looks at the screen from +x:
// y in [f - 0.2, f + 0.2] (rows, top row up), z in [-0.2, 0.2].
// BOUND=1: the same trough bounded_by a box instead of clipped (the
// quadric keeps its infinite surface; a ray that misses the bound's box
// sees nothing of it, as in POV-Ray): the focus is the same.
#version 3.7;
#ifndef (A) #declare A = 0.5; #end
#ifndef (BOUND) #declare BOUND = 0; #end
#declare F = 1 / (4 * A);
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.005 autostop 0 }
}
camera { orthographic location <0.05, F, 0> direction <-1, 0, 0>
  right <0, 0, 0.4> up <0, 0.4, 0> }
light_source { <0, 100, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
plane { x, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
quadric { <A, 0, 0>, <0, 0, 0>, <0, -1, 0>, 0
  #if (BOUND)
    bounded_by { box { <-1.001, -0.001, -1>, <1.001, 0.5, 1> } }
  #else
    clipped_by { plane { y, 0.5 } }
    clipped_by { plane { z, 1 } }
    clipped_by { plane { -z, 1 } }
  #end
  pigment { color rgb 0 }
  finish { ambient 0 diffuse 0 reflection rgb 1 }
  photons { target reflection on collect off }
}
