// SPDX-License-Identifier: MIT
// 245_merge_coincident_cap.pov: merges whose cylinder or cone has a cap
// lying in a box's face, as shapes3.inc's Round_Conic_Prism builds its
// end faces. POV-Ray's Cone::Inside tests in the shape's unit frame and
// shrinks a closed cylinder or cone by EPSILON (1e-10) there (grows an
// open one), so a point on the cap is outside it: the merge keeps the
// box's face and drops the cap (inside the closed box). iris tested the
// cap plane exactly, so rounding put about half the face points inside
// the cylinder; with the cap gone too the face had a speckled hole.
// Left: a cylinder along z, cap in the box's front face; middle: a cone,
// base in the front face, tip inside; right: the same box and cylinder
// turned, cap in the top face. 80x60 +A0.3: 28.4 dB before, identical
// after; Round_Conic_Prism (template 65) 22.7 dB -> identical.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -6> look_at <0, 0.6, 0> right x*4/3 angle 50 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <4, 3, -6> color rgb 0.3 }
plane { y, 0 pigment { checker rgb 1 rgb 0.5 scale 0.5 } }
merge {
  box { <-0.7, 0, -0.45>, <0.7, 1.4, 0.45> }
  cylinder { <0, 0.7, -0.45>, <0, 0.7, 0.45>, 0.55 }
  rotate y*20 translate <-2.1, 0, 0.3>
  pigment { rgb <0.9, 0.5, 0.3> } finish { phong 0.6 }
}
merge {
  box { <-0.6, 0, -0.45>, <0.6, 1.3, 0.45> }
  cone { <0, 0.65, -0.45>, 0.5, <0, 0.65, 0.3>, 0.1 }
  rotate <-10, -15, 0> translate <0, 0.1, 0>
  pigment { rgb <0.4, 0.8, 0.4> } finish { phong 0.6 }
}
merge {
  box { <-0.6, 0, -0.6>, <0.6, 0.9, 0.6> }
  cylinder { <0.1, 0, 0>, <0.1, 0.9, 0>, 0.45 }
  rotate <-25, 30, 0> translate <2, 0.3, 0.5>
  pigment { rgb <0.4, 0.5, 1> } finish { phong 0.6 }
}
