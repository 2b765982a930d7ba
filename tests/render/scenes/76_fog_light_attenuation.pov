// A light with media_attenuation: its shadow rays are dimmed by the
// fog (POV-Ray's ComputeShadowMedia runs the fog on them, attenuation
// only, no fog colour added), so a bright light far away in a dense fog
// lights the scene like a dim one (as interior/media/hollow1.pov). The
// camera is inside the back plane, which is hollow, so the fog applies
// (without media_attenuation this light, 4000, would swamp the image).
// Deterministic: default 35 dB bar.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2, -8> look_at <0, 1, 0> right x*4/3 }
fog { color rgb <0.5, 0.55, 0.6> distance 12 }
light_source { <60, 80, -40> color rgb 4000 media_attenuation on }
plane { y, 0 pigment { checker rgb <1, 1, 0.3> rgb <0.3, 0.8, 0.3> } hollow }
plane { z, 6 pigment { checker rgb 1 rgb 0.4 } hollow }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.8 } }
sphere { <1.4, 1, 2>, 1 pigment { rgb <0.2, 0.4, 0.9> } }
