// Parity scene: bounded_by as POV-Ray applies it (objects.cpp
// Find_Intersection, Ray_In_Bound): a shape is tested only for rays that
// meet its bound or start inside it, and all its crossings on those rays
// count, so a bound smaller than the shape cuts it along the bound's
// silhouette as seen along each ray (not along the bound's surface). The
// parser drops the bound of a cheap top-level shape (parse.cpp
// Link_To_Frame) but not the box it took from it: the infinite cylinder
// (a quadric) and the torus end at the bound's box, while the quartic
// keeps its bound sphere. iris once ignored every bound
// (objects/quartic/hyptorus.pov at 27.6 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -9> look_at <0, 0.3, 0> right x*4/3 angle 55 }
light_source { <-5, 8, -6> color rgb 1 }
light_source { <6, 3, -4> color rgb 0.4 }
background { rgb <0.15, 0.15, 0.2> }
// a hyperboloid of one sheet x^2 + z^2 - y^2 = 0.25, infinite
quartic {
  < 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 1, 0, 0, 0, 0,
    0, 0, 1, 0, -0.25 >
  sturm
  bounded_by { sphere { <0, 0.4, 0>, 1.3 } }
  pigment { rgb <1, 0.5, 0.3> }
  translate <-2.3, 0.5, 0>
}
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.16
  bounded_by { box { <-1, -1, -1>, <1, 1.4, 1> } }
  pigment { rgb <0.4, 0.8, 0.5> }
  translate <0.2, 0.5, 0>
}
torus { 0.8, 0.3
  bounded_by { box { <-0.5, -0.5, -1.2>, <0.6, 0.5, 1.2> } }
  pigment { rgb <0.5, 0.6, 1> }
  rotate -60 * x
  translate <2.4, 0.5, 0>
}
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }
