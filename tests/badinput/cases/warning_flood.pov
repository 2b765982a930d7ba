// expect: 0 9
#version 3.7;
// Found by libFuzzer (session 13): a loop whose body warns many times a
// turn (each stray '#' is a warning, as POV-Ray ignores it) filled 2.2
// million 3 KB diagnostics and took over 10 s. The first 1000 warnings
// are kept and printed, the rest counted ("N more warnings not shown").
#declare I = 0;
#while (I < 20000)
################################################################################################    #declare I = I + 1;
#end
camera { location -3*z look_at 0 }
sphere { 0, 1 pigment { rgb 1 } }
