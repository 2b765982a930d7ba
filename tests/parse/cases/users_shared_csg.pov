// options: -q -m 48
// Copies of a CSG share its children until they change (session 12):
// GonzalMZ's arosFractal redeclares a growing union from itself, which
// kept every copy (quadratic: over 1 GB in iris, 22 MB in POV-Ray). Here
// 2000 steps, about 1.8 GB before; under the 48 MiB given. The values
// are POV-Ray 3.7.0.10's own #debug output: a transformed copy moves,
// the original and the other copies do not.
#version 3.7;
#declare A = union { sphere { 0, 1 } box { -0.5, 0.5 translate y } }
#for (I, 1, 2000)
    #declare A = union { object { A } sphere { <I / 100, 0, 0>, 0.5 } }
#end
#declare B = object { A translate <0, 5, 0> scale 2 }
#declare C = union { object { A } object { A rotate 90 * z } }
#debug concat("A ", vstr(3, min_extent(A), ", ", 0, 2), " / ",
               vstr(3, max_extent(A), ", ", 0, 2), "\n")
#debug concat("B ", vstr(3, min_extent(B), ", ", 0, 2), " / ",
               vstr(3, max_extent(B), ", ", 0, 2), "\n")
#debug concat("C ", vstr(3, min_extent(C), ", ", 0, 2), " / ",
               vstr(3, max_extent(C), ", ", 0, 2), "\n")
#debug concat("A again ", vstr(3, max_extent(A), ", ", 0, 2), "\n")
object { C translate z }
object { A }
