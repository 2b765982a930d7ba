// Scattering media lit by a spotlight: the visible beam (the lit stretch
// of each ray found from the spotlight cone, POV-Ray's light intervals),
// a sphere in the beam whose shadow cuts it (shadow rays from the media
// samples), the floor lit through the media (media_attenuation on the
// shadow rays), and a shadowless fill light that does not scatter
// (shadowless lights take no part in media). Method 3 without jitter is
// deterministic in both renderers: default 35 dB bar.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 2, 0> right x*4/3 }
light_source { <0, 10, -10> color rgb 0.3 shadowless }
light_source { <-1, 6, 1> color rgb 2.5
  spotlight point_at <0.5, 0, 0> radius 12 falloff 18 tightness 1
  media_attenuation on
}
plane { y, 0 pigment { rgb 0.8 } }
box { <-4, 0.01, -3>, <4, 6, 4>
  pigment { rgbt 1 }
  hollow
  interior { media { scattering { 1, rgb 0.08 } intervals 2 samples 8 } }
}
sphere { <-0.5, 3.4, 0.7>, 0.5 pigment { rgb <0.9, 0.3, 0.2> } }
