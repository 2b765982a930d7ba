// SPDX-License-Identifier: MIT
// A declared orthographic camera with an angle and a look_at, used as
// 'camera { C1 }': POV-Ray 3.5+ takes only transforms after a camera
// identifier and sizes nothing again (Parse_Camera's only_mods path), so
// the copy renders as the camera written out. Session 12's rule that
// sizes an orthographic camera by its default look_at also resized the
// copy a second time: templates/Basic_Scenes/Orthographic_isometric.pov
// fell from 126.8 to 13.0 dB (this scene: 12.8 dB).
#version 3.7;
global_settings { assumed_gamma 1 }
#declare C1 = camera { orthographic angle 15 location <20, 20, -20>
                       right x * 4/3 look_at <0, 0.5, 0> }
camera { C1 }
light_source { <-10, 20, -20> rgb 1 }
sphere { 0, 1 pigment { checker rgb 1 rgb <1, 0, 0> scale 0.5 } }
plane { y, -1 pigment { checker rgb 0.2 rgb 0.8 } }
