// options: -q -w
// Forms of users' scenes whose values iris got wrong, printed with #debug.
// povray_user_forms.expect is NOT iris output: it is POV-Ray 3.7.0.10's
// own #debug output of this file (povray +Ipovray_user_forms.pov -D, its
// writes allowed), so every line must agree with POV-Ray:
// - pigment and pattern functions of images, density files and objects
//   (iris gave 0: what they read was not loaded for functions);
// - strings.inc's Parse_String, which writes a file and #includes it
//   (iris refuses writes by default: it keeps the text in memory);
// - a macro argument that is an array element is passed by reference;
// - vstr() of a float prints <f, 0, 0>, 2 to 5 components;
// - #read at the end of a file undefines the file identifier.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "strings.inc"
#declare Map = function { pigment { image_map { png "plasma3.png" interpolate 2 } } }
#declare Pat = function { pattern { image_pattern { png "plasma3.png" } } }
#declare Df3 = function { pattern { density_file df3 "spiral.df3" interpolate 1 } }
#declare Obj = function { pattern { object { sphere { 0, 0.5 } } } }
#declare ObjPig = function { pigment { object { box { -0.3, 0.3 } color rgb 0.2 color rgb <1, 0.5, 0> } } }
#debug concat("object ", str(Obj(0.1, 0.1, 0.1), 0, 3), " ", str(Obj(0.6, 0, 0), 0, 3),
              " pigment ", str(ObjPig(0, 0, 0).green, 0, 3), " ", str(ObjPig(1, 0, 0).green, 0, 3), "\n")
#declare Pts = array[3] { <0.3, 0.4, 0.5>, <0.71, 0.13, 0.2>, <0.05, 0.93, 0.66> }
#for (I, 0, 2)
  #declare P = Pts[I];
  #debug concat("map ", str(Map(P.x, P.y, P.z).red, 0, 6), " ", str(Map(P.x, P.y, P.z).gray, 0, 6),
                " pattern ", str(Pat(P.x, P.y, P.z), 0, 6), " df3 ", str(Df3(P.x, P.y, P.z), 0, 6), "\n")
#end
#declare V = Parse_String(concat("<", str(1.5, 0, 1), ", 2, 3>"));
#debug concat("Parse_String ", vstr(3, V, ",", 0, 1), "\n")
#macro Swap(A, B) #local T = A; #declare A = B; #declare B = T; #end
#declare Arr = array[3] { 1, 2, 3 }
Swap(Arr[0], Arr[2])
#debug concat("swap ", str(Arr[0], 0, 0), str(Arr[1], 0, 0), str(Arr[2], 0, 0), "\n")
#debug concat("vstr [", vstr(3, 2, ",", 0, 0), "] [", vstr(1, <1, 2, 3>, ",", 0, 0), "]\n")
#fopen Out "povray_user_forms.tmp" write
#write (Out, "1, 2, 3,\n")
#fclose Out
#declare N = 0;
#fopen In "povray_user_forms.tmp" read
#while (defined(In))
  #read (In, Item)
  #declare N = N + 1;
#end
#fclose In
#debug concat("reads ", str(N, 0, 0), " last ", str(Item, 0, 0), "\n")
