// Check 29 (optics.sh): photons aimed at a target union of two glass
// balls 2 apart, split (SPLIT=1, POV-Ray's default: one light x target
// pair per ball, each shot at its own bounding sphere) or not (SPLIT=0:
// the union's sphere). COUNT > 0 asks for 'count COUNT' instead of the
// spacing. 'autostop 1' makes POV-Ray shoot every ring up to the
// target's sphere, as iris does, so the emitted counts compare exactly.
#ifndef (SPLIT) #declare SPLIT = 1; #end
#ifndef (COUNT) #declare COUNT = 0; #end
global_settings { photons {
  autostop 1
  #if (COUNT > 0) count COUNT #else spacing 0.01 #end
} }
camera { location <0, 5, -8> look_at <0, 0, 0> }
light_source { <3, 10, -4> color rgb 1 }
plane { y, -1 pigment { rgb 1 } }
union {
  sphere { <-1, 0, 0>, 0.5 }
  sphere { < 1, 0, 0>, 0.5 }
  #if (!SPLIT) split_union off #end
  pigment { rgbf 1 } interior { ior 1.5 }
  photons { target reflection off refraction on }
}
