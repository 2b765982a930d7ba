// SPDX-License-Identifier: MIT
// slab.pov: a clear glass slab with parallel faces between the camera and
// the stage (stage.inc), dispersive or not (Declare=DISP=..., DSAMP=...).
// A slab with parallel faces has no net dispersion: every wavelength
// leaves it parallel to the ray that entered, only shifted sideways.
//   CAM 0: an orthographic camera looking along +z, so every camera ray
//          meets both faces at normal incidence: no wavelength bends at
//          all and each sees the same grey (lit, 0.8) wall point.
//   CAM 1: the stage's perspective camera through the slab, inclined by
//          up to ~25 degrees: the wavelengths shift sideways by different
//          amounts (colour fringes at the checker's edges), but the mean
//          colour of the image stays that of the non-dispersive slab.
#version 3.7;
#ifndef (DISP) #declare DISP = 1; #end
#ifndef (DSAMP) #declare DSAMP = 7; #end
#ifndef (CAM) #declare CAM = 0; #end
#include "stage.inc"

#if (CAM = 0)
camera {
    orthographic
    location <0, 1, -4>
    direction z
    right x * 2 * image_width / image_height
    up y * 2
}
#end

box {
    <-4, -1, -3>, <4, 4, -2.6>
    pigment { rgbf 1 } finish { Clear }
    interior { ior 1.5 dispersion DISP dispersion_samples DSAMP }
}
