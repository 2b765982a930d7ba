// SPDX-License-Identifier: MIT
// glass_box.pov: the seed paper's figure 11, a glass box on a white plane
// under a point light. The box is turned about two axes so that light
// enters through its top and one side face; the sloped faces act as prisms
// and split the light leaving the box into coloured fringes on the floor,
// around the bright caustic under the box. Renders in POV-Ray 3.7 (RGB
// baseline, +Q9) and in iris (spectral photons; dense flint N-SF11 from the
// built-in catalogue, whose dispersion shows the colours clearly).
#version 3.7;
// iris shoots 9x POV-Ray's photons: POV-Ray splits every photon that
// enters dispersive glass into dispersion_samples photons and keeps both
// the reflected and the refracted one, where each iris photon carries one
// wavelength and takes one path (Russian roulette); at the same spacing
// iris's caustic would have ~1/20 of POV-Ray's photons and show colour
// noise. (1.4 M photons stored, ~1.5 s on 2 cores.)
#ifdef (iris_version)
  #declare Spacing = 0.001;
#else
  #declare Spacing = 0.003;
#end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing Spacing autostop 0 jitter 0.4 }
}
camera { location <0, 5, -8> look_at <0, 0.6, 0> angle 40 }
light_source { <-2, 9, -3> color rgb 1 photons { refraction on reflection on } }
plane { y, 0
  pigment { color rgb 0.9 }
  finish { ambient 0 diffuse 0.8 }
}
box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6>
  rotate <35, 25, 0>
  translate <0, 1.4, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 specular 0.6 roughness 0.002
           reflection { 0.02, 1 fresnel } conserve_energy }
  interior {
    ior 1.78
    dispersion 1.04
    dispersion_samples 16
    #ifdef (iris_version)
      glass "N-SF11"
    #end
  }
  photons { target refraction on reflection on collect off }
}
