/* SPDX-License-Identifier: MIT */
/*
** test_geom_bound.c: what geom_prepare() resolves once instead of per ray,
** against answers found without it:
**  - bounded_by (bound.c): the bound's world box, kept in the profile, cuts
**    a shape exactly as the per-ray computation did, and as POV-Ray's box
**    test does (a torus cut by a box, worked out by hand); a CSG's bound
**    admits the rays POV-Ray's Ray_In_Bound admits;
**  - the exact curves of a linear prism (sweep.c): the Bezier hull
**    rejection before each cubic loses no crossing and no inside answer,
**    against a brute-force reference (dense sampling of the exact spline
**    and bisection).
*/
#include "config.h"

#include "testutil.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "geometry/geom.h"
#include "math/transform.h"

static iris_object mk(enum iris_object_kind k)
{
    iris_object o;
    memset(&o, 0, sizeof o);
    o.kind = k;
    return o;
}

/* A deterministic generator (xorshift), uniform in [0, 1). */
static double unit_rand(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* The crossings of 'o' (with 'prof') on the ray, sorted by t; the count. */
static int crossings(const iris_object *o, const struct geom_profile *prof,
                     vec3 ro, vec3 rd, double *t, int cap)
{
    struct isect_list l;
    isect_list_init(&l);
    geom_intersect(o, prof, ro, rd, 1e-9, INFINITY, &l);
    int n = l.n < cap ? l.n : cap;
    for (int i = 0; i < n; i++)
        t[i] = l.v[i].t;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (t[j] < t[i]) {
                double s = t[i];
                t[i] = t[j];
                t[j] = s;
            }
    int total = l.n;
    isect_list_fini(&l);
    return total;
}

/* The torus R 0.8, r 0.3 of parity scene 104, bounded by a box smaller
** than its own: rays worked out by hand. */
static void test_bound_torus_by_hand(void **state)
{
    (void)state;
    iris_object box = mk(IRIS_OBJ_BOX);
    box.u.box.lo = v3(-0.5, -0.5, -1.2);
    box.u.box.hi = v3(0.6, 0.5, 1.2);
    iris_object tor = mk(IRIS_OBJ_TORUS);
    tor.u.torus.major = 0.8;
    tor.u.torus.minor = 0.3;
    tor.bounded_by = &box;
    const char *why = "unset";
    struct geom_profile *prof = geom_prepare(&tor, &why);
    assert_null(why);
    assert_non_null(prof);
    assert_true(prof->bound.ready);
    /* the box (1.1 x 1 x 2.4 = 2.64) is smaller than the torus's (2.2 x
    ** 0.6 x 2.2 = 2.904): it cuts */
    assert_true(prof->bound.box_cuts);
    double t[8];
    /* along x through the centre: the box is met, all four crossings
    ** (x = -1.1, -0.5, 0.5, 1.1) count, also those outside the box */
    assert_int_equal(crossings(&tor, prof, v3(-5, 0, 0), v3(1, 0, 0), t, 8),
                     4);
    assert_near(t[0], 3.9, 1e-12);
    assert_near(t[1], 4.5, 1e-12);
    assert_near(t[2], 5.5, 1e-12);
    assert_near(t[3], 6.1, 1e-12);
    /* along z at x = 1: the torus is there (z = ±sqrt(1.1² - 1)) but the
    ** ray misses the box (x up to 0.6): nothing */
    assert_int_equal(crossings(&tor, prof, v3(1, 0, -5), v3(0, 0, 1), t, 8),
                     0);
    tor.bounded_by = NULL;
    assert_int_equal(crossings(&tor, NULL, v3(1, 0, -5), v3(0, 0, 1), t, 8),
                     2);
    assert_near(t[0], 5 - sqrt(0.21), 1e-12);
    geom_profile_free(prof);
}

/*
** Three bounded shapes of parity scene 104's kinds, transformed: a poly
** (whose bound POV-Ray keeps: also tested by itself), a torus and a
** sphere cut by boxes. On 20000 random rays the prepared profile gives
** the same crossings, to the bit, as the per-ray computation (no
** profile), which is what the images compared before and after.
*/
static void test_bound_prepared_same(void **state)
{
    (void)state;
    /* poly x² + y² + z² - 1 (POV-Ray's order), bounded by a sphere */
    double pc[10] = { 1, 0, 0, 0, 1, 0, 0, 1, 0, -1 };
    iris_object bsph = mk(IRIS_OBJ_SPHERE);
    bsph.u.sphere.centre = v3(0.3, 0.4, 0);
    bsph.u.sphere.radius = 0.8;
    iris_object poly = mk(IRIS_OBJ_POLY);
    poly.u.poly.order = 2;
    poly.u.poly.n_coeffs = 10;
    poly.u.poly.coeffs = pc;
    poly.bounded_by = &bsph;
    /* torus cut by a box, both rotated and moved as in scene 104 */
    iris_object bbox = mk(IRIS_OBJ_BOX);
    bbox.u.box.lo = v3(-0.5, -0.5, -1.2);
    bbox.u.box.hi = v3(0.6, 0.5, 1.2);
    iris_object tor = mk(IRIS_OBJ_TORUS);
    tor.u.torus.major = 0.8;
    tor.u.torus.minor = 0.3;
    tor.bounded_by = &bbox;
    xform a, b, m;
    xf_rotate(&a, v3(-60, 0, 0));
    xf_translate(&b, v3(2.4, 0.5, 0));
    xf_compose(&m, &a, &b);   /* rotate, then move */
    tor.transform = m;
    tor.has_transform = true;
    bbox.transform = m;
    bbox.has_transform = true;
    /* a sphere whose bound box is the smaller: scaled and moved */
    iris_object bb2 = mk(IRIS_OBJ_BOX);
    bb2.u.box.lo = v3(-0.5, -2, -0.5);
    bb2.u.box.hi = v3(0.5, 0.3, 2);
    iris_object sph = mk(IRIS_OBJ_SPHERE);
    sph.u.sphere.radius = 1;
    sph.bounded_by = &bb2;
    xf_scale(&sph.transform, v3(1, 2, 1.5));
    sph.has_transform = true;

    iris_object *objs[3] = { &poly, &tor, &sph };
    /* the rays aim near each shape's centre (world space) */
    const vec3 centre[3] = { v3(0, 0, 0), v3(2.4, 0.5, 0), v3(0, 0, 0) };
    uint64_t seed = 0x6a09e667f3bcc909u;
    int met = 0;
    for (int k = 0; k < 3; k++) {
        const char *why = "unset";
        struct geom_profile *prof = geom_prepare(objs[k], &why);
        assert_null(why);
        assert_non_null(prof);
        assert_true(prof->bound.ready);
        /* each bound is the smaller box, so the box test is exercised */
        assert_true(prof->bound.box_cuts);
        for (int r = 0; r < 20000; r++) {
            vec3 ro = v3(-3 + 6 * unit_rand(&seed), -3 + 6 * unit_rand(&seed),
                         -3 + 6 * unit_rand(&seed));
            ro = v3_add(ro, centre[k]);
            vec3 aim = v3_add(centre[k],
                              v3(-1.5 + 3 * unit_rand(&seed),
                                 -1.5 + 3 * unit_rand(&seed),
                                 -1.5 + 3 * unit_rand(&seed)));
            /* object space, as the accel layer hands rays over */
            vec3 rd = v3_sub(aim, ro);
            if (objs[k]->has_transform) {
                ro = xf_inv_point(&objs[k]->transform, ro);
                rd = xf_inv_dir(&objs[k]->transform, rd);
            }
            double t1[16], t2[16];
            int n1 = crossings(objs[k], prof, ro, rd, t1, 16);
            int n2 = crossings(objs[k], NULL, ro, rd, t2, 16);
            assert_int_equal(n1, n2);
            for (int i = 0; i < n1 && i < 16; i++)
                assert_true(t1[i] == t2[i]);
            met += n1 > 0;
        }
        geom_profile_free(prof);
    }
    /* the rays do meet the shapes (the comparison is not vacuous) */
    printf("# %d of 60000 rays met a shape\n", met);
    assert_true(met > 10000);
}

/* The exact cubic of spline segment 'c' at s (profile.c's convention). */
static iris_vec2 curve_at(const struct geom_curve *c, double s)
{
    iris_vec2 p;
    p.u = ((c->c[0].u * s + c->c[1].u) * s + c->c[2].u) * s + c->c[3].u;
    p.v = ((c->c[0].v * s + c->c[1].v) * s + c->c[2].v) * s + c->c[3].v;
    return p;
}

/* K(s) = (u(s) - ou) dv - (v(s) - ov) du: the curve's side of the line. */
static double side_at(const struct geom_curve *c, double s, double ou,
                      double ov, double du, double dv)
{
    iris_vec2 p = curve_at(c, s);
    return (p.u - ou) * dv - (p.v - ov) * du;
}

#define GRID 4000

/*
** The parameters in [0, 1) where curve 'c' crosses the line through
** (ou, ov) along (du, dv), by sampling K on a grid of GRID steps and
** bisecting each sign change; -1 when K comes within 1e-6 of zero
** without changing sign (a near-tangent line, whose crossings a grid
** cannot resolve: not compared).
*/
static int brute_params(const struct geom_curve *c, double ou, double ov,
                        double du, double dv, double *s_out)
{
    int n = 0;
    double prev = side_at(c, 0, ou, ov, du, dv);
    for (int i = 1; i <= GRID; i++) {
        double s = (double)i / GRID;
        double k = side_at(c, s, ou, ov, du, dv);
        if ((prev < 0) != (k < 0)) {
            double a = s - 1.0 / GRID, b = s, fa = prev;
            for (int it = 0; it < 100; it++) {
                double m = 0.5 * (a + b), fm = side_at(c, m, ou, ov, du, dv);
                if ((fm < 0) == (fa < 0)) {
                    a = m;
                    fa = fm;
                } else {
                    b = m;
                }
            }
            if (a < 1 - 1e-9)
                s_out[n++] = 0.5 * (a + b);
        } else if (fabs(k) < 1e-6 && i < GRID) {
            return -1;
        }
        prev = k;
    }
    return n;
}

/*
** The linear prism of parity scene 146 (cubic_spline, heights 0..1): on
** 3000 random rays its wall crossings are those of the brute-force
** reference on each exact curve, t to 1e-9 (the cubic solver's roots
** are full precision; the reference's bisection reaches 1e-16 in s);
** and the inside test (the even-odd rule on the exact curves, rejected
** by the same hulls) agrees with the reference's count of crossings to
** the right on 3000 random points.
*/
static void test_prism_curves_brute_force(void **state)
{
    (void)state;
    iris_vec2 pts[8] = { { 2, 0 }, { 0, -2 }, { -2, 0 }, { 0, 2 },
                         { 2, 0 }, { 0, -2 }, { -2, 0 }, { 0, 2 } };
    iris_object pr = mk(IRIS_OBJ_PRISM);
    pr.u.prism.spline = IRIS_SPLINE_CUBIC;
    pr.u.prism.sweep = 0;
    pr.u.prism.height1 = 0;
    pr.u.prism.height2 = 1;
    pr.u.prism.n_points = 8;
    pr.u.prism.points = pts;
    const char *why = "unset";
    struct geom_profile *p = geom_prepare(&pr, &why);
    assert_null(why);
    assert_non_null(p);
    assert_true(p->n_curves >= 4);
    uint64_t seed = 0xbb67ae8584caa73bu;
    int compared = 0, walls = 0;
    for (int r = 0; r < 3000; r++) {
        /* a ray at a height between the caps, running level, so every
        ** crossing is a wall's */
        vec3 ro = v3(-4 + 8 * unit_rand(&seed), 0.2 + 0.6 * unit_rand(&seed),
                     -4 + 8 * unit_rand(&seed));
        double ang = 2 * M_PI * unit_rand(&seed);
        vec3 rd = v3(cos(ang), 0, sin(ang));
        double ref[32];
        int nref = 0;
        bool skip = false;
        for (int ci = 0; ci < p->n_curves && !skip; ci++) {
            double s[8];
            int m = brute_params(&p->curves[ci], ro.x, ro.z, rd.x, rd.z, s);
            if (m < 0) {
                skip = true;
                break;
            }
            for (int k = 0; k < m; k++) {
                iris_vec2 q = curve_at(&p->curves[ci], s[k]);
                double t = (q.u - ro.x) * rd.x + (q.v - ro.z) * rd.z;
                if (t > 1e-9)
                    ref[nref++] = t;
            }
        }
        if (skip)
            continue;
        compared++;
        for (int i = 0; i < nref; i++)
            for (int j = i + 1; j < nref; j++)
                if (ref[j] < ref[i]) {
                    double x = ref[i];
                    ref[i] = ref[j];
                    ref[j] = x;
                }
        double t[32];
        int n = crossings(&pr, p, ro, rd, t, 32);
        if (n != nref)
            fail_msg("ray %d: %d crossings, reference %d", r, n, nref);
        for (int i = 0; i < n; i++)
            assert_near(t[i], ref[i], 1e-9);
        walls += n;
    }
    assert_true(compared > 2700);
    assert_true(walls > 1000);

    int inside_compared = 0, inside = 0;
    for (int k = 0; k < 3000; k++) {
        double u = -3 + 6 * unit_rand(&seed), v = -3 + 6 * unit_rand(&seed);
        /* crossings of the +u ray from (u, v): the line v = const */
        int count = 0;
        bool skip = false;
        for (int ci = 0; ci < p->n_curves; ci++) {
            double s[8];
            int m = brute_params(&p->curves[ci], u, v, 1, 0, s);
            if (m < 0) {
                skip = true;
                break;
            }
            for (int j = 0; j < m; j++)
                count += curve_at(&p->curves[ci], s[j]).u > u;
        }
        if (skip)
            continue;
        inside_compared++;
        bool in = geom_inside(&pr, p, v3(u, 0.5, v));
        assert_int_equal(in, count % 2 == 1);
        inside += in;
    }
    assert_true(inside_compared > 2700);
    assert_true(inside > 300);
    geom_profile_free(p);
}

/*
** bounded_by on CSG (geom_csg_bound_admits): POV-Ray's Ray_In_Bound, the
** ray (t >= 0 only) meets the bound or starts inside it, worked out by
** hand for a unit sphere about (2, 0, 0). The bound's answer alone
** decides: the CSG's children do not enter.
*/
static void test_bound_csg_by_hand(void **state)
{
    (void)state;
    iris_object b = mk(IRIS_OBJ_SPHERE);
    b.u.sphere.centre = v3(2, 0, 0);
    b.u.sphere.radius = 1;
    iris_object c = mk(IRIS_OBJ_INTERSECTION);
    assert_true(geom_csg_bound_admits(&c, v3(-5, 9, 0), v3(1, 0, 0)));
    c.bounded_by = &b;
    /* through the sphere; grazing past it at distance 1.5 */
    assert_true(geom_csg_bound_admits(&c, v3(-5, 0, 0), v3(1, 0, 0)));
    assert_true(geom_csg_bound_admits(&c, v3(-5, 0.99, 0), v3(1, 0, 0)));
    assert_false(geom_csg_bound_admits(&c, v3(-5, 1.5, 0), v3(1, 0, 0)));
    /* from inside, whatever the direction */
    assert_true(geom_csg_bound_admits(&c, v3(2, 0.5, 0), v3(0, 1, 0)));
    /* behind the origin only: not met */
    assert_false(geom_csg_bound_admits(&c, v3(5, 0, 0), v3(1, 0, 0)));
    /* an inverse bound is a hint only, as on shapes */
    b.inverse = true;
    assert_true(geom_csg_bound_admits(&c, v3(-5, 1.5, 0), v3(1, 0, 0)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bound_torus_by_hand),
        cmocka_unit_test(test_bound_csg_by_hand),
        cmocka_unit_test(test_bound_prepared_same),
        cmocka_unit_test(test_prism_curves_brute_force),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
