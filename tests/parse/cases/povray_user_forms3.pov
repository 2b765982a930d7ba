// options: -q -w
// Session 7's users' scenes, printed with #debug; povray_user_forms3.expect
// is NOT iris output: it is POV-Ray 3.7.0.10's own #debug output of this
// file (povray +Ipovray_user_forms3.pov -D), so every line must agree with
// POV-Ray. Each block was a difference:
// - a macro returning a value from a #switch clause goes on in the
//   caller's expression: concat(Cls(6), ...) and Cls(0) + 1 (iris stopped
//   at the clause's #break); a #switch nested in a clause picks its case
//   (iris took the outer #case's label for the inner one);
// - '#if (1) #if (C) #else': the #else right after the inner condition
//   belongs to the inner #if (iris ran it as the outer #if's #else and
//   skipped the branch);
// - after '#for (K, 0, 3)' K is 4, the first value that failed the test;
// - A[i][j] = v writes into an array held in an array; '#declare B = A'
//   copies the array (and arrays in an initialiser are copies);
// - a spline key given as a float is <v, v>, and the components a key
//   does not give keep the previous key's: at 1, <5, 5, 3>;
// - min_extent/max_extent: a cylinder or cone is boxed in its own frame
//   (tight along the axis), a sphere under a rotation keeps its tight
//   box, a CSG's box is made from its children once and then transformed
//   as a box (a rotated union of a sphere is 1.414 wide);
// - #ifdef/defined() of a reserved word: only the animation and image
//   size identifiers are defined (iris said every reserved word was);
// - POV-Ray 3.1's 'alpha' colour component: a warning, read as filter;
// - 'color 0.5' (a float, no rgb) is 0.5 in all five components, so it
//   filters and transmits (iris left filter and transmit 0);
// - functions.inc's internal functions (f_hetero_mf, f_helix1, ...) with
//   the argument counts POV-Ray requires.
#version 3.7;
#include "functions.inc"
#macro Cls(X)
  #switch (X)
    #case (0) 0 #break
    #range (1, 5) 1 #break
    #range (5, 10)
      #switch (mod(X, 2))
        #case (0) 2 #break
        #else 3
      #end
    #break
    #else 4
  #end
#end
#macro Name(X) #switch (X) #case (0) "zero" #break #else "other" #end #end
#debug concat("switch ", str(Cls(0), 0, 0), str(Cls(3), 0, 0),
  str(Cls(6), 0, 0), str(Cls(7), 0, 0), str(Cls(11), 0, 0),
  " sum ", str(Cls(6) + Cls(7) * 10, 0, 0), " ", Name(0), " ", Name(1), "\n")
#for (K, 0, 3) #end
#declare N = 0;
#for (J, 10, 0, -2.5) #declare N = N + 1; #end
#debug concat("for ", str(K, 0, 0), " ", str(J, 0, 1), " ", str(N, 0, 0), "\n")
#declare A = array[2] { array[2] {1, 2}, array[3] {3, 4, 5} }
#declare A[1][2] = 50;
#declare B = A;
#declare B[0][0] = 10;
#declare C = array[1] { A }
#declare A[0][1] = 20;
#debug concat("arrays ", str(A[0][0], 0, 0), " ", str(A[0][1], 0, 0), " ",
  str(A[1][2], 0, 0), " ", str(B[0][0], 0, 0), " ", str(B[0][1], 0, 0),
  " ", str(C[0][0][1], 0, 0), "\n")
#declare S = spline { linear_spline 0, <1, 2, 3>, 1, 5, 2, <7, 8> }
#declare F = spline { linear_spline 0, 1, 1, 3 }
#declare V = F(0.5);
#debug concat("spline ", vstr(3, S(1), ",", 0, 2), " ", vstr(3, S(1.5), ",", 0, 2),
  " ", vstr(3, V, ",", 0, 2), "\n")
#macro Ext(Name, O)
  #debug concat(Name, " ", vstr(3, min_extent(O), ",", 0, 4), " ",
    vstr(3, max_extent(O), ",", 0, 4), "\n")
#end
Ext("cylinder", cylinder { 0, 2 * y, 0.5 })
Ext("tilted", cylinder { 0, <1, 1, 0>, 0.5 })
Ext("cone", cone { 0, 1, 2 * y, 0.2 rotate 45 * z })
Ext("sphere", sphere { <3, 0, 0>, 0.5 rotate 30 * y })
Ext("ellipsoid", sphere { <3, 0, 0>, 0.5 scale <1, 2, 1> rotate 30 * y })
Ext("union", union { box { 0, 1 } sphere { 3 * x, 0.5 } rotate 30 * y })
#declare U = union { sphere { 0, 1 } }
Ext("object", union { object { U rotate 45 * y } translate y })
Ext("merge", merge { sphere { 0, 1 } cylinder { 0, 2 * x, 0.5 } rotate 90 * y })
#debug concat("internal ", str(f_hetero_mf(0.3, 1.7, 2.2, 0.5, 2, 6, 0.3, 1, 1), 0, 5),
  " ", str(f_helix1(0.5, 0.2, 0.3, 2, 3, 0.2, 0.5, 1, 1, 0.2), 0, 5),
  " ", str(f_blob(0.3, 0.2, 0.1, 1, 0.5, 0.4, 1, 0.3), 0, 5), "\n")
#debug concat("defined ", str(defined(pi), 0, 0), str(defined(clock), 0, 0),
  str(defined(x), 0, 0), str(defined(image_width), 0, 0),
  str(defined(frame_number), 0, 0), str(defined(U), 0, 0), "\n")
#ifdef (version) #debug "version defined\n" #else #debug "version undefined\n" #end
#declare Ca = color rgb <1, 1, 0> alpha 0.5;
#debug concat("alpha ", vstr(5, Ca, ",", 0, 2), "\n")
#declare Cf = color 0.5;
#declare Cr = rgb 0.5;
#debug concat("float colour ", vstr(5, Cf, ",", 0, 2), " ", vstr(5, Cr, ",", 0, 2), "\n")
#declare Cz = 0;
#if (1) #if (Cz) #debug "nested if wrong\n" #else #debug "nested if else\n" #end #end
