// options: -q -w
// Values users' scenes read, printed with #debug; povray_user_forms2.expect
// is NOT iris output: it is POV-Ray 3.7.0.10's own #debug output of this
// file (povray +Ipovray_user_forms2.pov -D, no +K, its writes allowed), so
// every line must agree with POV-Ray:
// - a still image has initial_frame = final_frame = 0 and initial_clock =
//   final_clock = 0 (iris said 1 for three of them);
// - vnormalize of a zero vector is only a warning in POV-Ray and gives
//   <0,0,0> (iris stopped), which transforms.inc's Spline_Trans reaches at
//   the start of a spline (through math.inc's VRotation);
// - #read of a file's last item, with no comma after it, undefines the file
//   at once (iris looped once more with the old values);
// - datetime() formats days since 2000-01-01 UTC (iris gave "").
#version 3.7;
#include "transforms.inc"
#debug concat("clock ", str(clock, 0, 3), " on ", str(clock_on, 0, 0),
  " frames ", str(initial_frame, 0, 0), " ", str(final_frame, 0, 0),
  " clocks ", str(initial_clock, 0, 3), " ", str(final_clock, 0, 3),
  " delta ", str(clock_delta, 0, 3), " frame ", str(frame_number, 0, 0), "\n")
#debug concat("vnormalize ", vstr(3, vnormalize(<0, 0, 0>), ",", 0, 3), "\n")
#declare S = spline { natural_spline 0, <-2, 0, 1>, 0.5, <0, 1, 1>, 1, <2, 0.5, 1> }
#declare P = vtransform(<0, 0.2, 0>, Spline_Trans(S, 0, y, 0.1, 0.5));
#debug concat("spline_trans at the start ", vstr(3, P, ",", 0, 4), "\n")
#declare P = vtransform(<0, 0.2, 0>, Spline_Trans(S, 0.5, y, 0.1, 0.5));
#debug concat("spline_trans inside ", vstr(3, P, ",", 0, 4), "\n")
#fopen Out "povray_user_forms2.tmp" write
#write (Out, "1.5, <1, 2, 3>, \"a\",\n2.5, <4, 5, 6>, \"b\"\n")
#fclose Out
#fopen In "povray_user_forms2.tmp" read
#declare N = 0;
#while (defined(In))
  #read (In, RF, RV, RS)
  #declare N = N + 1;
  #debug concat("read ", str(N, 0, 0), ": ", str(RF, 0, 1), " ", vstr(3, RV, ",", 0, 0), " ", RS, "\n")
#end
#debug concat("datetime ", datetime(0), " | ", datetime(366.75, "%d.%m.%Y %H:%M"), " | ", datetime(-1, "%j"), "\n")
