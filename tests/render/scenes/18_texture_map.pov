// texture_map and pigment_map blending.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -5> look_at <0, 0.8, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } } pigment { rgb 0.1 } } }
sphere { <0, 1, 0>, 1
  texture { gradient y texture_map {
    [0.3 pigment { rgb <0.1, 0.2, 0.9> } finish { phong 1 }]
    [0.7 pigment { rgb <0.9, 0.9, 0.9> } finish { diffuse 0.3 reflection 0.5 }] } scale 2 translate y*-1 } translate y*0 }
