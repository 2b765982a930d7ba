/* SPDX-License-Identifier: MIT */
/*
** test_julia_hcx.c: the hypercomplex julia_fractal (julia_hcx.c, julia.c)
** against the algebra's own rules and closed-form sets: the unit table
** (i² = j² = -1, k² = 1, ij = k), the duplex isomorphism built here
** independently, identities of the complex functions (exp(kt) = cosh t +
** k sinh t, ln exp q = q, sin² + cos² = 1, q · 1/q = 1, inverse
** functions), and the c = 0 sqr set, whose surface after n iterations is
** known in closed form.
*/
#include "config.h"

#include "testutil.h"

#include <string.h>

#include "geometry/geom.h"
#include "geometry/julia_hcx.h"

static const double E0[2] = { 0, 0 };

/* The duplex pair (x - w + (y + z)i, x + w + (y - z)i) of q */
static void duplex(const double q[4], double a[2], double b[2])
{
    a[0] = q[0] - q[3];
    a[1] = q[1] + q[2];
    b[0] = q[0] + q[3];
    b[1] = q[1] - q[2];
}

static void assert_q(const double r[4], const double e[4], double tol)
{
    for (int k = 0; k < 4; k++)
        assert_near(r[k], e[k], tol);
}

/* The multiplication table and the duplex isomorphism */
static void test_algebra(void **state)
{
    (void)state;
    const double one[4] = { 1, 0, 0, 0 }, i[4] = { 0, 1, 0, 0 },
                 j[4] = { 0, 0, 1, 0 }, k[4] = { 0, 0, 0, 1 };
    const double mone[4] = { -1, 0, 0, 0 }, mj[4] = { 0, 0, -1, 0 },
                 mi[4] = { 0, -1, 0, 0 };
    double r[4];
    hcx_mul(i, i, r);
    assert_q(r, mone, 0);
    hcx_mul(j, j, r);
    assert_q(r, mone, 0);
    hcx_mul(k, k, r);
    assert_q(r, one, 0);
    hcx_mul(i, j, r);
    assert_q(r, k, 0);
    hcx_mul(i, k, r);
    assert_q(r, mj, 0);
    hcx_mul(j, k, r);
    assert_q(r, mi, 0);
    /* Products map to component-wise complex products of the duplex
    ** pairs (exact in real arithmetic; 1e-14 is rounding at |q| ~ 1) */
    const double p[4] = { 0.3, -0.7, 0.45, 0.2 }, q[4] = { -0.9, 0.1,
                                                           0.35, -0.6 };
    double pa[2], pb[2], qa[2], qb[2], ra[2], rb[2];
    hcx_mul(p, q, r);
    duplex(p, pa, pb);
    duplex(q, qa, qb);
    duplex(r, ra, rb);
    assert_near(ra[0], pa[0] * qa[0] - pa[1] * qa[1], 1e-14);
    assert_near(ra[1], pa[0] * qa[1] + pa[1] * qa[0], 1e-14);
    assert_near(rb[0], pb[0] * qb[0] - pb[1] * qb[1], 1e-14);
    assert_near(rb[1], pb[0] * qb[1] + pb[1] * qb[0], 1e-14);
    double r2[4];
    hcx_mul(q, p, r2);
    assert_q(r2, r, 1e-15); /* commutative */
    /* sqr and cube both square in POV-Ray 3.7 (hcmplx.cpp's z3 rules) */
    double s1[4], s2[4];
    hcx_map(IRIS_JULIA_SQR, E0, p, s1);
    hcx_map(IRIS_JULIA_CUBE, E0, p, s2);
    hcx_mul(p, p, r);
    assert_q(s1, r, 1e-15);
    assert_q(s2, r, 1e-15);
}

/* The functions against identities that hold for every branch used */
static void test_functions(void **state)
{
    (void)state;
    double r[4], s[4], t[4];
    /* exp(kt) = cosh t + k sinh t, as k² = 1; exp(it) = cos t + i sin t */
    const double kt[4] = { 0, 0, 0, 0.7 }, it[4] = { 0, 0.7, 0, 0 };
    hcx_map(IRIS_JULIA_EXP, E0, kt, r);
    assert_q(r, (double[4]){ cosh(0.7), 0, 0, sinh(0.7) }, 1e-15);
    hcx_map(IRIS_JULIA_EXP, E0, it, r);
    assert_q(r, (double[4]){ cos(0.7), sin(0.7), 0, 0 }, 1e-15);
    /* Small q: every inverse function is on its principal branch, so
    ** f⁻¹(f(q)) = q to rounding (1e-12 allows for the cancellation
    ** inside the logarithm forms) */
    const double q[4] = { 0.21, -0.13, 0.08, 0.05 };
    static const int pairs[][2] = {
        { IRIS_JULIA_EXP, IRIS_JULIA_LN },
        { IRIS_JULIA_SIN, IRIS_JULIA_ASIN },
        { IRIS_JULIA_TAN, IRIS_JULIA_ATAN },
        { IRIS_JULIA_SINH, IRIS_JULIA_ASINH },
        { IRIS_JULIA_TANH, IRIS_JULIA_ATANH },
    };
    for (size_t n = 0; n < sizeof pairs / sizeof pairs[0]; n++) {
        hcx_map(pairs[n][0], E0, q, r);
        hcx_map(pairs[n][1], E0, r, s);
        assert_q(s, q, 1e-12);
    }
    /* POV-Ray's acos and acosh, ±i ln(z + sqrt(z² - 1)), leave the
    ** principal branch off the real axis (acos(cos q) may be -q), but
    ** cos(acos q) = q and cosh(acosh q) = q on every branch */
    const double qp[4] = { 0.9, 0.12, -0.05, 0.1 };
    hcx_map(IRIS_JULIA_ACOS, E0, qp, r);
    hcx_map(IRIS_JULIA_COS, E0, r, s);
    assert_q(s, qp, 1e-12);
    hcx_map(IRIS_JULIA_ACOSH, E0, qp, r);
    hcx_map(IRIS_JULIA_COSH, E0, r, s);
    assert_q(s, qp, 1e-12);
    /* sin² + cos² = 1 */
    hcx_map(IRIS_JULIA_SIN, E0, qp, r);
    hcx_map(IRIS_JULIA_COS, E0, qp, s);
    hcx_mul(r, r, r);
    hcx_mul(s, s, s);
    for (int k = 0; k < 4; k++)
        t[k] = r[k] + s[k];
    assert_q(t, (double[4]){ 1, 0, 0, 0 }, 1e-14);
    /* q · (1/q) = 1; the reciprocal's normal factor is -(1/q)² */
    hcx_map(IRIS_JULIA_RECIPROCAL, E0, qp, r);
    hcx_mul(r, qp, s);
    assert_q(s, (double[4]){ 1, 0, 0, 0 }, 1e-14);
    hcx_normal_factor(IRIS_JULIA_RECIPROCAL, E0, qp, s);
    hcx_mul(s, qp, s);
    hcx_mul(s, qp, s);
    assert_q(s, (double[4]){ -1, 0, 0, 0 }, 1e-14);
    /* pwr(q, 2, 0) = q², pwr(q, 0.5, 0)² = q */
    hcx_map(IRIS_JULIA_PWR, (double[2]){ 2, 0 }, qp, r);
    hcx_mul(qp, qp, s);
    assert_q(r, s, 1e-14);
    hcx_map(IRIS_JULIA_PWR, (double[2]){ 0.5, 0 }, qp, r);
    hcx_mul(r, r, r);
    assert_q(r, qp, 1e-14);
}

static iris_object julia(int fn, int iters)
{
    iris_object o;
    memset(&o, 0, sizeof o);
    o.kind = IRIS_OBJ_JULIA_FRACTAL;
    o.u.julia.type = 1; /* hypercomplex */
    o.u.julia.fn = fn;
    o.u.julia.iterations = iters;
    o.u.julia.precision = 20;
    return o;
}

/* The first hit of o + t d, t in (0, 100); its unit normal in *n */
static double first_hit(const iris_object *o, vec3 ro, vec3 rd, vec3 *n)
{
    struct isect_list l;
    isect_list_init(&l);
    geom_intersect(o, NULL, ro, rd, 0, 100, &l);
    double t = INFINITY;
    for (int i = 0; i < l.n; i++)
        if (l.v[i].t < t) {
            t = l.v[i].t;
            *n = v3_norm(l.v[i].n);
        }
    isect_list_fini(&l);
    return t;
}

/*
** c = 0, sqr, n iterations, slice w = 0: |q|² = (|a|² + |b|²)/2 for the
** duplex pair, and a, b square independently. POV-Ray tests z_0 ..
** z_(n-1) against 16, so the surface is where max(|a|, |b|)^(2^n) meets
** 16 (the other half is smaller and adds at most a factor 1/2 to |q|²,
** which moves the surface by ln 2 / 2^n relative: 7e-7 for n = 20, so
** the rays below cross where |a| = |b|, making it exact). Bisection
** stops at 1e-7 along the ray (POV-Ray's tolerance): hits agree to
** 2e-7. The normal is the gradient of |a|² + |b|², to 1e-6.
*/
static void test_zero_set(void **state)
{
    (void)state;
    int n = 20;
    double r = pow(16, ldexp(1, -n)); /* |a| = |b| = r at the surface */
    for (int fn = IRIS_JULIA_SQR; fn <= IRIS_JULIA_CUBE; fn++) {
        iris_object o = julia(fn, n);
        assert_null(geom_validate(&o));
        vec3 nr;
        /* Along x (a = b = x) */
        double t = first_hit(&o, v3(-5, 0, 0), v3(1, 0, 0), &nr);
        assert_near(t, 5 - r, 2e-7);
        assert_near(nr.x, -1, 1e-9);
        /* Along z at x = 0.5, y = 0: a = 0.5 + zi, b = conj(a) */
        double z = -sqrt(r * r - 0.25);
        t = first_hit(&o, v3(0.5, 0, -5), v3(0, 0, 1), &nr);
        assert_near(t, 5 + z, 2e-7);
        assert_near(nr.x, 0.5 / r, 1e-6);
        assert_near(nr.y, 0, 1e-6);
        assert_near(nr.z, z / r, 1e-6);
        /* Inside iff both halves have modulus <= r */
        assert_true(geom_inside(&o, NULL, v3(0.5, 0.3, 0.2)));  /* .71, .51 */
        assert_false(geom_inside(&o, NULL, v3(0.8, 0.7, 0)));   /* 1.06 */
        assert_false(geom_inside(&o, NULL, v3(0.1, 0.2, -0.9))); /* b 1.1 */
    }
}

/* Hypercomplex takes every function; quaternion only sqr and cube */
static void test_validate(void **state)
{
    (void)state;
    for (int fn = IRIS_JULIA_SQR; fn <= IRIS_JULIA_PWR; fn++) {
        iris_object o = julia(fn, 6);
        assert_null(geom_validate(&o));
        o.u.julia.type = 0;
        if (fn <= IRIS_JULIA_CUBE)
            assert_null(geom_validate(&o));
        else
            assert_non_null(geom_validate(&o));
    }
    /* exp with c = -2 on the real axis: x -> e^x - 2 has an attracting
    ** fixed point at -1.84 (slope 0.16), which 0 falls to (0, -1, -1.63,
    ** -1.80, ...); 1.5 escapes (1.5, 2.48, 9.9: |z|² > 16) */
    iris_object o = julia(IRIS_JULIA_EXP, 6);
    o.u.julia.data[0] = -2;
    assert_true(geom_inside(&o, NULL, v3(0, 0, 0)));
    assert_false(geom_inside(&o, NULL, v3(1.5, 0, 0)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_algebra),
        cmocka_unit_test(test_functions),
        cmocka_unit_test(test_zero_set),
        cmocka_unit_test(test_validate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
