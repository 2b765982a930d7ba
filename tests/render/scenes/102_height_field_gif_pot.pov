// Parity scene: height_field heights from GIF files as POV-Ray reads
// them (gif.cpp, imageutil.cpp image_height_at): a GIF gives its palette
// indices (index * 256 / 65536), not its colours; a POT file (Fractint's
// 16-bit format) is a GIF twice as wide whose left half holds the high
// bytes and right half the low bytes of each height. The images
// (maps/hf_index.gif, its palette running against the indices;
// maps/hf_16.pot) were written for this scene by
// tests/render/scenes/maps/mkgif.py with an LZW encoder. iris once read
// GIFs through the colour reader (the palette's red and green as two
// bytes; advanced/mtmand.pov at 10.0 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.2, -3.6> look_at <0, 0.2, 0.2> right x*4/3 angle 50 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.2, 0.25, 0.35> }
height_field { gif "maps/hf_index.gif"
  translate <-0.5, 0, -0.5> scale <2, 1, 1.5> translate <-1.05, 0, 0>
  pigment { gradient y color_map { [0 rgb <0.1, 0.4, 0.1>] [1 rgb <1, 0.9, 0.8>] } } }
height_field { pot "maps/hf_16.pot" smooth
  translate <-0.5, 0, -0.5> scale <2, 1, 1.5> translate <1.05, 0, 0>
  pigment { rgb <0.8, 0.7, 0.5> } finish { specular 0.4 } }
