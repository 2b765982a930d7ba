// SPDX-License-Identifier: MIT
// ball.pov: a small, fast caustic for tests/progressive/progressive.sh: a
// glass ball in a parallel beam exactly as wide as it, over a white floor
// seen at 40 degrees (bench/caustic_ball.pov with fewer photons).
#version 3.7;
#ifndef (Photons) #declare Photons = 5000; #end
#declare Elev = radians(40);
global_settings {
  assumed_gamma 1
  max_trace_level 6
  photons { count Photons autostop 0 jitter 0.4 }
}
camera { orthographic
  location <0, 10 * sin(Elev), -10 * cos(Elev)>
  right <2.4, 0, 0> up <0, 2.4 * sin(Elev), 0>
  look_at <0, 0, 0>
}
light_source { <0, 20, 0> color rgb 1 cylinder point_at <0, 0, 0>
  radius 1 falloff 1 tightness 0
  photons { refraction on reflection on }
}
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { <0, 2.5, 0>, 1
  pigment { color rgbf <1, 1, 1, 1> }
  finish { ambient 0 diffuse 0 }
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off }
}
