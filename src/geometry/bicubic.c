/* SPDX-License-Identifier: MIT */
/*
** bicubic.c: POV-Ray 3.7's tessellation of a bicubic_patch.
**
** POV-Ray (bezier.cpp; type 1 builds the tree once, type 0 walks the same
** recursion per ray, so both give the same surface) halves the Bezier net
** by de Casteljau at every level, in u (the first index of the 4 x 4
** control points, i.e. the rows as written) while the depth is below
** u_steps and in v (along a row) while it is below v_steps, and stops
** early where the sub-net is flat: all 16 control points lie within
** 'flatness' of the plane through three of its corners. Each leaf is the
** two triangles (P00, P03, P33) and (P00, P33, P30) of its corner
** points, with the patch's own normals at those corners. POV-Ray moves
** the control points by the object's transform before it subdivides, so
** flatness is measured in world space: the world net decides, the
** object-space net (halved alongside) gives the vertices, which accel
** then transforms like any mesh's. With flatness 0
** (the default) no net counts as flat and the grid is uniform,
** 2^u_steps x 2^v_steps cells; the default of 0 steps is one cell.
** accel/mesh.c hands the triangles to Embree.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>
#include <string.h>

#include "math/transform.h"
#include "util/mem.h"

#define MAX_STEPS 8          /* 2^16 cells at most; POV-Ray has no cap */
#define FLAT_EPS 1e-10       /* POV-Ray's EPSILON for coincident corners */

typedef vec3 net[4][4];      /* [u][v] */

struct tess {
    const iris_object *o;
    int su, sv;
    double flatness;
    int n, cap;
    vec3 *p, *nrm;
    iris_vec2 *uv;
    bool oom;
};

/* Halves the net along u (split_u) or v into a and b (de Casteljau). */
static void split(const net *in, bool split_u, net *a, net *b)
{
    for (int k = 0; k < 4; k++) {
        vec3 c[4];
        for (int m = 0; m < 4; m++)
            c[m] = split_u ? (*in)[m][k] : (*in)[k][m];
        vec3 p01 = v3_lerp(c[0], c[1], 0.5), p12 = v3_lerp(c[1], c[2], 0.5);
        vec3 p23 = v3_lerp(c[2], c[3], 0.5);
        vec3 q0 = v3_lerp(p01, p12, 0.5), q1 = v3_lerp(p12, p23, 0.5);
        vec3 mid = v3_lerp(q0, q1, 0.5);
        vec3 l[4] = { c[0], p01, q0, mid }, r[4] = { mid, q1, p23, c[3] };
        for (int m = 0; m < 4; m++) {
            if (split_u) {
                (*a)[m][k] = l[m];
                (*b)[m][k] = r[m];
            } else {
                (*a)[k][m] = l[m];
                (*b)[k][m] = r[m];
            }
        }
    }
}

/*
** POV-Ray's determine_subpatch_flatness: the largest distance of a
** control point from the plane through P00, P03 (or P33 when P03 falls
** on P00) and P30; -1 when those corners are degenerate (never flat).
*/
static double flatness(const net *P)
{
    vec3 v0 = (*P)[0][0], v1 = (*P)[0][3], v2;
    if (v3_len(v3_sub(v0, v1)) < FLAT_EPS) {
        v1 = (*P)[3][3];
        if (v3_len(v3_sub(v0, v1)) < FLAT_EPS)
            return -1;
        v2 = (*P)[3][0];
    } else {
        v2 = (*P)[3][0];
    }
    if (v3_len(v3_sub(v1, v2)) < FLAT_EPS)
        return -1;
    vec3 e1 = v3_sub(v0, v1), e2 = v3_sub(v2, v1);
    vec3 n = v3_cross(e1, e2);
    double l2 = v3_len2(n);
    if (l2 <= 1e-10 * v3_len2(e1) * v3_len2(e2))
        return -1;
    n = v3_scale(n, 1 / sqrt(l2));
    double d = -v3_dot(n, v0), dist = 0;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            dist = fmax(dist, fabs(v3_dot((*P)[i][j], n) + d));
    return dist;
}

/* The patch's normal at (u, v), as accel/mesh.c has always oriented it:
** d/dv x d/du in POV-Ray's (u = row) terms. */
static vec3 patch_normal(const iris_object *o, double u, double v)
{
    double bu[4], dbu[4], bv[4], dbv[4];
    for (int k = 0; k < 2; k++) {
        double t = k ? v : u, s = 1 - t;
        double *b = k ? bv : bu, *db = k ? dbv : dbu;
        b[0] = s * s * s;
        b[1] = 3 * t * s * s;
        b[2] = 3 * t * t * s;
        b[3] = t * t * t;
        db[0] = -3 * s * s;
        db[1] = 3 * s * s - 6 * t * s;
        db[2] = 6 * t * s - 3 * t * t;
        db[3] = 3 * t * t;
    }
    vec3 du = v3(0, 0, 0), dv = du;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            vec3 q = o->u.bicubic.points[4 * i + j];
            du = v3_madd(du, q, dbu[i] * bv[j]);
            dv = v3_madd(dv, q, bu[i] * dbv[j]);
        }
    return v3_cross(dv, du);
}

static void emit(struct tess *T, vec3 p, double u, double v)
{
    if (T->n == T->cap) {
        int cap = T->cap ? 2 * T->cap : 192;
        vec3 *np = iris_realloc(T->p, (size_t)cap * sizeof *np);
        if (np)
            T->p = np;
        vec3 *nn = iris_realloc(T->nrm, (size_t)cap * sizeof *nn);
        if (nn)
            T->nrm = nn;
        iris_vec2 *nu = iris_realloc(T->uv, (size_t)cap * sizeof *nu);
        if (nu)
            T->uv = nu;
        if (!np || !nn || !nu) {
            T->oom = true;
            return;
        }
        T->cap = cap;
    }
    T->p[T->n] = p;
    T->nrm[T->n] = patch_normal(T->o, u, v);
    /* POV-Ray's texture uv is (v, u) for the default uv_vectors */
    T->uv[T->n].u = v;
    T->uv[T->n].v = u;
    T->n++;
}

static void leaf(struct tess *T, const net *P, double u0, double u1,
                 double v0, double v1)
{
    emit(T, (*P)[0][0], u0, v0);
    emit(T, (*P)[0][3], u0, v1);
    emit(T, (*P)[3][3], u1, v1);
    emit(T, (*P)[0][0], u0, v0);
    emit(T, (*P)[3][3], u1, v1);
    emit(T, (*P)[3][0], u1, v0);
}

/* P: the object-space net, W: the same cell's world-space net. */
static void subdivide(struct tess *T, const net *P, const net *W, double u0,
                      double u1, double v0, double v1, int depth)
{
    if (T->oom)
        return;
    double f = flatness(W);
    bool more_u = depth < T->su, more_v = depth < T->sv;
    if ((f >= 0 && f < T->flatness) || (!more_u && !more_v)) {
        leaf(T, P, u0, u1, v0, v1);
        return;
    }
    net a, b, c, d, wa, wb, wc, wd;
    double um = (u0 + u1) / 2, vm = (v0 + v1) / 2;
    if (more_u && more_v) {
        net l, r, wl, wr;
        split(P, true, &l, &r);
        split(&l, false, &a, &b);
        split(&r, false, &c, &d);
        split(W, true, &wl, &wr);
        split(&wl, false, &wa, &wb);
        split(&wr, false, &wc, &wd);
        subdivide(T, &a, &wa, u0, um, v0, vm, depth + 1);
        subdivide(T, &b, &wb, u0, um, vm, v1, depth + 1);
        subdivide(T, &c, &wc, um, u1, v0, vm, depth + 1);
        subdivide(T, &d, &wd, um, u1, vm, v1, depth + 1);
    } else if (more_u) {
        split(P, true, &a, &b);
        split(W, true, &wa, &wb);
        subdivide(T, &a, &wa, u0, um, v0, v1, depth + 1);
        subdivide(T, &b, &wb, um, u1, v0, v1, depth + 1);
    } else {
        split(P, false, &a, &b);
        split(W, false, &wa, &wb);
        subdivide(T, &a, &wa, u0, u1, v0, vm, depth + 1);
        subdivide(T, &b, &wb, u0, u1, vm, v1, depth + 1);
    }
}

const char *geom_bicubic_tessellate(const iris_object *o, int *n_tris,
                                    vec3 **p, vec3 **n, iris_vec2 **uv)
{
    struct tess T;
    memset(&T, 0, sizeof T);
    T.o = o;
    int su = o->u.bicubic.u_steps, sv = o->u.bicubic.v_steps;
    T.su = su < 0 ? 0 : su > MAX_STEPS ? MAX_STEPS : su;
    T.sv = sv < 0 ? 0 : sv > MAX_STEPS ? MAX_STEPS : sv;
    T.flatness = o->u.bicubic.flatness;
    net P, W;
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            P[i][j] = o->u.bicubic.points[4 * i + j];
            if (!isfinite(P[i][j].x) || !isfinite(P[i][j].y) ||
                !isfinite(P[i][j].z))
                return "bicubic_patch has a control point that is not "
                       "finite";
            W[i][j] = o->has_transform ? xf_point(&o->transform, P[i][j])
                                       : P[i][j];
        }
    subdivide(&T, &P, &W, 0, 1, 0, 1, 0);
    if (T.oom) {
        iris_free(T.p);
        iris_free(T.nrm);
        iris_free(T.uv);
        return "out of memory";
    }
    *n_tris = T.n / 3;
    *p = T.p;
    *n = T.nrm;
    *uv = T.uv;
    return NULL;
}
