// Parity scene: focal blur's confidence test counts the transmit
// channel. POV-Ray's TraceRayWithFocalBlur stops adding blur rays when
// the variance of red, green, blue and transmit is under the bound; under
// +UA a blurred edge against the transparent background varies in
// transmit, so POV-Ray takes more rays there. iris tested r, g, b only
// and stopped after the first batch on these dark edges (reverted: 34.9
// dB over RGBA at 80x60 +UA -A; fixed: identical, hence the bar of 50;
// src/render/focalblur.c focal_blur_converged()).
// parity-min-psnr: 50 identical when fixed; the reverted render gives 34.9
// parity-options: +UA -A
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -4> look_at <0, 0, 0> angle 50
  aperture 0.4 blur_samples 4, 64 confidence 0.9 variance 1/256
  focal_point <0, 0, 3>
}
light_source { <-3, 5, -4> rgb 1 }
sphere { <-0.8, 0.2, 0>, 0.9 pigment { rgb 0.05 } }
box { <0.3, -1.2, -0.5>, <1.6, 0.4, 0.5>
  rotate <20, 30, 10>
  pigment { rgb <0.08, 0.05, 0.06> }
}
