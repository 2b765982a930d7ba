// Density patterns: densities multiply (a boxed density times a gradient
// with a density_map whose entries are densities), transforms inside the
// media move only the densities before them, and the object's own
// transforms (scale, rotate, translate after the interior) move the
// media with it. Emission and absorption together; method 3 with more
// samples and aa_level 4. Deterministic: default 35 dB bar.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <-3, 8, -4> color rgb 1 }
background { rgb 0.05 }
plane { y, 0 pigment { checker rgb 0.6 rgb 0.2 } }
box { -1, 1
  pigment { rgbt 1 }
  hollow
  interior {
    media {
      emission rgb <0.2, 0.9, 0.5>
      absorption 0.5
      samples 16 aa_level 4 aa_threshold 0.05
      density { boxed color_map { [0 rgb 0] [0.5 rgb 1] [1 rgb 2] } }
      density { gradient y
        density_map { [0 rgb 0.2]
          [0.5 bozo color_map { [0 rgb 0.3] [1 rgb 1.2] } scale 0.3]
          [1 rgb 1] }
        scale 2 translate -y }
    }
  }
  scale <1, 0.8, 0.8>
  rotate y*30
  translate <-1.3, 1, 0.5>
}
sphere { 0, 1
  pigment { rgbt 1 }
  hollow
  interior {
    media {
      emission rgb <1, 0.5, 0.2>
      density { wood turbulence 0.3 color_map { [0 rgb 0] [0.6 rgb 1.5] [1 rgb 0] }
        scale 0.4 }
      scale 0.5
    }
  }
  translate <1.4, 1.1, 0.5>
}
