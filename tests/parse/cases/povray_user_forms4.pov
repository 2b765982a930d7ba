// options: -q -w
// Session 10's users' scenes, printed with #debug; povray_user_forms4.expect
// is NOT iris output: it is POV-Ray 3.7.0.10's own #debug output of this
// file (povray +Ipovray_user_forms4.pov -D +GDfile), so every line must
// agree with POV-Ray. Each block was a difference:
// - concat() takes its strings without commas (Parse_Concat reads until
//   ')', Parse_Comma is optional): a macro's "b" followed by a
//   fall-through #case's "c" is "bc" (iris: "expected ')'"); datetime's
//   comma is optional too;
// - a spline called with a type, S(t, linear_spline), is evaluated as a
//   copy of that type (iris: "expected ')'");
// - a #for inside a macro or at the top of an include file makes its
//   variable in that scope, as #local (iris changed the global I);
// - int(-0.5) and div(-1, 2) are 0, not -0 (POV-Ray casts to int);
// - acos/asin outside [-1, 1] warn and take the nearest end (iris
//   stopped: "argument out of range");
// - str() of a number of 255 or more digits falls back to %g;
// - strcmp() is the difference of the first characters that differ
//   (iris: -1, 0 or 1);
// - a directive before an optional comma runs first, as in POV-Ray's
//   Parse_Comma: 'Pts[I] #if (I < N) , #end' in a prism's points and
//   'max(1 #if (C) , 5 #end)' (iris: "expected a numeric expression,
//   found ','"), and before the ')' ending concat();
// - the condition of #if, #elseif, #while and #switch is '(' float ')'
//   and no more (Parse_Cond_Param): in 'x #if (C) * 2 #end' the '* 2'
//   is the #if's body (iris read the condition as (C) * 2 and left the
//   function without the factor: 3 instead of 6); directives in a
//   function body run before its '}';
// - 'open' after a directive: 'cylinder { A, B, R #if (C) open #end }'
//   (iris: "unexpected 'open'"), and a sphere_sweep's tolerance;
// - "\u00e9" in a string is one character, as POV-Ray's String_To_UCS2
//   reads it (iris kept the six characters: strlen 9 for "caf\u00e9");
// - a bicubic_patch's min/max_extent is the box of its 16 control
//   points, moved by its transform (BicubicPatch::Compute_BBox; iris
//   asked the renderer, whose box of the surface ended at z = 0).
#version 3.7;
#macro Cl(V)
  #switch (V)
    #case (1) #case (2) "a" #break
    #range (3, 4) "b"
    #case (5) "c" #break
    #else "d"
  #end
#end
#declare S = "";
#for (I, 0, 6) #declare S = concat(S, Cl(I)); #end
#debug concat("concat ", S, " " "no" "commas", " ", datetime(0 "%Y-%m-%d"), "\n")

#declare Sp = spline { cubic_spline -1, <0,0,0>, 0, <1,0,0>, 1, <1,1,0>, 2, <0,1,1>, 3, <0,0,2> }
#debug concat("spline ", vstr(3, Sp(1.25), ",", 0, 4), " ",
  vstr(3, Sp(1.25, linear_spline), ",", 0, 4), " ",
  vstr(3, Sp(1.25, quadratic_spline), ",", 0, 4), "\n")
#debug concat("spline ", vstr(3, Sp(1.25, natural_spline), ",", 0, 4), " ",
  vstr(3, Sp(1.25), ",", 0, 4), "\n")

#declare I = 100;
#macro UsesI() #for (I, 0, 2) #end I #end
#declare T = 0;
#macro Sum3() #local S = 0; #for (T, 1, 3) #local S = S + T; #end S #end
#declare J = 100;
#include "inc/for_scope.inc"
#debug concat("for ", str(UsesI(), 0, 0), " ", str(I, 0, 0), " ",
  str(Sum3(), 0, 0), " ", str(T, 0, 0), " ", str(J, 0, 0), " ",
  str(JInInc, 0, 0), " ", str(defined(K), 0, 0), "\n")

#debug concat("int ", str(int(-0.5), 0, 3), " ", str(div(-1, 2), 0, 3), " ",
  str(int(-1.5), 0, 3), " ", str(div(-7.5, 2), 0, 3), "\n")
#debug concat("domain ", str(acos(1.0000000002), 0, 6), " ",
  str(acos(-1.5), 0, 6), " ", str(asin(1.5), 0, 6), " ",
  str(acos(vdot(vnormalize(<1,1,1>), vnormalize(<2,2,2>))), 0, 6), "\n")
#debug concat("str ", str(1e300, 0, 0), "|", str(-1e300, 10, 2), "|",
  str(1e260, -20, 3), "|", str(1e20, 0, 0), "\n")
#debug concat("strcmp ", str(strcmp("a", "d"), 0, 0), " ",
  str(strcmp("abc", "ab"), 0, 0), " ", str(strcmp("A", "a"), 0, 0), " ",
  str(strcmp("same", "same"), 0, 0), "\n")

#declare Pts = array[4] { <1,0>, <0,1>, <-1,0>, <1,0> };
#declare P = prism { linear_sweep linear_spline 0, 0.5, 4,
  #for (I, 0, 3) Pts[I] #if (I < 3) , #end #end }
#declare Q = prism { 0, 0.5, 4, #for (I, 0, 3) <I, 1> #if (I < 3) , #end #end }
#declare M = max(1 #if (1) , 5 #end) + min(3 #if (0) , 1 #end);
#declare C = concat("a" #if (1) , "b" #end #if (0) , "c" #end);
#debug concat("lists ", vstr(3, max_extent(P), ",", 0, 1), " ",
  vstr(3, max_extent(Q), ",", 0, 1), " ", str(M, 0, 0), " ", C, "\n")

#declare X = 1;
#declare Ft = function(x) { x #if (X) * 2 #end }
#declare Gt = function(x, y) { x #if (X) + y #end #if (0) * 100 #end }
#declare Cy = cylinder { 0, y, 0.5 #if (X) open #end scale 2 }
#declare Co = cone { 0, 1 #if (X) , #end y, 0.5 #if (X) open #end }
#declare Sw = sphere_sweep { linear_spline 2 #if (X) , #end <0,0,0>, 0.5,
  <2,0,0>, 0.25 #if (X) tolerance 0.01 #end }
#declare K = 0;
#while (K < 5) #if (K = 3) #declare Hit = K; #end #declare K = K + 1; #end
#debug concat("cond ", str(Ft(3), 0, 2), " ", str(Gt(2, 5), 0, 2), " ",
  vstr(3, max_extent(Cy), ",", 0, 2), " ", vstr(3, max_extent(Co), ",", 0, 2),
  " ", str(Hit, 0, 0), " ", vstr(3, max_extent(Sw), ",", 0, 2), "\n")

#declare Bi = bicubic_patch { type 0
  <0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,1,0>, <1,1,1>, <2,1,1>, <3,1,0>,
  <0,2,0>, <1,2,1>, <2,2,1>, <3,2,0>, <0,3,0>, <1,3,0>, <2,3,0>, <3,3,0> }
#declare Bi2 = object { Bi rotate x * 90 translate y }
#debug concat("patch ", vstr(3, min_extent(Bi), ",", 0, 4), " ",
  vstr(3, max_extent(Bi), ",", 0, 4), "\n")
#debug concat("patch ", vstr(3, min_extent(Bi2), ",", 0, 4), " ",
  vstr(3, max_extent(Bi2), ",", 0, 4), "\n")

#declare U = "caf\u00e9\u0041";
#debug concat("unicode ", str(strlen(U), 0, 0), " ",
  str(asc(substr(U, 4, 1)), 0, 0), " ", substr(U, 5, 1), "\n")
