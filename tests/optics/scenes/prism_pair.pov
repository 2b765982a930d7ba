// SPDX-License-Identifier: MIT
// prism_pair.pov (tests/optics/optics.sh, check "recombined"): the SCHOTT
// F2 prism of prism_spectrum.pov spreads a white (D65) beam 0.2 wide; a
// second, inverted F2 prism, its first face parallel to the first's exit
// face 0.1 beyond it, bends every wavelength back to the beam's
// direction: together a parallel plate split by an air gap. The wall at
// x = 6 gets the recombined beam, white in its middle (the wavelengths
// are shifted sideways by at most 0.033; the beam is 0.22 tall on the
// wall). SINGLE = 1 leaves out the second prism.
#version 3.7;
#ifndef (SINGLE) #declare SINGLE = 0; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.0005 autostop 0 }
}
// looking at the wall, y in [2.78, 3.18], z in [-0.1, 0.1]: 0.01 a pixel
// in a 20 x 40 image, rows along y (top row +y)
camera { orthographic location <5.5, 2.98, 0> direction <1, 0, 0>
  right <0, 0, 0.2> up <0, 0.4, 0> }
light_source { <-4.154, -0.562, 0> color rgb 1
  cylinder point_at <-0.5, 1.066, 0> radius 0.1 falloff 0.1 tightness 0
  photons { refraction on reflection off }
}
box { <6, -3, -1>, <6.1, 6, 1>
  pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
#declare Prism = prism { linear_sweep linear_spline -1.5, 1.5, 4,
  <-1, 0>, <1, 0>, <0, 1.732>, <-1, 0>
  rotate -90 * x
  translate <0, 0.2, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.62 #ifdef (iris_version) glass "F2" #end }
  photons { target refraction on reflection off collect off }
}
object { Prism }
#if (!SINGLE)
  // turned 180 degrees about z; the translation puts its apex at the
  // first prism's exit face's lower corner (1, 0.2) moved 0.1 along that
  // face's normal (cos 30, sin 30)
  object { Prism rotate 180 * z translate <1.0866, 2.182, 0> }
#end
