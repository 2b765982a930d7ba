// Parity scene: uv_mapping on boxes after a negative scale. POV-Ray's
// Box::Scale and Box::Translate move the corners of a box that has no
// transform yet (nothing but scale and translate so far) and order them
// per axis, so a mirroring scale leaves the box's own space, which
// Box::UVCoord unfolds into the cube cross, unmirrored: each face keeps
// its place and orientation in the cross. After a rotate the scale goes
// into the transform and the uv mirror with it (the middle box). Left: x
// mirrored after a translate; middle: rotated, then y mirrored; right:
// a union scaled by z -1.2 (its box takes it too), then rotated. iris
// composed every scale into the transform, so the faces of the left and
// right boxes showed mirrored checkers (reverted: 17.3 dB at 80x60 +A0.3;
// with the fold identical).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.2, -9> look_at <0, 0, 0> right x*4/3 angle 50 }
light_source { <-20, 30, -30> color rgb 1 }
background { rgb <0.1, 0.15, 0.3> }
#declare F = finish { ambient 0.25 diffuse 0.75 }
#declare P = pigment { uv_mapping checker rgb <0.9, 0.2, 0.1>, rgb <0.95, 0.95, 0.8>
                       scale <1/16, 1/9, 1> }
box { <-1, -1.2, -0.8>, <1, 1.2, 0.8> pigment { P } finish { F }
  translate <0.1, 0, 0> scale <-1, 1, 1> rotate <-25, 35, 10> translate <-2.6, 0, 0> }
box { <-1, -1.2, -0.8>, <1, 1.2, 0.8> pigment { P } finish { F }
  rotate <30, -40, 0> scale <1, -1, 1> }
union {
  box { <-1, -1.2, -0.8>, <1, 1.2, 0.8> pigment { P } finish { F } }
  scale <1, 1, -1.2> rotate <-20, 30, -10> translate <2.6, 0, 0>
}
