// ovus: both radius orders, the sphere substitute (top >= 2 x bottom),
// and CSG against the ovus's inside (a difference cut open by a box).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -7> look_at <0, 0.6, 0> right x*4/3 angle 50 }
light_source { <-5, 8, -10> color rgb 1 }
light_source { <6, 4, -6> color rgb 0.3 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }
ovus { 1, 0.6 translate <-2.2, 0, 0>
       pigment { rgb <1, 0.6, 0.2> } finish { phong 0.6 } }
ovus { 0.6, 0.9 rotate z*20 translate <0, 0.1, 0.5>
       pigment { rgb <0.3, 0.8, 0.4> } finish { phong 0.6 } }
ovus { 0.4, 0.8 translate <0.8, -0.6, -1.5>
       pigment { rgb <0.9, 0.9, 0.3> } }
difference {
  ovus { 0.9, 0.7 }
  box { <-1, 0.4, -2>, <0, 3, 0> }
  translate <2.2, 0, 0>
  pigment { rgb <0.4, 0.5, 1> } finish { phong 0.4 }
}
