/* SPDX-License-Identifier: MIT */
/*
** sphere_sweep.c: the union of the spheres swept along a spline.
**
** POV-Ray 3.7 (sphsweep.cpp, after van Wijk 1984) builds each segment as a
** centre polynomial c(u) and radius polynomial r(u), u in [0, 1]:
** linear_spline joins consecutive spheres (n - 1 segments of degree 1);
** b_spline (uniform cubic B-spline) and cubic_spline (Catmull-Rom) use
** four consecutive spheres per segment (n - 3 segments of degree 3), with
** the basis matrices below. The solid is the union over all segments and
** u of the balls |p - c(u)| <= |r(u)|; this file computes exactly that set.
**
** A ray o + s·d (unit d) meets the boundary of one segment's sweep either
** on an end sphere (u = 0 or 1) or on the envelope, where
**     f(s, u) = |o + s·d - c(u)|² - r(u)² = 0  and  df/du = 0.
** With e = (o - c)·d, g = |o - c|² - r², A = de/du and b = dg/du the
** second equation gives s = -b / (2A); putting it into the first leaves
**     b² - 4·A·e·b + 4·A²·g = 0,
** a polynomial of degree 2 (linear) or 10 (cubic) in u, whose roots in
** (0, 1) roots.c finds to full precision (POV-Ray eliminates the same
** way). The hit is then taken from the ball at that u, not from -b/2A:
** the envelope is stationary in u, so the ball's hit barely moves with
** the error of u. Where A vanishes s is not determined by u; there the
** ray meets the whole sphere at u, whose two hits become candidates
** (this is the case of a ray perpendicular to a straight segment, whose
** polynomial is then b², a double root).
**
** Candidates from every segment are then kept only where no ball of any
** segment contains the point strictly (min over all segments and u of f
** is not negative), and duplicates at the seams (the same crossing found
** as an end sphere and as an envelope: two entries or two exits in a
** row, which the boundary of a solid cannot have) are merged.
** POV-Ray instead counts entries and exits along the sorted list
** (Find_Valid_Points), which loses hits where parts touch; the surface is
** the same.
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/roots.h"

#include <math.h>
#include <stdlib.h>

#include "util/mem.h"

/* Rows: the coefficient of u^k; columns: the weight of sphere i + j. */
static const double catmull_rom[4][4] = {
    { 0.0, 1.0, 0.0, 0.0 },
    { -0.5, 0.0, 0.5, 0.0 },
    { 1.0, -2.5, 2.0, -0.5 },
    { -0.5, 1.5, -1.5, 0.5 },
};
static const double b_spline[4][4] = {
    { 1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0 },
    { -3.0 / 6, 0.0, 3.0 / 6, 0.0 },
    { 3.0 / 6, -6.0 / 6, 3.0 / 6, 0.0 },
    { -1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6 },
};

/* One segment: c(u) = sum c[k]·u^k, r(u) = sum r[k]·u^k, k <= deg. */
struct seg {
    int deg;
    vec3 c[4];
    double r[4];
};

static int n_segments(const iris_object *o)
{
    int n = o->u.sphere_sweep.n_spheres;
    return o->u.sphere_sweep.spline == 0 ? n - 1 : n - 3;
}

static struct seg segment(const iris_object *o, int i)
{
    struct seg s;
    const iris_vec3 *P = o->u.sphere_sweep.centres;
    const double *R = o->u.sphere_sweep.radii;
    if (o->u.sphere_sweep.spline == 0) {
        s.deg = 1;
        s.c[0] = P[i];
        s.c[1] = v3_sub(P[i + 1], P[i]);
        s.r[0] = R[i];
        s.r[1] = R[i + 1] - R[i];
        return s;
    }
    const double (*m)[4] = o->u.sphere_sweep.spline == 1 ? b_spline
                                                          : catmull_rom;
    s.deg = 3;
    for (int k = 0; k < 4; k++) {
        s.c[k] = v3(0, 0, 0);
        s.r[k] = 0;
        for (int j = 0; j < 4; j++) {
            s.c[k] = v3_madd(s.c[k], P[i + j], m[k][j]);
            s.r[k] += m[k][j] * R[i + j];
        }
    }
    return s;
}

static vec3 seg_c(const struct seg *s, double u)
{
    vec3 p = s->c[s->deg];
    for (int k = s->deg - 1; k >= 0; k--)
        p = v3_madd(s->c[k], p, u);
    return p;
}

static double seg_r(const struct seg *s, double u)
{
    double r = s->r[s->deg];
    for (int k = s->deg - 1; k >= 0; k--)
        r = s->r[k] + r * u;
    return r;
}

/* out = a·b for polynomials of degrees na, nb (ascending coefficients). */
static void pmul(const double *a, int na, const double *b, int nb,
                 double *out)
{
    for (int i = 0; i <= na + nb; i++)
        out[i] = 0;
    for (int i = 0; i <= na; i++)
        for (int j = 0; j <= nb; j++)
            out[i + j] += a[i] * b[j];
}

/* Extremes over u in [0, 1] of the polynomial p of degree n <= 6. */
static void prange(const double *p, int n, double *lo, double *hi)
{
    double d[6], r[6];
    *lo = *hi = p[0];
    double v1 = roots_eval(p, n, 1);
    *lo = fmin(*lo, v1);
    *hi = fmax(*hi, v1);
    if (n < 2)
        return;
    for (int k = 1; k <= n; k++)
        d[k - 1] = k * p[k];
    int m = roots_in_interval(d, n - 1, 0, 1, r);
    for (int i = 0; i < m; i++) {
        double v = roots_eval(p, n, r[i]);
        *lo = fmin(*lo, v);
        *hi = fmax(*hi, v);
    }
}

/* The Bezier control values of the polynomial a (degree 1 or 3) on
** [0, 1]: the polynomial stays within their range (convex hull). */
static void bezier(const double *a, int deg, double *b)
{
    if (deg == 1) {
        b[0] = a[0];
        b[1] = a[0] + a[1];
        return;
    }
    b[0] = a[0];
    b[1] = a[0] + a[1] / 3;
    b[2] = a[0] + (2 * a[1] + a[2]) / 3;
    b[3] = a[0] + a[1] + a[2] + a[3];
}

/*
** A box holding one segment's sweep: the box of the centre's Bezier
** control points grown by the largest |radius| control value. Cheap (it
** is built for every ray), exact for straight segments and tight for
** gentle curves.
*/
static void seg_box(const struct seg *s, vec3 *lo, vec3 *hi)
{
    double rb[4], rmax = 0;
    bezier(s->r, s->deg, rb);
    for (int j = 0; j <= s->deg; j++)
        rmax = fmax(rmax, fabs(rb[j]));
    double l[3], h[3];
    for (int k = 0; k < 3; k++) {
        double a[4], b[4];
        for (int j = 0; j <= s->deg; j++)
            a[j] = v3_comp(s->c[j], k);
        bezier(a, s->deg, b);
        l[k] = h[k] = b[0];
        for (int j = 1; j <= s->deg; j++) {
            l[k] = fmin(l[k], b[j]);
            h[k] = fmax(h[k], b[j]);
        }
        l[k] -= rmax;
        h[k] += rmax;
    }
    *lo = v3(l[0], l[1], l[2]);
    *hi = v3(h[0], h[1], h[2]);
}

/*
** Whether min over u in [0, 1] of |p - c(u)|² - r(u)², the "depth" of p
** in the segment's sweep (negative inside), is below 'thr' (<= 0). The
** minimum is that of the polynomial's values at u = 0, 1 and its
** critical points (prange); where u = 0 or 1 already decides, or a
** Bernstein bound proves every such value above thr, the critical points
** are not needed: the answer is the same, at a fraction of the cost.
*/
static bool seg_below(const struct seg *s, vec3 p, double thr)
{
    int n = s->deg;
    double q[7] = { 0 };
    /* |p - c(u)|² - r(u)²: w = p - c has coefficients w_0 = p - c_0,
    ** w_k = -c_k */
    vec3 w[4];
    for (int k = 0; k <= n; k++)
        w[k] = k ? v3_neg(s->c[k]) : v3_sub(p, s->c[0]);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            q[i + j] += v3_dot(w[i], w[j]) - s->r[i] * s->r[j];
    if (q[0] < thr || roots_eval(q, 2 * n, 1) < thr)
        return true;
    if (roots_surely_above(q, 2 * n, 0, 1, thr))
        return false;
    double lo, hi;
    prange(q, 2 * n, &lo, &hi);
    return lo < thr;
}

struct sweep {
    int n;
    struct seg *s;
    vec3 *lo, *hi;
    double scale;          /* largest extent or radius: for tolerances */
};

static bool sweep_init(const iris_object *o, struct sweep *w,
                       struct seg *sbuf, vec3 *lbuf, vec3 *hbuf, int cap)
{
    w->n = n_segments(o);
    if (w->n < 1)
        return false;
    if (w->n > cap) {
        sbuf = iris_malloc((size_t)w->n * sizeof *sbuf);
        lbuf = iris_malloc((size_t)w->n * sizeof *lbuf);
        hbuf = iris_malloc((size_t)w->n * sizeof *hbuf);
        if (!sbuf || !lbuf || !hbuf) {
            iris_free(sbuf);
            iris_free(lbuf);
            iris_free(hbuf);
            return false;
        }
    }
    w->s = sbuf;
    w->lo = lbuf;
    w->hi = hbuf;
    vec3 blo = v3(INFINITY, INFINITY, INFINITY), bhi = v3_neg(blo);
    for (int i = 0; i < w->n; i++) {
        w->s[i] = segment(o, i);
        seg_box(&w->s[i], &w->lo[i], &w->hi[i]);
        blo = v3_min(blo, w->lo[i]);
        bhi = v3_max(bhi, w->hi[i]);
    }
    w->scale = v3_max_comp(v3_sub(bhi, blo));
    return true;
}

static void sweep_fini(struct sweep *w, int cap)
{
    if (w->n > cap) {
        iris_free(w->s);
        iris_free(w->lo);
        iris_free(w->hi);
    }
}

/* Whether the depth of p in some segment whose box holds p is below thr
** (<= 0): the minimum over the segments, compared with thr. */
static bool sweep_below(const struct sweep *w, vec3 p, double thr)
{
    for (int i = 0; i < w->n; i++) {
        if (p.x < w->lo[i].x || p.x > w->hi[i].x || p.y < w->lo[i].y ||
            p.y > w->hi[i].y || p.z < w->lo[i].z || p.z > w->hi[i].z)
            continue;
        if (seg_below(&w->s[i], p, thr))
            return true;
    }
    return false;
}

#define CAP 16

/* Both crossings of the ray with the sphere (centre c, radius r). */
static void sphere_cands(vec3 o, vec3 d, vec3 c, double r, double s0,
                         struct isect_list *cand)
{
    vec3 oc = v3_sub(o, c);
    double tc = -v3_dot(oc, d);
    vec3 pc = v3_madd(oc, d, tc);
    double h2 = r * r - v3_len2(pc);
    if (!(h2 > 0))
        return;
    double h = sqrt(h2);
    for (int k = 0; k < 2; k++) {
        double s = k ? tc + h : tc - h;
        isect_push(cand, s0 + s, v3_sub(v3_madd(o, d, s), c), 0, 0);
    }
}

/*
** Envelope candidates of one segment, for the ray o + s·d (unit d) whose
** origin was moved by s0 along the ray to near the segment.
*/
static void envelope_cands(const struct seg *g, vec3 o, vec3 d, double s0,
                           struct isect_list *cand)
{
    int n = g->deg;
    vec3 w[4];
    for (int k = 0; k <= n; k++)
        w[k] = k ? v3_neg(g->c[k]) : v3_sub(o, g->c[0]);
    double e[4], gg[7] = { 0 }, A[3], b[6];
    for (int k = 0; k <= n; k++)
        e[k] = v3_dot(w[k], d);
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++)
            gg[i + j] += v3_dot(w[i], w[j]) - g->r[i] * g->r[j];
    for (int k = 1; k <= n; k++)
        A[k - 1] = k * e[k];
    for (int k = 1; k <= 2 * n; k++)
        b[k - 1] = k * gg[k];
    int na = n - 1, nb = 2 * n - 1, ne = n, ng = 2 * n;

    /* P = b² - 4·A·e·b + 4·A²·g, degree 2·nb = 4n - 2 */
    double bb[11], ae[6], aeb[11], aa[5], aag[11], P[11];
    int np = 2 * nb;
    pmul(b, nb, b, nb, bb);
    pmul(A, na, e, ne, ae);
    pmul(ae, na + ne, b, nb, aeb);
    pmul(A, na, A, na, aa);
    pmul(aa, 2 * na, gg, ng, aag);
    double pscale = 0;
    for (int k = 0; k <= np; k++) {
        double t2 = k <= na + ne + nb ? 4 * aeb[k] : 0;
        double t3 = k <= 2 * na + ng ? 4 * aag[k] : 0;
        P[k] = bb[k] - t2 + t3;
        pscale = fmax(pscale, fabs(bb[k]) + fabs(t2) + fabs(t3));
    }
    /* The speed |c'| sets the scale of A */
    double cscale = 0;
    for (int k = 1; k <= n; k++)
        cscale += v3_len(g->c[k]) + fabs(g->r[k]);

    double u[10];
    int nu = 0;
    bool all_zero = true;
    for (int k = 0; k <= np; k++)
        if (fabs(P[k]) > 1e-13 * pscale)
            all_zero = false;
    if (!all_zero)
        nu = roots_in_interval(P, np, 0, 1, u);
    for (int i = 0; i < nu; i++) {
        double Au = roots_eval(A, na, u[i]), bu = roots_eval(b, nb, u[i]);
        if (fabs(Au) <= 1e-12 * cscale)
            continue;   /* handled by the A = 0 spheres below */
        double s = -bu / (2 * Au);
        /* s = -b/2A amplifies the error of u where A is small. The point
        ** is also on the ball at u, and there the ray's distance to the
        ** ball is stationary in u (that is the envelope condition), so
        ** the ball's own hit nearest to s is off by O(du²) only */
        vec3 c = seg_c(g, u[i]);
        double r = seg_r(g, u[i]);
        vec3 oc = v3_sub(o, c);
        double B = v3_dot(oc, d), disc = B * B - (v3_len2(oc) - r * r);
        if (disc >= 0) {
            double h = sqrt(disc), sa = -B - h, sb = -B + h;
            s = fabs(sa - s) <= fabs(sb - s) ? sa : sb;
        }
        isect_push(cand, s0 + s, v3_sub(v3_madd(o, d, s), c), 0, 0);
    }

    /* Where A(u) = 0 (or everywhere, when the segment's centre moves
    ** perpendicular to the ray): the spheres at the stationary points */
    double ua[6];
    int nua = 0;
    bool a_zero = true;
    for (int k = 0; k <= na; k++)
        if (fabs(A[k]) > 1e-12 * cscale)
            a_zero = false;
    if (a_zero)
        nua = roots_in_interval(b, nb, 0, 1, ua);
    else if (na >= 1)
        nua = roots_in_interval(A, na, 0, 1, ua);
    for (int i = 0; i < nua; i++)
        sphere_cands(o, d, seg_c(g, ua[i]), seg_r(g, ua[i]), s0, cand);
}

static int cmp_t(const void *a, const void *b)
{
    double x = ((const struct geom_isect *)a)->t;
    double y = ((const struct geom_isect *)b)->t;
    return x < y ? -1 : x > y;
}

void geom_sphere_sweep_hits(const iris_object *o, vec3 ro, vec3 rd,
                            double t0, double t1, struct isect_list *out)
{
    struct seg sb[CAP];
    vec3 lb[CAP], hb[CAP];
    struct sweep w;
    double dl = v3_len(rd);
    if (!(dl > 0) || !sweep_init(o, &w, sb, lb, hb, CAP))
        return;
    vec3 d = v3_scale(rd, 1 / dl);
    struct isect_list cand;
    isect_list_init(&cand);
    for (int i = 0; i < w.n; i++) {
        double a = t0, b = t1;
        if (!geom_clip_box(w.lo[i], w.hi[i], ro, rd, &a, &b))
            continue;
        /* Work from the ray's closest approach to the segment's box
        ** centre: coordinates of the segment's size keep the envelope
        ** polynomial free of cancellation for far-away ray origins */
        vec3 mid = v3_scale(v3_add(w.lo[i], w.hi[i]), 0.5);
        double s0 = v3_dot(v3_sub(mid, ro), d);
        vec3 o2 = v3_madd(ro, d, s0);
        const struct seg *g = &w.s[i];
        if (i == 0)
            sphere_cands(o2, d, g->c[0], g->r[0], s0, &cand);
        sphere_cands(o2, d, seg_c(g, 1), seg_r(g, 1), s0, &cand);
        envelope_cands(g, o2, d, s0, &cand);
    }
    /* cand holds unit-speed distances; keep the boundary points. Along
    ** the boundary entries and exits alternate, so a run of candidates in
    ** one direction is one crossing found twice (an end sphere and the
    ** envelope of the next segment meet there): of entries the first is
    ** the boundary, of exits the last. */
    qsort(cand.v, (size_t)cand.n, sizeof *cand.v, cmp_t);
    /* f of a point on the surface is 0 to rounding (~1e-15 of size²,
    ** and the root's own error); a point deeper than tol / (2r) inside
    ** a ball of radius r is not on the surface */
    double tol = 1e-9 * w.scale * w.scale;
    int kept = 0;
    for (int i = 0; i < cand.n; i++) {
        double t = cand.v[i].t / dl;
        if (!(t > t0 && t < t1))
            continue;
        vec3 p = v3_madd(ro, rd, t);
        if (sweep_below(&w, p, -tol))
            continue;
        bool enter = v3_dot(cand.v[i].n, d) < 0;
        if (kept > 0 && (v3_dot(cand.v[kept - 1].n, d) < 0) == enter) {
            if (enter)
                continue;
            kept--;
        }
        cand.v[kept] = cand.v[i];
        cand.v[kept++].t = t;
    }
    for (int i = 0; i < kept; i++)
        isect_push(out, cand.v[i].t, cand.v[i].n, 0, 0);
    isect_list_fini(&cand);
    sweep_fini(&w, CAP);
}

bool geom_sphere_sweep_inside(const iris_object *o, vec3 p)
{
    struct seg sb[CAP];
    vec3 lb[CAP], hb[CAP];
    struct sweep w;
    if (!sweep_init(o, &w, sb, lb, hb, CAP))
        return false;
    bool in = sweep_below(&w, p, 0);
    sweep_fini(&w, CAP);
    return in;
}

bool geom_sphere_sweep_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    int n = n_segments(o);
    if (n < 1)
        return false;
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3_neg(*lo);
    for (int i = 0; i < n; i++) {
        struct seg s = segment(o, i);
        vec3 a, b;
        seg_box(&s, &a, &b);
        *lo = v3_min(*lo, a);
        *hi = v3_max(*hi, b);
    }
    return true;
}

const char *geom_sphere_sweep_check(const iris_object *o)
{
    int n = o->u.sphere_sweep.n_spheres;
    int sp = o->u.sphere_sweep.spline;
    if (sp < 0 || sp > 2)
        return "sphere_sweep has an unknown spline type";
    if (!o->u.sphere_sweep.centres || !o->u.sphere_sweep.radii ||
        n < (sp == 0 ? 2 : 4))
        return "too few modeling spheres for the sphere_sweep's spline "
               "(linear_spline needs 2, b_spline and cubic_spline 4)";
    for (int i = 0; i < n; i++) {
        iris_vec3 c = o->u.sphere_sweep.centres[i];
        double r = o->u.sphere_sweep.radii[i];
        if (!isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z) ||
            !isfinite(r))
            return "sphere_sweep has a centre or radius that is not finite";
    }
    return NULL;
}
