// Parity scene: bump_map (POV-Ray's three-sample image normal) from the
// suite's tile image, planar and repeated with bilinear interpolation,
// and once on a box; the interpolation and the bump_size both matter.
// parity-min-psnr: 31 iris is at 33.8 dB: the normals differ slightly along the texel edges of the tile, cause not yet found (textures/normals/bumpmap.pov is at 38.6 dB)
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -5> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-4, 6, -3> color rgb 1 }
plane { y, 0 pigment { rgb <0.8, 0.75, 0.6> }
  normal { bump_map { png "maps/tile.png" interpolate 2 bump_size 3 } rotate x*90 scale 1.5 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.9, 1> } finish { phong 0.6 }
  normal { bump_map { png "maps/tile.png" map_type 1 bump_size 2 } } }
box { <0.3, 0, -0.5>, <2.3, 2, 0.5> pigment { rgb <0.6, 0.8, 0.6> }
  normal { bump_map { png "maps/tile.png" once bump_size 4 } scale 2 translate x*0.3 } }
