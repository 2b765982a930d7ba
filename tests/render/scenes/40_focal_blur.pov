// focal_blur: camera aperture with the 37-point hexagonal pattern, in
// focus on the middle sphere; the near and far spheres and the checker
// blur (POV-Ray's TraceRayWithFocalBlur, src/render/focalblur.h). The
// variance bound is so low that every sample takes all 37 rays: the
// confidence test cannot stop early. iris takes POV-Ray's own aperture
// pattern, sub-pixel positions and jitter, so the blur's sampling noise
// is the same noise in both: the default bar of 35 dB needs no allowance
// (measured: identical PNGs; without the blur, 23.7 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
  location <0, 2, -6> look_at <0, 0.6, 0> right x*4/3 angle 45
  aperture 1.2
  blur_samples 37
  focal_point <0, 0.6, 0>
  confidence 0.9
  variance 0
}
light_source { <-5, 8, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.45> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 scale 0.5 } }
sphere { <-1.4, 0.6, -2.2>, 0.6 pigment { rgb <1, 0.4, 0.2> } finish { phong 0.6 } }
sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.3, 0.8, 0.3> } finish { phong 0.6 } }
sphere { <1.6, 0.6, 3>, 0.6 pigment { rgb <0.3, 0.4, 1> } finish { phong 0.6 } }
