// SPDX-License-Identifier: MIT
// mirror.pov (tests/optics/optics.sh, check "mirrors"): a parallel white
// beam falls straight down on an opaque mirror tilted 45 degrees, which
// sends it horizontally onto the white wall x = 3, square on; the wall
// is lit only by the mirror's photons (the light grazes it). Its
// irradiance is the mirror's reflectivity at 45 degrees as POV-Ray's
// finish defines it (povray-3.7-semantics.md §3.3 step 3). REFL: 1
// reflection rgb <0.9, 0.5, 0.2>; 2 reflection { 0.1, 0.9 falloff 2 };
// 3 reflection { 0.8 metallic } on pigment <0.9, 0.5, 0.2>; 4
// reflection { 0, 1 fresnel } with interior { ior 1.5 } (an opaque
// glazed surface).
#version 3.7;
#ifndef (REFL) #declare REFL = 1; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.0025 autostop 0 }
}
// looking at the wall from x = 2.5: y in [-0.5, 0.5] (rows, top +y), z
// in [-0.5, 0.5] (columns); the reflected beam covers |y| < 0.7, |z| < 1
camera { orthographic location <2.5, 0, 0> direction <1, 0, 0>
  right <0, 0, -1> up <0, 1, 0> }
light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
plane { -x, -3 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
// the mirror: its top face (2 x 2) through the origin, normal
// (sin 45, cos 45, 0)
box { <-1, -0.05, -1>, <1, 0, 1>
  rotate -45 * z
  pigment { color rgb #if (REFL = 3) <0.9, 0.5, 0.2> #else 0 #end }
  finish { ambient 0 diffuse 0
    #switch (REFL)
      #case (1) reflection rgb <0.9, 0.5, 0.2> #break
      #case (2) reflection { 0.1, 0.9 falloff 2 } #break
      #case (3) reflection { 0.8 metallic } #break
      #case (4) reflection { 0, 1 fresnel } #break
    #end
  }
  #if (REFL = 4) interior { ior 1.5 } #end
  photons { target reflection on collect off }
}
