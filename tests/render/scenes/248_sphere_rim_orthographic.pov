// SPDX-License-Identifier: MIT
// 248_sphere_rim_orthographic.pov: glass spheres under an orthographic
// camera whose pixel centres fall exactly on their rims and on the
// checker's edges behind them, as interior/atten1.pov. POV-Ray's sphere
// misses a ray whose half chord squared is at most 1e-10
// (Sphere::Intersect's EPSILON), so the rim pixels see the floor; iris
// hit them at a zero-length chord and refracted into black. Every other
// pixel's refracted ray lands on one side of a checker edge or the other
// by the last bits of the crossing, which POV-Ray's own sums fix
// (geometry/sphere_span.h). Without antialiasing (its jitter would move
// the samples off the rims): 80x60 -A 28.1 dB before (e9905d9),
// identical after.
// parity-options: -A
#version 3.7;
global_settings { assumed_gamma 1 }
// one unit a pixel: centres at x = i - 39.5, y = 29.5 - j
camera { orthographic location <0, 0, -100> right 80*x up 60*y
         look_at <0, 0, 0> }
light_source { <-100, 100, -200> color rgb 1 }
plane { -z, -20 pigment { checker color rgb <1, 1, 0> color rgb <0, 1, 0>
                          scale 4 }
        finish { ambient 0.2 diffuse 0.8 } }
// radius 5 about a pixel centre: the rim passes through twelve centres
#macro Glass(C, P)
  sphere { C, 5
    pigment { rgbt <1, 1, 1, 0.9> }
    finish { ambient 0 diffuse 0 phong 1 phong_size 200 }
    interior { ior 1.05 fade_distance 20 fade_power P }
  }
#end
Glass(<-19.5, 10.5, 0>, 0)
Glass(<0.5, 10.5, 0>, 1)
Glass(<20.5, 10.5, 0>, 2)
Glass(<-19.5, -9.5, 0>, 3)
Glass(<0.5, -9.5, 0>, 1001)
Glass(<20.5, -9.5, 0>, 3)
