// Methods 1 (random sample positions) and 2 (stratified, jittered), and
// method 3 with jitter, side by side in three emitting and absorbing
// boxes with a spherical density. Their samples are random and iris's
// random streams are not POV-Ray's (nor are POV-Ray's the same from run
// to run with two threads), so the noise differs pixel by pixel; 30
// samples per interval (methods 1 and 2: up to 60 while the variance is
// above POV-Ray's confidence threshold) keep it within the default 35 dB
// bar (measured: 46.7-46.9 dB), while a wrong estimator shows: without
// method 1's e^-σd weighting of each sample the scene measured 29.5 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.2, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-3, 8, -4> color rgb 1 }
background { rgb 0.05 }
plane { y, 0 pigment { checker rgb 0.6 rgb 0.2 } }
#macro Cloud(Method, Jit, X)
box { -0.8, 0.8
  pigment { rgbt 1 }
  hollow
  interior { media {
    method Method
    #if (Method = 3)
      samples 30 jitter Jit
    #else
      samples 30, 60 intervals 2 jitter Jit
    #end
    emission rgb <1.8, 1.2, 0.6>
    absorption 2
    density { spherical color_map { [0 rgb 0] [1 rgb 1.5] } scale 0.8 }
  } }
  translate <X, 1, 0>
}
#end
Cloud(1, 0, -1.8)
Cloud(2, 0.5, 0)
Cloud(3, 0.5, 1.8)
