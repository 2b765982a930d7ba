// options: -q
// min_extent/max_extent of a blob are POV-Ray's box of it: the bounding
// spheres of its positive components (Blob::Compute_BBox), transformed
// by the box's corners, wider than the blob itself. iris returned its
// own tight box (max x 4.2419 here). The #debug values are POV-Ray
// 3.7.0.10's output.
#version 3.7;
#declare B = blob { threshold 0.6
  sphere { <0, 0, 0>, 1, 1 }
  sphere { <1.5, 0.5, 0>, 0.8, 2 scale <1, 2, 1> }
  cylinder { <0, -1, 0>, <0, 1, 2>, 0.5, 1.5 }
  rotate 30 * y translate x }
#debug concat("min ", vstr(3, min_extent(B), " ", 0, 4), "\n")
#debug concat("max ", vstr(3, max_extent(B), " ", 0, 4), "\n")
