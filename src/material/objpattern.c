/* SPDX-License-Identifier: MIT */
/*
** objpattern.c: the inside test of an object pattern's object (see
** objpattern.h).
**
** The tree is walked as POV-Ray's Inside_Object walks it: a union or
** merge holds a point one of its children holds, an intersection one all
** of them hold, a difference one its first child holds and no other;
** 'inverse' flips the answer and clipped_by must hold the point too.
** Shapes answer in object space through geometry/'s geom_inside; the
** outlines that text, prism and lathe need are the only state, made once.
*/
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/geom.h"
#include "material/objpattern.h"
#include "math/transform.h"
#include "util/mem.h"

/* One prepared shape: its outline (NULL when it needs none) or the
** reason it cannot answer, reported once and then "outside". */
struct objpat_leaf {
    const iris_object *obj;
    struct geom_profile *prof;
    bool broken;
};

/* Deeper trees are malformed (or cyclic): the walk ends there. */
#define OBJPAT_DEPTH 64

static bool is_csg(enum iris_object_kind k)
{
    return k >= IRIS_OBJ_UNION && k <= IRIS_OBJ_LIGHT_GROUP;
}

static const struct objpat_leaf *find(const struct objpat_set *s,
                                      const iris_object *o)
{
    /* binary search by address (objpat_seal sorted them) */
    int lo = 0, hi = s ? s->n - 1 : -1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        uintptr_t a = (uintptr_t)s->v[mid].obj, b = (uintptr_t)o;
        if (a == b)
            return &s->v[mid];
        if (a < b)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return NULL;
}

static void report(const iris_scene *sc, FILE *log, const iris_object *o,
                   const char *why)
{
    if (!log)
        return;
    const char *file = "<unknown>";
    if (sc && o->loc.file > 0 && (int)o->loc.file < sc->n_files &&
        sc->files && sc->files[o->loc.file])
        file = sc->files[o->loc.file];
    fprintf(log, "%s:%u:%u: warning: this shape of an object pattern counts "
            "as outside everywhere: %s\n", file, (unsigned)o->loc.line,
            (unsigned)o->loc.col, why);
}

static bool push(struct objpat_set *s, struct objpat_leaf leaf)
{
    if (s->n == s->cap) {
        int cap = s->cap ? 2 * s->cap : 16;
        struct objpat_leaf *v = iris_realloc(s->v, (size_t)cap * sizeof *v);
        if (!v)
            return false;
        s->v = v;
        s->cap = cap;
    }
    s->v[s->n++] = leaf;
    return true;
}

static enum iris_status add_rec(struct objpat_set *s, const iris_scene *sc,
                                const iris_object *o, FILE *log, int depth)
{
    if (!o || depth > OBJPAT_DEPTH)
        return IRIS_OK;
    /* a linear scan: the set is unsorted while it grows, and object
    ** patterns hold few shapes */
    for (int i = 0; i < s->n; i++)
        if (s->v[i].obj == o)
            return IRIS_OK;
    enum iris_status st = IRIS_OK;
    if (is_csg(o->kind)) {
        for (int i = 0; st == IRIS_OK && o->u.csg.children &&
                        i < o->u.csg.n_children; i++)
            st = add_rec(s, sc, o->u.csg.children[i], log, depth + 1);
    } else {
        struct objpat_leaf leaf = { o, NULL, false };
        const char *why = NULL;
        if (geom_is_analytic(o->kind)) {
            why = geom_validate(o);
            if (!why)
                leaf.prof = geom_prepare(o, &why);
        } else if (o->kind != IRIS_OBJ_MESH && o->kind != IRIS_OBJ_TRIANGLE &&
                   o->kind != IRIS_OBJ_BICUBIC_PATCH) {
            /* POV-Ray's triangle and bicubic_patch have no inside (never
            ** inside, nothing to say); a height field's is not made here */
            why = "its inside test is not implemented for object patterns";
        }
        if (why) {
            leaf.broken = true;
            report(sc, log, o, why);
        }
        if (!push(s, leaf)) {
            geom_profile_free(leaf.prof);
            return IRIS_ENOMEM;
        }
    }
    for (int i = 0; st == IRIS_OK && o->clipped_by && i < o->n_clipped_by;
         i++)
        st = add_rec(s, sc, o->clipped_by[i], log, depth + 1);
    return st;
}

enum iris_status objpat_add(struct objpat_set *s, const iris_scene *sc,
                            const iris_object *o, FILE *log)
{
    return add_rec(s, sc, o, log, 0);
}

static int by_obj(const void *a, const void *b)
{
    uintptr_t x = (uintptr_t)((const struct objpat_leaf *)a)->obj;
    uintptr_t y = (uintptr_t)((const struct objpat_leaf *)b)->obj;
    return x < y ? -1 : x > y;
}

void objpat_seal(struct objpat_set *s)
{
    if (s && s->n > 1)
        qsort(s->v, (size_t)s->n, sizeof *s->v, by_obj);
}

void objpat_fini(struct objpat_set *s)
{
    if (!s)
        return;
    for (int i = 0; i < s->n; i++)
        geom_profile_free(s->v[i].prof);
    iris_free(s->v);
    memset(s, 0, sizeof *s);
}

/*
** A mesh's inside as POV-Ray's Mesh::Inside: the ray from 'p' along the
** mesh's inside_vector (object space) crosses the triangles an odd number
** of times; no inside_vector, no inside. Every triangle is tested: an
** object pattern's mesh is small, and this runs only for its texture.
*/
static bool mesh_inside(const iris_mesh_data *m, vec3 p)
{
    vec3 d = v3(m->inside_vector.x, m->inside_vector.y, m->inside_vector.z);
    if (!(v3_len2(d) > 0) || !m->tri_vertices || !m->vertices)
        return false;
    d = v3_norm(d);
    int count = 0;
    for (int i = 0; i < m->n_triangles; i++) {
        const int32_t *t = &m->tri_vertices[3 * i];
        vec3 a = m->vertices[t[0]], b = m->vertices[t[1]],
             c = m->vertices[t[2]];
        /* Moller-Trumbore: the crossing's barycentrics and distance */
        vec3 e1 = v3_sub(b, a), e2 = v3_sub(c, a);
        vec3 q = v3_cross(d, e2);
        double det = v3_dot(e1, q);
        if (fabs(det) < 1e-300)
            continue;
        vec3 s = v3_sub(p, a);
        double u = v3_dot(s, q) / det;
        if (u < 0 || u > 1)
            continue;
        vec3 r = v3_cross(s, e1);
        double v = v3_dot(d, r) / det;
        if (v < 0 || u + v > 1)
            continue;
        /* POV-Ray's mesh DEPTH_TOLERANCE */
        if (v3_dot(e2, r) / det > 1e-6)
            count++;
    }
    return count & 1;
}

static bool inside_rec(const struct objpat_set *s, const iris_object *o,
                       vec3 p, int depth)
{
    if (!o || depth > OBJPAT_DEPTH)
        return false;
    bool in;
    if (is_csg(o->kind)) {
        int nk = o->u.csg.children ? o->u.csg.n_children : 0;
        bool all = o->kind == IRIS_OBJ_INTERSECTION ||
                   o->kind == IRIS_OBJ_DIFFERENCE;
        in = all && nk > 0;
        for (int i = 0; i < nk; i++) {
            bool ci = inside_rec(s, o->u.csg.children[i], p, depth + 1);
            if (o->kind == IRIS_OBJ_DIFFERENCE && i > 0)
                ci = !ci;
            if (all && !ci) {
                in = false;
                break;
            }
            if (!all && ci) {
                in = true;
                break;
            }
        }
        in = in != o->inverse;
    } else {
        const struct objpat_leaf *leaf = find(s, o);
        vec3 lp = o->has_transform ? xf_inv_point(&o->transform, p) : p;
        if (leaf && leaf->broken) {
            in = false;
        } else if (o->kind == IRIS_OBJ_PLANE) {
            /* POV-Ray inverts a plane by flipping it, and the plane itself
            ** (within EPSILON) is inside both ways (as accel's node.c) */
            double d = v3_dot(v3_norm(o->u.plane.normal), lp) -
                       o->u.plane.distance;
            in = (o->inverse ? -d : d) < 1e-10;
        } else if (o->kind == IRIS_OBJ_MESH) {
            in = mesh_inside(&o->u.mesh, lp) != o->inverse;
        } else if (geom_is_analytic(o->kind)) {
            in = geom_inside(o, leaf ? leaf->prof : NULL, lp) != o->inverse;
        } else {
            /* triangle, bicubic_patch: no inside; inverse: all inside */
            in = o->inverse;
        }
    }
    for (int i = 0; in && o->clipped_by && i < o->n_clipped_by; i++)
        in = inside_rec(s, o->clipped_by[i], p, depth + 1);
    return in;
}

bool objpat_inside(const struct objpat_set *s, const iris_object *o, vec3 p)
{
    if (!isfinite(p.x) || !isfinite(p.y) || !isfinite(p.z))
        return false;
    return inside_rec(s, o, p, 0);
}
