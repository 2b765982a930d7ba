/* SPDX-License-Identifier: MIT */
/*
** test_roots_cubic.c: roots_in_interval() on cubics, whose critical
** points roots.c takes from the quadratic formula instead of recursing
** (the solver of the prism's and sor's exact curves), and on quartics,
** whose derivative is such a cubic.
**
** The references are independent of roots.c: cubics built from known
** roots, and for random coefficients a slow solver in long double (the
** derivative's roots by the quadratic formula, then 200 bisections in
** each monotone piece) compared at 1e-9, the accuracy the callers need
** (sweep.c polishes crossings to 1e-13 of the shape's size itself).
** roots_cubic(), the closed form with Newton's polish that the sor and
** prism use, against the same references and against
** roots_in_interval(): the same roots, the same count.
*/
#include "config.h"

#include "testutil.h"

#include <float.h>
#include <stdint.h>
#include <stdio.h>

#include "geometry/roots.h"

/* A deterministic generator (xorshift), uniform in [0, 1). */
static double unit_rand(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* c = k (t - r0)(t - r1)(t - r2), ascending. */
static void cubic_from_roots(double k, const double r[3], double c[4])
{
    c[3] = k;
    c[2] = -k * (r[0] + r[1] + r[2]);
    c[1] = k * (r[0] * r[1] + r[0] * r[2] + r[1] * r[2]);
    c[0] = -k * r[0] * r[1] * r[2];
}

/* Three known roots, in every order of magnitude of the leading
** coefficient and of the roots' spread: each comes back to 1e-12
** relative to the largest |root| (the coefficients are rounded once,
** moving well separated roots by a few ulps of that). */
static void test_cubic_known(void **state)
{
    (void)state;
    static const double sets[][3] = {
        { 1, 2, 3 }, { -5, 0.25, 7 }, { -1e-3, 0, 1e-3 },
        { 0.1, 0.2, 100 }, { -300, -299, 450 }, { 1e-6, 2e-6, 3e-6 },
    };
    static const double ks[] = { 1, -2.5, 1e-8, 3e7 };
    double c[4], out[3];
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++) {
        double rmax = fmax(fabs(sets[i][0]), fabs(sets[i][2]));
        double tol = 1e-12 * rmax;
        for (size_t j = 0; j < sizeof ks / sizeof ks[0]; j++) {
            cubic_from_roots(ks[j], sets[i], c);
            int n = roots_in_interval(c, 3, -INFINITY, INFINITY, out);
            assert_int_equal(n, 3);
            for (int k = 0; k < 3; k++)
                assert_near(out[k], sets[i][k], tol);
            /* only the middle root inside an interval around it */
            double a = 0.5 * (sets[i][0] + sets[i][1]);
            double b = 0.5 * (sets[i][1] + sets[i][2]);
            n = roots_in_interval(c, 3, a, b, out);
            assert_int_equal(n, 1);
            assert_near(out[0], sets[i][1], tol);
        }
    }
    /* One real root and a complex pair: (t - 2)(t² + 1) */
    double one[4] = { -2, 1, -2, 1 };
    assert_int_equal(roots_in_interval(one, 3, -10, 10, out), 1);
    assert_near(out[0], 2, 1e-15);
    /* Monotone, no critical point: t³ + t - 10 has its root at 2 */
    double mono[4] = { -10, 1, 0, 1 };
    assert_int_equal(roots_in_interval(mono, 3, 0, 5, out), 1);
    assert_near(out[0], 2, 1e-15);
    /* A triple root changes sign: t³ at 0, once */
    double tri[4] = { 0, 0, 0, 1 };
    assert_int_equal(roots_in_interval(tri, 3, -1, 1, out), 1);
    assert_near(out[0], 0, 1e-300);
    /* A double root where the polynomial is exactly 0 at its critical
    ** point is reported once, as roots.c always did: (t - 1)² (t + 2) */
    double dbl[4] = { 2, -3, 0, 1 };
    assert_int_equal(roots_in_interval(dbl, 3, -5, 5, out), 2);
    assert_near(out[0], -2, 1e-15);
    assert_near(out[1], 1, 1e-15);
    /* Its neighbour that only comes near zero has one root: + 1e-6 */
    dbl[0] += 1e-6;
    assert_int_equal(roots_in_interval(dbl, 3, -5, 5, out), 1);
    assert_near(out[0], -2 - 1e-6 / 9, 1e-12);
    /* Roots on the interval's ends are outside the open interval */
    static const double r123[3] = { 1, 2, 3 };
    cubic_from_roots(1, r123, c);
    assert_int_equal(roots_in_interval(c, 3, 1, 3, out), 1);
    /* Huge and tiny coefficients (the quadratic formula is scaled) */
    static const double rs[3] = { -1, 0.5, 2 };
    cubic_from_roots(1e150, rs, c);
    assert_int_equal(roots_in_interval(c, 3, -5, 5, out), 3);
    for (int k = 0; k < 3; k++)
        assert_near(out[k], rs[k], 1e-12);
    cubic_from_roots(1e-150, rs, c);
    assert_int_equal(roots_in_interval(c, 3, -5, 5, out), 3);
    for (int k = 0; k < 3; k++)
        assert_near(out[k], rs[k], 1e-12);
}

/* Horner in long double. */
static long double eval_l(const double *c, int deg, long double t)
{
    long double v = c[deg];
    for (int i = deg - 1; i >= 0; i--)
        v = v * t + c[i];
    return v;
}

/* sum |c_i| |t|^i: the size of the terms of the cubic at t. */
static long double terms_l(const double *c, long double t)
{
    long double s = 0, p = 1;
    for (int i = 0; i <= 3; i++) {
        s += fabsl((long double)c[i]) * p;
        p *= fabsl(t);
    }
    return s;
}

/* Bisection of c on [a, b] whose ends have opposite signs. */
static long double bisect_l(const double *c, int deg, long double a,
                            long double b)
{
    long double fa = eval_l(c, deg, a);
    for (int it = 0; it < 200; it++) {
        long double m = 0.5L * (a + b);
        long double fm = eval_l(c, deg, m);
        if (fm == 0)
            return m;
        if ((fm < 0) == (fa < 0)) {
            a = m;
            fa = fm;
        } else {
            b = m;
        }
    }
    return 0.5L * (a + b);
}

/*
** The reference: the real roots in (lo, hi) where the cubic changes sign,
** from its critical points by the quadratic formula and bisection, in
** long double. Returns -1 when a critical value is within 1e-12 of the
** size of the terms there (a near-double root, whose count depends on
** rounding in any solver: those cases are not compared).
*/
static int reference_cubic(const double *c, double lo, double hi,
                           long double *out)
{
    long double A = 3.0L * c[3], B = 2.0L * c[2], C = c[1];
    long double pts[4];
    int np = 0;
    pts[np++] = lo;
    long double disc = B * B - 4 * A * C;
    if (disc > 0) {
        long double s = sqrtl(disc);
        long double r1 = (-B - s) / (2 * A), r2 = (-B + s) / (2 * A);
        if (r1 > r2) {
            long double t = r1;
            r1 = r2;
            r2 = t;
        }
        if (r1 > lo && r1 < hi)
            pts[np++] = r1;
        if (r2 > lo && r2 < hi)
            pts[np++] = r2;
    }
    pts[np++] = hi;
    int n = 0;
    for (int k = 0; k + 1 < np; k++) {
        long double fa = eval_l(c, 3, pts[k]), fb = eval_l(c, 3, pts[k + 1]);
        /* near zero: against the size of the terms there (the scale of
        ** any evaluation's rounding) */
        if ((k > 0 && fabsl(fa) < 1e-12L * terms_l(c, pts[k])) ||
            (k + 2 < np && fabsl(fb) < 1e-12L * terms_l(c, pts[k + 1])))
            return -1;
        if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0))
            out[n++] = bisect_l(c, 3, pts[k], pts[k + 1]);
    }
    return n;
}

/*
** Random cubics (coefficients of mixed signs over twelve orders of
** magnitude, intervals of several sizes, as the prism's curves give
** them) against the long double reference: the same count, and each
** root to 1e-9 of max(1, |root|). Near-double roots are skipped (see
** reference_cubic); at least 90 % of the cases must be compared.
*/
static void test_cubic_random(void **state)
{
    (void)state;
    uint64_t seed = 0x2545f4914f6cdd1du;
    int compared = 0, total = 20000;
    for (int trial = 0; trial < total; trial++) {
        double c[4], out[3];
        long double ref[3];
        for (int i = 0; i < 4; i++) {
            double mag = pow(10, -6 + 12 * unit_rand(&seed));
            c[i] = (unit_rand(&seed) - 0.5) * mag;
        }
        double lo, hi;
        switch (trial % 4) {
        case 0: lo = -1e-12; hi = 1 - 1e-12; break; /* a curve's s */
        case 1: lo = -10; hi = 10; break;
        case 2: lo = -1e3 * unit_rand(&seed); hi = lo + 2e3; break;
        default: lo = -INFINITY; hi = INFINITY; break;
        }
        /* the reference needs a finite interval: Cauchy's bound */
        double rl = lo, rh = hi;
        if (!isfinite(lo)) {
            double b = 0;
            for (int i = 0; i < 3; i++)
                b = fmax(b, fabs(c[i] / c[3]));
            rl = -(1 + b);
            rh = 1 + b;
        }
        int nr = reference_cubic(c, rl, rh, ref);
        if (nr < 0)
            continue;
        compared++;
        int n = roots_in_interval(c, 3, lo, hi, out);
        if (n != nr)
            fail_msg("trial %d: %d roots, reference %d (c = %.17g %.17g "
                     "%.17g %.17g on %g..%g)", trial, n, nr, c[0], c[1],
                     c[2], c[3], lo, hi);
        for (int k = 0; k < n; k++)
            assert_near(out[k], (double)ref[k],
                        1e-9 * fmax(1, fabs((double)ref[k])));
    }
    printf("# %d of %d random cubics compared\n", compared, total);
    assert_true(compared >= total * 9 / 10);
}

/*
** Quartics with four known roots: their critical points come from the
** cubic path above, so this checks it inside the recursion (torus, blob
** and sphere_sweep polynomials go through it). Roots 0.05 apart or more
** in [-2, 2]: each back to 1e-9.
*/
static void test_quartic_through_cubic(void **state)
{
    (void)state;
    uint64_t seed = 0x853c49e6748fea9bu;
    for (int trial = 0; trial < 5000; trial++) {
        double r[4];
        for (;;) {
            for (int i = 0; i < 4; i++)
                r[i] = -2 + 4 * unit_rand(&seed);
            /* sort, and want separated roots */
            for (int i = 0; i < 4; i++)
                for (int j = i + 1; j < 4; j++)
                    if (r[j] < r[i]) {
                        double t = r[i];
                        r[i] = r[j];
                        r[j] = t;
                    }
            if (r[1] - r[0] > 0.05 && r[2] - r[1] > 0.05 &&
                r[3] - r[2] > 0.05)
                break;
        }
        double c[5] = { 1, 0, 0, 0, 0 };
        for (int k = 0; k < 4; k++) {
            for (int i = k + 1; i > 0; i--)
                c[i] = c[i - 1] - r[k] * c[i];
            c[0] = -r[k] * c[0];
        }
        double out[4];
        int n = roots_in_interval(c, 4, -3, 3, out);
        assert_int_equal(n, 4);
        for (int k = 0; k < 4; k++)
            assert_near(out[k], r[k], 1e-9);
    }
}

/*
** roots_cubic() on cubics with known roots: the sets above (spreads from
** 2e-6 to 750, leading coefficients 1e-8 to 3e7 and 1e±150), each root
** to 1e-12 of the largest |root| as for roots_in_interval (the rounding
** of the coefficients moves well separated roots by a few ulps of
** that; the polish leaves the closed form's own error, about 1e-15 of
** the spread, below it), the same count on sub-intervals; one real root
** (Cardano's branch) of both signs of R; a triple root (left to the
** bracketing solver); and the roots nearest the leading coefficient's
** vanishing (a sor's nearly horizontal ray).
*/
static void test_closed_known(void **state)
{
    (void)state;
    static const double sets[][3] = {
        { 1, 2, 3 }, { -5, 0.25, 7 }, { -1e-3, 0, 1e-3 },
        { 0.1, 0.2, 100 }, { -300, -299, 450 }, { 1e-6, 2e-6, 3e-6 },
        { -1, 0.5, 2 },
    };
    static const double ks[] = { 1, -2.5, 1e-8, 3e7, 1e150, -1e-150 };
    double c[4], out[3];
    for (size_t i = 0; i < sizeof sets / sizeof sets[0]; i++) {
        double rmax = fmax(fabs(sets[i][0]), fabs(sets[i][2]));
        double tol = 1e-12 * rmax;
        for (size_t j = 0; j < sizeof ks / sizeof ks[0]; j++) {
            cubic_from_roots(ks[j], sets[i], c);
            int n = roots_cubic(c, -INFINITY, INFINITY, out);
            assert_int_equal(n, 3);
            for (int k = 0; k < 3; k++)
                assert_near(out[k], sets[i][k], tol);
            double a = 0.5 * (sets[i][0] + sets[i][1]);
            double b = 0.5 * (sets[i][1] + sets[i][2]);
            n = roots_cubic(c, a, b, out);
            assert_int_equal(n, 1);
            assert_near(out[0], sets[i][1], tol);
            /* an interval holding none: the roots' span test */
            assert_int_equal(roots_cubic(c, 2 * rmax, 3 * rmax, out), 0);
        }
    }
    /* (t - 2)(t² + 1): R < 0; its mirror (t + 2)(t² + 1): R > 0 */
    double one[4] = { -2, 1, -2, 1 };
    assert_int_equal(roots_cubic(one, -10, 10, out), 1);
    assert_near(out[0], 2, 1e-15);
    double onem[4] = { 2, 1, 2, 1 };
    assert_int_equal(roots_cubic(onem, -10, 10, out), 1);
    assert_near(out[0], -2, 1e-15);
    /* t³ + t - 10 (Q < 0): 2 */
    double mono[4] = { -10, 1, 0, 1 };
    assert_int_equal(roots_cubic(mono, 0, 5, out), 1);
    assert_near(out[0], 2, 1e-15);
    /* a triple root: once, as roots_in_interval reports it */
    double tri[4] = { -1, 3, -3, 1 };
    assert_int_equal(roots_cubic(tri, -5, 5, out), 1);
    /* p's rounding near 1, ~1e-16, moves a triple root by its cube
    ** root, 5e-6 */
    assert_near(out[0], 1, 1e-5);
    /* Non-finite coefficients: no root, as roots_in_interval answers */
    for (int k = 0; k < 4; k++) {
        double bad[4] = { -6, 11, -6, 1 };
        bad[k] = NAN;
        assert_int_equal(roots_cubic(bad, -10, 10, out), 0);
        bad[k] = INFINITY;
        assert_int_equal(roots_cubic(bad, -10, 10, out), 0);
    }
    /* No cubic term: the quadratic (t - 1)(t - 3) */
    double quad[4] = { 3, -4, 1, 0 };
    assert_int_equal(roots_cubic(quad, -5, 5, out), 2);
    assert_near(out[0], 1, 1e-15);
    assert_near(out[1], 3, 1e-15);
    /* e t³ + (t - 1)(t - 2): the roots near 1 and 2 move by about
    ** e (root³ / p'(root)) and a third runs off to -1/e; checked
    ** against the long double reference below in the random test, here
    ** against the first-order root shifts to e² scale */
    for (int p10 = 3; p10 <= 12; p10++) {
        double e = pow(10, -p10);
        double cc[4] = { 2, -3, 1, e };
        int n = roots_cubic(cc, 0, 3, out);
        assert_int_equal(n, 2);
        /* p(t) = (t-1)(t-2) + e t³: root 1 + e (p' = -1), 2 - 8e (p' = 1) */
        assert_near(out[0], 1 + e, 10 * e * e + 1e-15);
        assert_near(out[1], 2 - 8 * e, 1000 * e * e + 1e-15);
    }
}

/*
** Near-double roots (t - 1)(t - 1 - δ)(t + 2), δ from 1e-1 to 1e-10 (the
** closest pairs reach the bracketing solver through roots_cubic's
** conditioning test). The coefficients' rounding, about 4e-16 of the
** terms' size (~8 at t = 1), is ~3e-15 of p; while that is far below
** the depth 3δ²/4 of p between the pair (δ >= 1e-7) both roots exist
** and move by about 3e-15 / |p'| = 1e-15/δ: checked to 1e-14/δ; the
** root at -2 (terms ~30, p' = 9) to 4e-15. Below, the rounded cubic no
** longer dips below 0 there and neither solver finds the pair: the same
** count and roots as roots_in_interval.
*/
static void test_closed_near_double(void **state)
{
    (void)state;
    static const double r0[3] = { -2, 1, 0 };
    for (int p10 = 1; p10 <= 10; p10++) {
        double dl = pow(10, -p10);
        double r[3] = { r0[0], r0[1], 1 + dl }, c[4], out[3], ref[3];
        cubic_from_roots(1, r, c);
        double tol = 1e-14 / dl;
        int n = roots_cubic(c, -5, 5, out);
        assert_int_equal(roots_in_interval(c, 3, -5, 5, ref), n);
        if (dl >= 1e-7) {
            assert_int_equal(n, 3);
            for (int k = 0; k < 3; k++)
                assert_near(out[k], r[k], tol);
        }
        assert_near(out[0], -2, 4e-15);
        for (int k = 0; k < n; k++)
            assert_near(out[k], ref[k], tol);
    }
}

/*
** roots_cubic() on the random cubics of test_cubic_random: against the
** long double reference, the same count and each root to 1e-9 of
** max(1, |root|), the callers' need, as there; against
** roots_in_interval() on every trial, near-double roots included, the
** same count (both report sign changes; roots_cubic leaves the unsure
** cases to it), and each root to 1e-12 of max(1, |root|) where the
** reference is sure (two full-precision solutions of one polynomial
** differ by its condition number times the rounding, which these
** random cubics keep far below 1e4 outside the skipped near-double
** cases).
*/
static void test_closed_random(void **state)
{
    (void)state;
    uint64_t seed = 0x9e3779b97f4a7c15u;
    int compared = 0, total = 20000;
    for (int trial = 0; trial < total; trial++) {
        double c[4], out[3], alt[3];
        long double ref[3];
        for (int i = 0; i < 4; i++) {
            double mag = pow(10, -6 + 12 * unit_rand(&seed));
            c[i] = (unit_rand(&seed) - 0.5) * mag;
        }
        double lo, hi;
        switch (trial % 4) {
        case 0: lo = -1e-12; hi = 1 - 1e-12; break;
        case 1: lo = -10; hi = 10; break;
        case 2: lo = -1e3 * unit_rand(&seed); hi = lo + 2e3; break;
        default: lo = -INFINITY; hi = INFINITY; break;
        }
        int n = roots_cubic(c, lo, hi, out);
        int na = roots_in_interval(c, 3, lo, hi, alt);
        if (n != na)
            fail_msg("trial %d: %d roots, roots_in_interval %d (c = %.17g "
                     "%.17g %.17g %.17g on %g..%g)", trial, n, na, c[0],
                     c[1], c[2], c[3], lo, hi);
        double rl = lo, rh = hi;
        if (!isfinite(lo)) {
            double b = 0;
            for (int i = 0; i < 3; i++)
                b = fmax(b, fabs(c[i] / c[3]));
            rl = -(1 + b);
            rh = 1 + b;
        }
        int nr = reference_cubic(c, rl, rh, ref);
        if (nr < 0)
            continue;
        compared++;
        assert_int_equal(n, nr);
        for (int k = 0; k < n; k++) {
            double sc = fmax(1, fabs((double)ref[k]));
            assert_near(out[k], (double)ref[k], 1e-9 * sc);
            assert_near(out[k], alt[k], 1e-12 * sc);
        }
    }
    printf("# %d of %d random cubics compared\n", compared, total);
    assert_true(compared >= total * 9 / 10);
}


/*
** roots_first_in_interval() (the torus's nearest crossing, accel/node.c)
** must store exactly the first roots roots_in_interval() stores: the
** same values to the bit, for every cap. Quartics from known roots (2 or
** 4 in the interval, one pair nearly double), random quartics, and
** degree-8 polynomials (Bernstein isolation) on random intervals; the
** known quartics must report their roots in order, so the comparison is
** not of two empty lists.
*/
static void test_first_roots(void **state)
{
    (void)state;
    uint64_t s = 0x9e3779b97f4a7c15ULL;
    int n_nonempty = 0;
    for (int it = 0; it < 3000; it++) {
        int deg = it % 3 == 2 ? 8 : 4;
        double c[9], r[8];
        if (it % 3 == 0) {
            /* (t - r0)(t - r1)(t - r2)(t - r3), r ascending in (-3, 3) */
            for (int k = 0; k < 4; k++)
                r[k] = -3 + 6 * unit_rand(&s);
            if (it % 7 == 0)
                r[1] = r[0] + 1e-7;          /* a nearly double pair */
            for (int i = 1; i < 4; i++)
                for (int j = i; j > 0 && r[j] < r[j - 1]; j--) {
                    double t = r[j];
                    r[j] = r[j - 1];
                    r[j - 1] = t;
                }
            c[0] = 1;
            for (int i = 1; i <= 4; i++)
                c[i] = 0;
            for (int k = 0; k < 4; k++)      /* multiply by (t - r[k]) */
                for (int i = k + 1; i >= 0; i--)
                    c[i] = (i > 0 ? c[i - 1] : 0) - r[k] * c[i];
        } else {
            for (int i = 0; i <= deg; i++)
                c[i] = 2 * unit_rand(&s) - 1;
        }
        double lo = -4 * unit_rand(&s), hi = 4 * unit_rand(&s);
        double all[8];
        int n = roots_in_interval(c, deg, lo, hi, all);
        if (it % 3 == 0) {
            int want = 0;
            for (int k = 0; k < 4; k++)
                if (r[k] > lo + 1e-6 && r[k] < hi - 1e-6 &&
                    !(it % 7 == 0 && k < 2))
                    want++;
            assert_true(n >= want);
        }
        if (n > 0)
            n_nonempty++;
        for (int cap = 1; cap <= deg; cap++) {
            double first[8];
            int m = roots_first_in_interval(c, deg, lo, hi, first, cap);
            assert_int_equal(m, n < cap ? n : cap);
            for (int i = 0; i < m; i++)
                assert_true(first[i] == all[i]);
        }
    }
    assert_true(n_nonempty > 1000);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cubic_known),
        cmocka_unit_test(test_cubic_random),
        cmocka_unit_test(test_quartic_through_cubic),
        cmocka_unit_test(test_closed_known),
        cmocka_unit_test(test_closed_near_double),
        cmocka_unit_test(test_closed_random),
        cmocka_unit_test(test_first_roots),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
