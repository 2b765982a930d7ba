// Parity scene: antialiasing method 2 (POV-Ray's AdaptiveSupersamplingM2)
// on features a fraction of a pixel wide: eight rods 0.1 to 0.9 pixel
// thick, a checkered sphere and stripes on the floor, subdivided down to
// 1/16 pixel with jitter. It pins the corner grid (every pixel's four
// corners at x -/+ 0.5, y -/+ 0.5, shared with the neighbours), the
// per-pixel subdivision buffer (edge mid-samples traced again for each
// pixel), the ">= threshold" test over the six corner pairs and the
// jitter scale 1 / (2^R + 1). iris and POV-Ray give identical 8-bit PNGs
// here; one step off gives (iris changed, POV-Ray as below): +R3 36.6 dB,
// -J 39.4, +A0.3 43.9, method 1 28.8, hence the bar of 50.
// The camera and the objects avoid exact symmetry on purpose: for an
// even image size the corner grid holds the rays x0 = 0 and y0 = 0
// (image column w/2 - 0.5), which in incdemo/chars, objects/bezier and
// qtvr/qtvrpanorama graze edges exactly, where the last bit of the hit
// decides (docs/parity.md section 4, "+AM2 thin lines").
// parity-min-psnr: 50 identical; one option step off gives 43.9 or less
// parity-options: +A0.2 +AM2 +R4 +J
#version 3.7;
global_settings { assumed_gamma 1 }
background { rgb <0.05, 0.07, 0.1> }
camera { location <0.137, 1.213, -5.071> look_at <0.0213, 0.4917, 0.0371>
  angle 47 }
light_source { <-3.1, 5.3, -4.2> rgb 1 }
#for (I, 0, 7)
  cylinder { <-2.03 + 0.57 * I, -0.1, 0.31>, <-1.71 + 0.57 * I, 2.1, 0.47>,
             0.004 + 0.003 * I pigment { rgb <1, 0.85, 0.3> } }
#end
sphere { <0.61, 0.83, 1.37>, 0.71
  pigment { checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale 0.137 }
  finish { phong 0.8 }
}
plane { y, 0
  pigment { gradient x color_map { [0.5 rgb 0.9] [0.5 rgb <0.1, 0.3, 0.6>] }
            scale 0.173 rotate y * 23.7 }
}
