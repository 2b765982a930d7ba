// bicubic_patch: a saddle and a dome in 2^u_steps x 2^v_steps cells
// (flatness 0: uniform), and a patch whose subdivision stops early where
// it is flatter than 'flatness', measured after its scale (POV-Ray moves
// the control points by the transform before it subdivides).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 4, -7> look_at <0, 0.3, 0> right x*4/3 angle 45 }
light_source { <-5, 8, -10> color rgb 1 }
light_source { <6, 4, -4> color rgb 0.3 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
bicubic_patch {
  type 1 flatness 0 u_steps 4 v_steps 4
  <0, -1.5, 2>, <1, -1.5, 0>, <2, -1.5, 0>, <3, -1.5, -2>,
  <0, -0.5, 0>, <1, -0.5, 0>, <2, -0.5, 0>, <3, -0.5, 0>,
  <0, 0.5, 0>, <1, 0.5, 0>, <2, 0.5, 0>, <3, 0.5, 0>,
  <0, 1.5, 2>, <1, 1.5, 0>, <2, 1.5, 0>, <3, 1.5, -2>
  pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 }
  scale 0.6 rotate -30*y translate <-2.5, 0.3, 0>
}
bicubic_patch {
  type 0 flatness 0 u_steps 3 v_steps 3
  <0, 0, 0>, <1, 0, 0>, <2, 0, 0>, <3, 0, 0>,
  <0, 0, 1>, <1, 2, 1>, <2, 2, 1>, <3, 0, 1>,
  <0, 0, 2>, <1, 2, 2>, <2, 2, 2>, <3, 0, 2>,
  <0, 0, 3>, <1, 0, 3>, <2, 0, 3>, <3, 0, 3>
  pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.6 }
  translate <0.3, -0.9, -1>
}
bicubic_patch {
  type 1 flatness 0.05 u_steps 6 v_steps 6
  <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
  <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
  <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
  <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
  pigment { checker rgb <1, 0.2, 0.2> rgb 1 scale 0.5 }
  finish { phong 0.6 }
  translate <-1.5, -1.5, 0> scale 0.5 rotate <30, -60, 0>
  translate <2.3, 0.6, 0.5>
}
