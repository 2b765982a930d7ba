// SPDX-License-Identifier: MIT
// gem.pov: a brilliant-cut diamond (intersection of facet planes) under a
// point light throws coloured "fire" on the table around it.
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 8
  photons { spacing 0.012 autostop 0 }
}
camera { location <0, 3, -4> look_at <0, 0.3, 0> angle 35 }
light_source { <2, 7, -3> color rgb 1.2 photons { refraction on reflection on } }
light_source { <-6, 6, -6> color rgb 0.2 shadowless }
plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0 diffuse 0.8 } }
#declare Gem = intersection {
  plane { y, 0.3 }                                  // table
  #for (I, 0, 7)                                    // crown facets
    plane { <0, 1.2, -1>, 0.75 rotate (I * 45 + 22.5) * y }
  #end
  #for (I, 0, 7)                                    // pavilion facets
    plane { <0, -1.05, -1>, 0.72 rotate I * 45 * y }
  #end
  cylinder { <0, -2, 0>, <0, 2, 0>, 1 }             // girdle
}
object { Gem
  translate <0, 0.75, 0>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 specular 0.8 roughness 0.001
           reflection { 0.05, 1 fresnel } }
  interior {
    ior 2.417
    dispersion 1.06
    dispersion_samples 8
    #ifdef (iris_version)
      glass "diamond"
    #end
  }
  photons { target refraction on reflection on collect off }
}
