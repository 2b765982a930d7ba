// Parity scene: bounded_by on CSG (shapes2.inc's Pyramid2, an intersection
// of five planes bounded_by a box). POV-Ray's parser gives the CSG its
// bound's box when smaller (parse.cpp Parse_Object_Mods) and keeps the
// bound of every CSG (Link_To_Frame), so the object is tested only for rays
// that meet the bound or start inside it (objects.cpp Find_Intersection,
// Ray_In_Bound; csg.cpp does the same for a bounded child). The infinite
// slanted planes are thus cut along the box's silhouette. iris once took
// a bound on CSG as a hint only: 21.25 dB here (inf with the fix).
#version 3.7;
#include "shapes.inc"
#include "shapes2.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 2.5, -7> look_at <0, 0.2, 0> right x*4/3 angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
background { rgb <0.15, 0.15, 0.2> }
object { Pyramid2 pigment { rgb <1, 0.6, 0.3> } translate <-1.6, 0, 0> }
// a bounded difference: a sphere minus a slab, bounded by a smaller box,
// cut along the box's silhouette
difference {
  sphere { 0, 1 }
  box { <-2, -0.2, -2>, <2, 0.2, 2> }
  bounded_by { box { <-0.45, -0.8, -0.45>, <0.45, 0.8, 0.45> } }
  pigment { rgb <0.4, 0.7, 1> }
  rotate 30 * y
  translate <1.4, 0.2, 0>
}
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }
