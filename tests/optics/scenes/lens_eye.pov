// SPDX-License-Identifier: MIT
// lens_eye.pov (tests/optics/optics.sh, check "camera rays through a
// lens"): chromatic aberration seen by camera rays through the N-BK7
// lens of lens_spectrum.pov. An orthographic camera looks straight down
// through the lens at a glowing white disc (radius 0.35, on the axis,
// y = -2.5: beyond the lens's foci near y = -1.2, so the rays through
// the lens have crossed the axis). A camera ray at height h from the
// axis lands at a distance from it that grows with h and with the
// wavelength's focal length: the disc is seen out to the h where that
// distance reaches 0.35, a little farther for red (longer focus) than
// for blue, so its image has a coloured rim. With PLAIN = 1 the lens has
// the fixed index 1.5168: the rim is sharp.
#version 3.7;
#ifndef (PLAIN) #declare PLAIN = 0; #end
global_settings { assumed_gamma 1 max_trace_level 10 }
background { color rgb 0 }
// rays straight down through x in [0.85, 1.15] (image rows, top row
// +x, 0.002 a row at +H150), z in [-0.004, 0.004]
camera { orthographic location <1, 5, 0> direction <0, -1, 0>
  right <0, 0, 0.008> up <0.3, 0, 0> }
disc { <0, -2.5, 0>, y, 0.35
  pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }
// biconvex lens: radii 4 and -4, 0.6 thick, vertices at y = 2.7 and 2.1
intersection {
  sphere { <0, -1.3, 0>, 4 }
  sphere { <0, 6.1, 0>, 4 }
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5168 dispersion_samples 64
    #ifdef (iris_version) #if (!PLAIN) glass "N-BK7" #end #end }
}
