// A macro argument that is nothing but an array element is passed by
// reference, as an identifier is (POV-Ray 3.7; checked with povray: it
// prints the same three lines): Swap(A[0], A[2]) exchanges the elements,
// Set(M[1][0]) of a 2-D array writes 7 there. An argument that is more
// than the element (A[1] + 0) is a value: the element keeps 20.
// options: -q
#macro Swap(P, Q) #local T = P; #declare P = Q; #declare Q = T; #end
#macro Set(V) #declare V = 7; #end
#declare A = array[3] { 10, 20, 30 }
Swap(A[0], A[2])
Set(A[1] + 0)
#declare M = array[2][2] { { 1, 2 }, { 3, 4 } }
#declare I = 1;
Set(M[I][0])
#debug concat("A = ", str(A[0], 0, 0), " ", str(A[1], 0, 0), " ", str(A[2], 0, 0), "\n")
#debug concat("M[1][0] = ", str(M[1][0], 0, 0), ", M[0][0] = ", str(M[0][0], 0, 0), "\n")
#declare S = array[2] { "left", "right" }
Swap(S[0], S[1])
#debug concat(S[0], " ", S[1], "\n")
