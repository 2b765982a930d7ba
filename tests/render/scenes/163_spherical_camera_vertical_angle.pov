// Parity scene: the spherical camera's two angles, 'angle H V' (POV-Ray
// reads an optional comma and then a vertical angle if a float follows;
// iris rejected the form without a comma and ignored V, using H/2). A
// ring of coloured boxes around the camera and a checkered floor: a
// wrong vertical field moves the horizon and every box edge. Reverted,
// iris rejects this scene ("unexpected number in camera"); with the
// comma form it used H/2 = 100 degrees: 14.0 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { spherical location <0, 1, 0> look_at <0, 1, 1> angle 200 60 }
light_source { <3, 8, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb <0.3, 0.4, 0.6> } }
#declare B = box { <-0.4, 0, -0.4>, <0.4, 1.6, 0.4> }
#for (I, 0, 7)
  object { B pigment { rgb <mod(I, 2), I / 7, 1 - I / 7> }
    translate <3 * sin(I * pi / 4), 0, 3 * cos(I * pi / 4)> }
#end
sphere { <0, 2.2, 2.5>, 0.4 pigment { rgb 1 } finish { phong 0.6 } }
