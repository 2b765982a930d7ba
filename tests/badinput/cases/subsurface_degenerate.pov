// expect: 0 -
// subsurface with nothing to transport: translucency 0 and negative (no
// mean free path), a black pigment (no albedo), a pigment above 1 (past
// the albedo table). POV-Ray divides by zero here; iris
// renders those layers without their diffuse term and without NaN.
#version 3.7;
global_settings { subsurface { samples 20, 5 } }
camera { location <0, 1, -3> look_at <0, 0.5, 0> }
light_source { <2, 5, -5>, rgb 1 }
sphere { <-0.6, 0.5, 0>, 0.4 pigment { rgb <2, 0, 1> }
         finish { subsurface { translucency <0, -1, 1e300> } } }
box { <0, 0, -0.3>, <0.6, 0.6, 0.3> pigment { rgb 0 }
      finish { subsurface { translucency 1 } } }
