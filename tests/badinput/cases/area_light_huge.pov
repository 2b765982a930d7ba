// expect: 0 10
#version 3.7;
// An area light of 2000 x 2000 = 4e6 sub-lights: more than
// IRIS_AREA_LIGHT_MAX_GRID (1024 x 1024), the shadow-ray table each
// trace context keeps. iris renders it as a point light at its centre
// (POV-Ray renders the area light); that used to happen without a word,
// now the parser warns at the sizes.
camera { location <0, 2, -5> look_at 0 }
light_source { <0, 5, -3>, rgb 1
  area_light x, z, 2000, 2000 adaptive 1 }
sphere { 0, 1 pigment { rgb 1 } }
plane { y, -1 pigment { rgb 0.5 } }
