// SPDX-License-Identifier: MIT
// lens_spectrum.pov (tests/optics/optics.sh, check "lens"): longitudinal
// chromatic aberration of a photon-mapped N-BK7 lens, made measurable on
// a floor. A narrow parallel pencil (radius 0.002) falls on the lens 1
// unit off its axis; after the lens each wavelength heads for its own
// focus on the axis, so beyond the foci the pencil fans out into a
// spectrum along -x on the floor. The light is the CIE fluorescent lamp
// F11, whose emission lines (435, 545, 610 nm) become three bright spots.
// The test traces the same pencil through the two spherical surfaces with
// Snell's law and n(lambda) of N-BK7 and compares the spots' positions.
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.00001 autostop 0 }
}
// looking straight down at the floor strip x in [-0.775, -0.625],
// z in [-0.01, 0.01]: image rows run along x (top row +x), 0.0005 a row
camera { orthographic location <-0.7, -3.4, 0> direction <0, -1, 0>
  right <0, 0, 0.02> up <0.15, 0, 0> }
light_source { <1, 10, 0> color rgb 1 parallel point_at <1, 0, 0>
  cylinder radius 0.002 falloff 0.002 tightness 0
  photons { refraction on reflection off }
  #ifdef (iris_version) spectrum "F11" #end
}
plane { y, -3.7 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
// biconvex lens: radii 4 and -4, 0.6 thick, vertices at y = 2.7 and 2.1
intersection {
  sphere { <0, -1.3, 0>, 4 }
  sphere { <0, 6.1, 0>, 4 }
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5168 #ifdef (iris_version) glass "N-BK7" #end }
  photons { target refraction on reflection off collect off }
}
