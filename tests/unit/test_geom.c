/* SPDX-License-Identifier: MIT */
/*
** test_geom.c: polynomial roots and the analytic shapes of src/geometry
** in object space, against closed-form answers.
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "geometry/geom.h"
#include "geometry/roots.h"

/* Expands prod (t - r_i) into ascending coefficients. */
static void from_roots(const double *r, int n, double *c)
{
    c[0] = 1;
    for (int i = 1; i <= n; i++)
        c[i] = 0;
    for (int k = 0; k < n; k++) {
        for (int i = k + 1; i > 0; i--)
            c[i] = c[i - 1] - r[k] * c[i];
        c[0] = -r[k] * c[0];
    }
}

/* Known simple roots come back to 1e-10: the coefficients themselves are
** exact in double for these small integers, so the only error is the
** refinement's, which stops at a few ulps. */
static void test_roots_known(void **state)
{
    (void)state;
    double r4[4] = { 1, 2, 3, 4 }, c[8], out[8];
    from_roots(r4, 4, c);
    int n = roots_in_interval(c, 4, -100, 100, out);
    assert_int_equal(n, 4);
    for (int i = 0; i < 4; i++)
        assert_near(out[i], r4[i], 1e-10);

    /* Only the roots inside the interval */
    n = roots_in_interval(c, 4, 1.5, 3.5, out);
    assert_int_equal(n, 2);
    assert_near(out[0], 2, 1e-10);
    assert_near(out[1], 3, 1e-10);

    /* Close roots and a far one; relative 1e-9 (conditioning of the
    ** pair 1, 1.001 costs ~3 digits of the 16) */
    double rc[4] = { -5, 1, 1.001, 100 };
    from_roots(rc, 4, c);
    n = roots_in_interval(c, 4, -INFINITY, INFINITY, out);
    assert_int_equal(n, 4);
    for (int i = 0; i < 4; i++)
        assert_rel(out[i], rc[i], 1e-9);

    /* Degree 6 */
    double r6[6] = { -3, -1, 0.5, 2, 7, 11 };
    from_roots(r6, 6, c);
    n = roots_in_interval(c, 6, -INFINITY, INFINITY, out);
    assert_int_equal(n, 6);
    for (int i = 0; i < 6; i++)
        assert_near(out[i], r6[i], 1e-8);

    /* (t² + 1)(t² + 4) has no real roots */
    double cc[5] = { 4, 0, 5, 0, 1 };
    assert_int_equal(roots_in_interval(cc, 4, -1e9, 1e9, out), 0);

    /* Leading zero coefficients reduce the degree: 2t - 1 */
    double lin[5] = { -1, 2, 0, 0, 0 };
    assert_int_equal(roots_in_interval(lin, 4, -10, 10, out), 1);
    assert_near(out[0], 0.5, 1e-15);

    /* NaN coefficients give no roots rather than garbage */
    double bad[3] = { 1, NAN, 1 };
    assert_int_equal(roots_in_interval(bad, 2, -10, 10, out), 0);
}

/* Multiplies c (degree n, ascending) by t² - 2·alpha·t + alpha² + beta2:
** a pair of complex roots alpha ± i·sqrt(beta2) when beta2 > 0. */
static void times_pair(double *c, int n, double alpha, double beta2)
{
    double q[3] = { alpha * alpha + beta2, -2 * alpha, 1 }, o[40] = { 0 };
    for (int i = 0; i <= n; i++)
        for (int j = 0; j < 3; j++)
            o[i + j] += c[i] * q[j];
    for (int i = 0; i <= n + 2; i++)
        c[i] = o[i];
}

/* A deterministic generator for the randomised cases (xorshift). */
static double unit_rand(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/*
** roots.c skips the whole solve when a Bernstein bound proves that the
** polynomial keeps one sign on the interval. The risk is a false proof
** that loses real roots; the hardest cases are polynomials that dip
** close to zero without crossing (complex pairs alpha ± i·beta near the
** interval) next to ones that barely cross. Each case is built from
** known roots, so the expected count and values are exact.
*/
static void test_roots_near_tangent(void **state)
{
    (void)state;
    double c[40], out[40];
    /* A real pair 0.3 ± 1e-7 between two far roots: same sign at both
    ** ends of [0, 1], so only the full solve can find it. The pair's
    ** roots are conditioned by their separation: |p'| ~ 2e-7·(2.3·3.3)
    ** against a Horner error ~1e-16·sum|c| ~ 2e-15 gives ~1e-9; 1e-8
    ** is a tenth of the separation. */
    double r2[2] = { -2, -3 };
    from_roots(r2, 2, c);
    times_pair(c, 2, 0.3, -1e-14);
    int n = roots_in_interval(c, 4, 0, 1, out);
    assert_int_equal(n, 2);
    assert_near(out[0], 0.3 - 1e-7, 1e-8);
    assert_near(out[1], 0.3 + 1e-7, 1e-8);
    /* The same dip not reaching zero: no root */
    from_roots(r2, 2, c);
    times_pair(c, 2, 0.3, 1e-14);
    assert_int_equal(roots_in_interval(c, 4, 0, 1, out), 0);

    /* Random degree 2..10 on [0, 1] and on a shifted interval: simple
    ** real roots (0.01 apart or more), roots outside, and complex pairs
    ** whose real part lies inside and imaginary part is 1e-4..1e-1 (a
    ** dip towards zero). Every real root inside must come back, as
    ** accurately as its conditioning allows. */
    uint64_t seed = 0x9e3779b97f4a7c15u;
    int unresolved = 0;
    for (int trial = 0; trial < 3000; trial++) {
        double lo = trial % 2 ? 0.0 : -3.0, hi = trial % 2 ? 1.0 : 5.0;
        double w = hi - lo;
        int nreal = (int)(unit_rand(&seed) * 4);
        double r[12];
        int nr = 0;
        for (int i = 0; i < nreal; i++) {
            double x = lo + w * (0.02 + 0.96 * unit_rand(&seed));
            bool close = false;
            for (int k = 0; k < nr; k++)
                if (fabs(r[k] - x) < 0.01 * w)
                    close = true;
            if (!close)
                r[nr++] = x;
        }
        int inside = nr;
        int nout = (int)(unit_rand(&seed) * 3);
        for (int i = 0; i < nout; i++)
            r[nr++] = unit_rand(&seed) < 0.5 ? lo - 0.5 * w * unit_rand(&seed) - 1e-3
                                             : hi + 0.5 * w * unit_rand(&seed) + 1e-3;
        from_roots(r, nr, c);
        int deg = nr;
        int npairs = 1 + (int)(unit_rand(&seed) * 3);
        double alphas[3];
        int na = 0;
        for (int i = 0; i < npairs && deg + 2 <= 10; i++) {
            double alpha = lo + w * unit_rand(&seed);
            double beta = w * pow(10, -4 + 3 * unit_rand(&seed));
            times_pair(c, deg, alpha, beta * beta);
            alphas[na++] = alpha;
            deg += 2;
        }
        /* A dip whose bottom (near alpha) lies below the rounding of
        ** double evaluation there (64 ulps of sum |c_k| |t|^k, measured
        ** in long double) has no sign double arithmetic can tell: any
        ** solver may see it cross zero, so its count is not checked (1
        ** trial in 3000, bottom 0.03 ulps of the sum) */
        bool resolvable = true;
        for (int i = 0; i < na; i++) {
            long double v = c[deg], S = fabs(c[deg]), t = alphas[i];
            for (int k = deg - 1; k >= 0; k--) {
                v = v * t + c[k];
                S = S * fabsl(t) + fabs(c[k]);
            }
            if (fabsl(v) < 64 * 2.2e-16L * S)
                resolvable = false;
        }
        n = roots_in_interval(c, deg, lo, hi, out);
        if (!resolvable) {
            unresolved++;
            continue;
        }
        assert_int_equal(n, inside);
        /* sort the expected roots */
        for (int i = 0; i < inside; i++)
            for (int k = i + 1; k < inside; k++)
                if (r[k] < r[i]) {
                    double t = r[i];
                    r[i] = r[k];
                    r[k] = t;
                }
        /* each to its condition: a Horner error of a few ulps of
        ** sum |c_k|·|t|^k moves a simple root by that over |p'| */
        for (int i = 0; i < inside; i++) {
            double S = 0, d = 0, tk = 1;
            for (int k = 0; k <= deg; k++) {
                S += fabs(c[k]) * tk;
                tk *= fabs(r[i]);
            }
            for (int k = deg; k >= 1; k--)
                d = d * r[i] + k * c[k];
            assert_near(out[i], r[i], 1e-12 * w + 64 * 2.2e-16 * S / fabs(d));
        }

        /* roots_surely_above: a yes must hold at every point of a dense
        ** grid; a level just below the grid's minimum (so truly below
        ** the polynomial there) may be "not proved", never the reverse */
        double vmin = INFINITY;
        for (int k = 0; k <= 4000; k++)
            vmin = fmin(vmin, roots_eval(c, deg, lo + w * k / 4000.0));
        double v = vmin - 0.5 * fabs(vmin) * unit_rand(&seed);
        if (roots_surely_above(c, deg, lo, hi, v))
            assert_true(vmin > v);
        assert_false(roots_surely_above(c, deg, lo, hi, vmin));
    }
    /* the checks above are not vacuous: almost every trial is checked */
    assert_true(unresolved <= 30);
    /* A clear case is proved: (t - 0.5)² + 0.3 > 0.005 on [0, 1] (its
    ** Bernstein coefficients less 0.005 are 0.545, 0.045, 0.545); its
    ** minimum 0.3 itself is not exceeded */
    double pos[3] = { 0.55, -1, 1 };
    assert_true(roots_surely_above(pos, 2, 0, 1, 0.005));
    assert_false(roots_surely_above(pos, 2, 0, 1, 0.3));
}

static iris_object mk(enum iris_object_kind k)
{
    iris_object o;
    memset(&o, 0, sizeof o);
    o.kind = k;
    return o;
}

/* Collects crossings sorted by t. */
static int hits(const iris_object *o, const struct geom_profile *p, vec3 ro,
                vec3 rd, struct geom_isect *out, int max)
{
    struct isect_list l;
    isect_list_init(&l);
    geom_intersect(o, p, ro, rd, 0, INFINITY, &l);
    int n = l.n < max ? l.n : max;
    for (int i = 0; i < l.n; i++)
        for (int j = i + 1; j < l.n; j++)
            if (l.v[j].t < l.v[i].t) {
                struct geom_isect s = l.v[i];
                l.v[i] = l.v[j];
                l.v[j] = s;
            }
    memcpy(out, l.v, (size_t)n * sizeof *out);
    int total = l.n;
    isect_list_fini(&l);
    return total;
}

static void assert_dir(vec3 n, vec3 want, double tol)
{
    n = v3_norm(n);
    assert_near(n.x, want.x, tol);
    assert_near(n.y, want.y, tol);
    assert_near(n.z, want.z, tol);
}

/* Sphere: t = distance - r and distance + r; normals radial. */
static void test_sphere(void **state)
{
    (void)state;
    iris_object s = mk(IRIS_OBJ_SPHERE);
    s.u.sphere.centre = v3(0, 0, 0);
    s.u.sphere.radius = 1;
    struct geom_isect h[4];
    assert_int_equal(hits(&s, NULL, v3(0, 0, -5), v3(0, 0, 1), h, 4), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_near(h[1].t, 6, 1e-12);
    assert_dir(h[0].n, v3(0, 0, -1), 1e-12);
    assert_dir(h[1].n, v3(0, 0, 1), 1e-12);
    /* Far away origin (1e8) keeps the precision of the closest-approach
    ** form: 1e-8 absolute is 1e-16 relative to the distance */
    assert_int_equal(hits(&s, NULL, v3(0, 0.6, -1e8), v3(0, 0, 1), h, 4), 2);
    assert_near(h[0].t, 1e8 - 0.8, 1e-7);
    assert_true(geom_inside(&s, NULL, v3(0.5, 0.5, 0.5)));
    assert_false(geom_inside(&s, NULL, v3(0.6, 0.6, 0.6)));
}

/* Box: entry and exit faces with their normals. */
static void test_box(void **state)
{
    (void)state;
    iris_object b = mk(IRIS_OBJ_BOX);
    b.u.box.lo = v3(1, 1, 1); /* corners in either order */
    b.u.box.hi = v3(-1, -2, -3);
    struct geom_isect h[4];
    assert_int_equal(hits(&b, NULL, v3(-5, 0, 0), v3(1, 0, 0), h, 4), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_near(h[1].t, 6, 1e-12);
    assert_dir(h[0].n, v3(-1, 0, 0), 0);
    assert_dir(h[1].n, v3(1, 0, 0), 0);
    /* Diagonal ray enters through -z (z extent 3 is deepest) */
    assert_int_equal(hits(&b, NULL, v3(0, 0, -5), v3(0, 0, 1), h, 4), 2);
    assert_near(h[0].t, 2, 1e-12);
    assert_dir(h[0].n, v3(0, 0, -1), 0);
    assert_int_equal(hits(&b, NULL, v3(0, 5, -5), v3(0, 0, 1), h, 4), 0);
    assert_true(geom_inside(&b, NULL, v3(0, -1.5, -2.5)));
    assert_false(geom_inside(&b, NULL, v3(0, 1.5, 0)));
}

/* Cylinder: side at radius, caps with axial normals; open has no caps. */
static void test_cylinder(void **state)
{
    (void)state;
    iris_object c = mk(IRIS_OBJ_CYLINDER);
    c.u.cylinder.base = v3(0, 0, 0);
    c.u.cylinder.cap = v3(0, 1, 0);
    c.u.cylinder.radius = 1;
    struct geom_isect h[4];
    assert_int_equal(hits(&c, NULL, v3(-5, 0.5, 0), v3(1, 0, 0), h, 4), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_dir(h[0].n, v3(-1, 0, 0), 1e-12);
    assert_int_equal(hits(&c, NULL, v3(0.5, 5, 0), v3(0, -1, 0), h, 4), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_near(h[1].t, 5, 1e-12);
    assert_dir(h[0].n, v3(0, 1, 0), 1e-12);
    assert_dir(h[1].n, v3(0, -1, 0), 1e-12);
    c.open = true;
    assert_int_equal(hits(&c, NULL, v3(0.5, 5, 0), v3(0, -1, 0), h, 4), 0);
    assert_true(geom_inside(&c, NULL, v3(0.5, 0.5, 0)));
    assert_false(geom_inside(&c, NULL, v3(0.5, 1.5, 0)));
}

/* Cone r = 1 - y/2 from y=0 to 2: at y=1 the radius is 0.5 and the
** outward normal is along (-1, 0.5, 0) at x = -0.5. */
static void test_cone(void **state)
{
    (void)state;
    iris_object c = mk(IRIS_OBJ_CONE);
    c.u.cone.base = v3(0, 0, 0);
    c.u.cone.cap = v3(0, 2, 0);
    c.u.cone.base_radius = 1;
    c.u.cone.cap_radius = 0;
    struct geom_isect h[4];
    assert_int_equal(hits(&c, NULL, v3(-5, 1, 0), v3(1, 0, 0), h, 4), 2);
    assert_near(h[0].t, 4.5, 1e-12);
    assert_near(h[1].t, 5.5, 1e-12);
    assert_dir(h[0].n, v3_norm(v3(-1, 0.5, 0)), 1e-12);
    /* Above the apex the mirrored nappe must not be hit */
    assert_int_equal(hits(&c, NULL, v3(-5, 3, 0), v3(1, 0, 0), h, 4), 0);
    /* Base cap */
    assert_int_equal(hits(&c, NULL, v3(0.2, -5, 0), v3(0, 1, 0), h, 4), 2);
    assert_near(h[0].t, 5, 1e-12);
    assert_dir(h[0].n, v3(0, -1, 0), 1e-12);
}

/* POV-Ray's Cone::Inside works in the shape's unit frame (a cylinder from
** z = 0 to 1 of radius 1; a cone with its apex at 0 and its wider end at
** z = 1 of radius 1) and shrinks a closed shape by EPSILON = 1e-10 there,
** grows an open one by it. Points 1e-12 from a cap or side are on the
** far side of that margin, where an exact test answers the opposite;
** those 1e-9 inside are inside either way. */
static void test_cone_inside_margin(void **state)
{
    (void)state;
    iris_object c = mk(IRIS_OBJ_CYLINDER);
    c.u.cylinder.base = v3(0, 0, 0);
    c.u.cylinder.cap = v3(0, 2, 0);
    c.u.cylinder.radius = 0.5;
    assert_false(geom_inside(&c, NULL, v3(0, 2 - 1e-12, 0)));
    assert_false(geom_inside(&c, NULL, v3(0, 1e-12, 0)));
    assert_false(geom_inside(&c, NULL, v3(0.5 - 1e-12, 1, 0)));
    assert_true(geom_inside(&c, NULL, v3(0, 2 - 1e-9, 0)));
    assert_true(geom_inside(&c, NULL, v3(0.5 - 1e-9, 1, 0)));
    c.open = true;
    assert_true(geom_inside(&c, NULL, v3(0, 2 + 1e-12, 0)));
    assert_false(geom_inside(&c, NULL, v3(0, 2 + 1e-9, 0)));

    /* r = 1 at y = 0 to 0.5 at y = 2: apex at y = 4, dist = 0.5 */
    iris_object k = mk(IRIS_OBJ_CONE);
    k.u.cone.base = v3(0, 0, 0);
    k.u.cone.cap = v3(0, 2, 0);
    k.u.cone.base_radius = 1;
    k.u.cone.cap_radius = 0.5;
    assert_false(geom_inside(&k, NULL, v3(0, 1e-12, 0)));
    assert_false(geom_inside(&k, NULL, v3(0, 2 - 1e-12, 0)));
    assert_false(geom_inside(&k, NULL, v3(0.75 - 1e-12, 1, 0)));
    assert_true(geom_inside(&k, NULL, v3(0.74, 1, 0)));
    assert_true(geom_inside(&k, NULL, v3(0, 1e-9, 0)));
    /* A double cone, r = -0.5 at y = 0 to 1 at y = 2 (zero at y = 2/3):
    ** |r(0.3)| = 0.275, |r(0.6)| = 0.05 */
    k.u.cone.base_radius = -0.5;
    k.u.cone.cap_radius = 1;
    assert_true(geom_inside(&k, NULL, v3(0.2, 0.3, 0)));
    assert_false(geom_inside(&k, NULL, v3(0.2, 0.6, 0)));
    assert_true(geom_inside(&k, NULL, v3(0.2, 1.5, 0)));
}

/* Torus R=2, r=0.5 about y: a ray along x meets radii 2.5, 1.5, 1.5, 2.5.
** Edge-on it is a thin quartic case; 1e-9 is far above double rounding of
** the refined roots. */
static void test_torus(void **state)
{
    (void)state;
    iris_object t = mk(IRIS_OBJ_TORUS);
    t.u.torus.major = 2;
    t.u.torus.minor = 0.5;
    struct geom_isect h[4];
    assert_int_equal(hits(&t, NULL, v3(-10, 0, 0), v3(1, 0, 0), h, 4), 4);
    assert_near(h[0].t, 7.5, 1e-9);
    assert_near(h[1].t, 8.5, 1e-9);
    assert_near(h[2].t, 11.5, 1e-9);
    assert_near(h[3].t, 12.5, 1e-9);
    assert_dir(h[0].n, v3(-1, 0, 0), 1e-9);
    assert_dir(h[1].n, v3(1, 0, 0), 1e-9);
    /* Through the tube vertically at x = 2: y = ±0.5 */
    assert_int_equal(hits(&t, NULL, v3(2, 10, 0), v3(0, -1, 0), h, 4), 2);
    assert_near(h[0].t, 9.5, 1e-9);
    assert_dir(h[0].n, v3(0, 1, 0), 1e-9);
    /* Through the hole: nothing */
    assert_int_equal(hits(&t, NULL, v3(0, 10, 0), v3(0, -1, 0), h, 4), 0);
    /* A very thin torus far away: r/R = 1e-4 at distance 1e4 */
    t.u.torus.minor = 2e-4;
    assert_int_equal(hits(&t, NULL, v3(-1e4, 0, 0), v3(1, 0, 0), h, 4), 4);
    assert_near(h[0].t, 1e4 - 2 - 2e-4, 1e-8);
    assert_true(geom_inside(&t, NULL, v3(2, 0, 1e-4)));
    assert_false(geom_inside(&t, NULL, v3(0, 0, 0)));
}

/*
** The written-out order-2 solver (poly.c quadric_roots) on the paraboloid
** y = x² + z² (POV-Ray's Paraboloid_Y: quadric <1,0,1>,<0,0,0>,<0,-1,0>,0),
** against hand-solved crossings:
**   - a ray along -y through x = 0.5 is linear in t (no t² term): one
**     crossing where y = 0.25, t = 9.75;
**   - from (-3, 5, 0) along (1, -1, 0)/sqrt2, s = t/sqrt2 solves
**     s² - 5s + 4 = 0: s = 1 and 4, points (-2, 4, 0) and (1, 1, 0), with
**     normals along the gradient (2x, -1, 2z);
**   - the horizontal line y = 1 in the plane z = 0 touches nothing it does
**     not cross twice (x = ±1), and the line y = -1 misses.
** The same coefficients as a poly and as the cubic (x² + z² - y)(x - 100),
** solved by the general root finder, give the same crossings below
** x = 100. Tolerance 1e-12: a few thousand ulps of these small numbers.
*/
static void test_quadric_fast(void **state)
{
    (void)state;
    double qc[10] = { 1, 0, 1, 0, 0, 0, 0, -1, 0, 0 };
    iris_object q = mk(IRIS_OBJ_QUADRIC);
    q.u.poly.order = 2;
    q.u.poly.n_coeffs = 10;
    q.u.poly.coeffs = qc;
    assert_null(geom_validate(&q));
    struct geom_isect h[4];
    assert_int_equal(hits(&q, NULL, v3(0.5, 10, 0), v3(0, -1, 0), h, 4), 1);
    assert_near(h[0].t, 9.75, 1e-12);
    assert_dir(h[0].n, v3_norm(v3(1, -1, 0)), 1e-12);

    double r2 = sqrt(2.0);
    assert_int_equal(hits(&q, NULL, v3(-3, 5, 0), v3(1, -1, 0), h, 4), 2);
    /* the direction is not unit: t is in its units, s = t */
    assert_near(h[0].t, 1, 1e-12);
    assert_near(h[1].t, 4, 1e-12);
    assert_dir(h[0].n, v3_norm(v3(-4, -1, 0)), 1e-12);
    assert_dir(h[1].n, v3_norm(v3(2, -1, 0)), 1e-12);
    assert_int_equal(hits(&q, NULL, v3(-3, 5, 0), v3(1 / r2, -1 / r2, 0), h,
                          4), 2);
    assert_near(h[0].t, r2, 1e-12);
    assert_near(h[1].t, 4 * r2, 1e-12);

    assert_int_equal(hits(&q, NULL, v3(-5, 1, 0), v3(1, 0, 0), h, 4), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_near(h[1].t, 6, 1e-12);
    assert_int_equal(hits(&q, NULL, v3(-5, -1, 0), v3(1, 0, 0), h, 4), 0);

    /* The general solver on a cubic with the same surface below x = 100 */
    int idx = 0, map[4][4][4];
    for (int i = 3; i >= 0; i--)
        for (int j = 3 - i; j >= 0; j--)
            for (int l = 3 - i - j; l >= 0; l--)
                map[i][j][l] = idx++;
    double c3[20] = { 0 };
    /* (x² + z² - y)(x - 100) = x³ + xz² - xy - 100x² - 100z² + 100y */
    c3[map[3][0][0]] = 1;
    c3[map[1][0][2]] = 1;
    c3[map[1][1][0]] = -1;
    c3[map[2][0][0]] = -100;
    c3[map[0][0][2]] = -100;
    c3[map[0][1][0]] = 100;
    iris_object cubic = mk(IRIS_OBJ_POLY);
    cubic.u.poly.order = 3;
    cubic.u.poly.n_coeffs = 20;
    cubic.u.poly.coeffs = c3;
    assert_null(geom_validate(&cubic));
    vec3 ro[3] = { v3(-3, 5, 0.5), v3(0.2, 9, -0.3), v3(-2, 0.5, -2) };
    vec3 rd[3] = { v3(0.7, -0.6, 0.1), v3(0.01, -1, 0.02), v3(0.5, 0.1, 0.6) };
    for (int k = 0; k < 3; k++) {
        struct isect_list a, b;
        isect_list_init(&a);
        isect_list_init(&b);
        geom_intersect(&q, NULL, ro[k], rd[k], 0, 10, &a);
        geom_intersect(&cubic, NULL, ro[k], rd[k], 0, 10, &b);
        assert_true(a.n > 0);
        assert_int_equal(a.n, b.n);
        for (int i = 0; i < a.n; i++) {
            assert_near(a.v[i].t, b.v[i].t, 1e-12);
            vec3 p = v3_madd(ro[k], rd[k], a.v[i].t);
            assert_near(p.x * p.x + p.z * p.z - p.y, 0, 1e-12);
        }
        isect_list_fini(&a);
        isect_list_fini(&b);
    }
}

/*
** POV-Ray's sphere uv (geom_sphere_uv): u is the angle about y measured
** from +x towards +z over 2 pi (Sphere::UVCoord: acos(x), 2 pi minus it
** where z < 0), v = 1/2 + latitude / pi. Points: +x on the equator
** (0, 1/2), +z (1/4, 1/2), -x (1/2, 1/2), -z (3/4, 1/2), the
** north pole v = 1 and 45 degrees south v = 1/4, for a sphere off the
** origin (the centre is subtracted). Exact up to rounding of atan2/asin.
*/
static void test_sphere_uv(void **state)
{
    (void)state;
    iris_object s = mk(IRIS_OBJ_SPHERE);
    s.u.sphere.centre = v3(1, 2, 3);
    s.u.sphere.radius = 2;
    struct { vec3 p; double u, v; } pts[] = {
        { { 3, 2, 3 }, 0, 0.5 },     { { 1, 2, 5 }, 0.25, 0.5 },
        { { -1, 2, 3 }, 0.5, 0.5 },  { { 1, 2, 1 }, 0.75, 0.5 },
        { { 1, 4, 3 }, 0.0, 1.0 },
        { { 1 + sqrt(2.0), 2 - sqrt(2.0), 3 }, 0, 0.25 },
    };
    for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++) {
        iris_vec2 uv = geom_sphere_uv(&s, pts[i].p);
        assert_near(uv.u, pts[i].u, 1e-12);
        assert_near(uv.v, pts[i].v, 1e-12);
    }
}

/*
** POV-Ray's box uv (Box::UVCoord, source/backend/shape/boxes.cpp): the
** hit point P taken to [0,1]^3 over the box, then per face (0 the low
** face, 1 the high one): X0 (z/4, 1/3 + y/3), X1 (3/4 - z/4, 1/3 + y/3),
** Y0 (1/4 + x/4, z/3), Y1 (1/4 + x/4, 1 - z/3), Z0 (1 - x/4, 1/3 + y/3),
** Z1 (1/4 + x/4, 1/3 + y/3). Box -1..1, -2..1, -3..1 (corners given high
** first); each ray crosses a pair of opposite faces at points worked out
** by hand below. Exact but for rounding: 1e-12.
*/
static void test_box_uv(void **state)
{
    (void)state;
    iris_object b = mk(IRIS_OBJ_BOX);
    b.u.box.lo = v3(1, 1, 1);
    b.u.box.hi = v3(-1, -2, -3);
    struct {
        vec3 ro, rd;
        double u0, v0, u1, v1; /* entry, exit */
    } rays[] = {
        /* (-1,-.5,0) then (1,-.5,0): P = (0|1, 1/2, 3/4) */
        { { -5, -0.5, 0 }, { 1, 0, 0 }, 0.1875, 0.5, 0.5625, 0.5 },
        /* (.5,1,-2) then (.5,-2,-2): P = (3/4, 1|0, 1/4) */
        { { 0.5, 5, -2 }, { 0, -1, 0 }, 0.4375, 1 - 0.25 / 3, 0.4375,
          0.25 / 3 },
        /* (-.5,.4,-3) then (-.5,.4,1): P = (1/4, 4/5, 0|1) */
        { { -0.5, 0.4, -10 }, { 0, 0, 1 }, 0.9375, 0.6, 0.3125, 0.6 },
    };
    for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
        struct geom_isect h[4];
        assert_int_equal(hits(&b, NULL, rays[i].ro, rays[i].rd, h, 4), 2);
        assert_near(h[0].uv.u, rays[i].u0, 1e-12);
        assert_near(h[0].uv.v, rays[i].v0, 1e-12);
        assert_near(h[1].uv.u, rays[i].u1, 1e-12);
        assert_near(h[1].uv.v, rays[i].v1, 1e-12);
    }
}

/* A quadric equal to the unit sphere (its SDL order: x², y², z², xy, xz,
** yz, x, y, z, 1), the same as an order-2 poly (POV-Ray's poly order: x²,
** xy, xz, x, y², yz, y, z², z, 1) and the quartic torus in poly form give
** the same hits as the dedicated shapes. */
static void test_poly(void **state)
{
    (void)state;
    double qc[10] = { 1, 1, 1, 0, 0, 0, 0, 0, 0, -1 };
    iris_object q = mk(IRIS_OBJ_QUADRIC);
    q.u.poly.order = 2;
    q.u.poly.n_coeffs = 10;
    q.u.poly.coeffs = qc;
    assert_null(geom_validate(&q));
    struct geom_isect h[4];
    assert_int_equal(hits(&q, NULL, v3(0, 0.6, -5), v3(0, 0, 1), h, 4), 2);
    assert_near(h[0].t, 4.2, 1e-12);
    assert_dir(h[0].n, v3(0, 0.6, -0.8), 1e-12);
    assert_true(geom_inside(&q, NULL, v3(0, 0, 0)));
    /* x² - y + 0.5·xz = 0 both ways: quadric order vs poly order */
    double qa[10] = { 1, 0, 0, 0, 0.5, 0, 0, -1, 0, 0 };
    double pa[10] = { 1, 0, 0.5, 0, 0, 0, -1, 0, 0, 0 };
    iris_object pq = mk(IRIS_OBJ_POLY);
    pq.u.poly.order = 2;
    pq.u.poly.n_coeffs = 10;
    pq.u.poly.coeffs = pa;
    q.u.poly.coeffs = qa;
    vec3 tp = v3(0.3, -0.7, 1.1);
    assert_near(geom_poly_eval(&q, tp), 0.09 + 0.7 + 0.5 * 0.33, 1e-15);
    assert_near(geom_poly_eval(&pq, tp), 0.09 + 0.7 + 0.5 * 0.33, 1e-15);

    /* Torus R=2, r=0.5: (x²+y²+z²+R²-r²)² - 4R²(x²+z²), order 4:
    ** x⁴+y⁴+z⁴+2x²y²+2x²z²+2y²z² + 2(R²-r²)(x²+y²+z²) - 4R²(x²+z²)
    ** + (R²-r²)² */
    double R2 = 4, r2 = 0.25, k = R2 - r2;
    double c4[35] = { 0 };
    /* index of x^i y^j z^k in POV-Ray's order */
    int idx = 0, map[5][5][5];
    for (int i = 4; i >= 0; i--)
        for (int j = 4 - i; j >= 0; j--)
            for (int l = 4 - i - j; l >= 0; l--)
                map[i][j][l] = idx++;
    assert_int_equal(idx, 35);
    c4[map[4][0][0]] = 1;
    c4[map[0][4][0]] = 1;
    c4[map[0][0][4]] = 1;
    c4[map[2][2][0]] = 2;
    c4[map[2][0][2]] = 2;
    c4[map[0][2][2]] = 2;
    c4[map[2][0][0]] = 2 * k - 4 * R2;
    c4[map[0][2][0]] = 2 * k;
    c4[map[0][0][2]] = 2 * k - 4 * R2;
    c4[map[0][0][0]] = k * k;
    iris_object p = mk(IRIS_OBJ_POLY);
    p.u.poly.order = 4;
    p.u.poly.n_coeffs = 35;
    p.u.poly.coeffs = c4;
    assert_int_equal(hits(&p, NULL, v3(-10, 0, 0), v3(1, 0, 0), h, 4), 4);
    assert_near(h[0].t, 7.5, 1e-9);
    assert_near(h[2].t, 11.5, 1e-9);
    assert_dir(h[0].n, v3(-1, 0, 0), 1e-9);
}

/* Blob of one sphere component R=2, strength 1, threshold 1/4: the
** surface is where (1 - r²/4)² = 1/4, r = 2·sqrt(1/2). A cylinder
** component of the same radius gives the same distance from its axis. */
static void test_blob(void **state)
{
    (void)state;
    iris_blob_component comp[2];
    memset(comp, 0, sizeof comp);
    comp[0].kind = 0;
    comp[0].a = v3(0, 0, 0);
    comp[0].radius = 2;
    comp[0].strength = 1;
    iris_object b = mk(IRIS_OBJ_BLOB);
    b.u.blob.threshold = 0.25;
    b.u.blob.n_components = 1;
    b.u.blob.components = comp;
    double rs = 2 * sqrt(0.5);
    struct geom_isect h[8];
    assert_int_equal(hits(&b, NULL, v3(-10, 0, 0), v3(1, 0, 0), h, 8), 2);
    assert_near(h[0].t, 10 - rs, 1e-9);
    assert_near(h[1].t, 10 + rs, 1e-9);
    assert_dir(h[0].n, v3(-1, 0, 0), 1e-9);
    assert_true(geom_inside(&b, NULL, v3(0, 1.4, 0)));
    assert_false(geom_inside(&b, NULL, v3(0, 1.5, 0)));

    comp[0].kind = 1;
    comp[0].a = v3(0, -1, 0);
    comp[0].b = v3(0, 1, 0);
    assert_int_equal(hits(&b, NULL, v3(-10, 0.3, 0), v3(1, 0, 0), h, 8), 2);
    assert_near(h[0].t, 10 - rs, 1e-9);
    /* Beyond the end, the hemisphere: distance to the end point */
    assert_int_equal(hits(&b, NULL, v3(-10, 1.5, 0), v3(1, 0, 0), h, 8), 2);
    assert_near(h[0].t, 10 - sqrt(rs * rs - 0.25), 1e-9);

    /* Two equal spheres: symmetric crossings */
    comp[0].kind = 0;
    comp[0].a = v3(-1, 0, 0);
    comp[1] = comp[0];
    comp[1].a = v3(1, 0, 0);
    b.u.blob.n_components = 2;
    b.u.blob.threshold = 0.6;
    int n = hits(&b, NULL, v3(-10, 0, 0), v3(1, 0, 0), h, 8);
    assert_int_equal(n, 2);
    assert_near(h[0].t - 10, -(h[1].t - 10), 1e-9);
}

/* superellipsoid <1, 1> is the unit sphere; <0.1, 0.1> nearly a cube. */
static void test_superellipsoid(void **state)
{
    (void)state;
    iris_object s = mk(IRIS_OBJ_SUPERELLIPSOID);
    s.u.superellipsoid.e = 1;
    s.u.superellipsoid.n = 1;
    struct geom_isect h[8];
    assert_int_equal(hits(&s, NULL, v3(0.3, 0.4, -5), v3(0, 0, 1), h, 8), 2);
    assert_near(h[0].t, 5 - sqrt(0.75), 1e-9);
    assert_dir(h[0].n, v3(0.3, 0.4, -sqrt(0.75)), 1e-6);
    s.u.superellipsoid.e = 0.1;
    s.u.superellipsoid.n = 0.1;
    assert_int_equal(hits(&s, NULL, v3(0.3, 0.4, -5), v3(0, 0, 1), h, 8), 2);
    /* |z|^20 = 1 - ((0.3^20+0.4^20)^(1)) ~ 1: z within 1e-8 of the face */
    assert_near(h[0].t, 4, 1e-6);
    assert_dir(h[0].n, v3(0, 0, -1), 1e-6);
}

/*
** isect_list.first_only (the accel's nearest-hit query): a shape that
** honours it returns one crossing, the nearest of those the full search
** gives for the same ray and interval, bit for bit (the search up to it
** is the same). Rays from outside, and from inside the box with t0 past
** the entry (a secondary ray), over superellipsoids (whole powers by
** squaring and pow) and julia_fractal sets (quaternion sqr and cube,
** hypercomplex sqr, exp and reciprocal: the complex functions' march
** steps with one iteration and bisects with POV-Ray 3.7's other one).
*/
static int first_only_multi; /* checks where the full search found more */

static void check_first_only(const iris_object *o, vec3 ro, vec3 rd,
                             double t0)
{
    struct isect_list all, first;
    isect_list_init(&all);
    isect_list_init(&first);
    first.first_only = true;
    geom_intersect(o, NULL, ro, rd, t0, INFINITY, &all);
    geom_intersect(o, NULL, ro, rd, t0, INFINITY, &first);
    if (all.n == 0) {
        assert_int_equal(first.n, 0);
    } else {
        int k = 0;
        for (int i = 1; i < all.n; i++)
            if (all.v[i].t < all.v[k].t)
                k = i;
        first_only_multi += all.n > 1;
        assert_int_equal(first.n, 1);
        assert_true(first.v[0].t == all.v[k].t);
        assert_true(first.v[0].n.x == all.v[k].n.x &&
                    first.v[0].n.y == all.v[k].n.y &&
                    first.v[0].n.z == all.v[k].n.z);
    }
    isect_list_fini(&all);
    isect_list_fini(&first);
}

static void test_first_only(void **state)
{
    (void)state;
    iris_object se[3] = { mk(IRIS_OBJ_SUPERELLIPSOID),
                          mk(IRIS_OBJ_SUPERELLIPSOID),
                          mk(IRIS_OBJ_SUPERELLIPSOID) };
    se[0].u.superellipsoid.e = 0.05;   /* powers 40 and 1 */
    se[0].u.superellipsoid.n = 0.05;
    se[1].u.superellipsoid.e = 0.3;    /* pow */
    se[1].u.superellipsoid.n = 2.5;
    se[2].u.superellipsoid.e = 1;      /* powers 2 and 1: the sphere */
    se[2].u.superellipsoid.n = 1;
    iris_object ju[5] = { mk(IRIS_OBJ_JULIA_FRACTAL),
                          mk(IRIS_OBJ_JULIA_FRACTAL),
                          mk(IRIS_OBJ_JULIA_FRACTAL),
                          mk(IRIS_OBJ_JULIA_FRACTAL),
                          mk(IRIS_OBJ_JULIA_FRACTAL) };
    const double c[5][4] = { { -0.083, 0.0, -0.83, -0.025 },
                             { -0.2, 0.0, 0.5, 0.0 },
                             { 0.2, 0.1, 0.59, -0.2 },
                             { -0.3, 0.5, 0.1, 0.1 },
                             { -0.2, 0.6, 0.2, -0.1 } };
    const int fn[5] = { IRIS_JULIA_SQR, IRIS_JULIA_CUBE, IRIS_JULIA_SQR,
                        IRIS_JULIA_EXP, IRIS_JULIA_RECIPROCAL };
    for (int j = 0; j < 5; j++) {
        for (int k = 0; k < 4; k++)
            ju[j].u.julia.data[k] = c[j][k];
        ju[j].u.julia.iterations = 8;
        ju[j].u.julia.precision = 20;
        ju[j].u.julia.fn = fn[j];
        ju[j].u.julia.type = j >= 2;   /* 1: hypercomplex */
    }
    uint64_t r = 12345;
    for (int i = 0; i < 200; i++) {
        double u[6];
        for (int k = 0; k < 6; k++) {
            r = r * 6364136223846793005u + 1442695040888963407u;
            u[k] = (double)(r >> 11) / 9007199254740992.0 * 2 - 1;
        }
        vec3 ro = v3(6 * u[0], 6 * u[1], -6);
        vec3 rd = v3_sub(v3(0.8 * u[3], 0.8 * u[4], 0.8 * u[5]), ro);
        for (int j = 0; j < 3; j++) {
            check_first_only(&se[j], ro, rd, 0);
            /* a ray starting inside the box, past a first crossing */
            check_first_only(&se[j], ro, rd, 0.99);
        }
        for (int j = 0; j < 5; j++) {
            check_first_only(&ju[j], ro, rd, 0);
            check_first_only(&ju[j], ro, rd, 0.99);
        }
    }
    /* not vacuous: many rays cross a shape more than once */
    print_message("# %d of 3200 checks had several crossings\n",
                  first_only_multi);
    assert_true(first_only_multi >= 200);
    /* <0.05, 0.05> along x: |x|^40 = 1 at x = -1 exactly, t = 4 (the
    ** squaring is within a few ulps; the bisection goes to the last bit) */
    struct geom_isect h[8];
    assert_int_equal(hits(&se[0], NULL, v3(-5, 0, 0), v3(1, 0, 0), h, 8), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_near(h[1].t, 6, 1e-12);
}

/* Lathe, sor and prism that are all the unit cylinder of height 1. */
static void test_sweeps(void **state)
{
    (void)state;
    iris_vec2 lp[4] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
    iris_object l = mk(IRIS_OBJ_LATHE);
    l.u.lathe.spline = IRIS_SPLINE_LINEAR;
    l.u.lathe.n_points = 4;
    l.u.lathe.points = lp;
    const char *why;
    struct geom_profile *p = geom_prepare(&l, &why);
    assert_non_null(p);
    struct geom_isect h[8];
    assert_int_equal(hits(&l, p, v3(-5, 0.5, 0), v3(1, 0, 0), h, 8), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_dir(h[0].n, v3(-1, 0, 0), 1e-12);
    assert_int_equal(hits(&l, p, v3(0.3, 5, 0), v3(0, -1, 0), h, 8), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_dir(h[0].n, v3(0, 1, 0), 1e-12);
    assert_true(geom_inside(&l, p, v3(0.5, 0.5, 0.5)));
    assert_false(geom_inside(&l, p, v3(0.8, 0.5, 0.8)));
    geom_profile_free(p);

    /* sor: r² constant 1 between y=0 and y=1, closed by caps */
    iris_vec2 sp[4] = { { 1, -1 }, { 1, 0 }, { 1, 1 }, { 1, 2 } };
    iris_object s = mk(IRIS_OBJ_SOR);
    s.u.lathe.n_points = 4;
    s.u.lathe.points = sp;
    p = geom_prepare(&s, &why);
    assert_non_null(p);
    assert_int_equal(hits(&s, p, v3(-5, 0.5, 0), v3(1, 0, 0), h, 8), 2);
    assert_near(h[0].t, 4, 1e-12);
    assert_int_equal(hits(&s, p, v3(0.3, 5, 0), v3(0, -1, 0), h, 8), 2);
    assert_near(h[1].t, 5, 1e-12);
    geom_profile_free(p);

    /* prism: a square with a square hole, linear sweep 0..1 */
    iris_vec2 pp[10] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 },
                         { -1, -1 }, { -0.5, -0.5 }, { 0.5, -0.5 },
                         { 0.5, 0.5 }, { -0.5, 0.5 }, { -0.5, -0.5 } };
    iris_object pr = mk(IRIS_OBJ_PRISM);
    pr.u.prism.spline = IRIS_SPLINE_LINEAR;
    pr.u.prism.height1 = 1;
    pr.u.prism.height2 = 0;
    pr.u.prism.n_points = 10;
    pr.u.prism.points = pp;
    p = geom_prepare(&pr, &why);
    assert_non_null(p);
    /* Along x at z = 0: outer wall, hole wall, hole wall, outer wall */
    assert_int_equal(hits(&pr, p, v3(-5, 0.5, 0), v3(1, 0, 0), h, 8), 4);
    assert_near(h[0].t, 4, 1e-12);
    assert_near(h[1].t, 4.5, 1e-12);
    assert_dir(h[0].n, v3(-1, 0, 0), 1e-12);
    assert_dir(h[1].n, v3(1, 0, 0), 1e-12); /* the hole's wall faces in */
    /* Down through the solid part: top cap then bottom cap */
    assert_int_equal(hits(&pr, p, v3(0.75, 5, 0), v3(0, -1, 0), h, 8), 2);
    assert_dir(h[0].n, v3(0, 1, 0), 0);
    assert_int_equal(hits(&pr, p, v3(0, 5, 0), v3(0, -1, 0), h, 8), 0);
    assert_true(geom_inside(&pr, p, v3(0.75, 0.5, 0)));
    assert_false(geom_inside(&pr, p, v3(0, 0.5, 0)));
    /* POV-Ray's Prism::Inside: height1 <= y < height2 (heights sorted),
    ** so the bottom face is inside and the top face is not */
    assert_true(geom_inside(&pr, p, v3(0.75, 0, 0)));
    assert_false(geom_inside(&pr, p, v3(0.75, 1, 0)));
    assert_false(geom_inside(&pr, p, v3(0.75, -1e-12, 0)));
    geom_profile_free(p);
    /* 'open' removes the caps */
    pr.open = true;
    p = geom_prepare(&pr, &why);
    assert_int_equal(hits(&pr, p, v3(0.75, 5, 0), v3(0, -1, 0), h, 8), 0);
    assert_int_equal(hits(&pr, p, v3(-5, 0.5, 0), v3(1, 0, 0), h, 8), 4);
    geom_profile_free(p);
}

/* Conic sweep: the square [-1,1]² scaled by the height y, for y in
** [0.5, 1]. Along x at y = 0.75 the walls are at x = ±0.75 and the +x
** wall is the plane x = y, outward normal (1, -1, 0)/sqrt(2). */
static void test_conic_prism(void **state)
{
    (void)state;
    iris_vec2 pp[5] = { { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 },
                        { -1, -1 } };
    iris_object pr = mk(IRIS_OBJ_PRISM);
    pr.u.prism.spline = IRIS_SPLINE_LINEAR;
    pr.u.prism.sweep = 1;
    pr.u.prism.height1 = 0.5;
    pr.u.prism.height2 = 1;
    pr.u.prism.n_points = 5;
    pr.u.prism.points = pp;
    const char *why;
    struct geom_profile *p = geom_prepare(&pr, &why);
    assert_non_null(p);
    struct geom_isect h[4];
    assert_int_equal(hits(&pr, p, v3(-5, 0.75, 0), v3(1, 0, 0), h, 4), 2);
    assert_near(h[0].t, 5 - 0.75, 1e-12);
    assert_near(h[1].t, 5 + 0.75, 1e-12);
    assert_dir(h[1].n, v3_norm(v3(1, -1, 0)), 1e-12);
    /* Down the axis: top cap at y = 1, bottom cap at y = 0.5 */
    assert_int_equal(hits(&pr, p, v3(0.2, 5, 0), v3(0, -1, 0), h, 4), 2);
    assert_near(h[1].t, 4.5, 1e-12);
    /* x = 0.6 is inside at y = 0.75 but outside at y = 0.55 */
    assert_true(geom_inside(&pr, p, v3(0.6, 0.75, 0)));
    assert_false(geom_inside(&pr, p, v3(0.6, 0.55, 0)));
    vec3 lo, hi;
    assert_true(geom_bounds(&pr, p, &lo, &hi));
    assert_near(hi.x, 1, 0);
    geom_profile_free(p);
}

/*
** Quadratic-spline lathe through (2,-1), (1,0), (2,1): POV-Ray's segment
** polynomial between the last two points is r = 1 + y², y in [0, 1].
** POV-Ray intersects the exact curve (lathe.cpp), so radii and normals
** must match it to rounding: 1e-12 on values of order 1 (the chords iris
** once used were off by up to 1e-3, and their interpolated normals by
** 2e-2). Oblique rays (a polynomial of degree 4 in s here) must land on
** the curve too, and the inside test must follow the curve, not a chord,
** 1e-7 either side of it.
*/
static void test_spline_lathe(void **state)
{
    (void)state;
    iris_vec2 lp[3] = { { 2, -1 }, { 1, 0 }, { 2, 1 } };
    iris_object l = mk(IRIS_OBJ_LATHE);
    l.u.lathe.spline = IRIS_SPLINE_QUADRATIC;
    l.u.lathe.n_points = 3;
    l.u.lathe.points = lp;
    const char *why;
    struct geom_profile *p = geom_prepare(&l, &why);
    assert_non_null(p);
    struct geom_isect h[8];
    for (double y = 0.1; y < 1; y += 0.2) {
        int n = hits(&l, p, v3(-5, y, 0), v3(1, 0, 0), h, 8);
        assert_int_equal(n, 2);
        assert_near(5 - h[0].t, 1 + y * y, 1e-12);
        /* The normal follows the curve: (1, -dr/dy) = (1, -2y) */
        vec3 want = v3_norm(v3(-1, -2 * y, 0));
        assert_dir(h[0].n, want, 1e-12);
        assert_true(geom_inside(&l, p, v3(1 + y * y - 1e-7, y, 0)));
        assert_false(geom_inside(&l, p, v3(1 + y * y + 1e-7, y, 0)));
    }
    /* Nearly horizontal rays (the sextic's root pairs almost merge):
    ** still both walls, on the curve */
    double dys[4] = { 1e-3, 1e-5, 1e-7, 1e-10 };
    for (int k = 0; k < 4; k++) {
        vec3 dir = v3(1, dys[k], 0.1), ro = v3(-5, 0.5, -0.5);
        int n = hits(&l, p, ro, dir, h, 8);
        assert_int_equal(n, 2);
        for (int i = 0; i < 2; i++) {
            vec3 q = v3_madd(ro, dir, h[i].t);
            assert_near(sqrt(q.x * q.x + q.z * q.z), 1 + q.y * q.y, 1e-12);
        }
    }
    /* Oblique rays: every crossing lies on r = 1 + y², 0 <= y < 1 (each
    ** enters the side and leaves by an open end, or crosses twice) */
    vec3 dirs[3] = { v3(1, 0.3, 0.2), v3(1, -0.05, 0.4), v3(1, 0.1, -0.3) };
    for (int k = 0; k < 3; k++) {
        vec3 ro = v3_madd(v3(0, 0.5, 0), dirs[k], -6);
        int n = hits(&l, p, ro, dirs[k], h, 8);
        assert_true(n >= 1);
        for (int i = 0; i < n && i < 8; i++) {
            vec3 q = v3_madd(ro, dirs[k], h[i].t);
            assert_near(sqrt(q.x * q.x + q.z * q.z), 1 + q.y * q.y, 1e-12);
        }
    }
    geom_profile_free(p);
}

/*
** sor through (1,-1), (1,0), (2,1), (2,2): POV-Ray's sor (sor.cpp, the
** documentation's definition) makes r² a cubic in y between the middle
** points with the slopes d(r²)/dy = 2 r_i (r_(i+1) - r_(i-1)) /
** (y_(i+1) - y_(i-1)) at them: 1 at y = 0 and 2 at y = 1, so r² =
** 1 + y + 5y² - 3y³ (Hermite: values 1 and 4, slopes 1 and 2). Crossings
** lie on it to rounding (1e-12) for horizontal and oblique rays, and the
** inside test follows it 1e-7 either side.
*/
static void test_sor_exact(void **state)
{
    (void)state;
    iris_vec2 sp[4] = { { 1, -1 }, { 1, 0 }, { 2, 1 }, { 2, 2 } };
    iris_object s = mk(IRIS_OBJ_SOR);
    s.u.lathe.n_points = 4;
    s.u.lathe.points = sp;
    s.open = true;
    const char *why;
    struct geom_profile *p = geom_prepare(&s, &why);
    assert_non_null(p);
    struct geom_isect h[8];
    for (double y = 0.05; y < 1; y += 0.15) {
        double r = sqrt(1 + y + 5 * y * y - 3 * y * y * y);
        assert_int_equal(hits(&s, p, v3(-5, y, 0), v3(1, 0, 0), h, 8), 2);
        assert_near(5 - h[0].t, r, 1e-12);
        /* normal of r² - f(y): (2r, -f'(y)) */
        vec3 want = v3_norm(v3(-2 * r, -(1 + 10 * y - 9 * y * y), 0));
        assert_dir(h[0].n, want, 1e-12);
        assert_true(geom_inside(&s, p, v3(0, y, r - 1e-7)));
        assert_false(geom_inside(&s, p, v3(0, y, r + 1e-7)));
    }
    vec3 dirs[2] = { v3(1, 0.2, 0.3), v3(1, 0.15, -0.5) };
    for (int k = 0; k < 2; k++) {
        vec3 ro = v3_madd(v3(0, 0.5, 0), dirs[k], -6);
        int n = hits(&s, p, ro, dirs[k], h, 8);
        assert_true(n >= 1);
        for (int i = 0; i < n && i < 8; i++) {
            vec3 q = v3_madd(ro, dirs[k], h[i].t);
            double y = q.y;
            assert_near(q.x * q.x + q.z * q.z,
                        1 + y + 5 * y * y - 3 * y * y * y, 1e-11);
        }
    }
    geom_profile_free(p);
}

/*
** A cubic_spline prism (linear sweep, heights 0..1) through (0,-2),
** (-2,0), (0,2), (2,0): its walls are POV-Ray's Catmull-Rom segments,
** p(s) = ½[(-s³+2s²-s) P0 + (3s³-5s²+2) P1 + (-3s³+4s²+s) P2 +
** (s³-s²) P3] (the documentation's basis, written here independently of
** profile.c's coefficient matrix). A ray along x at z = v meets the wall
** where v(s) = v (found here by bisection): the crossing must be on the
** curve to 1e-12 (chords were off by up to 1e-3), and the inside test
** must flip within 1e-7 of it.
*/
static void cr_point(const iris_vec2 *P, double s, double *u, double *v)
{
    double b0 = 0.5 * (-s * s * s + 2 * s * s - s);
    double b1 = 0.5 * (3 * s * s * s - 5 * s * s + 2);
    double b2 = 0.5 * (-3 * s * s * s + 4 * s * s + s);
    double b3 = 0.5 * (s * s * s - s * s);
    *u = b0 * P[0].u + b1 * P[1].u + b2 * P[2].u + b3 * P[3].u;
    *v = b0 * P[0].v + b1 * P[1].v + b2 * P[2].v + b3 * P[3].v;
}

static void test_spline_prism(void **state)
{
    (void)state;
    iris_vec2 pp[8] = { { 2, 0 }, { 0, -2 }, { -2, 0 }, { 0, 2 },
                        { 2, 0 }, { 0, -2 }, { -2, 0 }, { 0, 2 } };
    iris_object pr = mk(IRIS_OBJ_PRISM);
    pr.u.prism.spline = IRIS_SPLINE_CUBIC;
    pr.u.prism.height1 = 0;
    pr.u.prism.height2 = 1;
    pr.u.prism.n_points = 8;
    pr.u.prism.points = pp;
    const char *why;
    struct geom_profile *p = geom_prepare(&pr, &why);
    assert_non_null(p);
    struct geom_isect h[8];
    /* the segment from (-2,0) to (0,2): v rises from 0 to 2 */
    const iris_vec2 *seg = pp + 1;
    for (double v = 0.2; v < 2; v += 0.35) {
        double lo = 0, hi = 1, u, vv;
        for (int k = 0; k < 200; k++) {
            double m = 0.5 * (lo + hi);
            cr_point(seg, m, &u, &vv);
            if (vv < v)
                lo = m;
            else
                hi = m;
        }
        cr_point(seg, 0.5 * (lo + hi), &u, &vv);
        int n = hits(&pr, p, v3(-5, 0.5, v), v3(1, 0, 0), h, 8);
        assert_int_equal(n, 2);
        assert_near(-5 + h[0].t, u, 1e-12);
        assert_true(geom_inside(&pr, p, v3(u + 1e-7, 0.5, v)));
        assert_false(geom_inside(&pr, p, v3(u - 1e-7, 0.5, v)));
        /* and the top cap ends on the curve too */
        assert_int_equal(hits(&pr, p, v3(u + 1e-7, 5, v), v3(0, -1, 0), h, 8),
                         2);
        assert_int_equal(hits(&pr, p, v3(u - 1e-7, 5, v), v3(0, -1, 0), h, 8),
                         0);
    }
    geom_profile_free(p);
}

/* Polygon with a hole, and a disc with a hole. */
static void test_flat(void **state)
{
    (void)state;
    vec3 pts[10] = { { 0, 0, 0 }, { 4, 0, 0 }, { 4, 4, 0 }, { 0, 4, 0 },
                     { 0, 0, 0 }, { 1, 1, 0 }, { 3, 1, 0 }, { 3, 3, 0 },
                     { 1, 3, 0 }, { 1, 1, 0 } };
    iris_object p = mk(IRIS_OBJ_POLYGON);
    p.u.polygon.n_points = 10;
    p.u.polygon.points = pts;
    struct geom_isect h[4];
    assert_int_equal(hits(&p, NULL, v3(0.5, 0.5, -5), v3(0, 0, 1), h, 4), 1);
    assert_near(h[0].t, 5, 1e-12);
    assert_int_equal(hits(&p, NULL, v3(2, 2, -5), v3(0, 0, 1), h, 4), 0);
    assert_int_equal(hits(&p, NULL, v3(5, 2, -5), v3(0, 0, 1), h, 4), 0);

    iris_object d = mk(IRIS_OBJ_DISC);
    d.u.disc.centre = v3(0, 1, 0);
    d.u.disc.normal = v3(0, 2, 0);
    d.u.disc.radius = 2;
    d.u.disc.hole_radius = 1;
    assert_int_equal(hits(&d, NULL, v3(1.5, 5, 0), v3(0, -1, 0), h, 4), 1);
    assert_near(h[0].t, 4, 1e-12);
    assert_dir(h[0].n, v3(0, 1, 0), 0);
    assert_int_equal(hits(&d, NULL, v3(0.5, 5, 0), v3(0, -1, 0), h, 4), 0);
    /* POV-Ray: the disc's inside is the half-space behind its normal */
    assert_true(geom_inside(&d, NULL, v3(10, 0, 0)));
    assert_false(geom_inside(&d, NULL, v3(0, 2, 0)));

    iris_object pl = mk(IRIS_OBJ_PLANE);
    pl.u.plane.normal = v3(0, 2, 0);
    pl.u.plane.distance = 1;
    assert_int_equal(hits(&pl, NULL, v3(0, 5, 0), v3(0, -1, 0), h, 4), 1);
    assert_near(h[0].t, 4, 1e-12); /* unit normal, distance as given */
    assert_true(geom_inside(&pl, NULL, v3(0, 0.5, 0)));
    assert_false(geom_inside(&pl, NULL, v3(0, 1.5, 0)));
}

/* Text: the stem of "I" in POV-Ray's timrom.ttf, extruded 0..1 along z. */
static void test_text(void **state)
{
    (void)state;
    const char *font = POVRAY_INCLUDE_DIR "/timrom.ttf";
    FILE *f = fopen(font, "rb");
    if (!f)
        skip();
    fclose(f);
    iris_object t = mk(IRIS_OBJ_TEXT);
    t.u.text.font = "timrom.ttf"; /* bare name: found in POV-Ray's dir */
    t.u.text.string = "I";
    t.u.text.thickness = 1;
    const char *why;
    struct geom_profile *p = geom_prepare(&t, &why);
    assert_non_null(p);
    /* An em is 1 unit: a capital is about 0.6-0.7 high */
    assert_true(p->hi.v - p->lo.v > 0.5 && p->hi.v - p->lo.v < 0.8);
    double cx = 0.5 * (p->lo.u + p->hi.u), cy = 0.5 * (p->lo.v + p->hi.v);
    struct geom_isect h[4];
    assert_int_equal(hits(&t, p, v3(cx, cy, -5), v3(0, 0, 1), h, 4), 2);
    assert_near(h[0].t, 5, 1e-12);
    assert_near(h[1].t, 6, 1e-12);
    assert_dir(h[0].n, v3(0, 0, -1), 0);
    assert_true(geom_inside(&t, p, v3(cx, cy, 0.5)));
    assert_false(geom_inside(&t, p, v3(cx + 1, cy, 0.5)));
    /* POV-Ray's TrueType::Inside: 0 <= z <= depth, both faces inside */
    assert_true(geom_inside(&t, p, v3(cx, cy, 0)));
    assert_true(geom_inside(&t, p, v3(cx, cy, 1)));
    assert_false(geom_inside(&t, p, v3(cx, cy, -1e-12)));
    assert_false(geom_inside(&t, p, v3(cx, cy, 1 + 1e-12)));
    geom_profile_free(p);

    t.u.text.font = "/nonexistent/font.ttf";
    assert_null(geom_prepare(&t, &why));
    assert_non_null(why);
}

/*
** Text: "POV" in POV-Ray's povlogo.ttf, a symbol font with 5 glyphs. POV-Ray
** (ASCII charset) reads its Macintosh character map first, where 'P' is
** glyph 4 (the logo: advance 361, left bearing 1, xMin 1 in 512 units per
** em) and 'O', 'V' are glyph 0 (advance 512, xMin 0, xMax 343); FreeType's
** own choice, the Microsoft symbol map, has no 'P'. Laid out as
** truetype.cpp does: P from 0 to the pen at (361 - 1) / 512, then O and V
** each one em on, so the text ends at 360/512 + 1 + 343/512 =
** 2.373046875. POV-Ray 3.7 prints max_extent 2.373064 and min_extent x
** -0.000017 for it (its boxes are padded by about 2e-5); iris gave
** 2.6699 reading FreeType's map. Tolerance 1e-9: the outline's corners are
** on-curve points, exact in binary.
*/
static void test_text_pov_charmap(void **state)
{
    (void)state;
    FILE *f = fopen(POVRAY_INCLUDE_DIR "/povlogo.ttf", "rb");
    if (!f)
        skip();
    fclose(f);
    iris_object t = mk(IRIS_OBJ_TEXT);
    t.u.text.font = "povlogo.ttf";
    t.u.text.string = "POV";
    t.u.text.thickness = 1;
    const char *why;
    struct geom_profile *p = geom_prepare(&t, &why);
    assert_non_null(p);
    assert_near(p->lo.u, 0, 1e-9);
    assert_near(p->hi.u, 360.0 / 512 + 1 + 343.0 / 512, 1e-9);
    assert_near(p->hi.u, 2.373064, 5e-5); /* POV-Ray's own number */
    geom_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_roots_known),
        cmocka_unit_test(test_roots_near_tangent),
        cmocka_unit_test(test_sphere),
        cmocka_unit_test(test_box),
        cmocka_unit_test(test_cylinder),
        cmocka_unit_test(test_cone),
        cmocka_unit_test(test_cone_inside_margin),
        cmocka_unit_test(test_torus),
        cmocka_unit_test(test_poly),
        cmocka_unit_test(test_blob),
        cmocka_unit_test(test_superellipsoid),
        cmocka_unit_test(test_first_only),
        cmocka_unit_test(test_sweeps),
        cmocka_unit_test(test_conic_prism),
        cmocka_unit_test(test_spline_lathe),
        cmocka_unit_test(test_sor_exact),
        cmocka_unit_test(test_spline_prism),
        cmocka_unit_test(test_flat),
        cmocka_unit_test(test_text),
        cmocka_unit_test(test_text_pov_charmap),
        cmocka_unit_test(test_quadric_fast),
        cmocka_unit_test(test_sphere_uv),
        cmocka_unit_test(test_box_uv),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
