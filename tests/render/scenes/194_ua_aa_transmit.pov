// Parity scene: the antialiasing threshold counts the transmit channel.
// POV-Ray's method 1 and 2 compare samples by Colour_Distance_RGBT: the
// gamma-adjusted r, g, b differences plus the transmit difference. Under
// +UA the edge of a dark object against the transparent background
// differs by less than 0.3 in colour but by 1 in transmit, so POV-Ray
// supersamples it; iris compared r, g, b only and left these edges with
// one sample, which shows in the alpha channel (reverted: 29.4 dB over
// RGBA at 80x60 +A0.3 +UA; fixed: 69.4; src/render/eyepass.c
// aa_distance()).
// parity-options: +UA
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -4> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -4> rgb 1 }
sphere { <-0.9, 0.4, 0>, 0.7 pigment { rgb 0.02 } }
box { <0.3, -1.2, -0.5>, <1.6, 0.4, 0.5>
  rotate <20, 30, 10>
  pigment { rgb <0.05, 0.02, 0.03> }
}
#for (i, 0, 5)
  cylinder { <-2, -1.5 + 0.12 * i, 0>, <2, -0.9 + 0.3 * i, 0.5>, 0.03
    pigment { rgb 0.01 }
  }
#end
