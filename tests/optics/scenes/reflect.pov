// SPDX-License-Identifier: MIT
// reflect.pov (tests/optics/optics.sh, check "reflection"): a round
// parallel beam (a cylinder light, radius 0.3) falls at ANGLE degrees
// from the normal on a clear glass slab (n = 1.5, 0.1 thick); what the
// slab reflects, the first face's and the light coming back out after
// internal reflections, lands on a white screen square to the reflected
// beam. The screen is outside the incident beam: it sees photons only.
#version 3.7;
#ifndef (ANGLE) #declare ANGLE = 45; #end
#declare TH = radians(ANGLE);
#declare DIN = <sin(TH), -cos(TH), 0>;  // the beam's direction
#declare DOUT = <sin(TH), cos(TH), 0>;  // the reflected beam's
global_settings {
  assumed_gamma 1
  max_trace_level 20
  photons { spacing 0.001 autostop 0 }
}
// square to the reflected beam, 1 in front of the screen: the image is
// the central 0.4 x 0.4 of the beam's 0.6 wide footprint
camera { orthographic location 2 * DOUT direction DOUT
  right 0.4 * <cos(TH), -sin(TH), 0> up <0, 0, 0.4> }
light_source { -10 * DIN color rgb 1
  cylinder point_at <0, 0, 0> radius 0.3 falloff 0.3 tightness 0
  photons { refraction on reflection on }
}
disc { 3 * DOUT, DOUT, 0.6
  pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
box { <-1.5, -0.1, -1.5>, <1.5, 0, 1.5>
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off }
}
