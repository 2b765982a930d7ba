// expect: 2 7
// subsurface samples 1e9: a billion shadow rays per pixel would run for
// days; a located error at the keyword (the bound is 1000000).
#version 3.7;
global_settings {
  subsurface {
    samples 1e9, 1e9
  }
}
camera { location <0, 1, -3> look_at <0, 0.5, 0> }
light_source { <2, 5, -5>, rgb 1 }
sphere { <0, 0.5, 0>, 0.5 pigment { rgb 1 }
         finish { subsurface { translucency 1 } } }
