// options: -q -w
// Session 11: forms from users' scenes on GitHub that iris refused,
// printed with #debug. povray_user_forms6.expect is NOT iris output: it
// is POV-Ray 3.7.0.10's own #debug output of this file (povray
// +Ipovray_user_forms6.pov -D +GDfile), so every line must agree with
// POV-Ray. Each block was a difference:
// - '#undef A[i]' makes one element of an array uninitialised again
//   (POV-Ray's Remove_Symbol with is_array_elem), so that a function can
//   be declared there anew (a complex-function library keeps its
//   operators in an array; iris: "expected an object ..., found '['");
//   '#undef A' followed by a directive on the next line still undefines
//   the whole array;
// - 'x / 0' is POV-Ray's HUGE_VAL with a "Divide by zero" warning, not an
//   error (Parse_Term): '#declare Speed = D / clock;' in an animation
//   scene rendered at clock 0 (iris: "division by zero"). Only where such
//   a value goes into the scene is it refused.
#version 3.7;

#declare Ops = array[3];
#declare Ops[0] = function(a, b) { a + b }
#declare Ops[1] = function(a, b) { a * b }
#undef Ops[1]
#debug concat("undef1 ", str(defined(Ops[0]), 0, 0), " ",
              str(defined(Ops[1]), 0, 0), "\n")
#declare Ops[1] = function(a, b) { a - b }
#debug concat("redeclared ", str(Ops[0](5, 3), 0, 3), " ",
              str(Ops[1](5, 3), 0, 3), "\n")
#declare V = array[2][2] { {1, 2}, {3, 4} }
#undef V[1][0]
#debug concat("undef2 ", str(defined(V[1][0]), 0, 0), " ",
              str(defined(V[1][1]), 0, 0), " ", str(V[1][1], 0, 0), "\n")
#declare V[1][0] = 7;
#debug concat("again ", str(V[1][0] + V[0][1], 0, 0), "\n")
#declare W = array[2] {5, 6}
#undef W
#declare W = 8;
#debug concat("whole ", str(W, 0, 0), "\n")

#declare Clock = 0;
#declare Speed = 10 / Clock;
#declare Big = (Speed > 1e300);
#declare Zero = 0 / 0;
#debug concat("divide ", str(Big, 0, 0), " ", str((Zero > 1e300), 0, 0),
              " ", str(Clock, 0, 0), "\n")
#declare Vd = <1, 2, 3> / <1, 0, 2>;
#debug concat("vector ", str(Vd.x, 0, 3), " ", str((Vd.y > 1e300), 0, 0),
              " ", str(Vd.z, 0, 3), "\n")
