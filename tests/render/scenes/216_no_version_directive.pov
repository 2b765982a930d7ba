// A scene without any #version directive (none of its own, no include
// file that sets one), as many users' scenes are written. POV-Ray 3.7
// then renders with EffectiveLanguageVersion() 3.62: no assumed_gamma
// means no gamma correction, and a layered texture's opacity is 3.6's.
// The 'version' keyword still reads 3.7. iris rendered such a scene as a
// 3.7 one (gamma-corrected, 3.7 opacity): 13.6 dB at 80x60 +A0.3
// against POV-Ray; now identical.
camera { location <0, 2, -5> look_at <0, 0.8, 0> right x*4/3 }
light_source { <5, 10, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb <0.9, 0.9, 0.8> rgb <0.2, 0.3, 0.6> } }
sphere { <-1, 1, 0>, 1
    texture { pigment { rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
    texture { pigment { gradient y color_map { [0.5 rgbf <0, 1, 0, 1>]
                                               [0.5 rgbf <0, 0.6, 0, 0.3>] }
                        scale 0.5 } } }
sphere { <1.2, 0.8, 0.5>, 0.8
    pigment { rgb <0.3 + 0.2 * (version > 3.6), 0.5, 0.9> } }
