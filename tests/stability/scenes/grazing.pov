// SPDX-License-Identifier: MIT
// grazing.pov: the camera stands exactly in the floor plane and looks
// along it, so half the rays graze the floor at zero angle; a glass slab
// lies flat on the floor and a ball touches the floor at one point.
#version 3.7;
#include "stage.inc"
camera {
    location <0, 0, -4>
    look_at <0, 0, 0>
    angle 40
    right x * image_width / image_height
}
box { <-2, 0, -1>, <2, 1e-4, 1> pigment { rgbf 1 } finish { Clear }
      interior { ior 1.5 } Glass_photons() }
sphere { <0.5, 0.5, 0>, 0.5 pigment { rgbf 1 } finish { Clear }
         interior { ior 1.5 } Glass_photons() }
