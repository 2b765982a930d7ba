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
};

#endif
