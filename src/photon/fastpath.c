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
** no material code reads when the texture is one colour). Here the
** primitives sit in two flat arrays (spheres, planes) and the query is
** the arithmetic alone. When no primitive is transformed and no sphere
** needs uv (the caustic ball), the scan is compiled apart (query_plain):
** it calls no function, so it saves no registers and spills little;
** that and the per-kind loops took the ball's query from 323 to 269
** instructions (callgrind, photon_bench -t 1).
**
** SAME ANSWER. The sphere and plane solves are accel's (node.c
** sphere_nearest, plane_nearest) expression for expression, the
** primitives are scanned in accel's order (bounded ones in scene order,
** then the unbounded, the first of equal t kept; a plane whose normal is
** unusable, never hit, is left out), and eps is accel's
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
#include "geometry/sphere_span.h"
#include "math/transform.h"
#include "util/mem.h"

struct pfast_prim {
    const iris_object *obj;
    bool transformed;
    bool world;                /* sphere: transformed, solved as an
                                  untransformed one at c, radius rad
                                  (sphere_world_frame, as accel) */
    double sign;               /* -1 for an inverse object */
    unsigned skip;             /* ACCEL_SKIP_* bits of the object */
    vec3 c;                    /* sphere centre, or unit plane normal */
    double rad;                /* sphere radius, or plane distance */
    double inv_rad;            /* 1/rad (sphere) */
    vec3 wn;                   /* plane: its world normal at every hit */
    double size;               /* hit_epsilon's leaf size (0: unbounded) */
    bool needs_uv;             /* sphere: its texture may read uv */
};

/* The spheres and the planes sit in two arrays, each scanned by its own
** loop: no test of the kind per primitive, and accel's order (the bounded
** primitives, then the unbounded) is the order of the two loops. */
struct pfast {
    const struct accel *a;     /* for the queries the fast path leaves */
    int ns, np;
    bool plain;                /* none transformed, no sphere needs uv */
    double eps;                /* accel_epsilon() */
    struct pfast_prim s[PFAST_MAX_PRIMS];  /* spheres, in scene order */
    struct pfast_prim pl[PFAST_MAX_PRIMS]; /* usable planes, scene order */
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
    /* accel's order: the bounded primitives (spheres), then the
    ** unbounded (planes), each in scene order */
    for (int i = 0; i < scene->n_objects; i++) {
        const iris_object *o = scene->objects[i];
        bool sphere = o->kind == IRIS_OBJ_SPHERE;
        struct pfast_prim q = {
            .obj = o,
            .transformed = o->has_transform,
            .sign = o->inverse ? -1.0 : 1.0,
            .skip = own_skip(o),
        };
        if (sphere) {
            vec3 lo, hi;
            if (!accel_object_bounds(a, o, &lo, &hi)) {
                iris_free(f); /* accel left it out: not the same */
                return NULL;
            }
            q.world = sphere_world_frame(o, &q.c, &q.rad);
            if (!q.world) {
                q.c = o->u.sphere.centre;
                q.rad = o->u.sphere.radius;
            }
            q.inv_rad = 1.0 / q.rad;
            q.size = v3_max_comp(v3_sub(hi, lo));
            q.needs_uv = !texture_is_uniform(o->texture);
            f->s[f->ns++] = q;
        } else {
            /* node.c plane_nearest()'s normal does not depend on the
            ** ray: take it once */
            vec3 pn = v3_norm(o->u.plane.normal);
            q.c = pn;
            q.rad = o->u.plane.distance;
            q.size = 0.0;
            vec3 wn = o->has_transform ? xf_normal(&o->transform, pn) : pn;
            double len = v3_len(wn);
            q.wn = v3_scale(wn, q.sign / len);
            /* a plane whose normal is unusable is never hit (node.c):
            ** leave it out of the scan */
            if (isfinite(pn.x) && isfinite(pn.y) && isfinite(pn.z) &&
                len > 0 && isfinite(len))
                f->pl[f->np++] = q;
        }
    }
    f->plain = true;
    for (int i = 0; i < f->ns; i++)
        if (f->s[i].transformed || f->s[i].needs_uv)
            f->plain = false;
    for (int i = 0; i < f->np; i++)
        if (f->pl[i].transformed)
            f->plain = false;
    return f;
}

void pfast_destroy(struct pfast *f)
{
    iris_free(f);
}

bool pfast_plain(const struct pfast *f)
{
    return f->plain;
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
** ray lo + t·ld in object space, a = |ld|² (> 0); *n the unit world
** normal. 'may_xf' false (a constant): 's' is known untransformed, and
** the function calls nothing. */
static inline bool sphere_hit(const struct pfast_prim *s, vec3 lo, vec3 ld,
                              double a, double tmin, double tmax,
                              double *t_out, vec3 *n, bool may_xf)
{
    vec3 oc = v3_sub(lo, s->c);
    double tc, h;
    if (!sphere_span(oc, ld, a, s->rad, &tc, &h))
        return false;
    for (int k = 0; k < 2; k++) {
        double t = k ? tc + h : tc - h;
        /* (node.c also tests isfinite(t): t > tmin and t < tmax already
        ** exclude NaN and both infinities) */
        if (!(t > tmin && t < tmax))
            continue;
        vec3 on = v3_scale(v3_madd(oc, ld, t), s->inv_rad);
        if (!finite_v(on) || (on.x == 0 && on.y == 0 && on.z == 0))
            continue;
        vec3 wn = may_xf && s->transformed && !s->world
                      ? xf_normal(&s->obj->transform, on) : on;
        double len = v3_len(wn);
        if (!(len > 0) || !isfinite(len))
            continue;
        *t_out = t;
        *n = v3_scale(wn, s->sign / len);
        return true;
    }
    return false;
}

/* A transformed sphere: the ray taken to object space first (out of
** line: the common ball is untransformed). */
static __attribute__((noinline)) bool
sphere_hit_xf(const struct pfast_prim *s, const ray *r, double tmin,
              double tmax, double *t_out, vec3 *n)
{
    vec3 lo = xf_inv_point(&s->obj->transform, r->o);
    vec3 ld = xf_inv_dir(&s->obj->transform, r->d);
    double a = v3_len2(ld);
    if (!(a > 0))
        return false;
    return sphere_hit(s, lo, ld, a, tmin, tmax, t_out, n, true);
}

/* node.c plane_nearest(), with its normal taken at build time: the
** crossing t of the ray lo + t·ld, NaN or out of range for none. */
static inline double plane_t(const struct pfast_prim *s, vec3 lo, vec3 ld)
{
    vec3 pn = s->c;
    double dn = v3_dot(pn, ld);
    if (dn == 0)
        return NAN;
    return (s->rad - v3_dot(pn, lo)) / dn;
}

/* A sphere's uv for the hit kept (accel.c's geom_sphere_uv), out of line:
** only a patterned ball needs it. */
static __attribute__((noinline)) iris_vec2
sphere_uv(const struct pfast_prim *s, vec3 p)
{
    const iris_object *o = s->obj;
    return geom_sphere_uv(o, s->transformed ? xf_inv_point(&o->transform, p)
                                            : p);
}

/* The query, for pfast_intersect(). 'plain' (a constant where this is
** inlined) says that no primitive is transformed and no sphere needs uv:
** then the scan calls no function, and the compiler keeps it in scratch
** registers without saving any. */
static inline __attribute__((always_inline)) bool
query(const struct pfast *f, const ray *r, double tmin, double tmax,
      unsigned skip, struct hit *h, bool plain)
{
    /* (tmax > tmin is false for a NaN tmin or tmax) */
    if (!finite_v(r->o) || !finite_v(r->d) || !(tmax > tmin))
        return false;
    const struct pfast_prim *best = NULL;
    vec3 bn = v3(0, 0, 0);
    /* |d|², the a of every untransformed sphere (node.c computes it per
    ** sphere, the same value) */
    double a = v3_len2(r->d);
    for (int i = 0; i < f->ns; i++) {
        const struct pfast_prim *s = &f->s[i];
        if (s->skip & skip)
            continue;
        double t;
        vec3 n;
        if (!plain && s->transformed && !s->world
                ? sphere_hit_xf(s, r, tmin, tmax, &t, &n)
                : a > 0 && sphere_hit(s, r->o, r->d, a, tmin, tmax, &t, &n,
                                      !plain)) {
            tmax = t;
            best = s;
            bn = n;
        }
    }
    for (int i = 0; i < f->np; i++) {
        const struct pfast_prim *s = &f->pl[i];
        if (s->skip & skip)
            continue;
        double t = !plain && s->transformed
                       ? plane_t(s, xf_inv_point(&s->obj->transform, r->o),
                                 xf_inv_dir(&s->obj->transform, r->d))
                       : plane_t(s, r->o, r->d);
        if (t > tmin && t < tmax) { /* also excludes NaN and infinities */
            tmax = t;
            best = s;
            bn = s->wn;
        }
    }
    if (!best)
        return false;
    const iris_object *o = best->obj;
    h->t = tmax;
    h->p = v3_madd(r->o, r->d, tmax);
    h->n = h->shading_n = bn;
    h->uv.u = h->uv.v = 0;
    if (!plain && best->needs_uv) /* accel.c's geom_sphere_uv */
        h->uv = sphere_uv(best, h->p);
    h->obj = h->top = o;
    h->texture = o->texture;
    h->interior = o->interior;
    h->eps = accel_hit_epsilon(best->size, h->p, f->eps);
    /* accel_intersect() also requires a finite t and a finite, non-zero
    ** n. Both hold here without a test. t: tmin < t < the caller's tmax
    ** with tmin not NaN. n = wn·(±1/len), len = |wn| > 0 and finite with
    ** wn finite (tested above for a sphere, at build for a plane): len is
    ** at least sqrt of the least subnormal, ~2.2e-162, so 1/len is
    ** finite, and the largest |component| of n is 1/sqrt(3) or more
    ** (a little less where |wn|² is subnormal, still far from 0). Only
    ** p = o + t·d may overflow. */
    return finite_v(h->p);
}

static __attribute__((noinline)) bool
query_plain(const struct pfast *f, const ray *r, double tmin, double tmax,
            unsigned skip, struct hit *h)
{
    return query(f, r, tmin, tmax, skip, h, true);
}

static __attribute__((noinline)) bool
query_any(const struct pfast *f, const ray *r, double tmin, double tmax,
          unsigned skip, struct hit *h)
{
    return query(f, r, tmin, tmax, skip, h, false);
}

bool pfast_intersect(const void *ctx, const ray *r, double tmin, double tmax,
                     unsigned skip, struct hit *h)
{
    const struct pfast *f = ctx;
    return f->plain ? query_plain(f, r, tmin, tmax, skip, h)
                    : query_any(f, r, tmin, tmax, skip, h);
}
