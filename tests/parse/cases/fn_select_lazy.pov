// options: -q
// select() in functions evaluates only the arm chosen, as
// POV-Ray's compiled branches do (t-o-k's complex functions call a costly
// function in every arm of nested selects: 16.1 s of parsing, 4.6 s
// lazily). The values below are POV-Ray 3.7's own #debug output. F16
// nests 16 selects whose every arm calls the level below: 3^16 calls
// when every arm is evaluated (3 s), 16 when only the chosen one is.
#version 3.7;
#declare S3 = function(a) { select(a, 10, 20) }
#declare S4 = function(a) { select(a, 10, 20, 30) }
#declare N = function(a, b) {
    select(a, select(b, 1, 2, 3), select(b, 4, 6, 5),
           select(b + a, 7, 8)) }
#declare F0 = function(x) { x }
#macro Level(F)
    function(x) { select(x - 0.5, F(x) + 1, F(x) + 2, F(x) + 3) }
#end
#declare F1 = Level(F0)
#declare F2 = Level(F1)
#declare F3 = Level(F2)
#declare F4 = Level(F3)
#declare F5 = Level(F4)
#declare F6 = Level(F5)
#declare F7 = Level(F6)
#declare F8 = Level(F7)
#declare F9 = Level(F8)
#declare F10 = Level(F9)
#declare F11 = Level(F10)
#declare F12 = Level(F11)
#declare F13 = Level(F12)
#declare F14 = Level(F13)
#declare F15 = Level(F14)
#declare F16 = Level(F15)
#debug concat("S3 ", str(S3(-1), 0, 0), " ", str(S3(0), 0, 0), " ", str(S3(2), 0, 0), "\n")
#debug concat("S4 ", str(S4(-1), 0, 0), " ", str(S4(0), 0, 0), " ", str(S4(2), 0, 0), "\n")
#declare I = -1;
#while (I <= 1)
    #declare J = -1;
    #while (J <= 1)
        #debug concat("N(", str(I, 0, 0), ",", str(J, 0, 0), ") ", str(N(I, J), 0, 0), "\n")
        #declare J = J + 1;
    #end
    #declare I = I + 1;
#end
#debug concat("F16 ", str(F16(0), 0, 0), " ", str(F16(0.5), 0, 0), " ", str(F16(1), 0, 0), "\n")
