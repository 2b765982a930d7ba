// options: -q -m 64
// A deep normal_map tree used by many transformed objects must not be
// copied per transform (as users_shared_map_memory for pigment maps;
// POV-Ray shares blend maps). The tree below has 1023 normals; 200
// objects with 3 transforms each copied it 600 times and ran out of the
// 64 MiB given here. Shared, it fits.
#version 3.7;
#macro Tree(Level)
    normal { checker
    #if (Level > 0)
        Tree(Level - 1) Tree(Level - 1)
    #else
        normal { bumps 0.5 } normal { dents 0.5 }
    #end
    scale 0.5 }
#end
#declare N = Tree(9)
#for (I, 1, 200)
    sphere { 0, 1 normal { N rotate I * y } scale 1 + I / 100 translate I * x }
#end
#debug "200 spheres\n"
