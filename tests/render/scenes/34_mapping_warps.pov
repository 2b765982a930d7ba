// Parity scene: the mapping warps (planar, spherical, cylindrical,
// toroidal) as POV-Ray's warp_* functions map points: gradients with a
// frequency (not a transform, whose order relative to a warp{} the parser
// does not keep yet) wrapped around each shape, the translate after the
// warp centring the mapping on it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -0.5 pigment { rgb 0.6 } }
#declare M = color_map { [0.5 rgb <1, 0.2, 0.1>] [0.5 rgb <1, 1, 0.8>] }
sphere { 0, 1 translate <-2.6, 0.8, 0>
  pigment { gradient x frequency 8 color_map { M } warp { spherical }
            translate <-2.6, 0.8, 0> } }
sphere { 0, 0.6 translate <-2.6, 2.4, 0>
  pigment { gradient y frequency 5 color_map { M } warp { spherical }
            translate <-2.6, 2.4, 0> } }
cylinder { <0, -1.3, 0>, <0, 1.2, 0>, 0.8 translate <-0.4, 0.8, 0>
  pigment { gradient x frequency 6 color_map { [0.5 rgb <0.1, 0.3, 1>] [0.5 rgb 1] }
            warp { cylindrical orientation y dist_exp 1 } translate <-0.4, 0.8, 0> } }
torus { 0.8, 0.35 rotate -60*x translate <1.9, 0.9, 0>
  pigment { gradient y frequency 6 color_map { M } warp { toroidal major_radius 0.8 }
            rotate -60*x translate <1.9, 0.9, 0> } }
box { <-4, -0.5, 2>, <4, 2.5, 2.2>
  pigment { checker rgb 0.9 rgb <0.2, 0.6, 0.3> warp { planar z, 0.3 } } }
