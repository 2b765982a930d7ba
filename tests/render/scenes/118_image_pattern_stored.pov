// image_pattern_stored: POV-Ray reads an image_pattern's file with no
// gamma handling (Parse_Image: no gamma correction for height_field,
// bump_map and image_pattern), so the pattern is the grey of the stored
// values, not of the decoded (linear) ones; plain and interpolated.
// Measured against POV-Ray 3.7.0: 111.5 dB at 320x240; on decoded
// values 22.0 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0.5, -5> look_at <0, 0.5, 0> right x*4/3 angle 50 }
light_source { <-3, 6, -6> color rgb 1 }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_pattern { png "maps/tile.png" } color_map { [0 rgb <0,0,1>] [1 rgb <1,1,0>] } }
  scale <2, 1.5, 1> translate <-2.1, -0.25, 0> }
box { <0, 0, 0>, <1, 1, 0.1>
  pigment { image_pattern { png "maps/tile.png" interpolate 2 } color_map { [0 rgb <0,0,1>] [1 rgb <1,1,0>] } }
  scale <2, 1.5, 1> translate <0.1, -0.25, 0> }
