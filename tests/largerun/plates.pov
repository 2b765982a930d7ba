// SPDX-License-Identifier: MIT
// plates.pov: photons that deposit many times each, for
// tests/largerun/memory_limit.sh. A point light between two parallel
// plates that are both diffuse and perfect mirrors (reflection 1), both
// collecting photons: a photon bounces between them up to
// max_trace_level 60 and is stored at every bounce after the first
// (about 16 stores per photon emitted), so the count checked before
// shooting (one store per photon) underestimates the memory by 16x.
#version 3.7;
#ifndef (Photons) #declare Photons = 10000; #end
global_settings { photons { count Photons max_trace_level 60 autostop 0 } }
camera { location <0, 0.5, -30> look_at <0, 0.5, 0> }
light_source { <0, 0.5, 0> color rgb 1 photons { reflection on } }
#declare Plate = finish { ambient 0 diffuse 1 reflection 1 }
box { <-50, -1, -50>, <50, 0, 50> pigment { rgb 1 } finish { Plate }
  photons { target reflection on collect on } }
box { <-50, 1, -50>, <50, 2, 50> pigment { rgb 1 } finish { Plate }
  photons { reflection on collect on } }
