// SPDX-License-Identifier: MIT
// 260_targets_glass_in_union.pov: a glass ball flagged as a photon
// target inside a plain union with the table it stands on (a table with
// a glass on it, grouped): POV-Ray searches the children of every CSG for
// targets and links a split union's children to the scene, so the ball
// is a target of its own and casts its caustic on the table
// (src/photon/targets.c). iris looked only at the scene's top-level
// objects: no photons, the ball's shadow light grey (its filter) and no
// caustic in it.
// parity-min-psnr: 29 photon estimates on both sides (POV-Ray's jittered
// rings, iris's; scene 120's bar): measured 32.39 dB (iris seeds 1, 2:
// 32.81, 32.72; POV-Ray the same over 3 runs); 14.74 dB before
#version 3.7;
global_settings { assumed_gamma 1 photons { spacing 0.01 autostop 0 jitter 0.5 } }
camera { location <0, 4, -5> look_at <0, 0.4, 0.6> angle 40 }
light_source { <-2, 7, 2> color rgb 1.2 }
union {
  box { <-2, -0.2, -1.5>, <2, 0, 2.5> pigment { rgb 0.8 } finish { ambient 0 diffuse 0.8 } }
  sphere { <0, 0.7, 0>, 0.7
    pigment { rgbf <1, 1, 1, 0.95> }
    finish { ambient 0 diffuse 0 }
    interior { ior 1.5 }
    photons { target refraction on reflection off collect off }
  }
}
