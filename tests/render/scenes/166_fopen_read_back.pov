// Parity scene: a scene that writes data and reads it back in the same
// parse, the way users generate point lists: #write in a loop, then
// #while (defined(F)) #read, which ends because a #read that meets the
// end of the file closes it and undefines F (POV-Ray's rule), and
// #fclose of the undefined F. iris refuses writes by default; the text is
// kept in memory, so the read finds it (reverted: "cannot open").
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.3, 0.4, 0.6> } }
#fopen Out "166_fopen_read_back.txt" write
#for (I, 0, 7)
  #write (Out, <2 * cos(I * pi / 4), 0.5 + I * 0.2, 2 * sin(I * pi / 4)>, ",", I / 7, ",\n")
#end
#fclose Out
#fopen In "166_fopen_read_back.txt" read
#while (defined(In))
  #read (In, P, C)
  sphere { P, 0.35 pigment { rgb <C, 0.5, 1 - C> } }
#end
#fclose In
