// Parity scene: a blob whose components carry their own textures. POV-Ray
// shades every texture of the components a point lies within and mixes
// the colours by |field| (Blob::Determine_Textures; a negative component
// counts by its absolute field, a component without a texture with the
// blob's own), so the colours run into each other across the blob. Here
// with a component scaled into an ellipsoid, a pattern, a reflecting and
// a filtering texture (its shadow is blended too), and the whole blob
// transformed inside a union. iris showed the texture of the strongest
// component only, with hard seams (reverted: 31.7 dB at 80x60 +A0.3;
// with the blend identical).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.2, -6> look_at <0, 0.4, 0> angle 42 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8 rgb 0.6 } }
union {
  blob {
    threshold 0.3
    sphere { <-0.9, 0, 0>, 1.4, 1
      texture { pigment { rgb <1, 0.1, 0.1> } finish { phong 0.6 } } }
    sphere { <0, 0, 0>, 1, 1 scale <1.4, 0.8, 1> translate <0.9, 0, 0>
      texture { pigment { gradient y color_map { [0 rgb <0.1, 0.2, 1>] [1 rgb 1] } scale 0.5 } } }
    cylinder { <0, 0, -0.5>, <0, 1.5, 0.5>, 0.8, 1.2
      texture { pigment { rgb <1, 0.9, 0.2> filter 0.6 } finish { reflection 0.3 } } }
    sphere { <0, 1.2, -0.6>, 0.9, -0.6 }
    pigment { rgb <0.2, 1, 0.3> }
    rotate 20 * y
  }
  sphere { <2.2, -0.6, 0.8>, 0.4 pigment { rgb 0.9 } }
  translate <0.1, 0, 0.2>
}
