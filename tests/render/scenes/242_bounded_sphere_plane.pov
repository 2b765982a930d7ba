// SPDX-License-Identifier: MIT
// 242_bounded_sphere_plane.pov: bounded_by on a sphere and on a plane,
// the two shapes iris intersects by fast paths of its own (accel/node.c
// shape_nearest, accel.c plane_prepare). POV-Ray gives a shape its
// bound's box when that is smaller than its own and skips the shape for
// rays that miss the box (geometry/bound.c), so both are cut along the
// box's silhouette; the fast paths left out the bound and drew them
// whole. Left: a sphere bounded by a flat box, cut top and bottom;
// middle: a sphere bounded by a smaller sphere (its box); right: a plane
// bounded by a box, a tile cut square. They cast no shadow here: in
// POV-Ray the bounded plane's shadow depends on the render threads. Its
// shadow cache (TracePointLightShadowRay) keeps, per thread and light,
// the last opaque object a shadow ray hit, across blocks and misses, and
// tests it first by itself, without the bounding tree; a plane's, box's
// or poly's own box test always passes (Intersect_BBox), so once cached
// the bounded plane shadows every later point behind its infinite
// surface, from a 32x32 block boundary on (+WT4 against +WT1: 18.6
// dB). iris keeps images independent of the threads, so that is not
// reproduced. 80x60 +A0.3: 10.3 dB before, identical after.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.9, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <3, 2, -6> color rgb 0.3 }
plane { y, 0 pigment { checker rgb 1 rgb 0.6 scale 0.5 } }
sphere { <-1.6, 1, 0>, 0.9
  bounded_by { box { <-2.6, 0.6, -1>, <-0.6, 1.4, 1> } }
  pigment { rgb <0.2, 0.8, 0.3> } no_shadow }
sphere { <0.1, 1, 0>, 0.8 bounded_by { sphere { <0.1, 1.4, 0>, 0.5 } }
  pigment { rgb <1, 0.5, 0.2> } no_shadow }
plane { <1, 1, -1>, 1.2 bounded_by { box { <1, 0.2, -0.5>, <2.4, 1.8, 0.5> } }
  pigment { rgb <0.3, 0.5, 1> } no_shadow }
