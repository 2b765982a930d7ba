// Parity scene: objects stacked with min_extent/max_extent, as users place
// them. POV-Ray boxes a cylinder or cone in its own frame (tight along its
// axis), keeps a rotated sphere's box tight, and boxes a CSG once from its
// children, then moves the eight corners of that box with each later
// transform. iris padded cylinders and cones by their radius along the
// axis and boxed CSG from their transformed children, so every stacked
// piece sat at another height: 23.2 dB at 80x60 before the fix (22.9 at
// 160x120), 41.8 after (40.5 at 160x120). The #debug values themselves
// are checked in tests/parse/cases/povray_user_forms3.pov.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -8> look_at <0, 1.6, 0> angle 50 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.55 } }
#macro Stack(Under, Over)
  #local Top = max_extent(Under).y;
  object { Over translate (Top - min_extent(Over).y) * y }
#end
// a column: an upright cylinder, a rotated union on it, a cone on top
#declare Col = cylinder { 0, 1.2 * y, 0.35 pigment { rgb <0.9, 0.3, 0.2> } }
#declare Cap = union {
  box { <-0.5, 0, -0.5>, <0.5, 0.2, 0.5> }
  sphere { <0.4, 0.3, 0>, 0.15 }
  rotate 35 * y rotate 20 * z
  pigment { rgb <0.2, 0.5, 0.9> }
}
#declare Cap1 = object { Stack(Col, Cap) }
#declare Tip = cone { 0, 0.4, 0.8 * y, 0 pigment { rgb <0.95, 0.8, 0.2> } }
union { object { Col } object { Cap1 } object { Stack(Cap1, Tip) } translate -2 * x }
// a lying cylinder (its box is tight along x) with a ball on it
#declare Log = cylinder { <-0.8, 0.3, 0>, <0.8, 0.3, 0>, 0.3 rotate 25 * y pigment { rgb <0.5, 0.35, 0.2> } }
#declare Ball = sphere { <0, 0, 0>, 0.3 pigment { rgb <0.3, 0.8, 0.4> } }
union { object { Log } object { Stack(Log, Ball) } translate 0.6 * x }
// a tilted cone and a rotated merge stacked on it
#declare Horn = cone { 0, 0.45, <0.3, 1, 0.2>, 0.1 pigment { rgb <0.7, 0.3, 0.8> } }
#declare Block = merge {
  box { -0.3, 0.3 }
  cylinder { -0.5 * x, 0.5 * x, 0.15 }
  rotate <20, 40, 0>
  pigment { rgb <0.2, 0.7, 0.8> }
}
union { object { Horn } object { Stack(Horn, Block) } translate <2.4, 0, 0.5> }
