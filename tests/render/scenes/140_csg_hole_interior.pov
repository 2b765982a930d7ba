// Parity scene: a glass block with a hole cut by a CSG without an
// interior{} (difference { glass knight }, as advanced/glasschess). POV-Ray
// gives that CSG one default interior (ior 1) which every primitive of the
// hole shares (Parser::Post_Process), so a ray entering the hole through
// the box's face and leaving through the cylinder's is back in the glass
// and refracts when it leaves the block. iris once keyed the medium by
// the primitive hit: the ray stayed "inside" the box and left the glass
// unrefracted, showing the floor straight through (28.0 dB here, 63.0 dB
// with the fix; advanced/glasschess 25.7 -> 35.7 dB at 160x120).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 15 }
camera { location <2.2, 1.6, -3.2> look_at <0, 0.8, 0> right x*4/3 angle 40 }
light_source { <500, 50, -5> color rgb 1 }
background { rgb <0.3, 0.3, 0.5> }
plane { y, -0.01 pigment { checker rgb 1, rgb <0, 0, 0.4> scale 0.7 } }
difference {
  box { <-0.8, 0, -0.6>, <0.8, 1.8, 0.6>
    texture { pigment { rgbf <0.98, 1, 0.98, 1> }
              finish { ambient 0 diffuse 0 specular 1 roughness 0.001
                       reflection { 0, 1 fresnel } } }
    interior { ior 1.5 } }
  intersection {
    box { <-0.5, 0.3, -0.4>, <0.5, 1.5, 0.2> }
    cylinder { <0, 0.2, -0.4>, <0, 1.6, -0.4>, 0.55 }
    texture { pigment { rgbt <0.9, 0.9, 0.6, 0.9> } finish { reflection 0.1 } }
    rotate y*-20
  }
  no_shadow
}
