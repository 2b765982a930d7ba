// Parity scene: +UA in a #version 3.6 scene. POV-Ray's pre-3.7
// ComputeSky returns transparent black to a ray whose ticket has
// alphaBackground (eye and refracted rays), before the background and
// the sky sphere; reflected rays see the background colour. iris drew
// the legacy sky opaque under +UA, so the whole background had alpha 1
// (reverted: 6.8 dB over RGBA at 80x60 +UA -A; fixed: identical;
// src/render/trace.c sky_colour()).
// parity-options: +UA -A
#version 3.6;
global_settings { assumed_gamma 1 }
background { rgb <0.2, 0.5, 0.9> }
camera { location <0, 1, -4> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 5, -4> rgb 1 }
sphere { <-0.7, 0.7, 0>, 0.7
  pigment { rgb <0.8, 0.3, 0.2> }
  finish { reflection 0.5 }
}
sphere { <0.9, 0.6, 0>, 0.6
  pigment { rgbf <0.9, 1, 0.9, 0.9> }
  interior { ior 1.3 }
}
plane { y, 0 pigment { checker rgb 1 rgb <0.2, 0.7, 0.3> } }
