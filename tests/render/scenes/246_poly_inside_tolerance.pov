// SPDX-License-Identifier: MIT
// 246_poly_inside_tolerance.pov: POV-Ray's Poly::Inside counts a point as
// inside a poly, cubic or quartic where the polynomial, in the user's
// own coefficients, is below INSIDE_TOLERANCE = 1e-4, not below 0. With
// small coefficients the inside a CSG sees is much larger than the
// surface. Left: a box minus the sphere poly 0.0002 (r^2 - 1), inside for
// r^2 < 1.5, which takes the whole box (corners at r^2 = 1.47), so only
// the sphere's surface inside the box is left. Middle: a box intersected
// with the quartic torus 0.001 ((r^2 + R^2 - a^2)^2 - 4 R^2 (x^2 + z^2)),
// whose tolerance swells the tube. Right: the same torus as a quartic
// with coefficients near 1 (the band is 1e-4 thick: as before). iris
// tested p < 0: 80x60 +A0.3 29.3 dB before, identical after.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.6, 0> right x*4/3 angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <4, 3, -6> color rgb 0.3 }
plane { y, -0.2 pigment { checker rgb 1 rgb 0.5 scale 0.5 } }
#declare A = 0.0002;
difference {
  box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> }
  poly { 2, <A, 0, 0, 0, A, 0, 0, A, 0, -A> }
  translate <-2, 0.6, 0>
  pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.5 }
}
// torus R = 0.6, a = 0.25 about y, in quartic form, times K
#macro Torus4(K)
  #local R2 = 0.36; #local a2 = 0.0625; #local c = R2 - a2;
  quartic { <K, 0, 0, 0, 2*K, 0, 0, 2*K, 0, K*(2*c - 4*R2),
             0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
             K, 0, 0, 2*K, 0, K*2*c, 0, 0, 0, 0,
             K, 0, K*(2*c - 4*R2), 0, K*c*c> }
#end
intersection {
  object { Torus4(0.001) }
  box { <-1, -0.15, -1>, <1, 1, 1> }
  rotate x*-50 translate <0, 0.6, 0>
  pigment { rgb <0.4, 0.8, 0.4> } finish { phong 0.5 }
}
intersection {
  object { Torus4(1) }
  box { <-1, -0.15, -1>, <1, 1, 1> }
  rotate x*-50 translate <2, 0.6, 0>
  pigment { rgb <0.4, 0.5, 1> } finish { phong 0.5 }
}
