// Parity scene: image maps with 'interpolate 4', POV-Ray's normalised
// distance interpolation (imageutil.cpp norm_dist): each of the four
// texels around a point weighs 1 / its squared distance to the point,
// normalised, so a texel's colour holds near its centre and the blend
// between texels is steeper than bilinear's. Left: an image_map of the
// 16x16 tile magnified to about 2.5 pixels a texel at 80x60; right: the
// same as an image_pattern through a colour_map, and a bump_map, on a
// sphere. iris used the bilinear weights for both interpolations
// (reverted: 34.1 dB at 80x60 +A0.3, too near 35 to tell; with the
// weights identical, hence the bar below).
// parity-min-psnr: 50 bilinear weights in place of norm_dist's give 34.1
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -5> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -8> color rgb 1 }
plane { z, 0
  pigment { image_map { png "maps/tile.png" interpolate 4 }
            translate <-0.5, -0.5, 0> scale 3.2 translate <-1.7, 0, 0> }
  finish { ambient 0.3 diffuse 0.7 }
}
sphere { <1.6, 0, -0.6>, 1.3
  pigment { image_pattern { png "maps/tile.png" interpolate 4 }
            color_map { [0 rgb <0.1, 0.2, 0.9>] [1 rgb <1, 0.9, 0.2>] }
            translate <-0.5, -0.5, 0> scale 2 }
  normal { bump_map { png "maps/tile.png" interpolate 4 bump_size 3 }
           translate <-0.5, -0.5, 0> scale 2 }
  finish { ambient 0.2 diffuse 0.8 }
}
