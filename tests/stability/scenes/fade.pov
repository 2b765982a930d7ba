// SPDX-License-Identifier: MIT
// fade.pov: interior fading at the edge of its range. fade_distance FD
// (1e-9 makes the glass absorb almost everything within a nanometre),
// fade_power FP (2: POV-Ray's 1 / (1 + (d/fd)^2) law; 1001: exponential).
#version 3.7;
#ifndef (FD) #declare FD = 1e-9; #end
#ifndef (FP) #declare FP = 2; #end
#include "stage.inc"

sphere {
    <0, 0.7, 0>, 0.7
    pigment { rgbf 1 } finish { Clear }
    interior { ior 1.5 fade_distance FD fade_power FP
               fade_colour rgb <0.2, 0.5, 0.9> }
    Glass_photons()
}
