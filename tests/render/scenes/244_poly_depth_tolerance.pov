// SPDX-License-Identifier: MIT
// 244_poly_depth_tolerance.pov: POV-Ray's Poly::All_Intersections (poly,
// cubic, quartic) drops roots closer than DEPTH_TOLERANCE, 1e-4 along
// the unit object-space direction. Without that, a shadow ray leaving
// the sextic Sinsurf of shapesq.inc (POV-Ray's template
// Polynomial_Quartic/12_Sinsurf) found the surface again at roots the
// solver put a hair away, and the lit side was speckled with shadow.
// 80x60 +A0.3: 32.1 dB before, identical after.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "shapes.inc"
#include "shapesq.inc"
camera { location <0, 2.5, -6> look_at <0, 0.8, 0> right x*4/3 angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.4 }
plane { y, -1.01 pigment { checker rgb 1 rgb 0.5 } }
object { Sinsurf sturm
  pigment { rgb <1, 0.95, 0.9> } finish { phong 1 }
  rotate -90*y scale <-1, 1, 1> translate <1, 0, 20> }
