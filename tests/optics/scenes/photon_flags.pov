// SPDX-License-Identifier: MIT
// photon_flags.pov (tests/optics/optics.sh, check "photon flags"): the
// object and global photon keywords users write, on one layout: a
// parallel white light from straight above, a white floor, a clear slab
// of index 1 (a photon target that changes nothing) over x < 0, so the
// floor gets the light by photons under the slab and directly beside it.
// FLAG: 0 nothing more; 1 an opaque 'no_shadow' plate above the slab over
// -1.5 < x < -0.5 (photons skip no_shadow objects as shadow rays do:
// nothing changes); 2 the same plate without no_shadow (its shadow);
// 3 the plate clear, rgbf <0.6, 0.6, 0.6, 1>, 'photons { pass_through }'
// (photons go straight through it, filtered at both faces); 4 'target
// 0.5' on the slab (half the spacing: four times the photons); 5 global
// 'count 20000' instead of spacing; 6 the slab of index 1.5 with
// 'max_trace_level 1' for photons (they die inside: the floor keeps
// direct light, as POV-Ray); 7 the floor 'photons { collect off }'.
#version 3.7;
#ifndef (FLAG) #declare FLAG = 0; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { #if (FLAG = 5) count 20000 #else spacing 0.01 #end autostop 0
    #if (FLAG = 6) max_trace_level 1 #end }
}
// looking down at the floor, x in [-2, 2] (rows, top row x = -2),
// z in [-0.1, 0.1] (columns)
camera { orthographic location <0, 0.5, 0> direction <0, -1, 0>
  right <0, 0, 0.2> up <-4, 0, 0> }
light_source { <0, 30, 0> color rgb 1 parallel point_at <0, 0, 0>
  photons { refraction on reflection on }
}
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 }
  #if (FLAG = 7) photons { collect off } #end
}
box { <-2, 1, -1>, <0, 1.1, 1>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior #if (FLAG = 6) 1.5 #else 1 #end }
  photons { target #if (FLAG = 4) 0.5 #end refraction on reflection on
    collect off }
}
#if (FLAG >= 1 & FLAG <= 3)
box { <-1.5, 2, -1>, <-0.5, 2.1, 1>
  #if (FLAG = 3)
    pigment { color rgbf <0.6, 0.6, 0.6, 1> } finish { ambient 0 diffuse 0 }
    photons { pass_through }
  #else
    pigment { color rgb 1 }
  #end
  #if (FLAG = 1) no_shadow #end
}
#end
