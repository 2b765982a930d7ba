// parametric: a Moebius strip found by POV-Ray's interval subdivision
// (accuracy, max_gradient, precompute), with its finite-difference normal.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0, 0> right x*4/3 angle 40 }
light_source { <-5, 8, -10> color rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
plane { y, -1.5 pigment { checker rgb 0.9 rgb 0.3 } }
parametric {
  function { cos(u) + v*cos(u/2)*cos(u) }
  function { v*sin(u/2) }
  function { sin(u) + v*cos(u/2)*sin(u) }
  <0, -0.4>, <2*pi, 0.4>
  contained_by { box { <-1.5, -0.5, -1.5>, <1.5, 0.5, 1.5> } }
  max_gradient 2
  accuracy 0.01
  precompute 10, x, y, z
  rotate x*-30
  pigment { rgb <1, 0.6, 0.2> } finish { phong 0.5 }
}
