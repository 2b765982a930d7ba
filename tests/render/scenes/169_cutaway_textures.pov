// Parity scene: cutaway_textures. The cut faces left by untextured parts
// of a difference take the texture of the difference's first object
// (POV-Ray's CSG::Determine_Textures; without the keyword they get the
// default black texture). A plain difference, one declared and re-used
// with a transform, one inside an untextured union, and one whose cutter
// has its own texture (kept). iris ignored the keyword (black cut faces,
// 21.5 dB at 80x60); now they agree.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -6> look_at <0, 0.6, 0> }
light_source { <-4, 8, -6> color rgb 1 }
#declare Ball = difference {
  sphere { 0, 1 texture { pigment { gradient y
    color_map { [0 rgb <1, 0.2, 0.1>] [1 rgb <0.1, 0.3, 1>] } scale 2 translate -y } } }
  box { <0, 0, -2>, 2 }
  box { -2, <0, -0.4, 0> texture { pigment { rgb <0.1, 0.8, 0.2> } } }
  cutaway_textures
}
object { Ball rotate y * -30 translate <-1.4, 1, 0> }
union {
  object { Ball rotate y * 40 }
  cylinder { <0, -1, 0>, <0, -0.8, 0>, 0.3 pigment { rgb 0.8 } }
  scale 0.8 translate <1.3, 1, 0.5>
}
difference {
  box { -0.5, 0.5 pigment { checker rgb <1, 0.8, 0.2>, rgb <0.6, 0.2, 0.6> scale 0.25 } }
  sphere { <-0.5, 0.5, -0.5>, 0.6 }
  cutaway_textures
  translate <0, 0.5, -2>
}
plane { y, 0 pigment { rgb 0.8 } }
