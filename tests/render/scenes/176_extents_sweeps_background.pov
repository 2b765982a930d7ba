// Parity scene: more objects stacked with min_extent/max_extent, and a
// background with transmit. POV-Ray 3.7 boxes a sor by its profile's
// cubic segments (not its control points), a sphere_sweep by its control
// spheres (radii doubled for cubic_spline), a superellipsoid by +-1.0001
// and a disc or polygon with +-0.001 of thickness, whatever the renderer
// could bound tighter; iris used its renderer's tight boxes, so each
// piece on them sat at another height. Without +UA POV-Ray's parser
// composes a background on black, rgb * (1 - transmit), filter dropped;
// iris showed its rgb unscaled (sRGB 149 against 126 for a grey 0.3).
// 17.7 dB at 80x60 before both fixes (31.2 with an opaque background),
// pixel-identical after. The #debug values are checked in
// tests/unit/test_parse_parity.c (test_pov_extents).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3.2, -8> look_at <0, 1.5, 0> angle 52 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.4 }
background { rgbft <0.3, 0.5, 0.8, 0.3, 0.45> }
disc { 0, y, 6 pigment { checker rgb 0.85, rgb 0.55 } }
#macro Stack(Under, Over)
  #local Top = max_extent(Under).y;
  object { Over translate (Top - min_extent(Over).y) * y }
#end
#declare Ball = sphere { 0, 0.3 pigment { rgb <0.3, 0.8, 0.4> } }
// a vase (sor) with a ball on it
#declare Vase = sor { 6, <0, -0.2>, <0.45, 0>, <0.25, 0.6>, <0.5, 1.1>,
  <0.3, 1.5>, <0.6, 1.8> pigment { rgb <0.9, 0.3, 0.2> } }
union { object { Vase } object { Stack(Vase, Ball) } translate -2.4 * x }
// a cubic sweep arch with a superellipsoid on it, a ball on that
#declare Arch = sphere_sweep { cubic_spline 5, <-1, -0.5, 0>, 0.15,
  <-0.6, 0, 0>, 0.2, <0, 0.9, 0>, 0.15, <0.6, 0, 0>, 0.2, <1, -0.5, 0>, 0.15
  pigment { rgb <0.2, 0.5, 0.9> } }
#declare Block = superellipsoid { <0.3, 0.3> scale <0.35, 0.2, 0.35>
  rotate 20 * y pigment { rgb <0.95, 0.8, 0.2> } }
#declare Block1 = object { Stack(Arch, Block) }
union { object { Arch } object { Block1 } object { Stack(Block1, Ball) }
  translate <0, 0, 0.6> }
// a linear sweep post with a tilted polygon plate and a ball on it
#declare Post = sphere_sweep { linear_spline 2, <0, 0, 0>, 0.25,
  <0, 1.2, 0>, 0.1 pigment { rgb <0.7, 0.3, 0.8> } }
#declare Plate = polygon { 5, <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>,
  <-0.5, 0.5>, <-0.5, -0.5> rotate 80 * x rotate 30 * y
  pigment { rgb <0.2, 0.7, 0.8> } }
#declare Plate1 = object { Stack(Post, Plate) }
union { object { Post } object { Plate1 } object { Stack(Plate1, Ball) }
  translate 2.4 * x }
