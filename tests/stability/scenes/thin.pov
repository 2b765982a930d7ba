// SPDX-License-Identifier: MIT
// thin.pov: a glass shell of thickness T (1e-7 by default) around an air
// bubble, and a box of the same thickness standing in front of it.
// SKY = 1 adds a sphere of radius 1e6 around everything, hidden behind
// the floor and the wall: it must not change a pixel, though it makes the
// scene a million times larger than the shell.
#version 3.7;
#ifndef (T) #declare T = 1e-7; #end
#ifndef (SKY) #declare SKY = 0; #end
#include "stage.inc"
#if (SKY)
    sphere { 0, 1e6 hollow pigment { rgb <0.2, 0.3, 1> } finish { Matte } }
#end

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
