// Parity scene: an image read as data through a pigment function, as
// scenes build terrains and masks: an isosurface whose height is the grey
// level of an image_map (y - F(x, 0, z).gray), and a wall whose pigment
// is a function of the image's red channel. iris evaluated functions of
// image-based pigments and patterns without the images loaded, so both
// were 0 everywhere (a flat slab, a black wall): reverted, 9.7 dB.
// plasma3.png is one of the images POV-Ray installs beside its includes.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0.5, 1.1, -1.1> look_at <0.5, 0.1, 0.5> }
light_source { <3, 8, -4> color rgb 1 }
#declare Map = function { pigment { image_map { png "plasma3.png" interpolate 2 } } }
isosurface {
  function { y - Map(x, z, 0).gray * 0.3 }
  contained_by { box { <0, -0.01, 0>, <1, 0.31, 1> } }
  max_gradient 6
  pigment { gradient y color_map { [0 rgb <0.2, 0.5, 0.1>] [1 rgb 1] } scale 0.3 }
}
plane { z, 1.01
  pigment { function { Map(x, y, z).red } color_map { [0 rgb 0] [1 rgb <1, 0.8, 0.2>] } }
  finish { ambient 0.2 diffuse 0.8 } }
