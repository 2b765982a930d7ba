// options: -q
// Relational and logical operators on vectors, component by component,
// and POV-Ray's truth test (|x| > EPSILON = 1e-10). The .expect file is
// POV-Ray 3.7.0.10's own #debug output for this file (checked:
// identical; `povray +Iexpr_vector_compare.pov -D -F +W8 +H8`).
#version 3.7;
global_settings { assumed_gamma 1 }
#macro V(Name, N, A) #debug concat(Name, " <", vstr(N, A, ",", 0, 3), ">\n") #end
#macro F(Name, A) #debug concat(Name, " ", str(A, 0, 3), "\n") #end
// each component compared; a float fills every component
V("eq", 3, (<1,2,3> = <1,2,4>))
V("lt", 2, (<1,2> < <2,1>))
V("eqf", 3, (<1,2,3> = 2))
V("nef", 3, (2 != <1,2,3>))
V("ge", 3, (<1,2,3> >= <3,2,1>))
V("le5", 5, (<1,2,3,4,5> <= <5,4,3,2,1>))
V("gt", 3, (<3,2,1> > <1,2,3>))
// a shorter vector gets zeros: <1,2> is <1,2,0> against <1,2,3>
V("short", 3, (<1,2,3> = <1,2>))
V("chain", 3, (<1,2,3> < 2 < 1))
V("sum", 2, (<1,2> < <2,1>) + 0)
// & and | on each component, one precedence, from the left
V("and", 3, ((<1,2,3> = <1,2,4>) & <1,0,1>))
V("or", 3, (<1,2> | <0,0,3>))
V("not", 3, (!<1,0,3>))
F("andor", (1 | 0 & 0))
F("orand", (0 & 0 | 1))
// equality within an absolute 1e-10: 1e20 and 1e20+1e6 differ
F("eps_eq", (1 + 1e-11 = 1))
F("eps_big", (1e20 = 1e20 + 1e6))
F("eps_le", (1 + 1e-11 <= 1))
F("eps_ge", (1 >= 1 + 1e-11))
F("eps_ne", (1 != 1 + 1e-11))
F("eps_lt", (1 < 1 + 1e-11))
// below 1e-10 is false for &, |, !, ?: and #if
F("tiny_and", (1e-11 & 1))
F("tiny_or", (1e-11 | 0))
F("tiny_not", (!1e-11))
F("tiny_cond", (1e-11 ? 5 : 6))
#if (1e-11) #debug "tiny_if true\n" #else #debug "tiny_if false\n" #end
#if (0) #elseif (-1e-11) #debug "tiny_elseif true\n" #else #debug "tiny_elseif false\n" #end
#declare W = 1e-11; #while (W) #debug "tiny_while ran\n" #declare W = 0; #end
#debug "end\n"
camera { location <0,0,-5> look_at 0 }
