// SPDX-License-Identifier: MIT
// caustic_ball.pov: the clear-ball caustic of bench/error-vs-time.sh. A
// glass ball (ior 1.5, no dispersion, radius 1, centre 2.5 above a white
// floor) in a beam of parallel white light straight down: a cylindrical
// light whose beam is exactly as wide as the ball, so the floor gets only
// caustic light (no shadow edge of direct light, which would measure the
// antialiasing, not the photons). An orthographic camera 40 degrees above
// the horizon sees the floor square |x|, |z| <= 1.2 below the ball, past
// it (no camera ray meets the ball: the line to the floor point z0 passes
// |z0·sin(40) - 2.5·cos(40)| >= 1.14 from its centre).
// tools/ball_reference computes this image semi-analytically.
// Photon count: Declare=Photons=N (default 1e5); Photons=0 uses Spacing.
#version 3.7;
#ifndef (Photons) #declare Photons = 100000; #end
#ifndef (Spacing) #declare Spacing = 0.01; #end
// Fresnel=1: POV-Ray weighs refracted photons by 1 - F (iris always does)
#ifndef (Fresnel) #declare Fresnel = 0; #end
#declare Elev = radians(40);
global_settings {
  assumed_gamma 1
  max_trace_level 6
  photons {
    #if (Photons > 0) count Photons #else spacing Spacing #end
    autostop 0
    jitter 0.4
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
plane { y, 0
  pigment { color rgb 1 }
  finish { ambient 0 diffuse 1 }
}
sphere { <0, 2.5, 0>, 1
  pigment { color rgbf <1, 1, 1, 1> }
  #if (Fresnel)
    // photons lose the reflected share at each surface, as in nature
    finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } conserve_energy }
  #else
    finish { ambient 0 diffuse 0 }
  #end
  interior { ior 1.5 }
  photons { target refraction on reflection on collect off }
}
