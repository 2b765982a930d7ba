// Parity scene: a lathe's surface is its exact spline, as POV-Ray
// intersects it (lathe.cpp: each segment's polynomial solved for the
// ray: a polynomial of degree 6 in the spline parameter). The camera
// looks closely at the silhouette of a bezier bulge. iris once flattened
// each segment to 16 chords, which lie up to 5e-4 of the segment's size
// inside the curve: the silhouette became a polygon, and trace() on a
// lathe returned radii 0.25 % short (21.6 dB here, 58.5 with the fix;
// language/trace-wicker 34.1 dB -> identical, objects/lathe1b, lathe1c,
// lathe2 43-49 dB -> identical, at 160x120).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <2.12, 1.0, -12> look_at <2.12, 1.0, 0> right x*4/3 angle 1.2 }
light_source { <-30, 40, -60> color rgb 1 }
background { rgb <0.2, 0.3, 0.6> }
lathe {
  bezier_spline 4,
  <1, 0>, <2.6, 0.7>, <2.6, 1.3>, <1, 2>
  pigment { checker rgb <1, 0.9, 0.5>, rgb <0.7, 0.2, 0.1> scale 0.02 }
  finish { diffuse 0.8 phong 0.5 phong_size 40 }
}
