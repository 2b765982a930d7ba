// SPDX-License-Identifier: MIT
// prism.pov: an equilateral flint prism splits a narrow white beam (a
// cylindrical light, at the angle of minimum deviation) into a spectrum
// on the floor. POV-Ray shows 'dispersion_samples' hue bands; iris a
// continuous spectrum from the Sellmeier curve of SCHOTT F2.
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.001 autostop 0 }
}
camera { location <2.5, 5, -6> look_at <3.5, -0.6, 0> angle 45 }
// faint fill so that the scene is not black; it shoots no photons
light_source { <0, 10, -10> color rgb 0.1 shadowless }
// the beam: rising at 24 degrees onto the prism's left face
light_source { <-4.154, -0.562, 0> color rgb 3
  cylinder point_at <-0.5, 1.066, 0> radius 0.05 falloff 0.08 tightness 0
  photons { refraction on reflection off }
}
plane { y, -1 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
// equilateral prism, apex up, its axis along z
prism { linear_sweep linear_spline -1.5, 1.5, 4,
  <-1, 0>, <1, 0>, <0, 1.732>, <-1, 0>
  rotate -90*x
  translate <0, 0.2, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior {
    ior 1.62
    dispersion 1.04
    dispersion_samples 24
    #ifdef (iris_version)
      glass "F2"
    #end
  }
  photons { target refraction on reflection off collect off }
}
