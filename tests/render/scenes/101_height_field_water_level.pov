// Parity scene: height_field water_level as POV-Ray draws it
// (heightfield.cpp): the ray is clipped to the field's box, whose floor
// is the water level (bounding_corner1[Y] = 65536 * water_level), so the
// surface ends exactly at the level, across the grid cells, with no lid;
// the left field is smooth (its normals interpolated along the cut). A
// coarse grid (12x12 and 9x9) makes cells large: iris once dropped whole
// cells below the level and left the ones crossing it whole (a jagged
// staircase edge and slopes reaching under the level).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 2.6, -2.6> look_at <0, 0.25, 0.2> right x*4/3 angle 52 }
light_source { <-3, 6, -4> color rgb 1 }
background { rgb <0.15, 0.2, 0.3> }
height_field {
  function 12, 12 { 0.5 + 0.45 * sin(9 * x) * cos(7 * y) }
  water_level 0.45 smooth
  translate <-0.5, 0, -0.5> scale <1.4, 0.8, 1.4> translate <-0.75, 0, 0>
  pigment { rgb <1, 0.8, 0.5> } }
height_field {
  function 9, 9 { 1 - 2.2 * ((x - 0.5) * (x - 0.5) + (y - 0.5) * (y - 0.5)) - 0.3 * x }
  water_level 0.6
  translate <-0.5, 0, -0.5> scale <1.4, 0.8, 1.4> translate <0.75, 0, 0>
  pigment { rgb <0.6, 0.8, 1> } finish { specular 0.3 } }
plane { y, 0.2 pigment { rgb <0.25, 0.3, 0.35> } }
