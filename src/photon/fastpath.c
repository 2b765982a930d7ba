/* SPDX-License-Identifier: MIT */
/*
** fastpath.c: the photon tracer's ray query for a scene of a few spheres
** and planes (fastpath.h).
**
** WHY. A caustic scene is often a glass ball over a floor. accel answers
** such a scene with a linear scan too (accel.c, LINEAR_MAX), but each of
** the 3-4 queries of a photon also paid for the general query: finiteness
** and box tests, the dispatch through anode, the texture fallbacks, and
** the sphere's uv (atan2 and asin: a tenth of the photon pass, for a value
** no material code reads when the texture is one colour). Here the primitives sit in one flat array and
** the query is the arithmetic alone.
**
** SAME ANSWER. The sphere and plane solves are accel's (node.c
** sphere_nearest, plane_nearest) expression for expression, the
** primitives are scanned in accel's order (bounded ones in scene order,
** then the unbounded, the first of equal t kept), and eps is accel's
** hit_epsilon() from the same leaf size (the object's world box from
** accel_object_bounds()). tests/unit/test_pfast.c compares every field
** with accel_intersect() on random rays. The only difference is uv: 0 on
** a plane (as accel's) and on a sphere whose texture is one colour
** everywhere (nothing reads it there); geom_sphere_uv() otherwise.
*/
#include "config.h"

#include "photon/fastpath.h"

#include <math.h>

#include "geometry/geom.h"
#include "math/transform.h"
#include "util/mem.h"

struct pfast_prim {
    const iris_object *obj;
    bool sphere;               /* else a plane */
    bool transformed;
    double sign;               /* -1 for an inverse object */
    unsigned skip;             /* ACCEL_SKIP_* bits of the object */
    vec3 c;                    /* sphere centre, or unit plane normal */
    double rad;                /* sphere radius, or plane distance */
    double inv_rad;            /* 1/rad (sphere) */
    vec3 wn;                   /* plane: its world normal at every hit */
    bool valid;                /* plane: the normal is usable */
    double size;               /* hit_epsilon's leaf size (0: unbounded) */
    bool needs_uv;             /* sphere: its texture may read uv */
};

struct pfast {
    const struct accel *a;     /* for the queries the fast path leaves */
    int n;
    double eps;                /* accel_epsilon() */
    struct pfast_prim p[PFAST_MAX_PRIMS];
};

static unsigned own_skip(const iris_object *o)
{
    return (o->no_image ? ACCEL_SKIP_NO_IMAGE : 0) |
           (o->no_shadow ? ACCEL_SKIP_NO_SHADOW : 0) |
           (o->no_reflection ? ACCEL_SKIP_NO_REFLECTION : 0);
}

/* Whether texture 't' is one colour everywhere, every layer a solid
** pigment without a normal: then no material code reads a hit's uv, and
** the fast path may leave it 0. Anything patterned might be uv_mapped. */
static bool texture_is_uniform(const iris_texture *t)
{
    for (; t; t = t->next)
        if (t->map_pattern.kind != IRIS_PAT_NONE || t->normal ||
            !t->pigment || t->pigment->pattern.kind != IRIS_PAT_NONE)
            return false;
    return true;
}

/* Whether 'o' is a primitive the fast path answers as accel does. */
static bool eligible(const iris_object *o)
{
    return o && (o->kind == IRIS_OBJ_SPHERE || o->kind == IRIS_OBJ_PLANE) &&
           (o->n_clipped_by == 0 || !o->clipped_by) && o->texture &&
           !geom_validate(o);
}

struct pfast *pfast_build(const iris_scene *scene, const struct accel *a)
{
    if (!scene || !a || scene->n_objects <= 0 ||
        scene->n_objects > PFAST_MAX_PRIMS)
        return NULL;
    for (int i = 0; i < scene->n_objects; i++)
        if (!eligible(scene->objects[i]))
            return NULL;
    struct pfast *f = iris_calloc(1, sizeof *f);
    if (!f)
        return NULL;
    f->a = a;
    f->eps = accel_epsilon(a);
    /* accel's order: the bounded primitives, then the unbounded */
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < scene->n_objects; i++) {
            const iris_object *o = scene->objects[i];
            if ((o->kind == IRIS_OBJ_SPHERE) != (pass == 0))
                continue;
            struct pfast_prim *p = &f->p[f->n++];
            p->obj = o;
            p->sphere = o->kind == IRIS_OBJ_SPHERE;
            p->transformed = o->has_transform;
            p->sign = o->inverse ? -1.0 : 1.0;
            p->skip = own_skip(o);
            if (p->sphere) {
                vec3 lo, hi;
                if (!accel_object_bounds(a, o, &lo, &hi)) {
                    iris_free(f); /* accel left it out: not the same */
                    return NULL;
                }
                p->c = o->u.sphere.centre;
                p->rad = o->u.sphere.radius;
                p->inv_rad = 1.0 / p->rad;
                p->size = v3_max_comp(v3_sub(hi, lo));
                p->needs_uv = !texture_is_uniform(o->texture);
            } else {
                /* node.c plane_nearest()'s normal does not depend on the
                ** ray: take it once */
                vec3 pn = v3_norm(o->u.plane.normal);
                p->c = pn;
                p->rad = o->u.plane.distance;
                p->size = 0.0;
                vec3 wn = o->has_transform ? xf_normal(&o->transform, pn) : pn;
                double len = v3_len(wn);
                p->valid = isfinite(pn.x) && isfinite(pn.y) &&
                           isfinite(pn.z) && len > 0 && isfinite(len);
                p->wn = v3_scale(wn, p->sign / len);
            }
        }
    return f;
}

void pfast_destroy(struct pfast *f)
{
    iris_free(f);
}

const struct accel *pfast_accel(const struct pfast *f)
{
    return f->a;
}

/* isfinite() of all three components in one test: x - x is 0 for a
** finite x and NaN for an infinite or NaN one, so the sum is 0 exactly
** when all three are finite (half the instructions of three isfinite()s;
** the query tests five vectors) */
static inline bool finite_v(vec3 v)
{
    return (v.x - v.x) + (v.y - v.y) + (v.z - v.z) == 0.0;
}

/* node.c sphere_nearest(): the nearer crossing in (tmin, tmax) of the
** ray lo + t·ld in object space; *n the unit world normal. */
static bool sphere_hit(const struct pfast_prim *s, vec3 lo, vec3 ld,
                       double tmin, double tmax, double *t_out, vec3 *n)
{
    double a = v3_len2(ld);
    if (!(a > 0))
        return false;
    vec3 oc = v3_sub(lo, s->c);
    double tc = -v3_dot(oc, ld) / a;
    vec3 pc = v3_madd(oc, ld, tc);
    double num = s->rad * s->rad - v3_len2(pc);
    if (num < 0)
        return false;
    double h = sqrt(num / a);
    for (int k = 0; k < 2; k++) {
        double t = k ? tc + h : tc - h;
        /* (node.c also tests isfinite(t): t > tmin and t < tmax already
        ** exclude NaN and both infinities) */
        if (!(t > tmin && t < tmax))
            continue;
        vec3 on = v3_scale(v3_madd(oc, ld, t), s->inv_rad);
        if (!finite_v(on) || (on.x == 0 && on.y == 0 && on.z == 0))
            continue;
        vec3 wn = s->transformed ? xf_normal(&s->obj->transform, on) : on;
        double len = v3_len(wn);
        if (!(len > 0) || !isfinite(len))
            continue;
        *t_out = t;
        *n = v3_scale(wn, s->sign / len);
        return true;
    }
    return false;
}

/* node.c plane_nearest(), with its normal taken at build time. */
static bool plane_hit(const struct pfast_prim *s, vec3 lo, vec3 ld,
                      double tmin, double tmax, double *t_out, vec3 *n)
{
    vec3 pn = s->c;
    double dn = v3_dot(pn, ld);
    if (dn == 0 || !s->valid)
        return false;
    double t = (s->rad - v3_dot(pn, lo)) / dn;
    if (!(t > tmin && t < tmax)) /* also excludes NaN and infinities */
        return false;
    *t_out = t;
    *n = s->wn;
    return true;
}

bool pfast_intersect(const void *ctx, const ray *r, double tmin, double tmax,
                     unsigned skip, struct hit *h)
{
    const struct pfast *f = ctx;
    if (!finite_v(r->o) || !finite_v(r->d) || !(tmax > tmin) || isnan(tmin))
        return false;
    const struct pfast_prim *best = NULL;
    vec3 bn = v3(0, 0, 0);
    for (int i = 0; i < f->n; i++) {
        const struct pfast_prim *s = &f->p[i];
        if (s->skip & skip)
            continue;
        vec3 lo = r->o, ld = r->d;
        if (s->transformed) {
            lo = xf_inv_point(&s->obj->transform, r->o);
            ld = xf_inv_dir(&s->obj->transform, r->d);
        }
        double t;
        vec3 n;
        if (s->sphere ? sphere_hit(s, lo, ld, tmin, tmax, &t, &n)
                      : plane_hit(s, lo, ld, tmin, tmax, &t, &n)) {
            tmax = t;
            best = s;
            bn = n;
        }
    }
    if (!best)
        return false;
    const iris_object *o = best->obj;
    h->t = tmax;
    h->p = v3_madd(r->o, r->d, tmax);
    h->n = h->shading_n = bn;
    h->uv.u = h->uv.v = 0;
    if (best->needs_uv) /* accel.c's geom_sphere_uv, for the hit kept */
        h->uv = geom_sphere_uv(o, best->transformed
                                      ? xf_inv_point(&o->transform, h->p)
                                      : h->p);
    h->obj = h->top = o;
    h->texture = o->texture;
    h->interior = o->interior;
    h->eps = accel_hit_epsilon(best->size, h->p, f->eps);
    return isfinite(h->t) && finite_v(h->p) && finite_v(h->n) &&
           v3_len2(h->n) > 0;
}
