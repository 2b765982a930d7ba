// Parity scene: objects from POV-Ray's include files placed by their
// min_extent/max_extent, as users stack them, and sized by a vector's
// component. Each was placed elsewhere by iris before session 8:
// shapes3.inc's Segment_of_CylinderRing (its box left out the inner,
// inverted cylinder), Round_Conic_Prism (did not parse: '#if (C) #end' in
// a macro), Pyramid_N_AB (prisms bounded by the renderer's tight box),
// shapes.inc's Wedge in an intersection (a plane's half-space) and
// Connect_Spheres (a cone's frame runs from its small end), screen.inc's
// Screen_Object (a sphere under a matrix), meshmaker.inc's SweepSpline1
// (failed on FindPoint's ';;', then vlength(Waist(su).x) is
// vlength(Waist(su)) in POV-Ray), and 'scale V.y' (<V.y, V.y, V.z>).
// Before the fixes the scene did not parse (Round_Conic_Prism,
// SweepSpline1); after them 49.4 dB at 80x60. The #debug values are
// checked in tests/parse/cases/povray_inc*.pov and povray_period.pov.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "shapes.inc"
#include "shapes3.inc"
#include "meshmaker.inc"
camera { location <0, 4, -9> look_at <0, 1.4, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -5> color rgb 0.4 }
plane { y, 0 pigment { checker rgb 0.85, rgb 0.55 } }
#macro Stack(Under, Over)
  #local Top = max_extent(Under).y;
  object { Over translate (Top - min_extent(Over).y) * y }
#end
#macro Beside(Left, Right)
  #local Edge = max_extent(Left).x;
  object { Right translate (Edge - min_extent(Right).x + 0.1) * x }
#end
#declare Base = box { <-4.2, 0, -0.6>, <-3.2, 0.3, 0.6>
  pigment { rgb <0.6, 0.6, 0.65> } }
#declare Ring = object { Segment_of_CylinderRing(0.6, 0.4, 0.5, 250)
  rotate 20 * y pigment { rgb <0.9, 0.3, 0.2> } }
#declare Ring1 = object { Stack(Base, Ring) }
object { Base }
object { Ring1 }
#declare ConicPrism = object { Round_Conic_Prism(0.6, 0.2, 0.4, 0.8, 0.08, 0)
  rotate -90 * y pigment { rgb <0.2, 0.5, 0.9> } }
object { Stack(Ring1, ConicPrism) translate -3.7 * x }
#declare Pyr = object { Pyramid_N_AB(5, <0, 0, 0>, 0.6, <0.4, 1.2, 0.3>, 0.2)
  pigment { rgb <0.95, 0.8, 0.2> } }
#declare Pyr1 = object { Beside(Base, Pyr) }
object { Pyr1 }
#declare Slice = intersection { Wedge(120) sphere { 0, 0.6 }
  rotate 30 * y pigment { rgb <0.3, 0.8, 0.4> } }
object { Stack(Pyr1, Slice) translate -0.4 * x }
#declare Link = object { Connect_Spheres(<0, 0, 0>, 0.45, <0.8, 0.7, 0.5>, 0.15)
  pigment { rgb <0.8, 0.4, 0.8> } }
#declare Link1 = object { Beside(Pyr1, Link) }
object { Stack(Base, Link1) }
#declare Dot = sphere { 0, 0.3 matrix <1, 0.3, 0, 0, 1, 0.2, 0.1, 0, 1, 0, 0, 0>
  pigment { rgb <0.9, 0.6, 0.3> } }
object { Stack(Link1, Dot) translate 1.2 * x }
#declare Track = spline { cubic_spline -1, <0,-1,0>, 0, <0,0,0>, 1, <1,1,0>,
  2, <2,1,1>, 3, <3,0,2> }
#declare Shape = spline { linear_spline 0, <0.2,0,0>, 1, <0,0.2,0>,
  2, <-0.2,0,0>, 3, <0,-0.2,0>, 4, <0.2,0,0> }
#declare Waist = spline { linear_spline 0, <1,0,0>, 1, <0.5,0,0> }
#declare Tube = object { SweepSpline1(Track, Shape, Waist, 24, 12, "")
  pigment { rgb <0.4, 0.7, 0.9> } }
object { Stack(Base, Tube) translate 2.2 * x }
#declare Size = <0.25, 0.5, 0.35>;
sphere { 0, 1 scale Size.y translate <3.4, 0.5, -1.2>
  pigment { rgb <0.9, 0.9, 0.3> } }
