// Parity scene: a black_hole warp with repeat and turbulence (a copy of
// the hole in every repeat block, each centre jittered by PatternRands of
// the block's hash, after POV-Ray's parse-time check that moves the
// centre and grows the block; textures/pigments/blkhole.pov) and an
// image_map with map_type 5, POV-Ray's torus mapping around a major
// radius of 1 (textures/pigments/mappr2.pov). iris once took the hole's
// repeat and turbulence for separate warps and mapped the torus as a
// plane (blkhole 21.0 dB, mappr2 21.7 dB; 18.5 dB here).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -10> look_at <0, 0, 0> right x*4/3 angle 50 }
light_source { <-30, 50, -100> color rgb 1 }
box { <-5, -3.8, 0>, <0.2, 3.8, 1>
  pigment { gradient x color_map { [0 rgb <0.9, 0.6, 0.2>] [0.5 rgb <0.3, 0.1, 0>] [1 rgb <0.9, 0.6, 0.2>] }
    scale 0.25
    warp { black_hole <0, 0, 0>, 0.5 falloff 3 strength 0.75 inverse
      repeat <2, 1.5, 0> turbulence <1, 0.5, 0> }
    warp { black_hole <0.15, 0.125, 0>, 0.5 falloff 7 repeat <1.25, 1.25, 0>
      turbulence <0.25, 0.25, 0> } } }
torus { 1, 0.6 rotate -70*x translate <2.6, 0, 0>
  pigment { image_map { png "maps/tile.png" map_type 5 interpolate 2 } } }
