/* SPDX-License-Identifier: MIT */
/*
** parametric.c: the surface (x(u,v), y(u,v), z(u,v)) over a uv rectangle,
** found as POV-Ray 3.7 finds it (fpmetric.cpp).
**
** POV-Ray subdivides the uv rectangle depth first, always halving the
** longer side. For each cell it bounds each coordinate function from its
** four corner values and 'max_gradient' (a Lipschitz bound: between two
** values a and b a distance dx apart the function can reach
** max(a, b) + (max_gradient·dx - |a - b|)/2), turns the three bounds into
** slabs along the ray and drops the cell when the slabs are disjoint, lie
** outside the container box or beyond the nearest hit so far. A cell is a
** hit when its uv size, or the longest slab along the ray, is below
** 'accuracy'; its distance is the entry of the last slab computed. Only
** the nearest hit is reported (POV-Ray has no other: a parametric has no
** inside, so CSG sees one crossing), and the search starts 4·accuracy
** past the container's entry, or past the ray origin inside it.
**
** POV-Ray's quirks are kept because they shape the image: the functions
** are bounded as f - accuracy (its "threshold" argument, so the surface
** found is shifted by -accuracy on every axis), the normal is the cross
** product of forward differences of step 'accuracy' at the cell's low uv
** corner, and uv is the raw (u, v). With too small a max_gradient the
** bounds are wrong and parts of the surface are missed, in POV-Ray and
** here alike.
**
** 'precompute D x,y,z' is not only a cache: POV-Ray computes the bounds
** of the named functions on the cells of the first D levels of the same
** subdivision, from the corners at level D - 1 only, and gives each
** coarser cell the union of its two halves' bounds. Those are tighter
** than a coarse cell's own estimate and, with too small a max_gradient,
** find parts of the surface the plain search misses; the search uses
** them for every cell of those levels (geom_parametric_precompute, kept
** in the object's geom_profile).
*/
#include "config.h"

#include "geometry/geom.h"
#include "iris/fn.h"
#include "util/mem.h"

#include <math.h>

#define PAR_STACK 64     /* subdivision depth; POV-Ray's stack holds 32 */

struct par {
    const iris_fn *f[3];
    double acc, grad;
};

static struct par par_of(const iris_object *o)
{
    struct par p;
    p.f[0] = o->u.parametric.fx;
    p.f[1] = o->u.parametric.fy;
    p.f[2] = o->u.parametric.fz;
    p.acc = o->u.parametric.accuracy > 0 ? o->u.parametric.accuracy : 0.001;
    p.grad = o->u.parametric.max_gradient > 0
                 ? o->u.parametric.max_gradient : 1.0;
    return p;
}

static double eval(const iris_fn *f, double u, double v)
{
    double args[3] = { u, v, 0 };
    return iris_fn_eval(f, args, 3);
}

/* POV-Ray's Interval(): bounds over a span dx with end values a, b. */
static void span(double dx, double a, double b, double g, double *lo,
                 double *hi)
{
    double ofs = g * (dx - fabs(a - b) / g) / 2;
    if (ofs < 0)
        ofs = 0;
    *hi = fmax(a, b) + ofs;
    *lo = fmin(a, b) - ofs;
}

/*
** Bounds of f - acc over the cell [u0,u1]x[v0,v1] from the function's
** values at its corners c = { f(u0,v0), f(u0,v1), f(u1,v0), f(u1,v1) },
** as POV-Ray's Evaluate_Function_Interval_UV: the two v edges, then
** across u.
*/
static void cell_bounds(const struct par *p, const double c[4], double u0,
                        double u1, double v0, double v1, double *lo,
                        double *hi)
{
    double f00 = c[0] - p->acc, f01 = c[1] - p->acc;
    double f10 = c[2] - p->acc, f11 = c[3] - p->acc;
    double l0, h0, l1, h1, junk;
    span(v1 - v0, f00, f01, p->grad, &l0, &h0);
    span(v1 - v0, f10, f11, p->grad, &l1, &h1);
    span(u1 - u0, h0, h1, p->grad, &junk, hi);
    span(u1 - u0, l0, l1, p->grad, lo, &junk);
}

/* POV-Ray's cap on a cell's number (Max_intNumber): deeper cells are
** never in a precomputed table (depth <= 20) */
#define PAR_SECTOR_MAX 10000000L

/* The corner values of function 'f' on a cell, in cell_bounds' order. */
static void corners(const iris_fn *f, double u0, double u1, double v0,
                    double v1, double c[4])
{
    c[0] = eval(f, u0, v0);
    c[1] = eval(f, u0, v1);
    c[2] = eval(f, u1, v0);
    c[3] = eval(f, u1, v1);
}

/* POV-Ray's Precomp_Par_Int: cell 'n' of the tree over [u0,u1]x[v0,v1],
** halving the longer side (v only when strictly longer), the leaves
** (n >= 'last') bounded from their corners. */
static void precomp(const iris_object *o, struct geom_profile *g,
                    const struct par *p, long n, long last, double u0,
                    double u1, double v0, double v1)
{
    if (n >= last) {
        for (int k = 0; k < 3; k++) {
            if (!g->par_lo[k])
                continue;
            double c[4];
            corners(p->f[k], u0, u1, v0, v1, c);
            cell_bounds(p, c, u0, u1, v0, v1, &g->par_lo[k][n],
                        &g->par_hi[k][n]);
        }
        return;
    }
    if (u1 - u0 < v1 - v0) {
        double m = (v0 + v1) / 2;
        precomp(o, g, p, 2 * n, last, u0, u1, v0, m);
        precomp(o, g, p, 2 * n + 1, last, u0, u1, m, v1);
    } else {
        double m = (u0 + u1) / 2;
        precomp(o, g, p, 2 * n, last, u0, m, v0, v1);
        precomp(o, g, p, 2 * n + 1, last, m, u1, v0, v1);
    }
    for (int k = 0; k < 3; k++) {
        if (!g->par_lo[k])
            continue;
        g->par_lo[k][n] = fmin(g->par_lo[k][2 * n], g->par_lo[k][2 * n + 1]);
        g->par_hi[k][n] = fmax(g->par_hi[k][2 * n], g->par_hi[k][2 * n + 1]);
    }
}

bool geom_parametric_precompute(const iris_object *o,
                                struct geom_profile *g)
{
    int depth = o->u.parametric.precompute_depth;
    if (depth < 1 || depth > 20)
        return true; /* none (the parser refuses such a depth) */
    struct par p = par_of(o);
    long nmb = 1L << depth;
    for (int k = 0; k < 3; k++) {
        if (!(o->u.parametric.precompute_axes & (1 << k)))
            continue;
        g->par_lo[k] = iris_malloc((size_t)nmb * sizeof(double));
        g->par_hi[k] = iris_malloc((size_t)nmb * sizeof(double));
        if (!g->par_lo[k] || !g->par_hi[k])
            return false;
    }
    g->par_depth = depth;
    iris_vec2 a = o->u.parametric.uv_lo, b = o->u.parametric.uv_hi;
    precomp(o, g, &p, 1, 1L << (depth - 1), fmin(a.u, b.u), fmax(a.u, b.u),
            fmin(a.v, b.v), fmax(a.v, b.v));
    return true;
}

static void container(const iris_object *o, vec3 *lo, vec3 *hi)
{
    if (o->u.parametric.contained_kind == 1) {
        double r = fabs(o->u.parametric.radius);
        *lo = v3_sub(o->u.parametric.centre, v3(r, r, r));
        *hi = v3_add(o->u.parametric.centre, v3(r, r, r));
        return;
    }
    vec3 a = o->u.parametric.lo, b = o->u.parametric.hi;
    if (a.x == 0 && a.y == 0 && a.z == 0 && b.x == 0 && b.y == 0 &&
        b.z == 0) {
        /* no contained_by: POV-Ray's default box */
        a = v3(-1, -1, -1);
        b = v3(1, 1, 1);
    }
    *lo = v3_min(a, b);
    *hi = v3_max(a, b);
}

/* The ray's span in a container sphere, as POV-Ray's Sphere::Intersect
** gives it: both chord ends, the first behind the origin when the origin
** is inside (a box container starts at the origin instead), none when
** the origin is outside and the centre behind it, or the chord shorter
** than EPSILON (1e-10, on its squared half in unit-direction terms). */
static bool sphere_span(const iris_object *o, vec3 ro, vec3 rd, double *d1,
                        double *d2)
{
    double len = v3_len(rd), r = o->u.parametric.radius;
    if (!(len > 0))
        return false;
    vec3 dn = v3_scale(rd, 1 / len), oc = v3_sub(o->u.parametric.centre, ro);
    double oc2 = v3_len2(oc), tca = v3_dot(oc, dn);
    if (oc2 >= r * r && tca < 1e-10)
        return false;
    double h2 = r * r - oc2 + tca * tca;
    if (!(h2 > 1e-10))
        return false;
    *d1 = (tca - sqrt(h2)) / len;
    *d2 = (tca + sqrt(h2)) / len;
    return true;
}

void geom_parametric_hits(const iris_object *o,
                          const struct geom_profile *prof, vec3 ro, vec3 rd,
                          double t0, double t1, struct isect_list *out)
{
    struct par p = par_of(o);
    /* cells numbered below 'ntab' take precomputed bounds */
    long ntab = prof && prof->par_depth > 0 ? 1L << prof->par_depth : 0;
    vec3 blo, bhi;
    container(o, &blo, &bhi);
    /* The container along the ray, from the origin on (POV-Ray's box
    ** test starts at 0) */
    double d1 = 0, d2 = INFINITY;
    if (o->u.parametric.contained_kind == 1) {
        if (!sphere_span(o, ro, rd, &d1, &d2))
            return;
    } else if (!geom_clip_box(blo, bhi, ro, rd, &d1, &d2)) {
        return;
    }
    d1 += 4 * p.acc;
    if (d1 > d2)
        return;

    /* The stack of cells, each with the three functions' corner values
    ** (a child shares two corners with its parent, so a split costs two
    ** new points, not eight) */
    double ulo[PAR_STACK], uhi[PAR_STACK], vlo[PAR_STACK], vhi[PAR_STACK];
    double cv[PAR_STACK][3][4];
    long sec[PAR_STACK]; /* POV-Ray's SectorNum: the cell's number */
    iris_vec2 a = o->u.parametric.uv_lo, b = o->u.parametric.uv_hi;
    ulo[0] = fmin(a.u, b.u);
    uhi[0] = fmax(a.u, b.u);
    vlo[0] = fmin(a.v, b.v);
    vhi[0] = fmax(a.v, b.v);
    for (int k = 0; k < 3; k++) {
        cv[0][k][0] = eval(p.f[k], ulo[0], vlo[0]);
        cv[0][k][1] = eval(p.f[k], ulo[0], vhi[0]);
        cv[0][k][2] = eval(p.f[k], uhi[0], vlo[0]);
        cv[0][k][3] = eval(p.f[k], uhi[0], vhi[0]);
    }
    sec[0] = 1;
    double best = INFINITY, bu = 0, bv = 0;
    double P[3] = { ro.x, ro.y, ro.z }, D[3] = { rd.x, rd.y, rd.z };
    int i = 0;
    while (i >= 0) {
        double u0 = ulo[i], u1 = uhi[i], v0 = vlo[i], v1 = vhi[i];
        double len = u1 - u0;
        bool split_u = true;
        if (v1 - v0 > len) {
            len = v1 - v0;
            split_u = false;
        }
        double tlen = 0, pot = 0;
        double smin[3], smax[3];
        bool par[3], drop = false;
        for (int k = 0; k < 3 && !drop; k++) {
            double lo, hi;
            if (sec[i] < ntab && prof->par_lo[k]) {
                lo = prof->par_lo[k][sec[i]];
                hi = prof->par_hi[k][sec[i]];
            } else {
                cell_bounds(&p, cv[i][k], u0, u1, v0, v1, &lo, &hi);
            }
            /* POV-Ray's close(D, 0): an axis the ray is parallel to */
            par[k] = fabs(D[k]) < 1e-10;
            if (par[k]) {
                drop = hi < P[k] || lo > P[k];
                continue;
            }
            double s0 = (hi - P[k]) / D[k], s1 = (lo - P[k]) / D[k];
            smin[k] = fmin(s0, s1);
            smax[k] = fmax(s0, s1);
            if (smin[k] > d2 || smax[k] < d1 || (pot = smin[k]) > best) {
                drop = true;
                continue;
            }
            for (int j = 0; j < k; j++)
                if (!par[j] && (smin[k] > smax[j] || smax[k] < smin[j]))
                    drop = true;
            tlen = fmax(tlen, smax[k] - smin[k]);
        }
        if (drop) {
            i--;
            continue;
        }
        if (len > tlen)
            len = tlen;
        if (len < p.acc || i == PAR_STACK - 1) {
            if (best > pot && pot > d1) {
                best = pot;
                bu = u0;
                bv = v0;
            }
            i--;
            continue;
        }
        /* Split: slot i keeps the upper half (cell 2n + 1), slot i + 1
        ** the lower (2n), which is therefore searched first */
        sec[i] = sec[i] * 2 >= PAR_SECTOR_MAX ? PAR_SECTOR_MAX : sec[i] * 2;
        sec[i + 1] = sec[i];
        sec[i]++;
        ulo[i + 1] = u0;
        uhi[i + 1] = u1;
        vlo[i + 1] = v0;
        vhi[i + 1] = v1;
        for (int k = 0; k < 3; k++) {
            double *lw = cv[i + 1][k], *up = cv[i][k];
            if (split_u) {
                double m = (u0 + u1) / 2;
                double e0 = eval(p.f[k], m, v0), e1 = eval(p.f[k], m, v1);
                lw[0] = up[0];
                lw[1] = up[1];
                lw[2] = up[0] = e0;
                lw[3] = up[1] = e1;
            } else {
                double m = (v0 + v1) / 2;
                double e0 = eval(p.f[k], u0, m), e1 = eval(p.f[k], u1, m);
                lw[0] = up[0];
                lw[2] = up[2];
                lw[1] = up[0] = e0;
                lw[3] = up[2] = e1;
            }
        }
        if (split_u) {
            double m = (u0 + u1) / 2;
            uhi[i + 1] = m;
            ulo[i] = m;
        } else {
            double m = (v0 + v1) / 2;
            vhi[i + 1] = m;
            vlo[i] = m;
        }
        i++;
    }
    if (!(best < d2) || !(best > t0 && best < t1))
        return;
    /* Normal: forward differences of step 'accuracy' at the cell corner */
    double f0[3], fu[3], fv[3];
    for (int k = 0; k < 3; k++) {
        f0[k] = eval(p.f[k], bu, bv);
        fu[k] = eval(p.f[k], bu + p.acc, bv) - f0[k];
        fv[k] = eval(p.f[k], bu, bv + p.acc) - f0[k];
    }
    vec3 n = v3_cross(v3(fu[0], fu[1], fu[2]), v3(fv[0], fv[1], fv[2]));
    isect_push(out, best, n, bu, bv);
}

void geom_parametric_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    container(o, lo, hi);
}

const char *geom_parametric_check(const iris_object *o)
{
    if (!o->u.parametric.fx || !o->u.parametric.fy || !o->u.parametric.fz)
        return "parametric needs three functions";
    iris_vec2 a = o->u.parametric.uv_lo, b = o->u.parametric.uv_hi;
    if (!isfinite(a.u) || !isfinite(a.v) || !isfinite(b.u) ||
        !isfinite(b.v))
        return "parametric uv range is not finite";
    return NULL;
}
