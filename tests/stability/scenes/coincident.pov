// SPDX-License-Identifier: MIT
// coincident.pov: surfaces that lie on each other. Two glass balls with
// the same centre and radius, a box whose bottom face lies in the floor,
// two boxes sharing one face, and a disc lying in the back wall.
#version 3.7;
#include "stage.inc"

#declare G = interior { ior 1.5 }
sphere { <-0.7, 0.6, 0>, 0.6 pigment { rgbf 1 } finish { Clear } interior { G } Glass_photons() }
sphere { <-0.7, 0.6, 0>, 0.6 pigment { rgbf 1 } finish { Clear } interior { G } Glass_photons() }
box { <0.2, 0, -0.4>, <1, 0.8, 0.4> pigment { rgb <1, 0.3, 0.3> } finish { Matte } }
box { <0.2, 0, -0.4>, <1, 0.8, 0.4> pigment { rgb <0.3, 1, 0.3> } finish { Matte } }
box { <1, 0, -0.4>, <1.6, 0.5, 0.4> pigment { rgb <0.3, 0.3, 1> } finish { Matte } }
disc { <0, 1.5, 3>, -z, 0.5 pigment { rgb <1, 1, 0> } finish { Matte } }
