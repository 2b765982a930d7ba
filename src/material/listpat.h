/* SPDX-License-Identifier: MIT */
/*
** listpat.h: POV-Ray 3.7's square, triangular and cubic list patterns.
*/
#ifndef IRIS_MATERIAL_LISTPAT_H
#define IRIS_MATERIAL_LISTPAT_H
#include "math/vec3.h"

/* 'square A, B, C, D': the unit squares of the x-z plane take entry 0,
** 1, 2 or 3 by the parity of their floor(x) and floor(z). Returns 0..3. */
double pattern_square(vec3 p);

/* 'triangular A .. F': unit equilateral triangles in the x-z plane, six
** entries meeting around every vertex of the lattice (one vertex at the
** origin). Returns 0..5. */
double pattern_triangular(vec3 p);

/* 'cubic A .. F': the six pyramids from the origin through the faces of
** a cube, in the order +x, +y, +z, -x, -y, -z. Returns 0..5. */
double pattern_cubic(vec3 p);
#endif
