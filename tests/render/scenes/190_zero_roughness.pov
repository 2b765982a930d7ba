// Parity scene: `roughness 0`. POV-Ray 3.7 warns "Zero roughness used."
// and keeps 0 as the highlight's exponent (it stores 1/roughness and
// leaves a 0 uninverted): a flat specular term wherever the half vector
// faces the surface, and 0.5 as the albedo form's factor. iris refused the
// finish with an error (found by the robust helper's sweep, session 7);
// now it renders pixel for pixel as POV-Ray at 160x120.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1, -4> look_at 0 }
light_source { <-3, 5, -4> color rgb 1 }
sphere { 0, 1 pigment { rgb <0.4, 0.2, 0.1> } finish { specular 0.4 roughness 0 } }
sphere { <1.6,0,1>, 0.6 pigment { rgb <0.1, 0.2, 0.4> } finish { specular albedo 0.4 roughness 0 } }
plane { y, -1 pigment { checker rgb 1 rgb 0.5 } }
