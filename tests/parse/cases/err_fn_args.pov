// options: -q
// The argument count of a function call is checked as in POV-Ray 3.7:
// functions.inc's f_helix1 takes 10 (x, y, z and 7 parameters); POV-Ray
// stops on line 8 with "Expected ')', , found instead" at the 11th (iris
// used to take any count). A call in a function body with the wrong count
// is err_fn_args_body.pov; povray_user_forms3.pov has valid calls.
#include "functions.inc"
#declare V = f_helix1(0.5, 0.2, 0.3, 2, 3, 0.2, 0.5, 1, 1, 0.2, 0);
