// Parity scene: a light's looks_like object, rendered as an ordinary
// object at the light (POV-Ray moves it there) that casts no shadow, so
// the light shines out of it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -7> look_at <0, 1, 0> right x*4/3 }
plane { y, 0 pigment { checker rgb 1 rgb <0.4, 0.5, 0.7> } }
sphere { <1.5, 0.6, 0.5>, 0.6 pigment { rgb <0.9, 0.4, 0.2> } finish { phong 0.5 } }
light_source { <-0.8, 2.2, 0> color rgb <1, 0.95, 0.8>
  looks_like { sphere { 0, 0.35 pigment { rgbf <1, 0.9, 0.6, 0.2> } finish { ambient 1 diffuse 0 } } } }
light_source { <4, 8, -6> color rgb 0.3 }
