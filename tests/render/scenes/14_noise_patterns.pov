// bozo, granite, spotted, leopard with colour maps.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0, 0.5, 0> right x*4/3 }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { granite color_map { [0 rgb 0.9] [1 rgb 0.1] } scale 2 } }
sphere { <-1.6, 0.8, 0>, 0.8 pigment { bozo color_map { [0 rgb <1, 0, 0>] [1 rgb <1, 1, 0>] } scale 0.3 } }
sphere { <0, 0.8, 0>, 0.8 pigment { spotted noise_generator 1 scale 0.4 } }
sphere { <1.6, 0.8, 0>, 0.8 pigment { leopard color_map { [0 rgb <1, 0.8, 0.3>] [1 rgb 0.1] } scale 0.1 } }
