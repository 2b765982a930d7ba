// Parity scene: +UA with fog. POV-Ray's ComputeFog scales the ray's
// transmit channel by the greyscale of the fog's attenuation, as it
// scales the colour behind the fog, so a fogged background is partly
// opaque (alpha 1 - t * att). iris left the transmit alone, so the
// background behind the fog stayed as transparent as without it
// (reverted: 20.8 dB over RGBA at 80x60 +UA -A; fixed: identical;
// src/render/trace.c apply_fog()).
// parity-options: +UA -A
#version 3.7;
global_settings { assumed_gamma 1 }
background { rgbt <0.2, 0.5, 0.9, 0.5> }
camera { location <0, 1, -4> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 5, -4> rgb 1 }
fog { distance 6 rgbt <0.9, 0.8, 0.7, 0.1> }
sphere { <-0.7, 0.7, 0>, 0.7 pigment { rgb <0.8, 0.3, 0.2> } }
sphere { <0.9, 0.6, 0>, 0.6
  pigment { rgbf <0.9, 1, 0.9, 0.9> }
  interior { ior 1.3 }
}
box { <-3, -0.2, -1>, <3, 0, 4> pigment { checker rgb 1 rgb <0.2, 0.7, 0.3> } }
