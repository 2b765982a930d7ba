/* SPDX-License-Identifier: MIT */
/*
** test_geom_shapes.c: ovus, sphere_sweep, parametric, lemon and the
** bicubic_patch tessellation in object space, against closed-form answers
** (capsules, spheres, the ovus and lemon outlines built from their
** circles, the Bernstein form) and brute-force sampling of swept balls.
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <string.h>

#include "geometry/geom.h"
#include "iris/fn.h"
#include "iris/parse.h"
#include "math/transform.h"
#include "util/mem.h"

static iris_object mk(enum iris_object_kind k)
{
    iris_object o;
    memset(&o, 0, sizeof o);
    o.kind = k;
    return o;
}

/* All hits of the ray in (t0, t1), sorted ascending; returns the count. */
static int hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                double t1, double *t, vec3 *n, int cap)
{
    struct isect_list l;
    isect_list_init(&l);
    geom_intersect(o, NULL, ro, rd, t0, t1, &l);
    int k = l.n < cap ? l.n : cap;
    for (int i = 0; i < k; i++) {
        int m = i;
        for (int j = i + 1; j < l.n; j++)
            if (l.v[j].t < l.v[m].t)
                m = j;
        struct geom_isect s = l.v[i];
        l.v[i] = l.v[m];
        l.v[m] = s;
        t[i] = l.v[i].t;
        if (n)
            n[i] = v3_norm(l.v[i].n);
    }
    int total = l.n;
    isect_list_fini(&l);
    return total;
}

/* ------------------------------------------------------------------ */
/* ovus                                                                 */
/* ------------------------------------------------------------------ */

/*
** The ovus { 1, 1 } worked out by hand from its definition (POV-Ray 3.7
** Parse_Ovus): bottom sphere r 1 at 0, top sphere r 1 at y = 1, joined by
** the circle of radius C = 2 whose centre (-H, V) in the (rho, y) plane is
** at distance C - 1 = 1 from both sphere centres: V = 1/2, H = sqrt(3)/2.
** It touches the bottom circle at y = -1/2 and the top one at y = 3/2.
** The outline rho(y) is therefore, independently of the code's formulas:
*/
static double ovus11_rho(double y)
{
    if (y < -0.5)
        return sqrt(1 - y * y);
    if (y > 1.5)
        return sqrt(1 - (y - 1) * (y - 1));
    return sqrt(4 - (y - 0.5) * (y - 0.5)) - sqrt(3) / 2;
}

static void test_ovus_equal_radii(void **state)
{
    (void)state;
    iris_object o = mk(IRIS_OBJ_OVUS);
    o.u.ovus.r1 = 1;
    o.u.ovus.r2 = 1;
    assert_null(geom_validate(&o));
    double t[8];
    vec3 n[8];
    /* Horizontal rays through the axis at heights in all three parts and
    ** near both seams. The hits are roots of a sphere quadratic or of the
    ** torus quartic refined to full precision: 1e-9 relative leaves
    ** room for the conditioning of the quartic (~1e-12 here). */
    const double ys[] = { -0.9, -0.6, -0.5000001, -0.4999999, 0, 0.5, 1.2,
                          1.4999999, 1.5000001, 1.8, 1.99 };
    for (size_t i = 0; i < sizeof ys / sizeof ys[0]; i++) {
        double y = ys[i], r = ovus11_rho(y);
        int k = hits(&o, v3(-10, y, 0), v3(1, 0, 0), 0, 100, t, n, 8);
        assert_int_equal(k, 2);
        assert_rel(t[0], 10 - r, 1e-9);
        assert_rel(t[1], 10 + r, 1e-9);
        assert_true(n[0].x < 0 && n[1].x > 0);
    }
    /* The widest point, y = V = 1/2: rho = 2 - sqrt(3)/2, normal along x */
    int k = hits(&o, v3(0, 0.5, -5), v3(0, 0, 2), 0, 100, t, n, 8);
    assert_int_equal(k, 2);
    assert_rel(t[0], (5 - (2 - sqrt(3) / 2)) / 2, 1e-9);
    assert_near(n[0].z, -1, 1e-9);
    /* Along the axis: bottom at -1, top at 2 */
    k = hits(&o, v3(0, -5, 0), v3(0, 1, 0), 0, 100, t, n, 8);
    assert_int_equal(k, 2);
    assert_rel(t[0], 4, 1e-12);
    assert_rel(t[1], 7, 1e-12);
    /* A ray that passes just outside the widest point misses */
    k = hits(&o, v3(-5, 0.5, 2 - sqrt(3) / 2 + 1e-6), v3(1, 0, 0), 0, 100,
             t, n, 8);
    assert_int_equal(k, 0);
    /* Inside: points just within and just outside the outline */
    const double yi[] = { -0.9, 0, 0.5, 1.4, 1.9 };
    for (size_t i = 0; i < sizeof yi / sizeof yi[0]; i++) {
        double r = ovus11_rho(yi[i]);
        assert_true(geom_inside(&o, NULL, v3(r * 0.6, yi[i], r * 0.79)));
        assert_false(geom_inside(&o, NULL, v3(r * 0.6, yi[i], r * 0.81)));
    }
    vec3 lo, hi;
    assert_true(geom_bounds(&o, NULL, &lo, &hi));
    assert_true(lo.y <= -1 && hi.y >= 2 && hi.x >= 2 - sqrt(3) / 2);
}

/*
** Any ovus: the outline must be the bottom circle low down, the top circle
** high up, and in between a circle tangent to both (C¹ outline). Checked
** from hit distances alone: the outline is continuous across both seams
** and its slope matches on either side.
*/
static double ovus_rho(const iris_object *o, double y)
{
    double t[8];
    int k = hits(o, v3(-10, y, 0), v3(1, 0, 0), 0, 100, t, NULL, 8);
    return k == 2 ? 10 - t[0] : NAN;
}

/*
** Every surface crossing of an ovus along a ray is reported, the ones on
** the connection too: ovus.c skips the quartic for rays that miss the
** connection's slab or cylinder, and a wrong skip would lose exactly
** those. The reference is independent of the solver: geom_inside() on a
** dense grid along the ray (its changes of state are the crossings).
** Rays run from random points around the egg through random points in
** its box, many of them through the slab's edges, where the skip test
** is decided. Rays where two crossings (or a crossing and a grid
** sample's ambiguity) come within a few grid steps are tangent or
** nearly so, where a grid cannot count, and are left out.
*/
static void test_ovus_crossings(void **state)
{
    (void)state;
    const double radii[][2] = { { 1, 0.6 }, { 0.6, 0.9 }, { 0.4, 0.79 } };
    uint64_t seed = 88172645463325252u;
    int compared = 0;
    for (size_t c = 0; c < sizeof radii / sizeof radii[0]; c++) {
        iris_object o = mk(IRIS_OBJ_OVUS);
        o.u.ovus.r1 = radii[c][0];
        o.u.ovus.r2 = radii[c][1];
        vec3 lo, hi;
        assert_true(geom_bounds(&o, NULL, &lo, &hi));
        for (int k = 0; k < 400; k++) {
            double u[6];
            for (int i = 0; i < 6; i++) {
                seed ^= seed << 13;
                seed ^= seed >> 7;
                seed ^= seed << 17;
                u[i] = (double)(seed >> 11) / 9007199254740992.0;
            }
            /* from a sphere of radius 4 around the box's centre */
            vec3 mid = v3_scale(v3_add(lo, hi), 0.5);
            double th = 2 * M_PI * u[0], z = 2 * u[1] - 1;
            double rr = sqrt(1 - z * z);
            vec3 ro = v3_add(mid, v3_scale(v3(rr * cos(th), z, rr * sin(th)), 4));
            vec3 to = v3(lo.x + (hi.x - lo.x) * u[2],
                         lo.y + (hi.y - lo.y) * u[3],
                         lo.z + (hi.z - lo.z) * u[4]);
            vec3 rd = v3_norm(v3_sub(to, ro));
            double t[16];
            int n = hits(&o, ro, rd, 0, 8, t, NULL, 16);
            assert_true(n <= 16);
            /* the grid: 8 units in 40000 steps */
            const int N = 40000;
            double step = 8.0 / N, tr[16];
            int nt = 0;
            bool prev = geom_inside(&o, NULL, ro);
            for (int i = 1; i <= N && nt < 16; i++) {
                bool in = geom_inside(&o, NULL, v3_madd(ro, rd, i * step));
                if (in != prev)
                    tr[nt++] = (i - 0.5) * step;
                prev = in;
            }
            bool clear = true;
            for (int i = 1; i < n; i++)
                if (t[i] - t[i - 1] < 4 * step)
                    clear = false;
            for (int i = 1; i < nt; i++)
                if (tr[i] - tr[i - 1] < 4 * step)
                    clear = false;
            if (!clear)
                continue;
            compared++;
            assert_int_equal(n, nt);
            /* each crossing within the grid step that holds it */
            for (int i = 0; i < n; i++)
                assert_true(fabs(t[i] - tr[i]) <= step);
        }
    }
    /* nearly every ray is a clear case: the comparison is not vacuous */
    assert_true(compared > 1000);
}

static void test_ovus_shapes(void **state)
{
    (void)state;
    const double radii[][2] = { { 1, 0.5 }, { 1, 0.2 }, { 1, 1.5 },
                                { 0.8, 1.2 } };
    for (size_t c = 0; c < sizeof radii / sizeof radii[0]; c++) {
        iris_object o = mk(IRIS_OBJ_OVUS);
        double rb = radii[c][0], rt = radii[c][1];
        o.u.ovus.r1 = rb;
        o.u.ovus.r2 = rt;
        assert_null(geom_validate(&o));
        /* Extremes along the axis: -Rb and Rb + Rt */
        double t[8];
        assert_int_equal(hits(&o, v3(0, -5, 0), v3(0, 1, 0), 0, 100, t,
                              NULL, 8), 2);
        assert_rel(t[0], 5 - rb, 1e-12);
        assert_rel(t[1], 5 + rb + rt, 1e-12);
        /* Near the bottom pole the outline is the bottom sphere, near the
        ** top the top sphere */
        double y = -0.95 * rb;
        assert_rel(ovus_rho(&o, y), sqrt(rb * rb - y * y), 1e-9);
        y = rb + 0.95 * rt;
        assert_rel(ovus_rho(&o, y), sqrt(rt * rt - (y - rb) * (y - rb)),
                   1e-9);
        /* Scan the outline: no jump (a missing or misplaced part would
        ** jump by far more than the 1e-3 step allows) and the slope
        ** changes smoothly: second differences stay small (C¹; a kink of
        ** angle a shows as a second difference ~ a·step) */
        /* (away from the poles, where rho'' is unbounded; in this range
        ** |rho''|·step² < 2.5e-5, while a slope jump of 0.05 would give
        ** 5e-5) */
        double step = 1e-3, prev = NAN, prev2 = NAN;
        for (double yy = -0.8 * rb; yy < rb + 0.8 * rt; yy += step) {
            double r = ovus_rho(&o, yy);
            assert_false(isnan(r));
            if (!isnan(prev))
                assert_true(fabs(r - prev) < 0.02);
            if (!isnan(prev2))
                assert_true(fabs(r - 2 * prev + prev2) < 5e-5);
            prev2 = prev;
            prev = r;
        }
    }
    /* Rt >= 2·Rb: POV-Ray substitutes the sphere r Rt at (0, Rb, 0) */
    iris_object s = mk(IRIS_OBJ_OVUS);
    s.u.ovus.r1 = 0.5;
    s.u.ovus.r2 = 1;
    double t[8];
    assert_int_equal(hits(&s, v3(-10, 0.5, 0), v3(1, 0, 0), 0, 100, t,
                          NULL, 8), 2);
    assert_rel(t[0], 9, 1e-12);
    assert_rel(t[1], 11, 1e-12);
    assert_true(geom_inside(&s, NULL, v3(0, 1.4, 0)));
    assert_false(geom_inside(&s, NULL, v3(0, -0.6, 0)));
    /* Bad radii are reported, not rendered */
    s.u.ovus.r1 = -1;
    assert_non_null(geom_validate(&s));
    s.u.ovus.r1 = 0;
    assert_non_null(geom_validate(&s));
}

/* ------------------------------------------------------------------ */
/* sphere_sweep                                                         */
/* ------------------------------------------------------------------ */

static iris_object sweep(int spline, int n, iris_vec3 *c, double *r)
{
    iris_object o = mk(IRIS_OBJ_SPHERE_SWEEP);
    o.u.sphere_sweep.spline = spline;
    o.u.sphere_sweep.n_spheres = n;
    o.u.sphere_sweep.centres = c;
    o.u.sphere_sweep.radii = r;
    return o;
}

/*
** The capsule a-b of radius r, intersected independently: the infinite
** cylinder's quadratic clipped to the segment, and the two end spheres.
** The capsule is convex, so its hits are the smallest entry and largest
** exit of the three; returns 0 or 2.
*/
static int capsule(vec3 a, vec3 b, double r, vec3 o, vec3 d, double *t)
{
    double tin = INFINITY, tout = -INFINITY;
    vec3 w = v3_norm(v3_sub(b, a));
    double len = v3_len(v3_sub(b, a));
    for (int s = 0; s < 2; s++) {
        vec3 c = s ? b : a;
        vec3 oc = v3_sub(o, c);
        double B = v3_dot(oc, d), C = v3_len2(oc) - r * r, A = v3_len2(d);
        double disc = B * B - A * C;
        if (disc > 0) {
            tin = fmin(tin, (-B - sqrt(disc)) / A);
            tout = fmax(tout, (-B + sqrt(disc)) / A);
        }
    }
    vec3 oa = v3_sub(o, a);
    vec3 dp = v3_sub(d, v3_scale(w, v3_dot(d, w)));
    vec3 op = v3_sub(oa, v3_scale(w, v3_dot(oa, w)));
    double A = v3_len2(dp), B = v3_dot(op, dp), C = v3_len2(op) - r * r;
    double disc = B * B - A * C;
    if (A > 0 && disc > 0) {
        for (int s = -1; s <= 1; s += 2) {
            double tt = (-B + s * sqrt(disc)) / A;
            double h = v3_dot(v3_madd(oa, d, tt), w);
            if (h >= 0 && h <= len) {
                tin = fmin(tin, tt);
                tout = fmax(tout, tt);
            }
        }
    }
    if (!(tin < tout))
        return 0;
    t[0] = tin;
    t[1] = tout;
    return 2;
}

/* A few fixed rays at a capsule along x from -1 to 1, radius 0.5. */
static void check_capsule(const iris_object *o)
{
    const vec3 a = v3(-1, 0, 0), b = v3(1, 0, 0);
    const struct { vec3 o, d; } rays[] = {
        /* perpendicular to the axis: the envelope polynomial is b², a
        ** double root, handled by the A = 0 spheres */
        { { 0.3, 0.2, -5 }, { 0, 0, 1 } },
        { { -0.7, -0.1, 5 }, { 0, 0, -2 } },
        /* through an end cap only */
        { { 1.2, 0.1, -5 }, { 0, 0, 1 } },
        /* along the axis */
        { { -5, 0, 0 }, { 1, 0, 0 } },
        /* oblique, through side and cap */
        { { -4, 1, -3 }, { 0.8, -0.2, 0.6 } },
        { { 3, -2, 1 }, { -0.5, 0.45, -0.2 } },
        { { 0.95, 3, 0.01 }, { 0.01, -1, 0 } },
    };
    for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
        double te[2], t[8];
        vec3 n[8];
        int ke = capsule(a, b, 0.5, rays[i].o, rays[i].d, te);
        int k = hits(o, rays[i].o, rays[i].d, 0, 1e6, t, n, 8);
        assert_int_equal(k, ke);
        for (int j = 0; j < k; j++) {
            /* 1e-9 relative: both sides solve quadratics in double; the
            ** sweep's come from a degree-2 or degree-10 polynomial
            ** refined to a few ulps */
            assert_rel(t[j], te[j], 1e-9);
            /* outward normal: from the nearest axis point */
            vec3 p = v3_madd(rays[i].o, rays[i].d, t[j]);
            double h = fmax(-1, fmin(1, p.x));
            vec3 ne = v3_norm(v3_sub(p, v3(h, 0, 0)));
            assert_near(v3_dot(n[j], ne), 1, 1e-6);
        }
    }
    /* Inside / outside */
    assert_true(geom_inside(o, NULL, v3(0.9, 0.3, 0.3)));
    assert_true(geom_inside(o, NULL, v3(1.4, 0, 0)));
    assert_false(geom_inside(o, NULL, v3(0, 0.36, 0.36)));
    assert_false(geom_inside(o, NULL, v3(1.3, 0.3, 0.3)));
    vec3 lo, hi;
    assert_true(geom_bounds(o, NULL, &lo, &hi));
    assert_near(lo.x, -1.5, 1e-12);
    assert_near(hi.x, 1.5, 1e-12);
    assert_near(hi.y, 0.5, 1e-12);
    assert_near(lo.z, -0.5, 1e-12);
}

static void test_sweep_capsules(void **state)
{
    (void)state;
    /* Two equal spheres, linear: a capsule */
    iris_vec3 c2[2] = { { -1, 0, 0 }, { 1, 0, 0 } };
    double r2[2] = { 0.5, 0.5 };
    iris_object o = sweep(0, 2, c2, r2);
    assert_null(geom_validate(&o));
    check_capsule(&o);
    /* Three collinear spheres, linear: the same capsule with a seam */
    iris_vec3 c3[3] = { { -1, 0, 0 }, { 0.2, 0, 0 }, { 1, 0, 0 } };
    double r3[3] = { 0.5, 0.5, 0.5 };
    o = sweep(0, 3, c3, r3);
    check_capsule(&o);
    /* Collinear, equally spaced points: Catmull-Rom (cubic_spline) and
    ** the uniform B-spline both reduce to the straight line from the
    ** second to the next-to-last point at uniform speed, so 5 points at
    ** x = -2..2 sweep the capsule from -1 to 1 */
    iris_vec3 c5[5] = { { -2, 0, 0 }, { -1, 0, 0 }, { 0, 0, 0 },
                        { 1, 0, 0 }, { 2, 0, 0 } };
    double r5[5] = { 0.5, 0.5, 0.5, 0.5, 0.5 };
    o = sweep(2, 5, c5, r5);
    assert_null(geom_validate(&o));
    check_capsule(&o);
    o = sweep(1, 5, c5, r5);
    check_capsule(&o);
    /* Too few spheres for the spline */
    o = sweep(1, 3, c5, r5);
    assert_non_null(geom_validate(&o));
    o = sweep(0, 1, c5, r5);
    assert_non_null(geom_validate(&o));
}

/* Brute force: min over 20000 samples per segment of |p - c(u)| - |r(u)|
** (the signed distance to the union of balls, up to sampling). */
static double brute_depth(const iris_object *o, vec3 p)
{
    static const double M[2][4][4] = {
        { { 1.0 / 6, 4.0 / 6, 1.0 / 6, 0 }, { -0.5, 0, 0.5, 0 },
          { 0.5, -1, 0.5, 0 }, { -1.0 / 6, 0.5, -0.5, 1.0 / 6 } },
        { { 0, 1, 0, 0 }, { -0.5, 0, 0.5, 0 }, { 1, -2.5, 2, -0.5 },
          { -0.5, 1.5, -1.5, 0.5 } },
    };
    int sp = o->u.sphere_sweep.spline, n = o->u.sphere_sweep.n_spheres;
    const vec3 *P = o->u.sphere_sweep.centres;
    const double *R = o->u.sphere_sweep.radii;
    double best = INFINITY;
    int nseg = sp == 0 ? n - 1 : n - 3;
    for (int s = 0; s < nseg; s++)
        for (int k = 0; k <= 20000; k++) {
            double u = k / 20000.0;
            vec3 c = v3(0, 0, 0);
            double r = 0;
            if (sp == 0) {
                c = v3_lerp(P[s], P[s + 1], u);
                r = R[s] + u * (R[s + 1] - R[s]);
            } else {
                /* POV-Ray's basis, as [1 u u² u³]·M·[P_s .. P_s+3] */
                double pw[4] = { 1, u, u * u, u * u * u };
                for (int j = 0; j < 4; j++) {
                    double wj = 0;
                    for (int i = 0; i < 4; i++)
                        wj += pw[i] * M[sp - 1][i][j];
                    c = v3_madd(c, P[s + j], wj);
                    r += wj * R[s + j];
                }
            }
            best = fmin(best, v3_len(v3_sub(p, c)) - fabs(r));
        }
    return best;
}

static double rnd(unsigned *s)
{
    *s = *s * 1664525u + 1013904223u;
    return (*s >> 8) / 16777216.0;
}

/*
** Curved sweeps of every spline with varying radii: every hit lies on the
** boundary of the union of balls, and between hits the ray is inside
** exactly where brute-force sampling says so (checked at midpoints, and
** beyond the last hit). Sampling 20000 steps per segment resolves the
** distance to ~1e-4 here, so points within 3e-3 of the surface are not
** judged.
*/
static void test_sweep_splines(void **state)
{
    (void)state;
    iris_vec3 c[6] = { { -2, 0, 0 }, { -1, 1, 0.3 }, { 0, -0.5, 0 },
                       { 1, 0.8, -0.4 }, { 2, 0, 0.2 }, { 2.5, 1, 0 } };
    double r[6] = { 0.3, 0.5, 0.2, 0.4, 0.25, 0.35 };
    for (int sp = 0; sp < 3; sp++) {
        iris_object o = sweep(sp, 6, c, r);
        assert_null(geom_validate(&o));
        vec3 lo, hi;
        assert_true(geom_bounds(&o, NULL, &lo, &hi));
        unsigned seed = 7 + sp;
        int n_hit_rays = 0;
        for (int i = 0; i < 60; i++) {
            vec3 a = v3(lo.x + (hi.x - lo.x) * rnd(&seed),
                        lo.y + (hi.y - lo.y) * rnd(&seed),
                        lo.z + (hi.z - lo.z) * rnd(&seed));
            vec3 d = v3_norm(v3(rnd(&seed) - 0.5, rnd(&seed) - 0.5,
                                rnd(&seed) - 0.5));
            vec3 ro = v3_madd(a, d, -8);
            double t[32];
            int k = hits(&o, ro, d, 0, 100, t, NULL, 32);
            assert_true(k <= 32);
            if (k > 0)
                n_hit_rays++;
            /* Every hit on the surface: brute distance ~ 0 */
            for (int j = 0; j < k; j++)
                assert_near(brute_depth(&o, v3_madd(ro, d, t[j])), 0, 2e-4);
            /* Entries and exits alternate: inside between t[2j], t[2j+1] */
            assert_true(k % 2 == 0);
            for (int j = 0; j <= k; j++) {
                double ta = j ? t[j - 1] : 0, tb = j < k ? t[j] : 100;
                double tm = (ta + tb) / 2;
                vec3 p = v3_madd(ro, d, tm);
                double bd = brute_depth(&o, p);
                if (fabs(bd) < 3e-3)
                    continue;
                assert_int_equal(bd < 0, j % 2 == 1);
                assert_int_equal(geom_inside(&o, NULL, p), bd < 0);
            }
        }
        /* The rays aim through the box: many must hit, or the test
        ** would prove nothing */
        assert_true(n_hit_rays >= 15);
        /* The box holds the whole sweep: brute-force points on it */
        for (int i = 0; i < 200; i++) {
            vec3 p = v3(lo.x - 0.1 + (hi.x - lo.x + 0.2) * rnd(&seed),
                        lo.y - 0.1 + (hi.y - lo.y + 0.2) * rnd(&seed),
                        lo.z - 0.1 + (hi.z - lo.z + 0.2) * rnd(&seed));
            if (p.x < lo.x || p.y < lo.y || p.z < lo.z || p.x > hi.x ||
                p.y > hi.y || p.z > hi.z)
                assert_true(brute_depth(&o, p) > 0);
        }
    }
}

/* ------------------------------------------------------------------ */
/* parametric                                                           */
/* ------------------------------------------------------------------ */

/* The function k·trig1(param a)·trig2(param b), trig = 0 none, 1 cos,
** 2 sin (built as the parser would compile it). */
struct fn_buf {
    iris_fn fn;
    iris_fn_insn code[8];
};

static void trig_fn(struct fn_buf *f, double k, int a, int ta, int b, int tb)
{
    memset(f, 0, sizeof *f);
    int n = 0;
    f->code[n].op = IRIS_FN_CONST;
    f->code[n++].value = k;
    const int par[2] = { a, b }, trig[2] = { ta, tb };
    for (int i = 0; i < 2; i++) {
        if (!trig[i])
            continue;
        f->code[n].op = IRIS_FN_PARAM;
        f->code[n++].arg = par[i];
        f->code[n].op = IRIS_FN_BUILTIN;
        f->code[n].arg = trig[i] == 1 ? IRIS_FB_COS : IRIS_FB_SIN;
        f->code[n++].nargs = 1;
        f->code[n++].op = IRIS_FN_MUL;
    }
    f->fn.n_params = 3;
    f->fn.n_code = n;
    f->fn.code = f->code;
    f->fn.max_stack = 3;
    f->fn.n_results = 1;
}

/*
** The unit sphere as (cos u sin v, cos v, sin u sin v), u in [0, 2pi],
** v in [0, pi]: both partial derivatives of every coordinate are at most
** 1, so POV-Ray's default max_gradient 1 bounds it. The hits must lie on
** the analytic sphere within the method's accuracy: the cell found is
** smaller than 'accuracy' in uv or along the ray, and POV-Ray evaluates
** f - accuracy, moving the surface by accuracy on each axis; with rays
** no steeper than 45 degrees to the surface that is < 4·accuracy along
** the ray, so 5·accuracy is the bar.
*/
static void test_parametric_sphere(void **state)
{
    (void)state;
    struct fn_buf fx, fy, fz;
    trig_fn(&fx, 1, 0, 1, 1, 2);
    trig_fn(&fy, 1, 1, 1, 0, 0);
    trig_fn(&fz, 1, 0, 2, 1, 2);
    iris_object o = mk(IRIS_OBJ_PARAMETRIC);
    o.u.parametric.fx = &fx.fn;
    o.u.parametric.fy = &fy.fn;
    o.u.parametric.fz = &fz.fn;
    o.u.parametric.uv_lo.u = 0;
    o.u.parametric.uv_lo.v = 0;
    o.u.parametric.uv_hi.u = 2 * M_PI;
    o.u.parametric.uv_hi.v = M_PI;
    /* no contained_by: POV-Ray's box -1..1. The search starts 4·accuracy
    ** past the container's entry (POV-Ray's Depth1 += 4·accuracy), so
    ** the sphere's front pole, on the box face, is skipped and the ray
    ** finds the back */
    assert_null(geom_validate(&o));
    {
        double t[4];
        assert_int_equal(hits(&o, v3(0, 0, -5), v3(0, 0, 1), 0, 100, t,
                              NULL, 4), 1);
        assert_near(t[0], 6, 5 * 0.001);
        vec3 lo, hi;
        assert_true(geom_bounds(&o, NULL, &lo, &hi));
        assert_near(lo.x, -1, 0);
        assert_near(hi.z, 1, 0);
    }
    o.u.parametric.lo = v3(-2, -2, -2);
    o.u.parametric.hi = v3(2, 2, 2);
    const double accs[] = { 0, 0.01 };   /* 0: the default, 0.001 */
    for (int a = 0; a < 2; a++) {
        o.u.parametric.accuracy = accs[a];
        double acc = accs[a] > 0 ? accs[a] : 0.001;
        const double xy[][2] = { { 0, 0 }, { 0.3, 0.2 }, { -0.5, 0.4 },
                                 { 0.6, -0.3 }, { -0.2, -0.65 } };
        for (size_t i = 0; i < sizeof xy / sizeof xy[0]; i++) {
            double x = xy[i][0], y = xy[i][1];
            double t[4];
            vec3 n[4];
            int k = hits(&o, v3(x, y, -5), v3(0, 0, 1), 0, 100, t, n, 4);
            /* POV-Ray reports the nearest hit only */
            assert_int_equal(k, 1);
            double te = 5 - sqrt(1 - x * x - y * y);
            assert_near(t[0], te, 5 * acc);
            /* The normal from forward differences of step 'accuracy'
            ** points along ±(the sphere's normal) within ~2·accuracy
            ** radians; its sign follows the uv orientation */
            vec3 p = v3(x, y, -(5 - te));
            assert_near(fabs(v3_dot(n[0], v3_norm(p))), 1, 1e-2);
        }
        /* Misses: beside the sphere, and pointing away */
        double t[4];
        assert_int_equal(hits(&o, v3(0.8, 0.7, -5), v3(0, 0, 1), 0, 100, t,
                              NULL, 4), 0);
        assert_int_equal(hits(&o, v3(0, 0, -5), v3(0, 0, -1), 0, 100, t,
                              NULL, 4), 0);
        /* The search range: a hit beyond t1 is not reported */
        assert_int_equal(hits(&o, v3(0, 0, -5), v3(0, 0, 1), 0, 3.9, t,
                              NULL, 4), 0);
        /* ... nor one before t0 (nearer hits are not replaced by
        ** farther ones, as in POV-Ray) */
        assert_int_equal(hits(&o, v3(0, 0, -5), v3(0, 0, 1), 4.5, 100, t,
                              NULL, 4), 0);
    }
    /* No inside (POV-Ray has none); bounds are the container */
    assert_false(geom_inside(&o, NULL, v3(0, 0, 0)));
    vec3 lo, hi;
    assert_true(geom_bounds(&o, NULL, &lo, &hi));
    assert_near(lo.x, -2, 0);
    assert_near(hi.z, 2, 0);
    /* A container that cuts the sphere: only the part inside is found */
    o.u.parametric.lo = v3(-2, -2, 0);
    o.u.parametric.hi = v3(2, 2, 2);
    double t[4];
    assert_int_equal(hits(&o, v3(0, 0, -5), v3(0, 0, 1), 0, 100, t, NULL,
                          4), 1);
    assert_near(t[0], 6, 5 * 0.01);
}

/* ------------------------------------------------------------------ */
/* lemon                                                                */
/* ------------------------------------------------------------------ */

static iris_object lemon(vec3 base, double rb, vec3 cap, double rc,
                         double inner)
{
    iris_object o = mk(IRIS_OBJ_LEMON);
    o.u.lemon.base = base;
    o.u.lemon.cap = cap;
    o.u.lemon.base_radius = rb;
    o.u.lemon.cap_radius = rc;
    o.u.lemon.inner_radius = inner;
    return o;
}

/*
** Lemons worked out by hand. (1) Pointed ends, base <0,0,0>, cap <0,2,0>,
** inner radius 1.25: the arc through both tips with radius 1.25 has its
** centre at height 1 and 0.75 beyond the axis (0.75² + 1² = 1.25²), so
** rho(y) = sqrt(1.25² - (y - 1)²) - 0.75. (2) A barrel along z, ends of
** radius 1 at z = 0 and 2, inner radius 2: centre at z = 1 and
** sqrt(3) - 1 beyond the axis, rho(z) = sqrt(4 - (z - 1)²) - (sqrt(3) - 1),
** closed by discs unless open. (3) Inner radius 0 is raised to the
** smallest that reaches both rims, here the sphere of radius 1 at y = 1.
*/
static void test_lemon(void **state)
{
    (void)state;
    double t[8];
    vec3 n[8];
    iris_object o = lemon(v3(0, 0, 0), 0, v3(0, 2, 0), 0, 1.25);
    assert_null(geom_validate(&o));
    const double ys[] = { 0.2, 0.7, 1, 1.6, 1.95 };
    for (size_t i = 0; i < sizeof ys / sizeof ys[0]; i++) {
        double y = ys[i];
        double r = sqrt(1.25 * 1.25 - (y - 1) * (y - 1)) - 0.75;
        /* quartic roots refined to full precision: 1e-9 relative */
        assert_int_equal(hits(&o, v3(-10, y, 0), v3(1, 0, 0), 0, 100, t, n,
                              8), 2);
        assert_rel(t[0], 10 - r, 1e-9);
        assert_rel(t[1], 10 + r, 1e-9);
        assert_true(n[0].x < 0 && n[1].x > 0);
        assert_true(geom_inside(&o, NULL, v3(0.99 * r, y, 0)));
        assert_false(geom_inside(&o, NULL, v3(0, y, 1.01 * r)));
    }
    /* the outward normal at the equator is horizontal */
    assert_int_equal(hits(&o, v3(0, 1, -10), v3(0, 0, 1), 0, 100, t, n, 8),
                     2);
    assert_near(n[0].z, -1, 1e-9);
    assert_false(geom_inside(&o, NULL, v3(0, 2.1, 0)));

    iris_object b = lemon(v3(0, 0, 0), 1, v3(0, 0, 2), 1, 2);
    assert_null(geom_validate(&b));
    double h = sqrt(3) - 1;
    const double zs[] = { 0.1, 0.5, 1, 1.7 };
    for (size_t i = 0; i < sizeof zs / sizeof zs[0]; i++) {
        double z = zs[i], r = sqrt(4 - (z - 1) * (z - 1)) - h;
        assert_int_equal(hits(&b, v3(-10, 0, z), v3(1, 0, 0), 0, 100, t, n,
                              8), 2);
        assert_rel(t[0], 10 - r, 1e-9);
        assert_rel(t[1], 10 + r, 1e-9);
    }
    /* Through both end discs along the axis */
    assert_int_equal(hits(&b, v3(0.3, 0.2, -5), v3(0, 0, 1), 0, 100, t, n,
                          8), 2);
    assert_rel(t[0], 5, 1e-12);
    assert_rel(t[1], 7, 1e-12);
    assert_near(n[0].z, -1, 1e-12);
    assert_near(n[1].z, 1, 1e-12);
    /* open: the same ray passes through */
    b.open = true;
    assert_int_equal(hits(&b, v3(0.3, 0.2, -5), v3(0, 0, 1), 0, 100, t, n,
                          8), 0);
    vec3 lo, hi;
    assert_true(geom_bounds(&b, NULL, &lo, &hi));
    assert_true(lo.z <= 0 && hi.z >= 2 && hi.x >= 2 - h && lo.y <= h - 2);

    iris_object s = lemon(v3(0, 0, 0), 0, v3(0, 2, 0), 0, 0);
    assert_null(geom_validate(&s));
    assert_int_equal(hits(&s, v3(-10, 1, 0), v3(1, 0, 0), 0, 100, t, n, 8),
                     2);
    assert_rel(t[0], 9, 1e-12);
    assert_rel(t[1], 11, 1e-12);

    /* Bad input is reported */
    s = lemon(v3(1, 1, 1), 1, v3(1, 1, 1), 1, 2);
    assert_non_null(geom_validate(&s));
    s = lemon(v3(0, 0, 0), -1, v3(0, 1, 0), 1, 2);
    assert_non_null(geom_validate(&s));
}

/* ------------------------------------------------------------------ */
/* bicubic_patch tessellation                                           */
/* ------------------------------------------------------------------ */

/* The Bezier surface at (u, v), u along the first index (the rows as
** written), evaluated from the Bernstein form independently of the
** subdivision. */
static vec3 bezier_at(const iris_object *o, double u, double v)
{
    double bu[4], bv[4];
    for (int k = 0; k < 4; k++) {
        double c = k == 0 || k == 3 ? 1 : 3;
        bu[k] = c * pow(u, k) * pow(1 - u, 3 - k);
        bv[k] = c * pow(v, k) * pow(1 - v, 3 - k);
    }
    vec3 p = v3(0, 0, 0);
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            p = v3_madd(p, o->u.bicubic.points[4 * i + j], bu[i] * bv[j]);
    return p;
}

static int tess_count(const iris_object *o)
{
    int nt = -1;
    vec3 *p = NULL, *n = NULL;
    iris_vec2 *uv = NULL;
    assert_null(geom_bicubic_tessellate(o, &nt, &p, &n, &uv));
    iris_free(p);
    iris_free(n);
    iris_free(uv);
    return nt;
}

static void test_bicubic_tessellation(void **state)
{
    (void)state;
    iris_object o = mk(IRIS_OBJ_BICUBIC_PATCH);
    o.u.bicubic.type = 1;
    /* A dome: rows i, columns j; z rises in the middle */
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++)
            o.u.bicubic.points[4 * i + j] =
                v3(j, i * 0.7, (i == 1 || i == 2) && (j == 1 || j == 2)
                                   ? 2 : 0);
    /* flatness 0: the uniform grid, 2^2 cells in u (rows) by 2^1 in v */
    o.u.bicubic.u_steps = 2;
    o.u.bicubic.v_steps = 1;
    int nt = 0;
    vec3 *p = NULL, *n = NULL;
    iris_vec2 *uv = NULL;
    assert_null(geom_bicubic_tessellate(&o, &nt, &p, &n, &uv));
    assert_int_equal(nt, 4 * 2 * 2);
    for (int k = 0; k < 3 * nt; k++) {
        /* uv is POV-Ray's texture (v, u); vertices are corner points of
        ** the subdivided nets: on the surface to rounding (1e-12), at
        ** multiples of 1/4 in u and 1/2 in v */
        double u = uv[k].v, v = uv[k].u;
        assert_near(fmod(u * 4, 1), 0, 1e-12);
        assert_near(fmod(v * 2, 1), 0, 1e-12);
        vec3 e = bezier_at(&o, u, v);
        assert_near(v3_len(v3_sub(p[k], e)), 0, 1e-12);
        assert_true(v3_len(n[k]) > 0);
    }
    iris_free(p);
    iris_free(n);
    iris_free(uv);
    /* POV-Ray's default of 0 steps: one cell */
    o.u.bicubic.u_steps = o.u.bicubic.v_steps = 0;
    assert_int_equal(tess_count(&o), 2);
    /* flatness stops early: a flat net is one cell at any depth */
    iris_object f = o;
    for (int k = 0; k < 16; k++)
        f.u.bicubic.points[k].z = 0;
    f.u.bicubic.u_steps = f.u.bicubic.v_steps = 5;
    f.u.bicubic.flatness = 0.01;
    assert_int_equal(tess_count(&f), 2);
    f.u.bicubic.flatness = 0;
    assert_int_equal(tess_count(&f), 2 << 10);
    /* ... and is measured in world space, after the object's transform,
    ** as POV-Ray moves the control points: the dome subdivides further
    ** when scaled up than as it is */
    o.u.bicubic.u_steps = o.u.bicubic.v_steps = 6;
    o.u.bicubic.flatness = 0.05;
    int plain = tess_count(&o);
    assert_true(plain > 2 && plain < 2 << 12);
    xf_scale(&o.transform, v3(10, 10, 10));
    o.has_transform = true;
    int scaled = tess_count(&o);
    assert_true(scaled > plain);
}

/* ------------------------------------------------------------------ */
/* What the parser keeps for these shapes                               */
/* ------------------------------------------------------------------ */

static iris_scene *scene_of(const char *sdl)
{
    iris_scene *sc = NULL;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = iris_parse_string("t.pov", sdl, strlen(sdl), NULL,
                                            &sc, &d);
    for (int i = 0; i < d.n && st != IRIS_OK; i++)
        iris_diag_format(&d.items[i], stderr);
    iris_diag_list_fini(&d);
    assert_int_equal(st, IRIS_OK);
    assert_non_null(sc);
    assert_int_equal(sc->n_objects, 1);
    return sc;
}

/* parametric keeps accuracy and max_gradient and takes POV-Ray's
** 'precompute DEPTH, x, y, z'; bicubic_patch takes uv_vectors and has
** POV-Ray's default of 0 steps. */
static void test_parsed(void **state)
{
    (void)state;
    iris_scene *sc = scene_of(
        "parametric { function { u } function { v } function { 0 } "
        "<0, 0>, <1, 1> contained_by { box { -2, 2 } } "
        "accuracy 0.005 max_gradient 3 precompute 10, x, y, z "
        "pigment { rgb 1 } }");
    const iris_object *o = sc->objects[0];
    assert_int_equal(o->kind, IRIS_OBJ_PARAMETRIC);
    assert_near(o->u.parametric.accuracy, 0.005, 0);
    assert_near(o->u.parametric.max_gradient, 3, 0);
    assert_near(o->u.parametric.hi.x, 2, 0);
    iris_scene_destroy(sc);
    sc = scene_of("parametric { function { u } function { v } "
                  "function { 0 } <0, 0>, <1, 1> precompute 12 x,z }");
    assert_near(sc->objects[0]->u.parametric.accuracy, 0, 0);
    iris_scene_destroy(sc);
    sc = scene_of("bicubic_patch { type 1 flatness 0.1 "
                  "uv_vectors <0,0> <1,0> <1,1> <0,1> "
                  "<0,0,0>, <1,0,0>, <2,0,0>, <3,0,0>, <0,1,0>, <1,1,1>, "
                  "<2,1,1>, <3,1,0>, <0,2,0>, <1,2,1>, <2,2,1>, <3,2,0>, "
                  "<0,3,0>, <1,3,0>, <2,3,0>, <3,3,0> }");
    o = sc->objects[0];
    assert_int_equal(o->kind, IRIS_OBJ_BICUBIC_PATCH);
    assert_int_equal(o->u.bicubic.u_steps, 0);
    assert_int_equal(o->u.bicubic.v_steps, 0);
    assert_near(o->u.bicubic.points[15].y, 3, 0);
    iris_scene_destroy(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ovus_equal_radii),
        cmocka_unit_test(test_ovus_shapes),
        cmocka_unit_test(test_ovus_crossings),
        cmocka_unit_test(test_sweep_capsules),
        cmocka_unit_test(test_sweep_splines),
        cmocka_unit_test(test_parametric_sphere),
        cmocka_unit_test(test_lemon),
        cmocka_unit_test(test_bicubic_tessellation),
        cmocka_unit_test(test_parsed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
