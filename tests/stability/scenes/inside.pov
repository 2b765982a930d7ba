// SPDX-License-Identifier: MIT
// inside.pov: KIND 0 puts the camera inside a glass box, KIND 1 puts the
// light inside a glass ball (its shadow rays start inside the glass), both
// with dispersion so that the spectral path starts inside a medium too.
#version 3.7;
#ifndef (KIND) #declare KIND = 0; #end
#include "stage.inc"

#declare Disp_glass = interior { ior 1.5 dispersion 1.1 dispersion_samples 7 }
#if (KIND = 0)
    box {
        <-1, 0.5, -5>, <1, 2.5, -3>
        pigment { rgbf 1 } finish { Clear }
        interior { Disp_glass }
        Glass_photons()
    }
#else
    sphere {
        <-2, 5, -3>, 0.5
        pigment { rgbf 1 } finish { Clear }
        interior { Disp_glass }
        Glass_photons()
    }
#end
sphere { <0, 0.6, 0>, 0.6 pigment { rgb <1, 0.4, 0.2> } finish { Matte } }
