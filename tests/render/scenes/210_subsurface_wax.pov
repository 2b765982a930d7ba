// SPDX-License-Identifier: MIT
// 210_subsurface_wax.pov: POV-Ray 3.7's subsurface light transport
// (src/render/subsurface.c): a wax-coloured sphere with subsurface
// { translucency } on a plain floor, lit from the upper left. Its colour
// is the dipole BSSRDF's multiple scattering (the finish's diffuse term
// is left out), single scattering and, where the refracted eye ray
// leaves the sphere, the light behind it.
// parity-min-psnr: 45 both renderers sample the BSSRDF (200 surface
// points, 20 depths): POV-Ray's own images with +WT1 and +WT2 (its Halton
// sequences run on per thread) differ by 49.3 dB; iris's is 47.6 dB from
// either. Without subsurface (the diffuse term instead) it was 32.5 dB.
#version 3.7;
global_settings {
  assumed_gamma 1.0
  mm_per_unit 20
  subsurface { samples 200, 20 }
}
camera { location <0, 1.4, -4> look_at <0, 0.7, 0> angle 36 }
light_source { <-5, 8, -6> rgb 1 }
background { rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { rgb 0.5 } finish { ambient 0.1 diffuse 0.7 } }
sphere {
  <0, 0.8, 0>, 0.8
  pigment { rgb <0.9, 0.6, 0.3> }
  finish {
    ambient 0.05 diffuse 0.8 specular 0.3 roughness 0.05
    subsurface { translucency <2, 1, 0.5> }
  }
  interior { ior 1.4 }
}
