// Transparent boxes standing exactly on the floor plane: a filter box
// (no ior) and a rotated glass box (ior 1.3, as lights/shadows.pov's gold
// box), both with their bottom face at y = 0 on 'plane { y, 0 }'. An eye
// ray inside a box meets its bottom face and the floor at the same
// distance, bit for bit (the boxes are only turned about y and moved).
// POV-Ray's bounding tree tests unbounded objects (the plane) before
// every finite one and replaces a hit only by a strictly nearer one, so
// the tie goes to the floor, which is then seen (filtered, refracted)
// through the box. iris tested the plane last, kept the box's face, and
// the ray leaving it started on the floor and passed through it, so the
// floor under both boxes was black: 19.4 dB before the fix in
// accel_intersect (src/accel/accel.c), 54.5 dB after. (A cylinder is
// left out: POV-Ray computes its cap's distance in a scaled space, so
// its tie with the floor falls either way, pixel by pixel.)
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 5 }
camera { location <0, 9, -11> look_at <0, 0.5, 0> angle 50 }
light_source { <-10, 20, -10> color rgb 1 }
plane { y, 0
    pigment { checker rgb <0.86, 0.58, 0.44> rgb <0.3, 0.4, 0.6> scale 1.5 }
    finish { ambient 0.12 diffuse 0.8 } }
box { <-2, 0, -2>, <2, 3, 2>
    pigment { rgb <0.8, 0.5, 0.2> filter 0.9 }
    finish { ambient 0.1 diffuse 0.7 phong 1 phong_size 50 }
    translate <-3, 0, 0> }
box { <-1.5, -1, -1.5>, <1.5, 1, 1.5>
    pigment { rgbf <0.7, 0.9, 1.0, 0.9> }
    finish { ambient 0.05 diffuse 0.3 phong 1 phong_size 80 }
    interior { ior 1.3 }
    rotate -40*y translate <3, 1, 0.5> }
