// Layered textures: a transparent-spotted layer over a plain one.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 1, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 texture { pigment { rgb <0.2, 0.5, 0.2> } } texture { pigment { checker rgbt <1, 1, 1, 0> rgbt <0, 0, 0, 1> scale 0.5 } } }
sphere { <0, 1, 0>, 1
  texture { pigment { rgb <0.8, 0.1, 0.1> } finish { phong 0.5 } }
  texture { pigment { gradient y color_map { [0 rgbt <1, 1, 1, 1>] [0.5 rgbt <1, 1, 1, 1>] [0.5 rgbf <0.1, 0.1, 0.9, 0.5>] [1 rgbf <0.1, 0.1, 0.9, 0.5>] } scale 0.4 } }
}
