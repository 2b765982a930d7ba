// SPDX-License-Identifier: MIT
// shapes.pov: analytic shapes with degenerate or extreme parameters,
// solved by src/geometry. KIND picks the set: 0 degenerate sizes (zero
// and negative radii, zero-length cylinders and cones, inverted boxes:
// POV-Ray refuses some of them, iris skips them with a warning), 1 stiff polynomials (a torus whose minor
// radius exceeds the major one, a torus 1e-4 thin, a quartic with
// coefficients 1e8 apart, a blob with threshold 0), 2 extreme exponents
// (superellipsoids with e, n = 1e-3 and 20, an isosurface with a tiny
// max_gradient, a lathe and a prism with repeated points), 3 extreme
// transforms (scales of 1e-7 to 1e-12 on one axis, a nearly singular
// shear, objects moved 1e8 away and back), 4 work without end (a julia
// fractal with max_iteration 1e6 and precision 1e9, an isosurface of a
// function oscillating 1000 times per unit with max_gradient 1e9 and
// accuracy 1e-12, a blob of 2000 components in a row along the view):
// src/geometry caps or sorts the work per ray.
#version 3.7;
#ifndef (KIND) #declare KIND = 0; #end
// JITER: the julia fractal's max_iteration in KIND 4 (1e9: every inside
// point ran all of them before the per-ray budget was checked; minutes
// per ray until julia.c capped it at the budget, 1e6)
#ifndef (JITER) #declare JITER = 1000000; #end
#include "stage.inc"
#declare T = texture { pigment { rgb 1 } finish { Matte } }

#switch (KIND)
#case (0)
    sphere { <-1, 0.5, 0>, 0 texture { T } }
    sphere { <-1, 0.5, 0>, -0.3 texture { T } }
    cylinder { <0, 0.5, 0>, <0, 0.5, 0>, 0.3 texture { T } }
    cylinder { <0, 0.2, 0>, <0, 0.8, 0>, 0 texture { T } }
    cone { <1, 0.2, 0>, 0.3, <1, 0.2, 0>, 0.1 texture { T } }
    cone { <1, 0.2, 0>, 0, <1, 0.9, 0>, 0 texture { T } }
    box { <0.5, 1, 0.5>, <-0.5, 1.2, -0.5> texture { T } }
    box { <-1.5, 0, 0>, <-1.5, 1, 1> texture { T } }
    disc { <0, 1.5, 0>, <0, 0, 0>, 0.3 texture { T } }
    disc { <0, 1.5, 0>, -z, 0 texture { T } }
    torus { 0, 0 translate <1, 1.5, 0> texture { T } }
#break
#case (1)
    torus { 0.3, 0.5 translate <-1, 0.5, 0> texture { T } }
    torus { 0.5, 1e-4 rotate x * 90 translate <0, 0.7, 0> texture { T } }
    torus { 1e-6, 1e-6 translate <0, 0.2, -1> texture { T } }
    quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -2.0000001e8, 0, 0, 0, 0, 0, 0, 0,
               0, 0, 0, 1, 0, 0, 2, 0, 0.9e8, 0, 0, 0, 0, 0, 0, 0, 0, 1e8>
              sturm scale 0.3 translate <1, 0.7, 0> texture { T } }
    blob { threshold 0 sphere { 0, 0.4, 1 } sphere { x * 0.3, 0.4, 1 }
           translate <1, 0.5, -1> texture { T } }
    blob { threshold 1e-12 sphere { 0, 0.4, -1 } sphere { x * 0.3, 0.4, 1 }
           translate <-1, 1.2, -1> texture { T } }
#break
#case (3)
    sphere { 0, 1 scale <1e-7, 0.5, 0.5> translate <-1.2, 0.6, 0> texture { T } }
    box { -0.5, 0.5 matrix <1, 0, 0, 0, 1, 0, 0, 0, 1e-12, 0, 0, 0>
          translate <-0.3, 0.6, 0> texture { T } }
    torus { 0.4, 0.1 scale <1, 1e-9, 1> translate <0.5, 0.5, 0> texture { T } }
    sphere { 0, 0.3 matrix <1, 0, 0, 0.999999, 1e-6, 0, 0, 0, 1, 0, 0, 0>
             translate <1.3, 0.5, 0> texture { T } }
    cylinder { 0, y, 0.2 scale 1e-6 translate 1e6 * x translate -1e6 * x
               translate <0, 1.2, -0.5> texture { T } }
    union { sphere { 0, 0.2 } box { -0.15, 0.15 } texture { T }
            translate <1e8, 0, 0> translate <-1e8, 1.3, 0> }
    blob { threshold 0.5 sphere { 0, 0.3, 1 } scale <1, 1e-6, 1>
           translate <0, 1.6, 0> texture { T } }
#break
#case (4)
    julia_fractal {
        <-0.083, 0.0, -0.83, -0.025> quaternion sqr
        max_iteration JITER precision 1e9
        scale 0.5 translate <-0.6, 0.7, 0> texture { T }
    }
    isosurface {
        function { sin(x * 1000) * sin(y * 1000) * sin(z * 1000) - 0.1 }
        max_gradient 1e9 accuracy 1e-12
        contained_by { box { -0.4, 0.4 } }
        translate <0.7, 0.5, 0> texture { T }
    }
    // 2000 components in a row along the view: a ray meets all of them
    blob {
        threshold 0.5
        #for (I, 0, 1999)
            sphere { <0, 0, I * 0.0025>, 0.08, 1 }
        #end
        translate <0, 1.3, -1> texture { T }
    }
#break
#else
    superellipsoid { <1e-3, 1e-3> scale 0.3 translate <-1, 0.4, 0> texture { T } }
    superellipsoid { <20, 20> scale 0.3 translate <-0.3, 0.4, 0> texture { T } }
    superellipsoid { <0, 0> scale 0.3 translate <0.4, 0.4, 0> texture { T } }
    isosurface {
        function { x * x + y * y + z * z - 0.09 }
        max_gradient 1e-6 accuracy 1e-9
        contained_by { box { -0.4, 0.4 } }
        translate <1.1, 0.5, 0> texture { T }
    }
    lathe { linear_spline 5, <0, 0>, <0.3, 0>, <0.3, 0>, <0.3, 0.5>, <0, 0.5>
            translate <-1, 1.1, -0.5> texture { T } }
    prism { linear_sweep linear_spline 0, 0.3, 5,
            <0, 0>, <0.3, 0>, <0.3, 0>, <0.3, 0.3>, <0, 0>
            translate <0.5, 1.1, -0.5> texture { T } }
    prism { 0.2, 0.2, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> texture { T } }
    sphere_sweep { linear_spline 3, <0, 0, 0>, 0.1, <0, 0, 0>, 0.1,
                   <0.5, 0, 0>, 0 translate <0, 1.4, -1> texture { T } }
#end
