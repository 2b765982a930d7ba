// POV-Ray's own template snippets (examples/templates) that iris refused
// (session 10, round 2; each was a located parse error, so the scene did
// not render):
// - meshmaker.inc's TwoVarSurf of function(u, v) { ... x ... y ... }:
//   x and y are the registers loaded from u and v (FNCode::compile_variable);
// - a Parametric of function(x, y) { ... u ... v ... } (template p_Lathe):
//   u and v are x and y;
// - shapes3.inc's Rounded_Tube called with a comma after its last
//   argument (Invoke_Macro's Parse_Comma after every argument);
// - an isosurface of a pigment function's .hf (MegaPOV's height field
//   value, FNCode::compile_member).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "meshmaker.inc"
#include "shapes3.inc"
#include "functions.inc"
camera { location <0, 3, -6.5> look_at <0, 0.4, 0> angle 60 }
light_source { <-5, 10, -8> color rgb 1 }
light_source { <5, 4, -6> color rgb 0.4 }
plane { y, -1 pigment { checker rgb 1 rgb 0.5 } }

#declare SF = function {
  pigment { boxed color_map { [0 rgb 0] [0.5 rgb 0.5] [1 rgb 1] }
    scale <0.5, 1, 0.5> rotate -90 * x }
}
#declare HF = function(u, v) { -1 * SF(x / 3, y / 3, z / 3).gray }
object { TwoVarSurf(HF, <-1.5, 1.5>, <-1.5, 1.5>, 24, 24, "",)
  pigment { rgb <1, 0.6, 0.2> } rotate 90 * x scale 0.8 translate <-2.6, 0.5, 0> }

#declare Sp = spline { cubic_spline
  -1, <1, 0, 0>, 0, <1, 0, 0>, 0.3, <1.2, 0, 0>, 0.7, <0.5, 0, 0>,
  1, <1, 0, 0>, 2, <1, 0, 0> }
#macro p_Lathe(Spline)
  #local __S = function { spline { Spline } }
  Parametric(
    function(x, y) { (__S(u).x * sin(v) / 2) },
    function(x, y) { u },
    function(x, y) { (__S(u).x * cos(v) / 2) },
    <0, 0>, <1, 2 * pi>, 16, 16, "")
#end
object { p_Lathe(Sp) pigment { rgb <0.3, 0.6, 1> } scale 1.4 translate <0, -0.9, 0> }

object { Rounded_Tube(0.9, 0.5, 0.1, 0.6, 0,)
  pigment { rgb <0.4, 1, 0.4> } translate <2.6, -0.9, -0.5> }

#declare Fl = function { pigment { wood scale 0.5 turbulence 0.3
  color_map { [0 rgb 0] [1 rgb 1] } } }
isosurface { function { f_sphere(x, y, z, 0.8) - Fl(x, y, z).hf * 0.3 }
  contained_by { sphere { 0, 1.2 } } max_gradient 15
  pigment { rgb <1, 0.3, 0.5> } translate <2.2, 1.2, 1> }
