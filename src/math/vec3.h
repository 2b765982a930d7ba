/* SPDX-License-Identifier: MIT */
/*
** vec3.h: 3-vectors in double precision, as small inline functions.
**
** The type is iris_vec3 from scene.h, so scene data and core maths share
** it without conversion.
*/
#ifndef IRIS_MATH_VEC3_H
#define IRIS_MATH_VEC3_H

#include <math.h>

#include "iris/scene.h"

typedef iris_vec3 vec3;

static inline vec3 v3(double x, double y, double z)
{
    vec3 r = { x, y, z };
    return r;
}
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 v3_scale(vec3 a, double s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
static inline double v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
    return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double v3_len2(vec3 a) { return v3_dot(a, a); }
static inline double v3_len(vec3 a) { return sqrt(v3_dot(a, a)); }
/* Returns 'a' scaled to unit length, or 'a' itself when it has none. */
static inline vec3 v3_norm(vec3 a)
{
    double l = v3_len(a);
    return l > 0 ? v3_scale(a, 1.0 / l) : a;
}
/* a + b*s */
static inline vec3 v3_madd(vec3 a, vec3 b, double s)
{
    return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}
static inline vec3 v3_lerp(vec3 a, vec3 b, double t)
{
    return v3(a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
}
static inline double v3_max_comp(vec3 a)
{
    return fmax(a.x, fmax(a.y, a.z));
}
static inline vec3 v3_min(vec3 a, vec3 b) { return v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z)); }
static inline vec3 v3_max(vec3 a, vec3 b) { return v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z)); }
static inline double v3_comp(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }

/* Mirror reflection of incident 'i' about unit normal 'n'. */
static inline vec3 v3_reflect(vec3 i, vec3 n)
{
    return v3_madd(i, n, -2.0 * v3_dot(i, n));
}

/* An orthonormal basis around unit 'n' (Duff et al. 2017). */
static inline void v3_basis(vec3 n, vec3 *t, vec3 *b)
{
    double sign = copysign(1.0, n.z);
    double a = -1.0 / (sign + n.z);
    double c = n.x * n.y * a;
    *t = v3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    *b = v3(c, sign + n.y * n.y * a, -n.y);
}

#endif
