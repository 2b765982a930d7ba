// Media photons of coloured light (advanced/optics.pov's construction):
// a box with a 'filter 1' yellow pigment and a blue 'reflection', without
// an interior, splits a white spotlight beam in fog that is the photon
// target (docs/media.md, "Media photons"): the blue goes sideways, the
// yellow straight on. Behind the split the photons carry one wavelength
// each (the split depends on it) and their media photons keep it, so a
// gather sphere of 100 media photons holds the wavelengths of only the
// ~25 paths crossing it: iris's coloured beams have a colour noise that
// POV-Ray's rgb photons do not, hence the lower bar (the white beam
// before the split has none). Measured 28.3 dB; 11.2 dB before media
// photons and the photons' passage through filters without an interior.
// Session 7: paths now carry three sibling wavelengths through the media
// and take turns depositing; 26.4 dB at the default seed, over seeds 1-12
// a mean of 28.16 dB (28.61 with one wavelength; each seed spreads about
// 1 dB): the 20,000 photons' noise, not a bias (tests/unit/test_pmedia.c
// test_sibling_media checks the colour against the spectral expectation).
// parity-min-psnr: 26 wavelength-sampled media photons: colour noise
#version 3.7;
global_settings {
  assumed_gamma 1
  photons { count 20000 media 60, 1 }
}
camera { location <0, 9, -0.01> look_at <0, 0, 0> angle 45 }
light_source { <0, 20, -5> color rgb 0.3
  photons { refraction off reflection off }
  media_interaction off
}
light_source { <-60, 0.5, 0> color rgb 1
  spotlight radius 0.6 falloff 0.8 point_at <0, 0.5, 0>
  photons { refraction on reflection on }
}
box { <-50, -1, -50>, <50, 0, 50>
  pigment { checker rgb 0.7, rgb 0.25 }
  finish { ambient 0 }
}
box { <-4, 0.01, -2.5>, <4, 1.2, 2.5> hollow
  pigment { rgbf 1 }
  finish { ambient 0 diffuse 0 }
  interior { media {
    scattering { 1, rgb 0.6 extinction 0 }
    method 3 intervals 1 samples 4
  } }
  photons { target }
}
box { <-0.05, 0, -1>, <0, 1, 1>
  pigment { rgbf <1, 1, 0, 1> }
  finish { ambient 0 diffuse 0 reflection rgb <0, 0, 1> }
  rotate -y*45
  translate <-1, 0, 0>
}
