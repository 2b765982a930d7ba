// SPDX-License-Identifier: MIT
// 211_subsurface_backlit.pov: a thin subsurface slab lit only from behind
// (src/render/subsurface.c). The face the camera sees gets no direct
// light: what shows is the dipole's light entering the back face (the
// sample base half-way between the faces), single scattering along the
// refracted eye ray, and the unscattered ray leaving the back face.
// parity-min-psnr: 33 noisy on both sides (400 surface points, 100
// depths): POV-Ray's own images with +WT1 and +WT2 differ by 36.5 dB,
// iris's is 36.5 dB from either (at 800, 200 samples: 41.2 and 40.5,
// no bias showing). Without subsurface the face is dark: 5.8 dB.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 10
  subsurface { samples 400, 100 }
}
camera { location <0, 0.3, -5> look_at <0, 0.2, 0> angle 36 }
light_source { <1.5, 3, 6> rgb 1.5 }
background { rgb <0.1, 0.1, 0.2> }
plane { y, -1.2 pigment { checker rgb 0.3 rgb 0.6 } }
box {
  <-1, -1, -0.08>, <1, 1, 0.08>
  pigment { rgb <0.8, 0.75, 0.6> }
  finish {
    ambient 0 diffuse 0.9
    subsurface { translucency <3, 2, 1> }
  }
  interior { ior 1.3 }
  rotate y * 25
}
