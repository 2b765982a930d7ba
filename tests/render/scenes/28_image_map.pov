// image_map: planar (repeated, interpolated) and spherical.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { image_map { png "maps/tile.png" interpolate 2 } rotate x*90 scale 2 } }
sphere { <-1.1, 1, 0>, 1 pigment { image_map { png "maps/tile.png" map_type 1 } } }
box { <0.3, 0, -0.5>, <2.3, 2, 0.5> pigment { image_map { png "maps/tile.png" once } scale 2 translate x*0.3 } }
