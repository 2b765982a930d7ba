/* SPDX-License-Identifier: MIT */
/*
** query.h: how the tracer asks the scene about rays.
**
** The tracer calls the scene through this small table so that its unit
** tests can run against a scene double (a sphere and a plane with exact
** answers) while the real render uses src/accel (Embree). render.c fills
** it from an accel; nothing else in src/render knows which one it is.
*/
#ifndef IRIS_RENDER_QUERY_H
#define IRIS_RENDER_QUERY_H

#include <stdbool.h>

#include "accel/accel.h"

struct rquery {
    const void *impl;
    bool (*intersect)(const void *impl, const ray *r, double tmin,
                      double tmax, unsigned skip, struct hit *h);
    bool (*inside)(const void *impl, const iris_object *obj, vec3 p);
    double eps;                /* offset for secondary rays (accel_epsilon) */
    /* A world box holding every point inside 'obj'; false when there is
    ** none (unbounded, or not known). May be NULL. */
    bool (*inside_bounds)(const void *impl, const iris_object *obj,
                          vec3 *lo, vec3 *hi);
    /* The test of one primitive, a hit's 'prim' (accel_prim_hit): true
    ** when it has a crossing in (tmin, tmax), its t in '*t'; 'intersect'
    ** with the same arguments then hits something at or before *t. May
    ** be NULL (no shadow cache: trace.c point_shadow), and then so is
    ** intersect_prim. */
    bool (*prim_hit)(const void *impl, const void *prim, const ray *r,
                     double tmin, double tmax, unsigned skip, double *t);
    /* 'intersect' that also sets the hit's 'prim' (accel_intersect_prim);
    ** set together with prim_hit */
    bool (*intersect_prim)(const void *impl, const ray *r, double tmin,
                           double tmax, unsigned skip, struct hit *h);
};

#endif
