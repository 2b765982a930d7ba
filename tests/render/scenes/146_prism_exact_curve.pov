// Parity scene: a prism's wall (linear_sweep) follows its exact spline,
// as POV-Ray intersects it (prism.cpp: a cubic in the spline parameter
// per segment), and its caps and inside test read the same curve. The
// camera looks closely at the top edge of a cubic_spline prism, where
// the cap meets the curved wall. iris once flattened each segment to 16
// chords, up to 5e-4 of the segment's size inside the curve (31.4 dB here,
// identical with the fix; objects/prism3b 45.7 -> 126.9 and prism3c 41.9 ->
// 128.9 dB at 160x120). Conic sweeps are still flattened.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -6> look_at <0.0, 1, -1.9> right x*4/3 angle 3 }
light_source { <-30, 40, -60> color rgb 1 }
background { rgb <0.2, 0.3, 0.6> }
prism {
  cubic_spline
  0, 1, 8,
  <2, 0>, <0, -2>, <-2, 0>, <0, 2>, <2, 0>, <0, -2>, <-2, 0>, <0, 2>
  pigment { checker rgb <1, 0.9, 0.5>, rgb <0.2, 0.5, 0.2> scale 0.02 }
  finish { diffuse 0.8 phong 0.5 phong_size 40 }
}
