/* SPDX-License-Identifier: MIT */
/*
** render_double.c: exact sphere and plane intersection for the tracer's
** unit tests (see render_double.h).
*/
#include "config.h"

#include <math.h>

#include "render_double.h"

#include <string.h>

#include "render/trace.h"

static bool skipped(const iris_object *o, unsigned skip)
{
    return ((skip & ACCEL_SKIP_NO_IMAGE) && o->no_image) ||
           ((skip & ACCEL_SKIP_NO_SHADOW) && o->no_shadow) ||
           ((skip & ACCEL_SKIP_NO_REFLECTION) && o->no_reflection);
}

/* The nearest root of the object in (tmin, tmax), or -1. */
static double hit_object(const iris_object *o, const ray *r, double tmin,
                         double tmax, vec3 *n)
{
    if (o->kind == IRIS_OBJ_SPHERE) {
        vec3 oc = v3_sub(r->o, o->u.sphere.centre);
        double b = v3_dot(oc, r->d);
        double c = v3_dot(oc, oc) - o->u.sphere.radius * o->u.sphere.radius;
        double disc = b * b - c;
        if (disc < 0)
            return -1;
        double s = sqrt(disc);
        double t = -b - s;
        if (!(t > tmin))
            t = -b + s;
        if (!(t > tmin) || !(t < tmax))
            return -1;
        *n = v3_norm(v3_sub(v3_madd(r->o, r->d, t), o->u.sphere.centre));
        return t;
    }
    if (o->kind == IRIS_OBJ_PLANE) {
        vec3 pn = v3_norm(o->u.plane.normal);
        double den = v3_dot(pn, r->d);
        if (fabs(den) < 1e-15)
            return -1;
        double t = (o->u.plane.distance - v3_dot(pn, r->o)) / den;
        if (!(t > tmin) || !(t < tmax))
            return -1;
        *n = pn;
        return t;
    }
    return -1;
}

static bool dbl_intersect(const void *impl, const ray *r, double tmin,
                          double tmax, unsigned skip, struct hit *h)
{
    const struct dbl_scene *d = impl;
    bool found = false;
    for (int i = 0; i < d->n; i++) {
        const iris_object *o = d->objs[i];
        if (skipped(o, skip))
            continue;
        vec3 n;
        double t = hit_object(o, r, tmin, tmax, &n);
        if (t < 0)
            continue;
        tmax = t;
        found = true;
        h->t = t;
        h->p = v3_madd(r->o, r->d, t);
        h->n = o->inverse ? v3_neg(n) : n;
        h->shading_n = h->n;
        h->uv.u = h->uv.v = 0;
        h->obj = h->top = o;
        h->texture = o->texture;
        h->interior = o->interior;
        h->eps = 1e-6; /* the double's accel epsilon (dbl_query) */
    }
    return found;
}

static bool dbl_inside(const void *impl, const iris_object *o, vec3 p)
{
    (void)impl;
    bool in = false;
    if (o->kind == IRIS_OBJ_SPHERE)
        in = v3_len(v3_sub(p, o->u.sphere.centre)) < o->u.sphere.radius;
    else if (o->kind == IRIS_OBJ_PLANE)
        in = v3_dot(v3_norm(o->u.plane.normal), p) < o->u.plane.distance;
    return o->inverse ? !in : in;
}

void dbl_query(const struct dbl_scene *d, struct rquery *q)
{
    q->impl = d;
    q->intersect = dbl_intersect;
    q->inside = dbl_inside;
    q->eps = 1e-6;
    q->inside_bounds = NULL;
    q->prim_hit = NULL;
    q->intersect_prim = NULL;
}

void dbl_shoot(const struct tracer *t, struct trace_ctx *c, vec3 o, vec3 d,
               double rgb[3])
{
    struct tray r;
    memset(&r, 0, sizeof r);
    r.r.o = o;
    r.r.d = v3_norm(d);
    trace_containing(t, o, &r.st);
    c->level = 0;
    trace_ray(c, &r, 1.0, false, rgb);
}
