// Parity scene: +UA with a background that transmits. POV-Ray's
// ComputeReflection clears the trace ticket's alphaBackground, so a
// reflected ray (and all it spawns) sees the background opaque: its
// colour, not scaled by 1 - transmit, and no transmit; eye and refracted
// rays see it transparent. iris gave reflected rays the eye ray's
// transparent background, which darkened every mirror image of the sky
// (reverted: 22.1 dB over RGBA at 80x60 +UA -A; fixed: identical;
// src/render/trace.c reflect(), sky_colour()).
// parity-options: +UA -A
#version 3.7;
global_settings { assumed_gamma 1 }
background { rgbt <0.2, 0.5, 0.9, 0.6> }
camera { location <0, 1, -4> look_at <0, 0.6, 0> angle 50 }
light_source { <-3, 5, -4> rgb 1 }
sphere { <0, 0.8, 0>, 0.8
  pigment { rgb <0.8, 0.3, 0.2> }
  finish { diffuse 0.2 ambient 0 reflection 0.8 }
}
plane { y, 0
  pigment { checker rgb 1 rgb <0.2, 0.7, 0.3> }
  finish { reflection 0.3 }
}
