// options: -q
// min() and max() take infinite arguments (session 12): POV-Ray's x / 0
// is HUGE_VAL with a warning, and min(1 / 0, 4) is 4 (t-o-k's scenes
// bound values so). The #debug values are POV-Ray 3.7.0.10's output.
// An infinite result is still refused where it is used.
#version 3.7;
#declare Zero = 0;
#debug concat("a ", str(min(1 / Zero, 4), 0, 3), "\n")
#debug concat("b ", str(max(-(1 / Zero), 4), 0, 3), "\n")
#debug concat("c ", str(min(4, 1 / Zero, 2), 0, 3), "\n")
#debug concat("d ", str(max(-3, -(1 / Zero)) * 2, 0, 3), "\n")
sphere { 0, min(1 / Zero, 2 / Zero) }
