// SPDX-License-Identifier: MIT
// cornell_glass.pov: a Cornell box (red and green walls, open at the
// front) with a glass sphere that focuses the ceiling light into a
// caustic on the floor. radiosity{} turns on diffuse interreflection
// (in iris a final gather whose rays read a global photon map; in
// POV-Ray its radiosity), as in the seed paper's figure 9: the white
// walls pick up red and green.
#version 3.7;
global_settings {
  assumed_gamma 1
  max_trace_level 10
  // 1.3 M photons: with 0.006 (333 k) the sphere's reflected caustic on
  // the back wall broke into rainbow blotches (each photon is one
  // wavelength); this costs 0.6 s more of an 800x600 render's 14 s
  photons { spacing 0.003 autostop 0 }
  radiosity { count 200 nearest_count 10 error_bound 0.5 recursion_limit 3 }
}
camera { location <0, 2.75, -10.5> look_at <0, 2.5, 0> angle 36 }
light_source { <0, 5.3, 0> color rgb 1
  area_light <1, 0, 0>, <0, 0, 1>, 3, 3 adaptive 1 jitter
  photons { refraction on reflection on }
}
#declare White = texture { pigment { color rgb 0.75 } finish { ambient 0 diffuse 0.8 } }
box { <-2.75, -0.1, -2.75>, <2.75, 0, 2.75> texture { White } }      // floor
box { <-2.75, 5.5, -2.75>, <2.75, 5.6, 2.75> texture { White } }     // ceiling
box { <-2.75, 0, 2.75>, <2.75, 5.5, 2.85> texture { White } }        // back
box { <-2.85, 0, -2.75>, <-2.75, 5.5, 2.75>                          // left
  pigment { color rgb <0.75, 0.1, 0.1> } finish { ambient 0 diffuse 0.8 }
}
box { <2.75, 0, -2.75>, <2.85, 5.5, 2.75>                            // right
  pigment { color rgb <0.1, 0.75, 0.1> } finish { ambient 0 diffuse 0.8 }
}
box { <-1.8, 0, 0.2>, <-0.4, 2.8, 1.6> rotate 15 * y texture { White } }
sphere { <0.9, 1.1, -0.9>, 1.1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 specular 0.5 roughness 0.002
           reflection { 0.02, 1 fresnel } }
  interior {
    ior 1.5
    #ifdef (iris_version)
      abbe 1.5168, 64.17
    #end
  }
  photons { target refraction on reflection on collect off }
}
