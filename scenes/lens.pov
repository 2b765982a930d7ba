// SPDX-License-Identifier: MIT
// lens.pov: a biconvex crown-glass lens focuses a parallel beam on a
// floor; its focus is coloured by longitudinal chromatic aberration.
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.01 autostop 0 }
}
camera { location <0, 5, -6> look_at <0, 0.5, 0> angle 40 }
light_source { <0, 20, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
light_source { <5, 10, -10> color rgb 0.2 shadowless }
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 0.9 } }
// two spheres of radius 4 whose lens-shaped intersection is 0.6 thick,
// held 2.4 above the floor (focal length about 4)
intersection {
  sphere { <0, -3.7, 0>, 4 }
  sphere { <0, 3.7, 0>, 4 }
  translate <0, 2.4, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 specular 0.5 roughness 0.003 }
  interior {
    ior 1.52
    dispersion 1.02
    dispersion_samples 8
    #ifdef (iris_version)
      glass "N-BK7"
    #end
  }
  photons { target refraction on reflection on collect off }
}
