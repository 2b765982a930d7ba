// Parity scene: height_field heights as POV-Ray reads an image: a palette
// PNG gives its palette indices (index * 256 / 65536), not the colours'
// grey; an 8-bit RGB PNG gives red as the high byte and green as the low
// byte (blue ignored); each grid cell is split along the diagonal from
// (x+1, z) to (x, z+1). The images (maps/hf_palette.png, maps/hf_rg.png)
// were written for this scene by tests/render/scenes/maps/mkhf.py; their
// palette runs against the indices and their green channel ripples, so
// the grey level would give other shapes. iris once took the grey level
// and the other diagonal (advanced/sunsethf.pov 15.9 dB, 15.9 dB here).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.2, -3.6> look_at <0, 0.2, 0.2> right x*4/3 angle 50 }
light_source { <-4, 8, -5> color rgb 1 }
background { rgb <0.2, 0.25, 0.35> }
height_field { png "maps/hf_palette.png"
  translate <-0.5, 0, -0.5> scale <2, 1, 1.5> translate <-1.05, 0, 0>
  pigment { gradient y color_map { [0 rgb <0.1, 0.4, 0.1>] [1 rgb <1, 0.9, 0.8>] } } }
height_field { png "maps/hf_rg.png"
  translate <-0.5, 0, -0.5> scale <2, 0.8, 1.5> translate <1.05, 0, 0>
  pigment { rgb <0.8, 0.7, 0.5> } finish { specular 0.4 } }
