// SPDX-License-Identifier: MIT
// slab.pov (tests/optics/optics.sh, checks "slab" and "colour"): a clear
// glass slab (n = 1.5, no dispersion, no absorption) over a white floor,
// under a parallel light tilted TILT degrees from the vertical, white
// (D65) or, with KELVIN > 0, a blackbody of that temperature (SPEC: a
// tabulated illuminant). The
// floor under the slab is lit only through it, by photons; the floor
// beside it by the light directly. Their ratio is the
// slab's transmittance, independent of the light's units; each side's
// colour is the light's. IOR and FADE vary the slab.
#version 3.7;
#ifndef (TILT) #declare TILT = 0; #end
#ifndef (KELVIN) #declare KELVIN = 0; #end
// SPEC: the light's tabulated spectrum, 1 CIE illuminant A, 2 CIE F11
#ifndef (SPEC) #declare SPEC = 0; #end
#ifndef (IOR) #declare IOR = 1.5; #end
// FADE > 0: a grey exponential absorption, fade_distance FADE
#ifndef (FADE) #declare FADE = 0; #end
// SPACING: the photons' spacing (finer for the grazing-incidence check)
#ifndef (SPACING) #declare SPACING = 0.008; #end
global_settings {
  assumed_gamma 1
  max_trace_level 20
  photons { spacing SPACING autostop 0 }
}
// between the slab and the floor, looking straight down at x in
// [c - 1, c + 1], z in [-1, 1], c = 1.05 tan(TILT): where the slab's
// shadow edge falls (the light comes from -x), so that the left half of
// the image is lit through the slab and the right half directly
#declare C = 1.05 * tan(radians(TILT));
camera { orthographic location <C, 0.5, 0> direction <0, -1, 0>
  right <2, 0, 0> up <0, 0, 2> }
light_source { <0, 10, 0> color rgb 1 parallel point_at <0, 0, 0>
  rotate TILT * z
  photons { refraction on reflection on }
  #ifdef (iris_version)
    #if (KELVIN > 0) blackbody KELVIN #end
    #if (SPEC = 1) spectrum "A" #end
    #if (SPEC = 2) spectrum "F11" #end
  #end
}
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
// the slab, 0.1 thick, 3 x 3: light entering through its edges lands
// outside the measured floor
box { <-3, 1, -1.5>, <0, 1.1, 1.5>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior IOR
    #if (FADE > 0) fade_distance FADE fade_power 1001 fade_colour rgb 0.5 #end
  }
  photons { target refraction on reflection on collect off }
}
