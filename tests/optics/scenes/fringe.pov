// SPDX-License-Identifier: MIT
// fringe.pov (tests/optics/optics.sh, check "camera rays"): chromatic
// aberration of camera rays. An orthographic camera looks through an
// equilateral SCHOTT F2 prism (apex up, axis along z; as in
// prism_spectrum.pov, along the beam of that scene) at a thin glowing
// white line y = -0.55 on a black wall x = 4. Each wavelength of a camera
// ray bends by its own index, so the line is seen smeared into a
// spectrum along the image's height. With PLAIN = 1 the prism has the
// fixed index 1.62 (no dispersion): the line is seen sharp.
#version 3.7;
#ifndef (PLAIN) #declare PLAIN = 0; #end
// DISP > 0 (check "extreme dispersion"): POV-Ray's 'ior 1.62 dispersion
// DISP' in place of F2
#ifndef (DISP) #declare DISP = 0; #end
global_settings { assumed_gamma 1 max_trace_level 10 }
background { color rgb 0 }
// rays along (3.654, 1.628) (rising 24 degrees), from the points
// (-4.154, -0.562) + s (-0.40697, 0.91344) for s in [-0.12, 0.24] (image
// rows, top row s = 0.24, 0.0015 a row) and z in [-0.01, 0.01]
camera { orthographic
  location <-4.154, -0.562, 0> + 0.06 * <-0.40697, 0.91344, 0>
  direction <0.91344, 0.40697, 0>
  right <0, 0, 0.02> up 0.36 * <-0.40697, 0.91344, 0> }
// the line: 0.004 high, glowing with colour 1 (ambient, no lights); only
// 0.0001 deep, so that its top face, which the rays see from above, adds
// nothing
box { <4, -0.552, -1>, <4.0001, -0.548, 1>
  pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }
prism { linear_sweep linear_spline -1.5, 1.5, 4,
  <-1, 0>, <1, 0>, <0, 1.732>, <-1, 0>
  rotate -90 * x
  translate <0, 0.2, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.62 dispersion_samples 64
    #if (DISP > 0) dispersion DISP
    #else #ifdef (iris_version) #if (!PLAIN) glass "F2" #end #end #end }
}
