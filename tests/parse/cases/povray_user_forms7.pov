// options: -q
// Users' forms of session 12, with POV-Ray 3.7.0.10's own #debug output:
// 'tau' is a word of POV-Ray 3.8 only, so 3.7 scenes declare their own
// (aelnonym's camlight.inc: 10 scenes refused before); old scenes write
// 'declare' and 'include' without '#' among the scene's items, which
// POV-Ray's Parse_Frame runs with a warning (gnu0000's SPIN4/5).
#version 3.7;
#declare tau = 0.25;
#local Twice = 2 * tau;
#debug concat("tau ", str(tau, 0, 3), " twice ", str(Twice, 0, 3), "\n")
#macro Turn(tau) tau * 360 #end
#debug concat("Turn ", str(Turn(0.5), 0, 1), "\n")
declare Width = 3;
declare Shape = sphere { 0, Width }
object { Shape }
#debug concat("Width ", str(Width, 0, 1), " ", str(max_extent(Shape).x, 0, 1), "\n")
include "math.inc"
#debug concat("even ", str(even(4), 0, 0), "\n")
