// material_map: one texture per texel, numbered by the image's palette
// index (a palette PNG whose colours run against the indices) or by its
// red byte (a grey PNG whose values pass the texture count, so the
// modulo shows), as POV-Ray's material_map (imageutil.cpp). The box's
// transforms after the material_map move the pattern and its textures
// together (the gradient inside a texture follows the scale). Measured
// against POV-Ray 3.7.0: identical at 80x60 (PSNR inf), 107.7 dB at
// 320x240; numbering by colours instead of indices, or a plain modulo
// (POV-Ray 3.7.1's rule), drops it below 20 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> right x*4/3 angle 50 }
light_source { <-3, 8, -6> color rgb 1 }
background { rgb <0.1, 0.1, 0.2> }

box { <0, 0, 0>, <1, 1, 0.1>
  texture {
    material_map { png "maps/matmap_palette.png"
      texture { pigment { rgb <1, 0.2, 0.1> } }
      texture { pigment { rgb <0.1, 0.8, 0.2> } finish { phong 0.8 } }
      texture { pigment { gradient y color_map { [0 rgb 0] [1 rgb <1, 1, 0>] } scale 0.5 } }
      texture { pigment { rgb <0.2, 0.3, 1> } }
      texture { pigment { rgb 1 } finish { ambient 0.5 diffuse 0.2 } }
    }
  }
  scale <3.2, 2.4, 1> translate <-3.3, 0, 0>
}

sphere { <1.7, 1.2, 0>, 1.2
  texture {
    material_map { png "maps/matmap_grey.png"
      texture { pigment { rgb <1, 0.6, 0> } }
      texture { pigment { rgb <0, 0.7, 0.7> } }
      texture { pigment { checker rgb 1 rgb <0.8, 0, 0.5> scale 0.2 } }
      texture { pigment { rgb <0.3, 0.3, 0.3> } }
    }
    scale 2.4 translate <0.5, 0, 0>
  }
}

plane { y, 0 texture {
  material_map { png "maps/matmap_palette.png" once
    texture { pigment { rgb <0.8, 0.8, 0.6> } }
    texture { pigment { rgb <0.5, 0.2, 0.1> } }
  }
  rotate x*90 scale 4 translate <-2, 0, -2>
} }
