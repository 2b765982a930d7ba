// SPDX-License-Identifier: MIT
// targets.pov: where photon targets are found (tests/optics/targets.sh,
// docs/optics.md check 29). Mirror balls and a mirror ring (opaque,
// reflection 1) over a white floor that collects, a point light above.
// The mirrors have diffuse 0.01 so that a photon meeting a mirror a
// second time is stored there by both programs (POV-Ray stores photons
// on every surface, iris only on diffuse ones: docs/photons.md). CASE
// picks how the flagged objects are grouped:
//   1 a ball flagged as a target in a plain union with a box that is
//     not one (a table with a glass on it, grouped)
//   2 a flagged union (split) of two balls 2 apart
//   3 a flagged union (split) of a ring around a ball: the children's
//     bounding spheres overlap
//   4 case 2 as a merge    5 case 2 with split_union off
//   6 case 2 clipped by a box holding both
//   7 a flagged ball, the first object of a difference that is not
//     flagged (a box cut off below it)
//   8 a flagged ball in an intersection that is not flagged
//   9 case 1 in a light_group (no global_lights: no photons)
//  10 case 9 with global_lights on
//  11 case 2 with a ball's own 'target 0.5' (the union's spacing wins)
//  12 case 2 with a ball's own 'reflection off' (the union's wins)
//  13 a flagged ball under a clear plate with 'pass_through' (a cloud):
//     photons through the plate that miss the ball are not stored
// Cases 14-16 ask for 'count 20000' photons, whose spacing comes from the
// target's bounding sphere: POV-Ray bounds a blob by its components'
// bounding spheres (src/photon/povbox.c), wider than iris's box:
//  14 a mirror blob of one upright cylinder component
//  15 lights/glassthing.pov's glass at half size: a blob in a merge, cut
//     by a plane
//  16 a turned blob: a squashed sphere, a slanted cylinder and a
//     negative sphere component
//  17 a flagged ball subtracted from a box in a difference that is not
//     flagged: a mirror bowl in the box's top
#ifndef (CASE) #declare CASE = 1; #end
global_settings { assumed_gamma 1 photons {
  #if (CASE >= 14 & CASE <= 16) count 20000 #else spacing 0.02 #end
  autostop 1 jitter 0 } }
camera { location <0, 6, -8> look_at <0, 0.5, 0> angle 40 }
light_source { <3, 10, -4> color rgb 1 }
plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }
#declare Mirror = texture { pigment { rgb 0 } finish { ambient 0 diffuse 0.01 reflection 1 } }
#declare Ball1 = sphere { <-1, 1, 0>, 0.5 texture { Mirror } }
#declare Ball2 = sphere { <1, 1, 0>, 0.5 texture { Mirror } }
#declare Table = box { <-2, 0, -2>, <2, 0.2, 2> pigment { rgb 1 } }
#declare Glass = sphere { <0, 0.7, 0>, 0.5 texture { Mirror } photons { target reflection on } }
#macro Flag() photons { target reflection on } #end
#switch (CASE)
#case (1) union { object { Table } object { Glass } } #break
#case (2) union { object { Ball1 } object { Ball2 } Flag() } #break
#case (3)
  union {
    difference { cylinder { 0.3*y, 0.8*y, 2 } cylinder { 0, y, 1.8 } }
    sphere { 0.8*y, 0.6 }
    texture { Mirror } Flag()
  }
#break
#case (4) merge { object { Ball1 } object { Ball2 } Flag() } #break
#case (5) union { object { Ball1 } object { Ball2 } split_union off Flag() } #break
#case (6)
  union { object { Ball1 } object { Ball2 }
    clipped_by { box { <-2, 0, -1>, <2, 2, 1> } } Flag() }
#break
#case (7) difference { object { Ball1 Flag() } box { <-2, -1, -2>, <2, 0.8, 2> } } #break
#case (8) intersection { object { Ball1 Flag() } box { <-2, 0.8, -2>, <2, 2, 2> } } #break
#case (9) light_group { union { object { Table } object { Glass } } } #break
#case (10) light_group { union { object { Table } object { Glass } } global_lights on } #break
#case (11) union { object { Ball1 photons { target 0.5 } } object { Ball2 } Flag() } #break
#case (12) union { object { Ball1 photons { reflection off } } object { Ball2 } Flag() } #break
#case (13)
  object { Ball2 Flag() }
  box { <-3, 3, -3>, <3, 3.1, 3> pigment { rgbf <1, 1, 1, 0.8> } finish { diffuse 0 }
    photons { collect off pass_through } }
#break
#case (14)
  blob { threshold 0.25 cylinder { <0, 0.3, 0>, <0, 1.7, 0>, 0.5, 1 }
    texture { Mirror } Flag() }
#break
#case (15)
  intersection {
    merge {
      blob { threshold 0.25
        cylinder { -1.2*y, 1.2*y, 0.35, 1 }
        cylinder { <0, 1, 0.3>, <0, 1, -0.3>, 0.125, 1 }
        cylinder { <0.25, 1.2, 0>, <-0.25, 1.2, 0>, 0.2, -1 } }
      box { <-0.75, 0, -0.15>, <0.75, 0.6, 0.15> }
      cylinder { <-0.75, 0.6, 0>, <0.75, 0.6, 0>, 0.15 }
    }
    plane { -y, 0.001 }
    texture { Mirror } Flag()
  }
#break
#case (16)
  blob { threshold 0.3
    sphere { 0, 0.6, 1 scale <1, 0.5, 1> }
    cylinder { <-0.5, 0, -0.3>, <0.5, 0.4, 0.3>, 0.3, 1 }
    sphere { <0.3, 0, 0>, 0.2, -1 }
    rotate 30*z translate y
    texture { Mirror } Flag() }
#break
#case (17)
  difference { box { <-2, 0.2, -2>, <2, 1, 2> pigment { rgb 1 } } object { Ball1 Flag() } }
#break
#end
