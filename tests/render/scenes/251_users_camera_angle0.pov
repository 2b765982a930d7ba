// SPDX-License-Identifier: MIT
// 'angle 0' in a perspective camera, as users write it for "no angle":
// POV-Ray's Parse_Camera applies an angle only when it is above 0 (and
// refuses 180 or more and negative ones), so the direction given stays,
// here 2*z, a narrower view than the default's 1*z. Before session 11
// iris refused the scene ("camera angle must be in (0, 180) degrees").
#version 3.7;
global_settings { assumed_gamma 1 }
camera {
    location <0, 1, -5>
    direction 2 * z
    right x * image_width / image_height
    angle 0
    look_at <0, 0.5, 0>
}
light_source { <-4, 8, -6> rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <0, 0.7, 0>, 0.7 pigment { rgb <1, 0.4, 0.2> } }
sphere { <1.6, 0.4, 1>, 0.4 pigment { rgb <0.2, 0.6, 1> } }
