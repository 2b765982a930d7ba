// SPDX-License-Identifier: MIT
// rainbow.pov (tests/optics/optics.sh, check "rainbow"): the primary
// rainbow of a water cylinder (radius 1, axis along y, distilled water at
// 20 C from the catalogue) lit across its axis by a parallel beam
// travelling -z. Rays square to the axis stay in their plane z-x, where
// the cylinder deviates them as a drop does in the plane of a ray, so the
// bow appears on the screen z = 5 (on the light's side) as lines
// x = const, one per wavelength. The beam (a cylinder light of radius
// 0.12) covers only the impact parameters 0.75..0.99 around the rainbow
// ray's 0.87, on the +x side, and |y| < 0.12. The light is the CIE F11
// lamp, whose emission lines make three sharp bows.
#version 3.7;
// SECONDARY = 1: the secondary bow (two internal reflections), which the
// cylinder sends to the +x side: the beam narrowed to impact parameters
// 0.91..0.99 around its minimum-deviation ray's 0.95, denser photons,
// the screen and camera mirrored to x > 0 (rows run along x from 6 at
// the top edge, 0.01 a row)
#ifndef (SECONDARY) #declare SECONDARY = 0; #end
global_settings {
  assumed_gamma 1
  max_trace_level 10
  photons { spacing (SECONDARY ? 0.0001 : 0.0004) autostop 0 }
}
// looking at the screen from the cylinder's side, x in [-6.5, -4.5],
// y in [-0.05, 0.05]: image rows run along x (top row +x), 0.01 a row
camera { orthographic location <(SECONDARY ? 5 : -5.5), 0, 4> direction <0, 0, 1>
  right <0, 0.1, 0> up <2, 0, 0> }
#declare B = (SECONDARY ? 0.95 : 0.87);
#declare W = (SECONDARY ? 0.04 : 0.12);
light_source { <B, 0, 10> color rgb 1
  cylinder point_at <B, 0, 0> radius W falloff W tightness 0
  photons { refraction on reflection on }
  #ifdef (iris_version) spectrum "F11" #end
}
// the screen, on the -x side, where the bow falls (x = -5.4 .. -5.8)
box { <(SECONDARY ? 2 : -8), -3, 5>, <(SECONDARY ? 8 : -2), 3, 5.1>
  pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
cylinder { <0, -1, 0>, <0, 1, 0>, 1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.333 #ifdef (iris_version) glass "water_20C" #end }
  photons { target refraction on reflection on collect off }
}
