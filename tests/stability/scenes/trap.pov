// SPDX-License-Identifier: MIT
// trap.pov: total internal reflection traps. KIND 0: the camera sits
// inside a glass ball of index IOR, 0.45 of the radius from its centre,
// and looks along the wall: rays along the view axis meet the wall at
// asin(0.9) = 64 degrees, past the critical angle of any IOR > 1.11, and
// circle the ball as in a whispering gallery (the ball seen from inside);
// KIND 1: the camera sits inside a long glass slab and
// looks along it at a grazing angle, so most rays stay trapped between
// the two faces. max_trace_level 256 (POV-Ray's maximum) and
// adc_bailout 0 let a trapped ray bounce as long as POV-Ray would allow:
// the render time must stay bounded all the same.
#version 3.7;
#ifndef (IOR) #declare IOR = 1.5; #end
#ifndef (KIND) #declare KIND = 0; #end
#include "stage.inc"
global_settings { max_trace_level 256 adc_bailout 0 }

#if (KIND = 0)
    sphere {
        <-0.45, 1.6, -4.2>, 0.5
        pigment { rgbf 1 } finish { Clear }
        interior { ior IOR }
        Glass_photons()
    }
#else
    box {
        <-3, 1.55, -6>, <3, 1.65, 6>
        pigment { rgbf 1 } finish { Clear }
        interior { ior IOR }
        Glass_photons()
    }
#end
sphere { <0.8, 0.5, 0.5>, 0.5 pigment { rgb <1, 0.4, 0.2> } finish { Matte } }
