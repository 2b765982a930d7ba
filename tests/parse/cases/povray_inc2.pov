// options: -q -w
// Every macro of shapes.inc (but the text ones) and shapes3.inc called
// once or more, the object's min_extent/max_extent printed with #debug
// (rounded to 5 decimals: POV-Ray sums some boxes in another order).
// povray_inc2.expect is NOT iris output: it is POV-Ray 3.7.0.10's own
// #debug output of this file (povray +Ipovray_inc2.pov -D +GDfile, run in
// this directory), so every line must agree with POV-Ray. Fixed by it:
// - '#if (C) #end' in a macro body: the #end read as the end of the
//   expression C closed the macro (shapes3.inc's Round_Conic_Prism and
//   Half_Hollowed_Rounded_Cylinder1/2: "the #if has no #end");
// - the box of an intersection or difference leaves out its inverted
//   members (an 'inverse' child, a subtracted one) and height fields,
//   counts a plane as its half-space, and an empty or over-large box
//   (> 1e6) is POV-Ray's infinite one (Segment_of_CylinderRing, Wedge,
//   Round_Conic_Torus);
// - prisms (linear and bezier splines) and meshes are bounded as POV-Ray
//   does, their own box transformed as a box (Pyramid_N_AB,
//   Round_Pyramid_N_in, Round_N_Tube_Polygon, Quad, HF_*).
#version 3.7;
#include "inc/print.inc"
#include "colors.inc"
#include "shapes.inc"
#declare B = box { <-1,-2,-3>, <1,2,3> rotate y*30 translate x }
#declare OP = <0,0,0>; #declare ON = <0,0,0>;
QF("isect", Isect(<0,0,-10>, z, B, OP)) QP("isect_pt", OP)
QF("isect_miss", Isect(<0,10,-10>, z, B, OP))
QF("isectn", IsectN(<5,0.5,0>, -x, sphere { 0, 2 }, OP, ON)) QP("isectn_pt", OP) QP("isectn_n", ON)
#declare Mn = 0; #declare Mx = 0;
Extents(B, Mn, Mx) QP("extents_min", Mn) QP("extents_max", Mx)
QE("center_object", Center_Object(B, x+z))
QE("align_object", Align_Object(B, -y, <1,1,1>))
QE("wedge", intersection { Wedge(60) sphere { 0, 1 } })
#declare W = object { Wedge(60) } QF("wedge_in", inside(W, <0.5, 0, -0.5>))
QF("wedge_out", inside(W, <-0.5, 0, 0.5>))
QE("spheroid", Spheroid(<1,2,3>, <1,2,0.5>))
QE("supertorus", Supertorus(2, 0.5, 0.5, 2, 0.001, 10))
#declare ST = object { Supertorus(2, 0.5, 0.5, 2, 0.001, 10) } QF("supertorus_in", inside(ST, <2,0,0>)) QF("supertorus_out", inside(ST, <0,0,0>))
QE("supercone", Supercone(<0,0,0>, 1, 2, <0,3,0>, 0.5, 1))
QE("connect_spheres", Connect_Spheres(<0,0,0>, 1, <3,1,0.5>, 0.25))
QE("wire_box_union", Wire_Box_Union(<-1,-1,-1>, <1,2,1>, 0.1))
QE("wire_box_merge", Wire_Box_Merge(<-1,-1,-1>, <1,2,1>, 0.1))
QE("wire_box", Wire_Box(<1,1,1>, <-1,-2,-1>, 0.2, 0))
QE("round_box_union", Round_Box_Union(<-1,-1,-1>, <1,2,1>, 0.1))
QE("round_box_merge", Round_Box_Merge(<-1,-1,-1>, <1,2,1>, 0.1))
QE("round_box", Round_Box(<1,1,1>, <-1,-2,-1>, 0.2, 1))
QE("round_cyl_union", Round_Cylinder_Union(<0,0,0>, <0,2,1>, 1, 0.2))
QE("round_cyl_merge", Round_Cylinder_Merge(<0,0,0>, <0,2,1>, 1, 0.2))
QE("round_cyl", Round_Cylinder(<0,0,0>, <2,0,0>, 0.5, 0.1, 0))
QE("round_cone_union", Round_Cone_Union(<0,0,0>, 1, <0,2,0>, 0.5, 0.1))
QE("round_cone_merge", Round_Cone_Merge(<0,0,0>, 1, <0,2,0>, 0.5, 0.1))
QE("round_cone", Round_Cone(<0,0,0>, 1, <1,2,0>, 0.5, 0.1, 0))
QE("round_cone2_union", Round_Cone2_Union(<0,0,0>, 1, <0,2,0>, 0.5))
QE("round_cone2_merge", Round_Cone2_Merge(<0,0,0>, 1, <0,2,0>, 0.5))
QE("round_cone2", Round_Cone2(<0,0,0>, 1, <2,2,0>, 0.5, 1))
QE("round_cone3_union", Round_Cone3_Union(<0,0,0>, 1, <0,2,0>, 0.5))
QE("round_cone3_merge", Round_Cone3_Merge(<0,0,0>, 1, <0,2,0>, 0.5))
QE("round_cone3", Round_Cone3(<0,0,0>, 1, <2,2,0>, 0.5, 0))
QE("quad", mesh { Quad(<0,0,0>, <1,0,0>, <1,1,0.5>, <0,1,0>) })
QE("smooth_quad", mesh { Smooth_Quad(<0,0,0>, z, <2,0,0>, z, <2,1,0>, y, <0,1,0>, y) })
#declare HFn = function (x, y, z) { 0.5 + 0.5*sin(x*6)*cos(z*4) }
QE("hf_square", HF_Square(HFn, 1, 0, <10, 8>, 0, "", <-1,0,-1>, <2,1,3>))
QE("hf_square_s", HF_Square(HFn, 0, 1, 6, 1, "", <-1,0,-1>, <2,1,3>))
QE("hf_sphere", HF_Sphere(HFn, 1, 0, 12, 1, "", <1,2,3>, 2, 0.5))
QE("hf_cylinder", HF_Cylinder(HFn, 1, 1, <12, 6>, 0, "", <0,0,0>, <0,3,0>, 1, 0.3))
QE("hf_torus", HF_Torus(HFn, 1, 0, <16, 8>, 1, "", 2, 0.5, 0.2))
#include "shapes3.inc"
QE("seg_object", Segment_of_Object(sphere { <0,0,0>, 1 }, 60))
QE("seg_object2", Segment_of_Object(box { <-1,-1,-1>, <2,1,1> }, 250))
QE("seg_cylring", Segment_of_CylinderRing(2, 1.5, 1, 100))
QE("seg_torus", Segment_of_Torus(2, 0.5, -120))
QE("round_n_tube_poly", Round_N_Tube_Polygon(6, 0.1, 2, 0.3, 0, 0))
QE("round_n_tube_poly_f", Round_N_Tube_Polygon(5, 0.1, 2, 0.3, 1, 1))
QE("pyramid_n", Pyramid_N(6, 2, 1, 3))
QE("pyramid_n_ab", Pyramid_N_AB(5, <0,0,0>, 2, <1,3,1>, 0.5))
QE("column_n", Column_N(8, 1, 2))
QE("column_n_ab", Column_N_AB(7, <0,0,0>, <2,3,0>, 0.5))
QE("egg_shape", Egg_Shape(1.2, 1.8))
QE("egg", object { Egg })
QE("facetted_sphere", Facetted_Sphere(4, 12))
QE("facetted_egg_shape", Facetted_Egg_Shape(4, 10, 1.2, 1.6))
QE("facetted_egg", Facetted_Egg(5, 12))
QE("ring_sphere", Ring_Sphere(2, 2.5, 0.05, 0.08, 6, 5))
QE("round_pyr_in", Round_Pyramid_N_in(6, <0,0,0>, 2, <0,3,0>, 1, 0.1, 1, 0))
QE("round_pyr_out", Round_Pyramid_N_out(5, <0,0,0>, 2, <1,3,0>, 0.5, 0.1, 0, 1))
QE("rounded_tube", Rounded_Tube(2, 1.5, 0.2, 1, 0))
QE("rounded_tube_ab", Rounded_Tube_AB(<0,0,0>, <1,3,0>, 1, 0.7, 0.1, 1))
QE("round_cyl_tube", Round_Cylinder_Tube(<0,0,0>, <0,2,1>, 1, 0.2, 0, 0))
QE("round_cyl_tube_f", Round_Cylinder_Tube(<0,0,0>, <2,0,0>, 1, 0.2, 1, 1))
QE("round_conic_torus", Round_Conic_Torus(1.5, 0.5, 1.2, 0.2, 0))
QE("round_conic_prism", Round_Conic_Prism(1.5, 0.5, 1.2, 2, 0.2, 1))
QE("hhrc1", Half_Hollowed_Rounded_Cylinder1(3, 1, 0.1, 1.5, 0))
QE("hhrc2", Half_Hollowed_Rounded_Cylinder2(3, 1, 0.3, 0.1, 1.5, 1))
