// options: -q -w
// Splines of the four types inside and outside their keys, a spline
// function, a transform function and both inside a function body.
// spline_povray.expect is POV-Ray 3.7.0.10's own #debug output of this
// file, not iris output: every value must agree to the 9 decimals printed.
#version 3.7;
#declare SL = spline { linear_spline 0, <0,0,0> 1, <1,2,0> 2, <3,1,1> 4, <2,5,2> }
#declare SQ = spline { quadratic_spline 0, <0,0,0> 1, <1,2,0> 2, <3,1,1> 4, <2,5,2> }
#declare SC = spline { cubic_spline 0, <0,0,0> 1, <1,2,0> 2, <3,1,1> 4, <2,5,2> 5, <1,1,1> }
#declare SN = spline { natural_spline 0, <0,0,0> 1, <1,2,0> 2, <3,1,1> 4, <2,5,2> 5, <1,1,1> }
#declare T = array[8] { -0.5, 0, 0.3, 1, 1.5, 2.7, 4.2, 6 }
#for (I, 0, 7)
  #declare A = SL(T[I]); #declare B = SQ(T[I]); #declare C = SC(T[I]); #declare D = SN(T[I]);
  #debug concat("L ", str(T[I],0,2), " ", vstr(3, A, " ", 0, 9), "\n")
  #debug concat("Q ", str(T[I],0,2), " ", vstr(3, B, " ", 0, 9), "\n")
  #debug concat("C ", str(T[I],0,2), " ", vstr(3, C, " ", 0, 9), "\n")
  #debug concat("N ", str(T[I],0,2), " ", vstr(3, D, " ", 0, 9), "\n")
#end
#declare F = function { spline { SN } }
#declare G = function { transform { rotate 30*y scale <1,2,3> translate x } }
#debug concat("F ", vstr(3, F(2.7), " ", 0, 9), "\n")
#declare H = function { F(x).y + G(x, y, z).z }
#debug concat("H ", str(H(2.7, 1, 2), 0, 9), "\n")
#debug concat("G ", vstr(3, G(1, 2, 3), " ", 0, 9), "\n")
