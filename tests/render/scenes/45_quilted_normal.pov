// Parity scene: the quilted normal. POV-Ray displaces the normal by the
// quilted cell vector itself (a normal-only pattern like bumps), not by
// the slope of the quilted value, and with the control0/control1 cubic.
// iris once took the slope (textures/patterns/quilted.pov 30.8 dB,
// quilt2.pov 18.4 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 angle 45 }
light_source { <-5, 8, -6> color rgb 1 }
plane { y, 0 pigment { rgb <0.9, 0.85, 0.7> }
  normal { quilted 0.6 control0 0 control1 1 scale 0.4 } }
sphere { <-1.3, 1, 0>, 1 pigment { rgb <0.8, 0.85, 1> } finish { phong 1 phong_size 400 }
  normal { quilted 0.4 control0 1 control1 1 scale 0.3 } }
box { <0.3, 0, -0.8>, <2.1, 1.8, 0.8> rotate y*20 pigment { rgb <1, 0.8, 0.8> }
  normal { quilted 1 control0 0.5 control1 1 scale 0.5 } }
