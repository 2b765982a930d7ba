// Parity scene: quilted with control0 0 and control1 0 written out. That
// is a legal profile (the cubic becomes t³: flat cell middles, steep cell
// edges), not "unset": POV-Ray's defaults are 1 and 1, set when the
// pattern is named. iris read 0 and 0 as unset and used 1 and 1, so the
// normal and the pigment below showed the default quilt (reverted:
// 16.1 dB at 80x60 +A0.3; fixed: identical; textures/patterns/quilt2's
// first cube).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -6> look_at <0, 0, 0> angle 45 }
light_source { <300, 500, -500> color rgb 0.7 }
light_source { <-50, 10, -500> color rgb 0.5 }
box { -1, 1 scale 0.9
  pigment { rgb 1 }
  normal { quilted 5 control0 0 control1 0 scale 0.85 }
  finish { phong 1 phong_size 400 }
  rotate <-30, 30, 0> translate <-1.3, 0, 0>
}
sphere { <1.3, 0, 0>, 1
  pigment { quilted control0 0 control1 0 scale 0.5
            color_map { [0 rgb <0.1, 0.2, 0.8>] [0.3 rgb <1, 0.9, 0.3>] } }
}
