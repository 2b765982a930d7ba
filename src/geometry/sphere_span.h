/* SPDX-License-Identifier: MIT */
/*
** sphere_span.h: where a ray o + t·d meets a sphere, as the centre of the
** chord tc and its half-length h (the crossings are tc - h and tc + h).
**
** Shared by geom_sphere_hits() (quadrics.c), the accelerator's own sphere
** paths (accel/node.c) and the photon fast path (photon/fastpath.c),
** which must all find the same t to the last bit.
**
** For a unit direction (|d|² within 1e-9 of 1: every camera and reflected
** ray) from within 1e4 radii of the centre, the arithmetic is POV-Ray's
** (Sphere::Intersect): h² = r² - |c - o|² + tc², tc = (c - o)·d, with no
** division by |d|², and its grazing miss (below). That is the rounding
** POV-Ray's images carry: a pattern that changes at the surface itself
** (onion at radius 1 on a unit sphere, textures/pigments/cantelop.pov)
** takes one side or the other by the sign of that rounding, and a ray
** refracted through glass lands on one side or the other of a checker
** edge (interior/atten1.pov), so only the same sums give the same pixels
** (tests/render/scenes/247_sphere_surface_pattern.pov,
** 248_sphere_rim_orthographic.pov). The subtraction loses about
** |c - o|²/r² ulps of h², at most 1e8 ulps (2e-8 r²) there.
** Farther origins, other directions (transformed rays, unnormalised
** shadow rays) keep the closest-approach form (Haines et al., Ray Tracing
** Gems ch. 7), which keeps full precision for rays starting far away.
*/
#ifndef IRIS_GEOMETRY_SPHERE_SPAN_H
#define IRIS_GEOMETRY_SPHERE_SPAN_H

#include <math.h>
#include <stdbool.h>

#include "iris/scene.h"
#include "math/transform.h"
#include "math/vec3.h"

/* False on a miss (or a zero direction); 'oc' is o - c, 'a' is |d|². */
static inline bool sphere_span(vec3 oc, vec3 d, double a, double rad,
                               double *tc, double *h)
{
    if (!(a > 0))
        return false;
    double h2, oc2 = v3_len2(oc), r2 = rad * rad;
    if (fabs(a - 1.0) < 1e-9 && oc2 <= 1e8 * r2) {
        vec3 co = v3_scale(oc, -1.0);
        *tc = v3_dot(co, d);
        h2 = r2 - oc2 + *tc * *tc;
        /* POV-Ray's grazing test: a half chord up to 1e-5 (h² <= EPSILON
        ** = 1e-10) is a miss; relative to r² below radius 1, so that
        ** spheres smaller than that, never hit in POV-Ray, stay visible */
        if (!(h2 > 1e-10 * fmin(1.0, r2)))
            return false;
    } else {
        *tc = -v3_dot(oc, d) / a;
        vec3 pc = v3_madd(oc, d, *tc);
        h2 = (r2 - v3_len2(pc)) / a;
    }
    if (!(h2 >= 0))
        return false;
    *h = sqrt(h2);
    return true;
}

/*
** Whether sphere 'o' is moved only by rotations, translations and uniform
** scales (its transform's columns orthogonal and of one length, to
** 1e-12), and then its world centre and radius. POV-Ray applies such
** moves to the centre and radius (Sphere::Translate, Rotate, Scale) and
** solves in world space; solving in object space rounds the crossing
** differently. accel (node.c) and the photon fast path
** (photon/fastpath.c) both solve such a sphere as an untransformed one at
** *wc, radius *wr. False for other objects, for bounded_by (whose box
** cuts the shape in object space) and for a radius that is not positive
** (its normals point inwards in object space).
*/
static inline bool sphere_world_frame(const iris_object *o, vec3 *wc,
                                      double *wr)
{
    if (!o || o->kind != IRIS_OBJ_SPHERE || !o->has_transform ||
        o->bounded_by || !(o->u.sphere.radius > 0))
        return false;
    const double (*m)[4] = o->transform.m;
    vec3 c0 = v3(m[0][0], m[1][0], m[2][0]);
    vec3 c1 = v3(m[0][1], m[1][1], m[2][1]);
    vec3 c2 = v3(m[0][2], m[1][2], m[2][2]);
    double l0 = v3_len2(c0), tol = 1e-12 * l0;
    if (!(l0 > 0) || !(fabs(v3_len2(c1) - l0) <= tol) ||
        !(fabs(v3_len2(c2) - l0) <= tol) || !(fabs(v3_dot(c0, c1)) <= tol) ||
        !(fabs(v3_dot(c0, c2)) <= tol) || !(fabs(v3_dot(c1, c2)) <= tol))
        return false;
    vec3 c = xf_point(&o->transform, o->u.sphere.centre);
    double r = sqrt(l0) * o->u.sphere.radius;
    if (!isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z) || !(r > 0) ||
        !isfinite(r))
        return false;
    *wc = c;
    *wr = r;
    return true;
}

#endif
