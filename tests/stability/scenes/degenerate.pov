// SPDX-License-Identifier: MIT
// degenerate.pov: triangles with no area (a point, a line, a repeated
// vertex), a smooth triangle with zero normals, and one good triangle so
// that the mesh is not empty. Only the good one may be seen.
#version 3.7;
#include "stage.inc"

mesh {
    triangle { <0, 1, 0>, <0, 1, 0>, <0, 1, 0> }
    triangle { <-1, 0.5, 0>, <0, 1, 0>, <1, 1.5, 0> }
    triangle { <-1, 0.5, 0>, <-1, 0.5, 0>, <1, 1.5, 0> }
    smooth_triangle { <-1, 0.2, 0>, <0, 0, 0>, <1, 0.2, 0>, <0, 0, 0>,
                      <0, 1.2, 0>, <0, 0, 0> }
    triangle { <0.5, 0.2, -0.5>, <1.5, 0.2, -0.5>, <1, 1.2, -0.5> }
    pigment { rgb 1 } finish { Matte }
}
triangle { <-1, 1, -1>, <-1, 1, -1>, <-1, 1, -1> pigment { rgb 1 } finish { Matte } }
smooth_triangle { <-1.5, 0.2, -1>, <0, 0, 0>, <-0.5, 0.2, -1>, <0, 0, 0>,
                  <-1, 1.2, -1>, <0, 0, 0> pigment { rgb 1 } finish { Matte } }
