// legacy_image_map: in a #version 3.6 scene POV-Ray 3.7 reads an image
// file without gamma information as stored, whatever assumed_gamma says
// (Parse_Image's AssumedGamma36 mode makes the file's default gamma the
// working gamma, so decoding and the conversion back cancel). iris's
// decoded (linear) texels are therefore encoded back; decoded texels
// came out darker. Measured against POV-Ray 3.7.0: 73.5 dB at 80x60,
// 108.7 dB at 320x240 (17.7 dB with decoded texels).
#version 3.6;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { image_map { png "maps/tile.png" interpolate 2 } rotate x*90 scale 2 } }
sphere { <-1.1, 1, 0>, 1 pigment { image_map { png "maps/tile.png" map_type 1 } } }
box { <0.3, 0, -0.5>, <2.3, 2, 0.5> pigment { image_map { png "maps/matmap_palette.png" once } scale 2 translate x*0.3 } }
