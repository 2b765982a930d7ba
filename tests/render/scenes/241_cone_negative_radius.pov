// SPDX-License-Identifier: MIT
// 241_cone_negative_radius.pov: a cone's radii are signed in POV-Ray
// (Cone::Compute_Cone_Data): the radius runs linearly from base to cap
// and the surface is x^2 + y^2 = r(z)^2, so radii of opposite signs make
// a double cone meeting where r = 0 (POV-Ray's own template
// 33_cone_double.txt). When the larger radius is negative the cone
// becomes a cylinder of that size, when it is 0 (the other negative)
// nothing; a cylinder's negative radius is its size. Left to right: a
// closed double cone, an open one seen from above, two negative radii
// (a cylinder of radius 0.3), -1 and 0 (nothing) and a cylinder of
// radius -0.3. iris took the radii's absolute values (and skipped the
// cylinder): 80x60 +A0.3 21.5 dB before, identical after. (When the
// negative end is the wider one, POV-Ray's bounding box, of the larger
// signed radius, cuts that end: not reproduced, so not shown.)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.7, 0> right x*4/3 angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <4, 3, -6> color rgb 0.3 }
plane { y, 0 pigment { checker rgb 1 rgb 0.5 scale 0.5 } }
cone { <-2.2, 0, 0>, -0.4, <-2.2, 1.5, 0>, 0.8
  pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 } }
cone { <-0.6, 0, 0>, -0.3, <-0.6, 1.5, 0>, 0.6 open
  pigment { rgb <0.3, 0.6, 1> } rotate x*-25 }
cone { <0.6, 0, 0>, -0.6, <0.6, 1.2, 0>, -0.3 pigment { rgb <0.4, 1, 0.4> } }
cone { <1.2, 0, 1>, -1, <1.2, 1.2, 1>, 0 pigment { rgb 1 } }
cylinder { <1.8, 0, 0>, <1.8, 1, 0>, -0.3 pigment { rgb <1, 0.4, 0.8> } }
