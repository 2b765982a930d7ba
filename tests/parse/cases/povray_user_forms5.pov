// options: -q -w
// Session 10's second round: POV-Ray's template snippets that iris
// refused, printed with #debug. povray_user_forms5.expect is NOT iris
// output: it is POV-Ray 3.7.0.10's own #debug output of this file
// (povray +Ipovray_user_forms5.pov -D +GDfile), so every line must agree
// with POV-Ray. Each block was a difference:
// - x, y, z, u and v in a function body are POV-Ray's three registers
//   (FNCode::compile_variable, compile_parameters): x and u are the
//   parameter named x or u (the last one if both), y and v the one named
//   y or v, z the one named z, and 0 without such a parameter. So in
//   function(u,v) 'x' is u (meshmaker.inc's mesh_by_2varfunction), in
//   function(x,y) 'u' is x (p_Lathe), in function(a,b) 'x' is 0 (iris:
//   "unexpected 'x' in function");
// - a macro call's last argument may be followed by a comma (Invoke_Macro
//   calls Parse_Comma after each argument): shapes3.inc's Rounded_Tube
//   template and meshmaker's SweepSpline1/2 (iris: "too many parameters
//   in the call of macro");
// - a pigment function's .hf (MegaPOV's height field value,
//   (red + green/255) * 0.996093) and .grey (FNCode::compile_member;
//   Isosurfaces_by_pattern_functions template 99; iris: "undeclared
//   identifier 'hf'"); .gray and .hf of a spline function weigh its
//   x, y and z the same way (iris gave x).
#version 3.7;

#declare F1 = function(u, v) { x * 10 + y + z * 100 }
#declare F2 = function(x, y) { u * 10 + v }
#declare F3 = function(a, b) { a + x + y + z + u + v }
#declare F4 = function(x, u) { x * 10 + u }
#declare F5 = function(a, v) { y * 10 + a }
#declare F6 = function { u * 10 + v + z }
#declare F7 = function(u, v, z) { x + y * 10 + z * 100 }
#debug concat("regs ", str(F1(2, 3), 0, 3), " ", str(F2(2, 3), 0, 3), " ",
  str(F3(2, 3), 0, 3), " ", str(F4(2, 3), 0, 3), " ", str(F5(2, 3), 0, 3),
  " ", str(F6(2, 3, 4), 0, 3), " ", str(F7(2, 3, 4), 0, 3), "\n")

#macro M(A, B,) A * 10 + B #end
#macro N(A, B) A * 10 + B #end
#declare Q = 7;
#debug concat("comma ", str(M(4, 5,), 0, 3), " ", str(N(4, 5,), 0, 3), " ",
  str(N(4, Q, ), 0, 3), " ", str(N(4,
  5, // the last one
  ), 0, 3), "\n")

#declare P = function {
  pigment { gradient x color_map { [0 rgb <0, 0.5, 1>] [1 rgb <1, 0.2, 0>] } }
}
// (outside a function body POV-Ray refuses .hf: only compile_member has it)
#declare G = function { P(x, y, z).hf }
#declare H = function { P(x, y, z).grey }
#declare K = function { P(x, y, z).hf * 2 + P(x, y, z).gray }
#debug concat("hf ", str(G(0.25, 0, 0), 0, 6), " ", str(H(0.5, 0, 0), 0, 6),
  " ", str(K(0.75, 0, 0), 0, 6), "\n")
#declare S = function { spline { linear_spline 0, <0.2, 0.4, 0.6>, 1, <1, 1, 1> } }
#declare SG = function { S(x).gray }
#declare SH = function { S(x).hf }
#debug concat("spline ", str(SG(0.5, 0, 0), 0, 6), " ",
  str(SH(0.5, 0, 0), 0, 6), "\n")
