// Parity scene: a declared finish starts from the #default finish, not
// from the built-in one (POV-Ray's Parse_RValue copies the default
// texture's finish before parsing the block). Here #default sets ambient
// 0.6 and diffuse 0.2; the declared finishes change only other members,
// so both spheres keep the strong ambient and weak diffuse. iris once
// started a declared finish from ambient 0.1 / diffuse 0.6, as
// incdemo/shapes.pov (#default { finish { ambient 0 } }, then
// #declare ShinyFinish = finish { ... }) showed: every shiny object was
// 0.1 x its pigment too bright there (25.1 dB). The right sphere also
// layers an inline finish on the declared one (finish { F2 phong 0.5 }).
#version 3.7;
global_settings { assumed_gamma 1 }
#default { finish { ambient 0.6 diffuse 0.2 } }
#declare F1 = finish { specular 0.4 roughness 0.02 }
#declare F2 = finish { brilliance 2 }
camera { location <0, 1.2, -5> look_at <0, 0.6, 0> right x*4/3 angle 50 }
light_source { <-4, 6, -5> color rgb 1 }
background { rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { checker rgb <0.2, 0.3, 0.4> rgb <0.4, 0.5, 0.6> } }
sphere { <-1.1, 0.9, 0>, 0.9 pigment { rgb <0.9, 0.4, 0.2> } finish { F1 } }
sphere { < 1.1, 0.9, 0>, 0.9 pigment { rgb <0.2, 0.5, 0.9> }
         finish { F2 phong 0.5 } }
