// SPDX-License-Identifier: MIT
// thin.pov: a glass shell of thickness T (1e-7 by default) around an air
// bubble, and a box of the same thickness standing in front of it.
#version 3.7;
#ifndef (T) #declare T = 1e-7; #end
#include "stage.inc"

difference {
    sphere { <0, 0.7, 0>, 0.7 }
    sphere { <0, 0.7, 0>, 0.7 - T }
    pigment { rgbf 1 } finish { Clear }
    interior { ior 1.5 }
    Glass_photons()
}
box {
    <-1.2, 0, -1>, <-0.4, 1, -1 + T>
    pigment { rgbf 1 } finish { Clear }
    interior { ior 1.5 }
    Glass_photons()
}
