// Parity scene: the normal of a quaternion julia_fractal as POV-Ray
// computes it (quatern.cpp CalcNormal): the gradient of |q_n|^2 through
// the Jacobian of all max_iteration steps, taken at the inside end of the
// crossing, the Jacobian starting at the identity on x, y, z (the
// slice's dependence of w on x, y, z left out: the right fractal has a
// tilted slice, where that matters). iris once took the gradient at the
// outside end up to the escaping step (30.4 dB here, 44.5 with the fix;
// objects/fractal1 31.4 -> 56.2 dB and fractal3 31.4 -> 39.8 dB at
// 160x120). sqr on the left, cube on the right; the rest of the
// difference is scattered pixels where the fold is steep.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -4.2> look_at <0, 0, 0> right x*4/3 angle 45 }
light_source { <-20, 30, -100> color rgb <1, 0.55, 0.45> }
light_source { <200, 300, -500> color rgb <0.95, 0.85, 0.7> }
#default { pigment { rgb 1 } finish { ambient 0 diffuse 0.9 phong 0.6 phong_size 60 } }
julia_fractal {
  <-0.083, 0.0, -0.83, -0.025>
  quaternion sqr
  max_iteration 8
  precision 15
  scale 1.3 translate <-1.35, 0, 0>
}
julia_fractal {
  <-0.03, 0.5, -0.2, -0.5>
  quaternion cube
  max_iteration 8
  precision 15
  slice <0.3, 0.2, 0.1, 1>, 0.1
  rotate y*90
  scale 1.6 translate <1.35, 0, 0>
}
