// Parity scene: text { internal N ... }, POV-Ray's built-in fonts, which
// are copies of the four fonts it installs (1 timrom, 2 cyrvetic, 3
// crystal, other numbers povlogo). iris skipped such text with a warning
// ("cannot open the font file"): reverted, the three words are missing
// and the image is at 18.0 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at <0, 1, 0> }
light_source { <-3, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.3, 0.4, 0.6> } }
text { internal 1 "Times" 0.2, 0 pigment { rgb <1, 0.3, 0.2> } translate <-2.2, 1.6, 0> }
text { internal 2 "Cyr" 0.2, 0 pigment { rgb <0.2, 0.8, 0.3> } translate <0.4, 1.6, 0> }
text { internal 3 "Crystal" 0.2, 0 pigment { rgb <0.2, 0.4, 1> } translate <-2, 0.5, 0> }
