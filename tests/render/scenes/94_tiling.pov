// The tiling pattern, all 27 types of POV-Ray 3.7's TilingPattern (iris's
// src/material/tiling.c and penrose.c), each on one square of a 7x4 board
// seen from above. The colour_map runs smoothly through [0, 1] so that
// every tile's distance-to-centre ramp is compared, not only which band a
// point falls in; the steps at the band boundaries are tile edges, which
// both renderers antialias. Each board is moved by its own offset so that
// the folds of the pattern's cells are not all in one place. Before
// tiling.c iris evaluated every tiling as 0: PSNR 8.9 dB (now identical
// at 80x60, 107 dB at 480x360).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { orthographic location <0, 10, 0> look_at <0, 0, 0>
         right x*12 up z*9 }
light_source { <0, 50, 0> color rgb 1 }
#declare Ramp = color_map {
    [0.0 rgb <0.9, 0.1, 0.1>] [0.3 rgb <0.9, 0.9, 0.2>]
    [0.5 rgb <0.1, 0.7, 0.2>] [0.7 rgb <0.2, 0.6, 0.9>]
    [1.0 rgb <0.1, 0.1, 0.4>]
}
#declare F = finish { ambient 0.2 diffuse 0.8 }
plane { y, 0 pigment { rgb 0.5 } finish { F } }
#declare I = 0;
#while (I < 27)
    #declare T = I + 1;
    box { <-0.82, 0, -1.07>, <0.82, 0.1, 1.07>
        pigment { tiling T color_map { Ramp } scale 0.3
                  translate <0.13 * T, 0, 0.07 * T> }
        finish { F }
        translate <(mod(I, 7) - 3) * 12 / 7, 0, (1.5 - div(I, 7)) * 2.25> }
    #declare I = I + 1;
#end
