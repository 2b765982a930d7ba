/* SPDX-License-Identifier: MIT */
/*
** transform.h: affine transforms (iris_transform from scene.h).
**
** POV-Ray composes transforms left to right as written: 'scale 2
** translate x' scales first. xf_compose(a, b) is "a, then b".
*/
#ifndef IRIS_MATH_TRANSFORM_H
#define IRIS_MATH_TRANSFORM_H

#include <stdbool.h>

#include "iris/scene.h"
#include "math/vec3.h"

typedef iris_transform xform;

void xf_identity(xform *t);
void xf_translate(xform *t, vec3 v);
/* Returns false (and sets identity) when a factor is 0: POV-Ray warns and
** uses 1 for that axis, and so must the caller. */
void xf_scale(xform *t, vec3 v);
/* Rotation by the angles in degrees about x, then y, then z (POV-Ray). */
void xf_rotate(xform *t, vec3 degrees);
/* Rotation by 'degrees' about unit 'axis'. */
void xf_axis_rotate(xform *t, vec3 axis, double degrees);
/* 'matrix <...12 values...>' as POV-Ray reads it (row vectors). Returns
** false when the matrix is singular. */
bool xf_matrix(xform *t, const double v[12]);
/* The inverse transform. */
void xf_inverse(xform *out, const xform *t);
/* out = a then b. 'out' may alias either. */
void xf_compose(xform *out, const xform *a, const xform *b);

vec3 xf_point(const xform *t, vec3 p);
vec3 xf_dir(const xform *t, vec3 d);
vec3 xf_inv_point(const xform *t, vec3 p);
vec3 xf_inv_dir(const xform *t, vec3 d);
/* Transforms a surface normal from local to world (not normalised). */
vec3 xf_normal(const xform *t, vec3 n);

/*
** The frame POV-Ray gives an axis along unit 'd' (its
** Compute_Coordinate_Transform, for cylinders, cones and a blob's
** cylinder components): x, y and z turned about z x d by the angle
** between z and d, so that e[2] = d; along -z a half turn about x.
*/
void xf_axis_frame(vec3 d, vec3 e[3]);

#endif
