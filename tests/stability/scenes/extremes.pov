// SPDX-License-Identifier: MIT
// extremes.pov: degenerate objects and photon settings, one per KIND
// (stability.sh). KIND -1 is the stage alone, the image the degenerate
// ones must equal where POV-Ray drops or repairs them.
#version 3.7;
#ifndef (KIND) #declare KIND = -1; #end
#declare PHOTONS = (KIND = 4);
#include "stage.inc"
#declare G = material { texture { pigment { rgbf 1 } finish { Clear } }
                        interior { ior 1.5 } }
// FAR = R: a sphere of radius R behind the back wall (z = 3), hidden
#ifdef (FAR)
    sphere { <0, 0, 10 + FAR>, FAR pigment { rgb 1 } finish { Matte } }
#end
#switch (KIND)
#case (0) // radius 0: skipped with a warning (line 17)
    sphere { <0, 0.6, 0>, 0 material { G } }
#break
#case (1) // a zero scale on one axis: POV-Ray warns and uses 1 (line 21)
    sphere { <0, 0.6, 0>, 0.6 material { G }
        scale <1, 0, 1> }
#break
#case (2) // ... which is this sphere
    sphere { <0, 0.6, 0>, 0.6 material { G } scale <1, 1, 1> }
#break
#case (3) // a matrix of zeros cannot be inverted: an error (line 28)
    sphere { <0, 0.6, 0>, 0.6 material { G }
        matrix <0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0> }
#break
#case (4) // photons { count 0 }: no photons, a finite image
    global_settings { photons { count 0 } }
    sphere { <0, 0.6, 0>, 0.6 material { G }
        photons { target refraction on reflection on } }
#break
#end
