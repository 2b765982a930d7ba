// SPDX-License-Identifier: MIT
// An image named without its extension: POV-Ray's FindFile tries the
// extensions of the type given ('png "linux"' reads linux.png; .png and
// .PNG, .jpg/.jpeg for jpeg, ...). iris said "cannot find image file"
// before session 12 (PeterBachour's POVRay-SapinDeNoel). 'gamma srgb'
// overrides an image's decoding gamma with the sRGB curve (Parse_Gamma;
// WarrenGames' jars): iris expected a number.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0.3, 0> angle 55 }
light_source { <-3, 8, -5> rgb 1 }
background { rgb <0.4, 0.5, 0.6> }
plane { y, 0 pigment { image_map { png "maps/tile" gamma srgb } rotate 90 * x scale 0.7 } }
height_field { gif "maps/hf_index" smooth
               pigment { rgb <0.9, 0.6, 0.3> }
               translate <-0.5, 0, -0.5> scale <1.6, 0.5, 1.6> translate x }
