// options: -q
// min_extent/max_extent of quadrics as POV-Ray boxes them when it parses
// them (Quadric::Compute_BBox): an ellipsoid in normal form, also moved
// by linear terms, gets its semi-axes; every other quadric the infinite
// box (its cylinders, cones, ... come out longer than CRITICAL_LENGTH
// against the parse-time clip box); transforms move the box's corners.
// The .expect file is POV-Ray 3.7.0.10's own #debug output for this
// file (checked: identical). Six decimals: POV-Ray keeps boxes in single
// precision, which these values survive.
#version 3.7;
global_settings { assumed_gamma 1 }
#macro B(Name, O)
  #debug concat(Name, " min ", vstr(3, min_extent(O), ",", 0, 6), "\n")
  #debug concat(Name, " max ", vstr(3, max_extent(O), ",", 0, 6), "\n")
#end
B("ellipsoid", quadric { <1,4,9>, <0,0,0>, <0,0,0>, -1 })
B("negated", quadric { <-1,-4,-9>, <0,0,0>, <0,0,0>, 1 })
B("radius2", quadric { <1,1,1>, <0,0,0>, <0,0,0>, -4 })
// x^2 + y^2 + z^2 - 2x + 4y + 1 = 0: centre <1,-2,0>, radius 2
B("linear", quadric { <1,1,1>, <0,0,0>, <-2,4,0>, 1 })
B("scaled", quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 scale <2,1,1> translate x })
B("rotated", quadric { <1,4,1>, <0,0,0>, <0,0,0>, -1 rotate 45*z })
// a mixed term below POV-Ray's EPSILON (1e-10) counts as 0
B("tiny_mixed", quadric { <1,1,1>, <1e-11,0,0>, <0,0,0>, -1 })
B("cylinder", quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 })
B("cone", quadric { <1,-1,1>, <0,0,0>, <0,0,0>, 0 })
B("paraboloid", quadric { <1,0,1>, <0,0,0>, <0,-1,0>, 0 })
B("mixed", quadric { <1,1,1>, <0.5,0,0>, <0,0,0>, -1 })
B("no_surface", quadric { <1,1,1>, <0,0,0>, <0,0,0>, 1 })
// the infinite box scaled by 0.5 is half as large
B("inf_scaled", quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 scale 0.5 })
B("inf_grown", quadric { <1,0,1>, <0,0,0>, <0,0,0>, -1 scale 3 })
B("huge", quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1e12 })
B("in_csg", intersection { quadric { <1,1,1>, <0,0,0>, <0,0,0>, -1 } box { 0, 2 } })
camera { location <0,0,-5> look_at 0 }
