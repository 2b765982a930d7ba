// SPDX-License-Identifier: MIT
// photon_file.pov: tests/progressive/ball.pov (a glass ball's caustic on
// a white floor) with photons { save_file } (Mode=1) or { load_file }
// (Mode=2) of "ball.photons" in the working directory, for
// tests/largerun/photon_file.sh.
#version 3.7;
#ifndef (Photons) #declare Photons = 5000; #end
#ifndef (Mode) #declare Mode = 0; #end
#declare Elev = radians(40);
global_settings {
  assumed_gamma 1
  max_trace_level 6
  photons {
    count Photons autostop 0 jitter 0.4
    #if (Mode = 1) save_file "ball.photons" #end
    #if (Mode = 2) load_file "ball.photons" #end
  }
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
