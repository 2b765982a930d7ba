// SPDX-License-Identifier: MIT
// scale0.pov: 'scale SC' with SC = 0 must warn at line 9 and render as
// with SC = 1 (POV-Ray changes a zero scale factor to 1).
#version 3.7;
#ifndef (SC) #declare SC = 1; #end
#include "stage.inc"
sphere {
    <0, 0.7, 0>, 0.7
    scale SC
    pigment { rgb <1, 0.4, 0.2> } finish { Matte }
}
