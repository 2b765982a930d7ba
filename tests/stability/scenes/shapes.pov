// SPDX-License-Identifier: MIT
// shapes.pov: analytic shapes with degenerate or extreme parameters,
// solved by src/geometry. KIND picks the set: 0 degenerate sizes (zero
// and negative radii, zero-length cylinders and cones, inverted boxes:
// POV-Ray refuses some of them, iris skips them with a warning), 1 stiff polynomials (a torus whose minor
// radius exceeds the major one, a torus 1e-4 thin, a quartic with
// coefficients 1e8 apart, a blob with threshold 0), 2 extreme exponents
// (superellipsoids with e, n = 1e-3 and 20, an isosurface with a tiny
// max_gradient, a lathe and a prism with repeated points).
#version 3.7;
#ifndef (KIND) #declare KIND = 0; #end
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
