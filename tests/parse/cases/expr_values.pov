// options: -q
// Expression values; the .expect file is POV-Ray 3.7.0.10's own #debug
// output for this file (checked: identical).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare V = vrotate(x, <0,0,90>);
#debug concat("vrot ", vstr(3, V, ",", 0, 6), "\n")
#declare V = vaxis_rotate(x, y, 90);
#debug concat("vaxis ", vstr(3, V, ",", 0, 6), "\n")
#debug concat("str ", str(5, -3, 0), "|", str(3.14159, 0, 2), "|", str(2.5, 0, -1), "|", str(7, 5, 1), "\n")
#debug concat("sel ", str(select(0, 1, 2, 3), 0, 0), " ", str(select(0,1,2),0,0), "\n")
#declare G = rgb <1,0,0>;
#debug concat("gray ", str(G.gray, 0, 6), "\n")
#declare C = srgb 0.5;
#debug concat("srgb ", str(C.red, 0, 8), "\n")
#debug concat("div ", str(div(-7, 2), 0, 0), " mod ", str(mod(-7, 2), 0, 0), "\n")
#macro F(N) #if (N <= 1) 1 #else N * F(N - 1) #end #end
#debug concat("fact ", str(F(10), 0, 0), "\n")
#declare X = 0; #for (I, 3, 1, -1) #declare X = X*10 + I; #end
#debug concat("for ", str(X, 0, 0), "\n")
#switch (5) #case (5) #debug "c5\n" #case (6) #debug "c6\n" #break #else #debug "else\n" #end
#declare A = array[2] { <1,2> <3,4> };
#debug concat("arr ", str(A[1].v, 0, 0), "\n")
#debug concat("bool ", str(true + yes + on - off, 0, 0), "\n")
#debug concat("cmp ", str(("ab" < "b"), 0, 0), "\n")
camera { location <0,0,-5> look_at 0 } 
