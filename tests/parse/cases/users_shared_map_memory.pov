// options: -q -m 64
// A deep pigment_map tree used by many transformed objects must not be
// copied per transform (mscharrer's tree_of_squares_v4: 2 GiB in iris,
// 158 MB in POV-Ray, which shares blend maps). The tree below has 1023
// pigments (~0.6 MB); 200 objects with 3 transforms each copied it 600
// times (~340 MB) and ran out of the 64 MiB given here. Shared, it fits.
#version 3.7;
#macro Tree(Level)
    pigment { checker
    #if (Level > 0)
        Tree(Level - 1) Tree(Level - 1)
    #else
        rgb 0 rgb 1
    #end
    scale 0.5 }
#end
#declare P = Tree(9)
#for (I, 1, 200)
    sphere { 0, 1 pigment { P rotate I * y } scale 1 + I / 100 translate I * x }
#end
#debug "200 spheres\n"
