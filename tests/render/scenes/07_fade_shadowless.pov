// Light fading with distance, a shadowless fill light, ambient and emission.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> right x*4/3 }
light_source { <0, 3, -1> color rgb 2 fade_distance 2 fade_power 2 }
light_source { <6, 6, -6> color rgb 0.3 shadowless }
plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.05 } }
sphere { <-1.5, 0.6, 1>, 0.6 pigment { rgb <0.2, 0.4, 1> } finish { emission 0.4 } }
sphere { <1.5, 0.6, 1>, 0.6 pigment { rgb <1, 0.8, 0.2> } finish { ambient 0.3 diffuse 0.4 } }
