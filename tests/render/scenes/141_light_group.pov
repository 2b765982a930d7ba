// Parity scene: light_group. A group's lights light only the objects in
// it (POV-Ray's Promote_Local_Lights), and the group's objects see the
// scene's lights only with global_lights on (3.7's default is off). The
// left sphere has a red light of its own and no scene light; the middle
// group keeps the scene's light and subtracts some with a negative light
// (advanced/abyss darkens its mines so); the right sphere and the floor
// are lit by the scene's light alone, with the shadow of a group sphere
// that its group light casts onto its own box. iris once made every
// group light a scene light (19.3 dB here; advanced/abyss 20.3 dB, its
// submarine black under the mines' negative lights; 55.0 with the fix).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -9> look_at <0, 0.6, 0> right x*4/3 angle 45 }
light_source { <-20, 30, -20> color rgb 1 }
plane { y, -1 pigment { checker rgb 0.8, rgb 0.4 } }
light_group {
  light_source { <3, 6, -6> color rgb <1, 0.3, 0.2> }
  sphere { <-2.2, 0, 0>, 1 pigment { rgb 1 } }
  box { <-3.4, -1, 1.2>, <-1, 0.5, 1.6> pigment { rgb 0.9 } }
}
light_group {
  light_source { <0, 10, -10> color rgb -0.6 shadowless }
  sphere { <0, 0, 0>, 1 pigment { rgb <0.4, 1, 0.6> } finish { phong 0.5 } }
  global_lights on
  translate y*0.2
}
sphere { <2.2, 0, 0>, 1 pigment { rgb <0.6, 0.7, 1> } }
