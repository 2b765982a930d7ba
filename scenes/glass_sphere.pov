// SPDX-License-Identifier: MIT
// glass_sphere.pov: the seed paper's scene, a dispersive glass sphere over
// a white plane (raised 0.6 so that its focus falls near the floor) under a
// point light; the caustic below it shows the spectrum at its rim. Renders
// in POV-Ray 3.7 (RGB baseline, +Q9) and in iris (spectral photons; N-BK7
// from the built-in catalogue).
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.01 autostop 0 jitter 0.4 }
}
camera { location <0, 4, -7> look_at <0, 0.6, 0> angle 40 }
light_source { <-3, 8, -2> color rgb 1 photons { refraction on reflection on } }
plane { y, 0
  pigment { color rgb 0.9 }
  finish { ambient 0 diffuse 0.8 }
}
sphere { <0, 1.6, 0>, 1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.002
           reflection { 0.02, 1 fresnel } conserve_energy }
  interior {
    ior 1.5
    dispersion 1.05
    dispersion_samples 16
    #ifdef (iris_version)
      glass "N-BK7"
    #end
  }
  photons { target refraction on reflection on collect off }
}
