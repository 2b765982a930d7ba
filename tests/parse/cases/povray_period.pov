// options: -q -w
// POV-Ray's period operator (Parse_Num_Factor) puts the component it
// takes in the first place and leaves the others as they were: where a
// vector is read (vlength, vnormalize, vrotate, vcross, scale, translate)
// V.y is <V.y, V.y, V.z>, unless an operator with a vector operand (or a
// float read before it) promoted it; a float's .y is the float where a
// vector is read. povray_period.expect is NOT iris output: it is POV-Ray
// 3.7.0.10's own #debug output of this file (povray +Ipovray_period.pov
// -D +GDfile). iris took V.y as a float everywhere (vlength(V.x) was
// 3*sqrt(3), POV-Ray 5*sqrt(2)).
#version 3.7;
#include "inc/print.inc"
#declare F = 2;
#declare V = <3,4,5>;
#declare T = <1,2,3,4>;
#declare W = spline { linear_spline 0, <3,4,0>, 1, <3,4,0> }
QF("vlength_dot", vlength(V.x))
QF("vlength_spline_dot", vlength(W(0.5).x))
QF("vlength_spline_dot_y", vlength(W(0.5).y))
QF("vlength_4d_dot", vlength(T.x))
QP("vnormalize_dot", vnormalize(V.y))
QP("vrotate_dot", vrotate(V.z, y))
QP("vcross_dot", vcross(V.y, x))
QE("scale_dot", sphere { 0, 1 scale V.y })
QE("translate_dot", sphere { 0, 1 translate V.x })
// a float operand after the period keeps the leftovers, one before it or
// a vector operand promotes the component
QF("dot_plus_float", vlength(V.x + 0))
QF("dot_times_float", vlength(V.x * 1))
QF("float_times_dot", vlength(1 * V.x))
QF("negated_dot", vlength(-V.x))
QP("vector_times_dot", <1,2,3> * V.z)
QP("colour_dot", rgb V.y)
// declared or passed, a component is a plain float
#declare D = V.x;
QF("declared_dot", vlength(D))
QF("passed_dot", V.y)
// a float's components: .x anywhere, .y where a vector is read
QF("float_x", F.x)
QF("vlength_float_y", vlength(F.y))
QF("paren_float_y", vlength((F + 1).y))
QE("scale_float_plus", sphere { 0, 1 scale 2 + F.y })
#declare Q = <1,2,3> + F.y;
QP("vector_plus_float_y", Q)
