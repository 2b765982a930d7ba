// SPDX-License-Identifier: MIT
// 92_julia_hypercomplex.pov: julia_fractal in the hypercomplex algebra
// (src/geometry/julia.c, julia_hcx.c): sqr with objects/fractal4's
// parameter, cube (which POV-Ray 3.7 iterates as z², like sqr) and sqr
// through a slice that is not the w = 0 hyperplane. The old iris skipped
// hypercomplex julia_fractal with a warning: 23.7 dB.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -9> look_at <0, 0, 0> angle 40 }
light_source { <-4, 6, -8> color rgb 1 }
background { rgb <0.2, 0.25, 0.3> }
#declare F = finish { ambient 0.1 diffuse 0.8 phong 0.4 phong_size 30 }
julia_fractal {
    <-0.745, 0, 0.113, 0.05> hypercomplex sqr
    max_iteration 9 precision 20
    pigment { rgb <0.9, 0.5, 0.6> } finish { F }
    scale <0.8, 1.6, 0.8> rotate <135, -30, 0> translate <-1.7, 0.3, 0>
}
julia_fractal {
    <-0.2, 0.6, 0.2, -0.1> hypercomplex cube
    max_iteration 8 precision 30
    pigment { rgb <0.5, 0.8, 0.5> } finish { F }
    rotate <30, 20, 0> translate <1.6, 1, 0>
}
julia_fractal {
    <0.3, -0.4, 0.1, 0.2> hypercomplex sqr
    slice <0.2, 0.1, -0.3, 1>, 0.1
    max_iteration 8 precision 30
    pigment { rgb <0.5, 0.6, 0.9> } finish { F }
    rotate <-40, 30, 0> translate <1.6, -1.3, 0>
}
