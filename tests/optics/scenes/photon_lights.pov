// SPDX-License-Identifier: MIT
// photon_lights.pov (tests/optics/optics.sh, check "photon power"): the
// light of four kinds of light source through a slab of index 1 (a
// photon target that neither bends, reflects nor absorbs) onto a white
// floor, lit by photons under the slab (x < 0) and directly beside it
// (x > 0). The light hangs 3 above the floor at x = 0, so the two halves
// of the floor get the same light where photons carry the same power
// per area as the direct term: POV-Ray's normalisation, "flux per area =
// the light's colour" (povray-3.7-semantics.md §2.3), with the light's
// fade and spot attenuation. LIGHT: 1 point light with fade_distance 1,
// fade_power 2; 2 spotlight (radius 20, falloff 40, tightness 5,
// pointing down); 3 cylinder light (radius 1, falloff 1.6, tightness 2,
// pointing down); 4 area light 1 x 1, 5 x 5, its photons shot from every
// element ('photons { area_light }'); 5 a narrow spotlight (radius 10,
// falloff 20, tightness 0, pointing down: its cone meets the floor at
// |x| = 3 tan 20 = 1.092, inside the view).
#version 3.7;
#ifndef (LIGHT) #declare LIGHT = 1; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing 0.004 autostop 0 }
}
// looking down at the floor, x in [-2, 2] (rows, top row x = -2: the
// photon half first), z in [-0.1, 0.1] (columns)
camera { orthographic location <0, 0.5, 0> direction <0, -1, 0>
  right <0, 0, 0.2> up <-4, 0, 0> }
light_source { <0, 3, 0> color rgb 1
  #switch (LIGHT)
    #case (1) fade_distance 1 fade_power 2 #break
    #case (2) spotlight point_at <0, 0, 0> radius 20 falloff 40 tightness 5
      #break
    #case (3) cylinder point_at <0, 0, 0> radius 1 falloff 1.6 tightness 2
      #break
    #case (4) area_light <1, 0, 0>, <0, 0, 1>, 5, 5 #break
    #case (5) spotlight point_at <0, 0, 0> radius 10 falloff 20 tightness 0
      #break
  #end
  photons { refraction on reflection on #if (LIGHT = 4) area_light #end }
}
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
// 0.1 thick, index 1: the photons cross it unchanged (no Fresnel
// reflection, so no Russian roulette); its edge x = 0 is under the light
box { <-4, 1, -2>, <0, 1.1, 2>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1 }
  photons { target refraction on reflection on collect off }
}
