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

/* Crossings of an analytic leaf: solved in object space. */
static void shape_hits(const struct anode *n, vec3 o, vec3 d, double tmin,
                       double tmax, struct ahit_list *out)
{
    const iris_object *obj = n->obj;
    vec3 lo = o, ld = d;
    if (obj->has_transform) {
        lo = xf_inv_point(&obj->transform, o);
        ld = xf_inv_dir(&obj->transform, d);
    }
    struct isect_list l;
    isect_list_init(&l);
    geom_intersect(obj, n->prof, lo, ld, tmin, tmax, &l);
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

bool node_nearest(const struct anode *n, vec3 o, vec3 d, double tmin,
                  double tmax, unsigned skip, struct ahit *best)
{
    struct ahit_list l;
    ahit_list_init(&l);
    node_hits(n, o, d, tmin, tmax, skip, &l);
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
    bool in = false;
    switch (n->kind) {
    case AN_SHAPE: {
        vec3 lp = n->obj->has_transform
                      ? xf_inv_point(&n->obj->transform, p) : p;
        in = geom_inside(n->obj, n->prof, lp) != n->inverted;
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
