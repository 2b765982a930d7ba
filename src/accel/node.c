/* SPDX-License-Identifier: MIT */
/*
** node.c: crossings and inside tests of shape leaves and CSG nodes.
**
** A CSG node gathers every crossing of its children along the ray and
** keeps those that lie on its boundary: all of them for a union; for a
** merge those not inside any other child; for an intersection those
** inside every other child (POV-Ray's All_Intersections + Inside). Then
** 'clipped_by' keeps the crossings inside every clipping object.
*/
#include "config.h"

#include "accel/node.h"

#include <math.h>
#include <string.h>

#include "geometry/sphere_span.h"
#include "math/transform.h"
#include "util/mem.h"

void ahit_list_init(struct ahit_list *l)
{
    l->v = l->buf;
    l->n = 0;
    l->cap = (int)(sizeof l->buf / sizeof l->buf[0]);
}

void ahit_list_fini(struct ahit_list *l)
{
    if (l->v != l->buf)
        iris_free(l->v);
    ahit_list_init(l);
}

void ahit_push(struct ahit_list *l, const struct ahit *h)
{
    if (l->n == l->cap) {
        int cap = l->cap * 2;
        struct ahit *nv = iris_malloc((size_t)cap * sizeof *nv);
        if (!nv)
            return; /* out of memory: the crossing is lost, never a crash */
        memcpy(nv, l->v, (size_t)l->n * sizeof *nv);
        if (l->v != l->buf)
            iris_free(l->v);
        l->v = nv;
        l->cap = cap;
    }
    l->v[l->n++] = *h;
}

/* geom_intersect() of a shape leaf, with what the build prepared. */
static void leaf_intersect(const struct anode *n, vec3 lo, vec3 ld,
                           double tmin, double tmax, struct isect_list *l)
{
    if (n->has_blob_box && !n->obj->bounded_by) {
        geom_blob_hits_in_box(n->obj, n->blob_lo, n->blob_hi, lo, ld, tmin,
                              tmax, l);
        return;
    }
    geom_intersect(n->obj, n->prof, lo, ld, tmin, tmax, l);
}

/*
** The crossing of a plane leaf without bounded_by, for shape_hits():
** geom_plane_hits() with its unit normal (plane_n, the same v3_norm) and
** the world normal shape_hits() would compute from it, taken once by the
** build (plane_wn), so the crossing is the same to the bit without the
** crossing list and the two transforms of the normal. The facets of a
** cut gem are planes: a CSG query asks every one of them.
*/
static void plane_hits(const struct anode *n, vec3 lo, vec3 ld, double tmin,
                       double tmax, struct ahit_list *out)
{
    if (!n->plane_wn_ok)
        return; /* isect_push or shape_hits would drop its crossing */
    vec3 pn = n->plane_n;
    double dn = v3_dot(pn, ld);
    if (dn == 0)
        return;
    double t = (n->obj->u.plane.distance - v3_dot(pn, lo)) / dn;
    /* no isfinite(t): t < tmax fails for +inf, t > tmin for -inf
    ** and NaN, whatever tmin and tmax are */
    if (!(t > tmin && t < tmax))
        return;
    struct ahit h;
    h.t = t;
    h.n = h.sn = n->plane_wn;
    h.uv.u = h.uv.v = 0;
    h.leaf = n;
    h.texture = NULL;
    ahit_push(out, &h);
}

void node_sphere_world_prepare(struct anode *n)
{
    n->sphere_world = n->kind == AN_SHAPE &&
                      sphere_world_frame(n->obj, &n->sphere_wc,
                                         &n->sphere_wr);
}

/*
** shape_hits() of a sphere_world leaf: geom_sphere_hits() and the loop
** below for an untransformed sphere at sphere_wc, radius sphere_wr, step
** for step (the same t and normals), in world space.
*/
static void sphere_world_hits(const struct anode *n, vec3 o, vec3 d,
                              double tmin, double tmax,
                              struct ahit_list *out)
{
    double rad = n->sphere_wr, tc, h;
    vec3 oc = v3_sub(o, n->sphere_wc);
    if (!sphere_span(oc, d, v3_len2(d), rad, &tc, &h))
        return;
    for (int k = 0; k < 2; k++) {
        double t = k ? tc + h : tc - h;
        if (!(t > tmin && t < tmax))
            continue;
        vec3 wn = v3_scale(v3_madd(oc, d, t), 1.0 / rad);
        double len = v3_len(wn);
        if (!(len > 0) || !isfinite(len))
            continue;
        struct ahit a;
        a.t = t;
        a.n = a.sn = v3_scale(wn, (n->inverted ? -1.0 : 1.0) / len);
        a.uv.u = a.uv.v = 0;
        a.leaf = n;
        a.texture = NULL;
        ahit_push(out, &a);
    }
}

/* Crossings of an analytic leaf: solved in object space. */
static void shape_hits(const struct anode *n, vec3 o, vec3 d, double tmin,
                       double tmax, struct ahit_list *out)
{
    const iris_object *obj = n->obj;
    if (n->sphere_world) {
        sphere_world_hits(n, o, d, tmin, tmax, out);
        return;
    }
    vec3 lo = o, ld = d;
    if (obj->has_transform) {
        lo = anode_inv_point(&obj->transform, o);
        ld = anode_inv_dir(&obj->transform, d);
    }
    if (obj->kind == IRIS_OBJ_PLANE && !obj->bounded_by) {
        plane_hits(n, lo, ld, tmin, tmax, out);
        return;
    }
    struct isect_list l;
    isect_list_init(&l);
    leaf_intersect(n, lo, ld, tmin, tmax, &l);
    for (int i = 0; i < l.n; i++) {
        struct ahit h;
        vec3 wn = obj->has_transform ? xf_normal(&obj->transform, l.v[i].n)
                                     : l.v[i].n;
        double len = v3_len(wn);
        if (!(len > 0) || !isfinite(len))
            continue;
        wn = v3_scale(wn, (n->inverted ? -1.0 : 1.0) / len);
        h.t = l.v[i].t;
        h.n = h.sn = wn;
        h.uv = l.v[i].uv;
        h.leaf = n;
        h.texture = NULL;
        /* A blob component's own texture, where it has one */
        if (obj->kind == IRIS_OBJ_BLOB && l.v[i].part >= 0 &&
            l.v[i].part < obj->u.blob.n_components)
            h.texture = obj->u.blob.components[l.v[i].part].texture;
        ahit_push(out, &h);
    }
    isect_list_fini(&l);
}

static bool clips_ok(const struct anode *n, vec3 p)
{
    for (int i = 0; i < n->n_clips; i++)
        if (!node_inside(n->clips[i], p))
            return false;
    return true;
}

/* Whether a crossing of child 'k' at 'p' lies on the CSG node's surface. */
static bool csg_keeps(const struct anode *n, int k, vec3 p)
{
    for (int j = 0; j < n->n_kids; j++) {
        if (j == k)
            continue;
        bool in = node_inside(n->kids[j], p);
        if (n->op == AN_MERGE && in)
            return false;
        if (n->op == AN_INTERSECTION && !in)
            return false;
    }
    return true;
}

void node_hits(const struct anode *n, vec3 o, vec3 d, double tmin,
               double tmax, unsigned skip, struct ahit_list *out)
{
    if (n->bounded) {
        double a = tmin, b = tmax;
        if (!geom_clip_box(n->lo, n->hi, o, d, &a, &b))
            return;
    }
    node_hits_in_box(n, o, d, tmin, tmax, skip, out);
}

void node_hits_in_box(const struct anode *n, vec3 o, vec3 d, double tmin,
                      double tmax, unsigned skip, struct ahit_list *out)
{
    int first = out->n;
    switch (n->kind) {
    case AN_SHAPE:
        if (!(n->skip & skip))
            shape_hits(n, o, d, tmin, tmax, out);
        break;
    case AN_MESH:
        if (!(n->skip & skip))
            amesh_hits(n, o, d, tmin, tmax, out);
        break;
    case AN_CSG:
        /* bounded_by on CSG: POV-Ray's Ray_In_Bound (geometry/bound.c) */
        if (n->obj->bounded_by && !geom_csg_bound_admits(n->obj, o, d))
            break;
        for (int k = 0; k < n->n_kids; k++) {
            int from = out->n;
            node_hits(n->kids[k], o, d, tmin, tmax, skip, out);
            if (n->op == AN_UNION)
                continue;
            /* Keep in place the crossings on this node's boundary */
            int w = from;
            for (int i = from; i < out->n; i++)
                if (csg_keeps(n, k, v3_madd(o, d, out->v[i].t)))
                    out->v[w++] = out->v[i];
            out->n = w;
        }
        break;
    }
    if (n->n_clips) {
        int w = first;
        for (int i = first; i < out->n; i++)
            if (clips_ok(n, v3_madd(o, d, out->v[i].t)))
                out->v[w++] = out->v[i];
        out->n = w;
    }
}

/* A crossing's world-space unit normal (xf NULL: object space is world
** space), turned for an inverted leaf; false when it is degenerate, and
** the crossing is then skipped, as the general path skips it. */
static inline bool leaf_normal(const struct anode *n, const xform *xf,
                               vec3 on, vec3 *out)
{
    vec3 wn = xf ? xf_normal(xf, on) : on;
    double len = v3_len(wn);
    if (!(len > 0) || !isfinite(len))
        return false;
    *out = v3_scale(wn, (n->inverted ? -1.0 : 1.0) / len);
    return true;
}

/* The leaf's crossing at t becomes the nearest hit (the fast paths'
** answer; the texture is chosen by the caller). */
static inline void keep_hit(struct ahit *best, const struct anode *n,
                            double t, vec3 nrm, iris_vec2 uv)
{
    best->t = t;
    best->n = best->sn = nrm;
    best->uv = uv;
    best->leaf = n;
    best->texture = NULL;
}

/*
** The nearest crossing of a sphere leaf with the object-space ray lo + t·ld:
** geom_sphere_hits() step for step (the same t and normal), without the
** crossing list, for the commonest primitive of POV-Ray's scenes.
*/
/* always_inline: with two call sites (world-frame and object-space
** spheres) GCC kept it out of line, +4% instructions on ntreal */
static inline __attribute__((always_inline)) bool
sphere_nearest(const struct anode *n, vec3 c, double rad, const xform *xf,
               vec3 lo, vec3 ld, double tmin, double tmax, struct ahit *best)
{
    vec3 oc = v3_sub(lo, c);
    double tc, h;
    if (!sphere_span(oc, ld, v3_len2(ld), rad, &tc, &h))
        return false;
    for (int k = 0; k < 2; k++) {
        double t = k ? tc + h : tc - h;
        /* no isfinite(t): see plane_hits() */
        if (!(t > tmin && t < tmax))
            continue;
        vec3 on = v3_scale(v3_madd(oc, ld, t), 1.0 / rad);
        if (!isfinite(on.x) || !isfinite(on.y) || !isfinite(on.z) ||
            (on.x == 0 && on.y == 0 && on.z == 0))
            continue;
        vec3 nrm;
        if (!leaf_normal(n, xf, on, &nrm))
            continue;
        /* uv 0: geom_sphere_uv, asked for the hit kept */
        keep_hit(best, n, t, nrm, (iris_vec2){ 0, 0 });
        return true;
    }
    return false;
}

/*
** The crossing of a plane leaf: geom_plane_hits() with the normal
** normalised once at build time (node.h plane_n), without the crossing
** list. Planes are met by nearly every ray of a scene with a floor.
*/
static bool plane_nearest(const struct anode *n, vec3 lo, vec3 ld,
                          double tmin, double tmax, struct ahit *best)
{
    const iris_object *obj = n->obj;
    vec3 pn = n->plane_n;
    double dn = v3_dot(pn, ld);
    if (dn == 0)
        return false;
    double t = (obj->u.plane.distance - v3_dot(pn, lo)) / dn;
    /* no isfinite(t): see plane_hits() */
    if (!(t > tmin && t < tmax) || !isfinite(pn.x) || !isfinite(pn.y) ||
        !isfinite(pn.z))
        return false;
    vec3 wn = obj->has_transform ? xf_normal(&obj->transform, pn) : pn;
    double len = v3_len(wn);
    if (!(len > 0) || !isfinite(len))
        return false;
    best->t = t;
    best->n = best->sn = v3_scale(wn, (n->inverted ? -1.0 : 1.0) / len);
    best->uv.u = best->uv.v = 0;
    best->leaf = n;
    best->texture = NULL;
    return true;
}

/*
** The nearest crossing of a box leaf with the object-space ray lo + t·ld:
** geom_box_hits() in its parts (the same t, normal and uv), without the
** crossing list, and the uv of the crossing kept only. As shape_nearest()
** does for any shape, a crossing whose world normal is degenerate is
** skipped for the next.
*/
static bool box_nearest(const struct anode *n, vec3 lo, vec3 ld, double tmin,
                        double tmax, struct ahit *best)
{
    const iris_object *obj = n->obj;
    struct geom_box_cross c[2];
    int nc = geom_box_crossings(obj, lo, ld, tmin, tmax, c);
    for (int k = 0; k < nc; k++) {
        vec3 nrm;
        if (!leaf_normal(n, obj->has_transform ? &obj->transform : NULL,
                         geom_box_normal(&c[k]), &nrm))
            continue;
        keep_hit(best, n, c[k].t, nrm, geom_box_uv(obj, lo, ld, &c[k]));
        return true;
    }
    return false;
}

/*
** The nearest crossing of a cylinder or cone leaf: geom_cone_hits() in
** its parts, from the frame the build took (node.h 'cone'), chosen as
** shape_nearest() chooses from its crossing list
** (the first of the nearest in the solver's order, skipping those whose
** world normal is degenerate), with the uv (an atan2) of that crossing
** only.
*/
static bool cone_nearest(const struct anode *n, vec3 lo, vec3 ld,
                         double tmin, double tmax, struct ahit *best)
{
    const iris_object *obj = n->obj;
    struct geom_cone_cross c[4];
    int nc = geom_cone_crossings_in(obj, &n->cone, lo, ld, tmin, tmax, c);
    for (;;) {
        int k = -1;
        for (int i = 0; i < nc; i++)
            if (c[i].t > tmin && c[i].t < tmax && (k < 0 || c[i].t < c[k].t))
                k = i;
        if (k < 0)
            return false;
        vec3 nrm;
        if (!leaf_normal(n, obj->has_transform ? &obj->transform : NULL,
                         c[k].n, &nrm)) {
            c[k].t = NAN; /* never nearest again */
            continue;
        }
        /* uv (an atan2 on the side) only when a texture reads it */
        keep_hit(best, n, c[k].t, nrm,
                 n->uv_read ? geom_cone_uv(&c[k]) : (iris_vec2){ 0, 0 });
        return true;
    }
}

/*
** The nearest crossing of a torus leaf: the first root of its quartic
** only (geom_torus_first; refining the others was a third of a torus
** query), its normal, and its uv (two atan2) only when a texture reads
** it. Where the general path would look past that root (it is outside
** (tmin, tmax) after rounding, or its normal is degenerate), the whole
** solve is made: returns -1 and the caller takes the general path. Not
** inlined: inside node_nearest_in_box() it made the sphere's path spill
** registers (10_glass +0.3 % eye-pass instructions).
*/
static __attribute__((noinline)) int
torus_nearest(const struct anode *n, vec3 lo, vec3 ld, double tmin,
              double tmax, struct ahit *best)
{
    const iris_object *obj = n->obj;
    struct geom_torus_cross c;
    int r = geom_torus_first(obj, lo, ld, tmin, tmax, &c);
    if (r <= 0)
        return r;
    vec3 nrm;
    if (!(c.t > tmin && c.t < tmax) ||
        !leaf_normal(n, obj->has_transform ? &obj->transform : NULL, c.n,
                     &nrm))
        return -1;
    keep_hit(best, n, c.t, nrm,
             n->uv_read ? geom_torus_uv(&c) : (iris_vec2){ 0, 0 });
    return 1;
}

/*
** node_nearest() of a shape leaf without clipping, the most common
** primitive: the crossings are solved as in shape_hits() but only the
** nearest one's normal is taken to world space, and nothing is copied
** into an ahit_list. Same answer as the general path: the first of the
** nearest crossings in the solver's order, skipping crossings whose world
** normal is degenerate.
*/
static bool shape_nearest(const struct anode *n, vec3 o, vec3 d,
                          double tmin, double tmax, struct ahit *best)
{
    const iris_object *obj = n->obj;
    if (n->sphere_world) /* an untransformed sphere at sphere_wc */
        return sphere_nearest(n, n->sphere_wc, n->sphere_wr, NULL, o, d,
                              tmin, tmax, best);
    vec3 lo = o, ld = d;
    if (obj->has_transform) {
        lo = anode_inv_point(&obj->transform, o);
        ld = anode_inv_dir(&obj->transform, d);
    }
    /* bounded_by goes through geom_intersect (its box cuts the shape) */
    if (obj->kind == IRIS_OBJ_SPHERE && !obj->bounded_by)
        return sphere_nearest(n, obj->u.sphere.centre, obj->u.sphere.radius,
                              obj->has_transform ? &obj->transform : NULL,
                              lo, ld, tmin, tmax, best);
    if (obj->kind == IRIS_OBJ_PLANE && !obj->bounded_by)
        return plane_nearest(n, lo, ld, tmin, tmax, best);
    if (obj->kind == IRIS_OBJ_BOX && !obj->bounded_by)
        return box_nearest(n, lo, ld, tmin, tmax, best);
    if ((obj->kind == IRIS_OBJ_CYLINDER || obj->kind == IRIS_OBJ_CONE) &&
        !obj->bounded_by)
        return cone_nearest(n, lo, ld, tmin, tmax, best);
    /* Marked unlikely: as a plain test it moved GCC's choice of
    ** registers on the sphere's path above (ntreal +0.3 % eye-pass
    ** instructions) */
    if (__builtin_expect(obj->kind == IRIS_OBJ_TORUS, 0) &&
        !obj->bounded_by) {
        int r = torus_nearest(n, lo, ld, tmin, tmax, best);
        if (r >= 0)
            return r > 0;
    }
    struct isect_list l;
    isect_list_init(&l);
    l.first_only = true;
    leaf_intersect(n, lo, ld, tmin, tmax, &l);
    bool found = false;
    for (;;) {
        int k = -1;
        for (int i = 0; i < l.n; i++)
            if (l.v[i].t > tmin && l.v[i].t < tmax &&
                (k < 0 || l.v[i].t < l.v[k].t))
                k = i;
        if (k < 0)
            break;
        const struct geom_isect *e = &l.v[k];
        vec3 wn = obj->has_transform ? xf_normal(&obj->transform, e->n) : e->n;
        double len = v3_len(wn);
        if (!(len > 0) || !isfinite(len)) {
            l.v[k].t = NAN; /* never nearest again */
            continue;
        }
        wn = v3_scale(wn, (n->inverted ? -1.0 : 1.0) / len);
        best->t = e->t;
        best->n = best->sn = wn;
        best->uv = e->uv;
        best->leaf = n;
        best->texture = NULL;
        if (obj->kind == IRIS_OBJ_BLOB && e->part >= 0 &&
            e->part < obj->u.blob.n_components)
            best->texture = obj->u.blob.components[e->part].texture;
        found = true;
        break;
    }
    isect_list_fini(&l);
    return found;
}

bool node_nearest(const struct anode *n, vec3 o, vec3 d, double tmin,
                  double tmax, unsigned skip, struct ahit *best)
{
    if (n->bounded) {
        double a = tmin, b = tmax;
        if (!geom_clip_box(n->lo, n->hi, o, d, &a, &b))
            return false;
    }
    return node_nearest_in_box(n, o, d, tmin, tmax, skip, best);
}

/* lazy_nearest() keeps where each child's crossings start in an array
** on the stack: a CSG node with more children than this takes the
** general path (the same answer). */
#define LAZY_MAX_KIDS 64

/*
** node_nearest_in_box() of a CSG node or a clipped leaf, lazily: the raw
** crossings are gathered as node_hits_in_box() gathers them (each child's
** own crossings, already filtered by that child), but this node's own
** tests, the boundary test of a CSG node (an inside test of every other
** child per crossing) and the clipping, are asked of the crossings in
** order of t, only until one passes. Filtering every crossing and then
** taking the nearest asked them all: on a gem cut from 17 planes, 19
** crossings times up to 17 inside tests, for the one that is kept.
** Same answer: the tests are pure functions of the crossing and its
** point (computed by the same expression), and among crossings of equal
** t the first in gathering order wins both ways.
** Returns -1 when the node does not fit (too many children): the caller
** then takes the general path. Not inlined: in node_nearest_in_box() its
** loops made the shape paths' registers spill (ntreal +0.25 % eye-pass
** instructions once box_nearest and cone_nearest joined them).
*/
static __attribute__((noinline)) int
lazy_nearest(const struct anode *n, vec3 o, vec3 d, double tmin,
                        double tmax, unsigned skip, struct ahit *best)
{
    if (n->kind == AN_CSG && n->n_kids > LAZY_MAX_KIDS)
        return -1;
    int start[LAZY_MAX_KIDS + 1]; /* child k's crossings: start[k].. */
    struct ahit_list l;
    ahit_list_init(&l);
    switch (n->kind) {
    case AN_SHAPE:
        if (!(n->skip & skip))
            shape_hits(n, o, d, tmin, tmax, &l);
        break;
    case AN_MESH:
        if (!(n->skip & skip))
            amesh_hits(n, o, d, tmin, tmax, &l);
        break;
    case AN_CSG:
        /* bounded_by on CSG: POV-Ray's Ray_In_Bound (geometry/bound.c) */
        if (n->obj->bounded_by && !geom_csg_bound_admits(n->obj, o, d))
            break;
        for (int k = 0; k < n->n_kids; k++) {
            start[k] = l.n;
            node_hits(n->kids[k], o, d, tmin, tmax, skip, &l);
        }
        start[n->n_kids] = l.n;
        break;
    }
    bool boundary = n->kind == AN_CSG && n->op != AN_UNION;
    bool found = false;
    for (;;) {
        int i = -1;
        for (int j = 0; j < l.n; j++)
            if (l.v[j].t > tmin && l.v[j].t < tmax &&
                (i < 0 || l.v[j].t < l.v[i].t))
                i = j;
        if (i < 0)
            break;
        vec3 p = v3_madd(o, d, l.v[i].t);
        bool keep = true;
        if (boundary) {
            int k = 0;
            while (start[k + 1] <= i)
                k++;
            keep = csg_keeps(n, k, p);
        }
        if (keep && clips_ok(n, p)) {
            *best = l.v[i];
            found = true;
            break;
        }
        l.v[i].t = NAN; /* never nearest again */
    }
    ahit_list_fini(&l);
    return found;
}

bool node_nearest_in_box(const struct anode *n, vec3 o, vec3 d, double tmin,
                         double tmax, unsigned skip, struct ahit *best)
{
    if (n->kind == AN_SHAPE && n->n_clips == 0) {
        if (n->skip & skip)
            return false;
        return shape_nearest(n, o, d, tmin, tmax, best);
    }
    if (n->lazy) {
        int r = lazy_nearest(n, o, d, tmin, tmax, skip, best);
        if (r >= 0)
            return r > 0;
    }
    struct ahit_list l;
    ahit_list_init(&l);
    node_hits_in_box(n, o, d, tmin, tmax, skip, &l);
    int k = -1;
    for (int i = 0; i < l.n; i++)
        if (l.v[i].t > tmin && l.v[i].t < tmax &&
            (k < 0 || l.v[i].t < l.v[k].t))
            k = i;
    if (k >= 0)
        *best = l.v[k];
    ahit_list_fini(&l);
    return k >= 0;
}

bool node_inside(const struct anode *n, vec3 p)
{
    /* Outside the inside's box: no transform, no shape test. Most inside
    ** tests (CSG filtering, the interiors holding a blur ray's origin)
    ** are far from the object. */
    if (n->vol_bounded &&
        !(p.x >= n->vlo.x && p.x <= n->vhi.x && p.y >= n->vlo.y &&
          p.y <= n->vhi.y && p.z >= n->vlo.z && p.z <= n->vhi.z))
        return false;
    bool in = false;
    switch (n->kind) {
    case AN_SHAPE: {
        vec3 lp = n->obj->has_transform
                      ? anode_inv_point(&n->obj->transform, p) : p;
        if (n->obj->kind == IRIS_OBJ_PLANE) {
            /* POV-Ray inverts a plane by flipping its normal and offset,
            ** and counts points within EPSILON (1e-10) of it as inside:
            ** the plane itself is inside a plane and its inverse alike,
            ** so a face lying on a cutting plane survives the cut. */
            double s = v3_dot(n->plane_n, lp) - n->obj->u.plane.distance;
            in = (n->inverted ? -s : s) < 1e-10;
        } else {
            in = geom_inside(n->obj, n->prof, lp) != n->inverted;
        }
        break;
    }
    case AN_MESH:
        in = amesh_inside(n, p) != n->inverted;
        break;
    case AN_CSG:
        in = n->op == AN_INTERSECTION && n->n_kids > 0;
        for (int k = 0; k < n->n_kids; k++) {
            bool kin = node_inside(n->kids[k], p);
            if (n->op == AN_INTERSECTION && !kin) {
                in = false;
                break;
            }
            if (n->op != AN_INTERSECTION && kin) {
                in = true;
                break;
            }
        }
        break;
    }
    return in && clips_ok(n, p);
}
