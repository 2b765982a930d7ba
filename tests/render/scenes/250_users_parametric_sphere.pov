// SPDX-License-Identifier: MIT
// A parametric surface cut by a sphere container: POV-Ray's
// Parse_Parametric takes 'contained_by { sphere { C, R } }' as well as a
// box, and the intersection searches only the ray's chord through the
// sphere. The sheet is wider than the sphere, so its rim shows the
// sphere's outline (a box container would show a square one). Before
// session 11 iris refused the sphere ("expected box").
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 3, -4> look_at <0, 0, 0> angle 45 }
light_source { <-3, 6, -5> rgb 1 }
background { rgb <0.2, 0.3, 0.4> }
parametric {
    function { u }
    function { 0.3 * sin(2 * u) * cos(2 * v) }
    function { v }
    <-2, -2>, <2, 2>
    contained_by { sphere { <0.2, 0, 0.1>, 1.4 } }
    max_gradient 2
    accuracy 0.002
    pigment { checker rgb <1, 0.8, 0.3> rgb <0.3, 0.5, 1> scale 0.25 }
    finish { ambient 0.2 diffuse 0.8 }
}
