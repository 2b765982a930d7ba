// Absorbing media: a hollow box of absorbing media in front of a bright
// checker wall dims it by exp(-sigma * path), more in red than in blue;
// the same media in a sphere that is not hollow shows nothing, since
// POV-Ray computes media only for rays in hollow interiors (the sphere
// still casts no shadow: shadow rays skip its media as well). Constant
// media: one interval, exact in both renderers (default 35 dB bar).
// The wall is a box, not a plane: the camera would be inside 'plane { z,
// 3 }', which is not hollow, and would then see no media at all.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -6> look_at <0, 1, 0> right x*4/3 }
light_source { <2, 6, -6> color rgb 1.2 }
box { <-10, 0, 3>, <10, 10, 3.5>
  pigment { checker rgb 1 rgb 0.5 scale 0.5 } finish { ambient 0.4 } }
plane { y, 0 pigment { rgb 0.7 } }
box { <-2.2, 0.2, -0.5>, <-0.2, 2.2, 1.5>
  pigment { rgbt 1 }
  hollow
  interior { media { absorption rgb <1.2, 0.5, 0.15> } }
}
sphere { <1.3, 1.1, 0.5>, 0.9
  pigment { rgbt 1 }
  interior { media { absorption rgb <1.2, 0.5, 0.15> } }
}
