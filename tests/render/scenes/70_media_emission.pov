// Emitting media (docs/media.md): a hollow, invisible sphere whose media
// emits with a spherical density (bright core, fading to the rim), and a
// second one emitting uniformly with some absorption, in front of a
// checker floor. Method 3 (the 3.7 default) without jitter samples at
// fixed places, so POV-Ray's image is reproduced exactly: the default
// 35 dB bar needs no allowance.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-3, 8, -4> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, 0 pigment { checker rgb 0.8 rgb 0.3 } }
sphere { 0, 1
  pigment { rgbt 1 }
  hollow
  interior {
    media {
      emission rgb <1.2, 0.6, 0.2>
      density { spherical color_map { [0 rgb 0] [1 rgb 1] } }
    }
  }
  translate <-1.2, 1.2, 0>
}
sphere { <1.3, 1, 0.5>, 0.9
  pigment { rgbt 1 }
  hollow
  interior { media { emission rgb <0.1, 0.5, 0.8> absorption 0.6 } }
}
