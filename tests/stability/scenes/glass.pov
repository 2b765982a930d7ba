// SPDX-License-Identifier: MIT
// glass.pov: a glass ball and a tilted glass slab, with the index of
// refraction model chosen from the command line (Declare=NAME=VALUE):
//   IOR, DISP (dispersion), DSAMP (dispersion_samples),
//   MODEL 0 = POV-Ray's ior/dispersion, 1 = Sellmeier (B, C), 2 = the
//   seed paper's ior_decay N1, N2, SPREAD.
// The slab is seen at grazing incidence along its top face.
#version 3.7;
#ifndef (IOR) #declare IOR = 1.5; #end
#ifndef (DISP) #declare DISP = 1; #end
#ifndef (DSAMP) #declare DSAMP = 7; #end
#ifndef (MODEL) #declare MODEL = 0; #end
#ifndef (B1) #declare B1 = 1; #end
#ifndef (C1) #declare C1 = 0.25; #end
#ifndef (SPREAD) #declare SPREAD = 100; #end
#include "stage.inc"

#declare Glass_interior = interior {
    ior IOR
    dispersion DISP
    dispersion_samples DSAMP
    #ifdef (iris_version)
        #switch (MODEL)
        #case (1) sellmeier <B1, 0, 0>, <C1, 0, 0> #break
        #case (2) ior_decay 1.6, 1.4, SPREAD #break
        #end
    #end
}

sphere {
    <-0.6, 0.7, 0>, 0.7
    pigment { rgbf 1 } finish { Clear }
    interior { Glass_interior }
    Glass_photons()
    scale S
}

// A slab whose top face the camera sees at about 1 degree.
box {
    <-0.5, 0, -0.5>, <0.5, 0.05, 0.5>
    rotate x * -21.5
    translate <0.9, 0.9, -0.3>
    pigment { rgbf 1 } finish { Clear }
    interior { Glass_interior }
    Glass_photons()
    scale S
}
