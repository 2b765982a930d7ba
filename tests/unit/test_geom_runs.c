/* SPDX-License-Identifier: MIT */
/*
** test_geom_runs.c: the runs of a straight-segment profile (geom.h,
** profile.c) and what text rays skip with them (sweep.c), against
** answers found without them:
**  - the even-odd inside test gives, point for point, what the plain loop
**    over every segment gives (it must: images stay the same to the bit),
**    and away from the outline what the smooth shapes the outline
**    approximates give (an independent geometric answer);
**  - a ray through the extrusion finds the same crossings, bit for bit and
**    in the same order, with and without the runs, and the crossings a
**    brute-force line-segment solution (Cramer's rule, written here)
**    finds, to 1e-9 of the profile's size.
** The profile is a row of wavy "glyphs" (150-point outer contours with
** 60-point holes, as a font's letters are), an open chain besides.
*/
#include "config.h"

#include "testutil.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/geom.h"

#define GLYPHS 6
#define N_OUT 150
#define N_IN 60
#define R_OUT 0.4
#define R_IN 0.15
#define WAVE 0.2

/* A deterministic generator (xorshift), uniform in [0, 1). */
static double unit_rand(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* Radius of glyph contour 'r0' at angle th: a circle with five waves. */
static double wavy(double r0, double th)
{
    return r0 * (1 + WAVE * sin(5 * th));
}

static iris_vec2 vtx(int g, double r0, int n, int i)
{
    double th = 2 * M_PI * i / n;
    iris_vec2 v = { g + wavy(r0, th) * cos(th), wavy(r0, th) * sin(th) };
    return v;
}

/* The row of glyphs, each closed outer contour and hole a group, as
** text.c builds them; then one open chain (not a polygon: its crossings
** must still be the loop's). */
static struct geom_profile *row(void)
{
    struct geom_profile *p = geom_profile_new(16);
    assert_non_null(p);
    for (int g = 0; g < GLYPHS; g++) {
        for (int i = 0; i < N_OUT; i++)
            assert_true(geom_profile_add(p, vtx(g, R_OUT, N_OUT, i),
                                         vtx(g, R_OUT, N_OUT, i + 1)));
        assert_true(geom_profile_close_group(p));
        for (int i = N_IN; i > 0; i--)
            assert_true(geom_profile_add(p, vtx(g, R_IN, N_IN, i),
                                         vtx(g, R_IN, N_IN, i - 1)));
        assert_true(geom_profile_close_group(p));
    }
    for (int i = 0; i < 40; i++) {
        iris_vec2 a = { 0.15 * i, -1.0 + 0.1 * sin(i) };
        iris_vec2 b = { 0.15 * (i + 1), -1.0 + 0.1 * sin(i + 1) };
        assert_true(geom_profile_add(p, a, b));
    }
    geom_profile_finish(p);
    p->h1 = 0;
    p->h2 = 0.2;
    assert_true(p->n_runs > 0);  /* else nothing here tests them */
    return p;
}

/* The even-odd rule over every segment, as profile.c's loop has it. */
static bool inside_plain(const struct geom_profile *p, double u, double v)
{
    int parity = 0;
    for (int i = 0; i < p->n_seg; i++) {
        iris_vec2 a = p->a[i], b = p->b[i];
        if ((a.v > v) == (b.v > v))
            continue;
        parity ^= a.u + (v - a.v) * (b.u - a.u) / (b.v - a.v) > u;
    }
    return parity;
}

static void test_inside_same(void **state)
{
    (void)state;
    struct geom_profile *p = row();
    uint64_t s = 0x9e3779b97f4a7c15ULL;
    int in = 0, smooth = 0;
    for (int k = 0; k < 40000; k++) {
        double u = -1 + (GLYPHS + 1) * unit_rand(&s);
        double v = -1.3 + 2 * unit_rand(&s);
        bool got = geom_profile_inside2d(p, u, v);
        assert_int_equal(got, inside_plain(p, u, v));
        in += got;
        /* The smooth shapes, 0.02 from their outlines (the 150- and
        ** 60-gons deviate from them by under 0.01): inside the outer,
        ** outside the hole. The open chain lies below v = -0.85. */
        if (v < -0.7)
            continue;
        int g = (int)floor(u + 0.5);
        if (g < 0 || g >= GLYPHS)
            g = g < 0 ? 0 : GLYPHS - 1;
        double du = u - g, r = hypot(du, v), th = atan2(v, du);
        double ro = wavy(R_OUT, th), ri = wavy(R_IN, th);
        if (fabs(r - ro) < 0.02 || fabs(r - ri) < 0.02)
            continue;
        assert_int_equal(got, r < ro && r > ri);
        smooth++;
    }
    /* the sample meets both answers often */
    assert_true(in > 4000 && smooth > 20000);
    geom_profile_free(p);
}

static int by_t(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The crossings of o + t d (t > 0) with the walls and caps of the
** extrusion from z = h1 to h2, by Cramer's rule on each wall segment
** and the plain inside test on the caps. Returns their count. */
static int brute_hits(const struct geom_profile *p, vec3 o, vec3 d,
                      double *ts)
{
    int n = 0;
    for (int i = 0; i < p->n_seg; i++) {
        /* o.uv + t d.uv = a + s (b - a) */
        double eu = p->b[i].u - p->a[i].u, ev = p->b[i].v - p->a[i].v;
        double det = d.x * -ev - d.y * -eu;
        if (det == 0)
            continue;
        double ru = p->a[i].u - o.x, rv = p->a[i].v - o.y;
        double t = (ru * -ev - rv * -eu) / det;
        double sp = (d.x * rv - d.y * ru) / det;
        double z = o.z + t * d.z;
        if (t > 0 && sp >= 0 && sp < 1 && z > p->h1 && z < p->h2)
            ts[n++] = t;
    }
    for (int k = 0; k < 2 && d.z != 0; k++) {
        double t = ((k ? p->h2 : p->h1) - o.z) / d.z;
        if (t > 0 && inside_plain(p, o.x + t * d.x, o.y + t * d.y))
            ts[n++] = t;
    }
    qsort(ts, (size_t)n, sizeof *ts, by_t);
    return n;
}

static void test_rays_same(void **state)
{
    (void)state;
    struct geom_profile *p = row();
    uint64_t s = 0x2545f4914f6cdd1dULL;
    static double ref[4096], got[4096];
    int total = 0;
    for (int k = 0; k < 6000; k++) {
        /* From in front of the row towards a point of it: along z as a
        ** camera's rays, or slanted as a light's (1 in 3) */
        vec3 o = v3(-1 + (GLYPHS + 1) * unit_rand(&s),
                    -1.3 + 2.2 * unit_rand(&s), -3);
        vec3 to = v3(-1 + (GLYPHS + 1) * unit_rand(&s),
                     -1.3 + 2.2 * unit_rand(&s), 0.1);
        if (k % 3 == 0)
            o = v3_add(o, v3(6 * unit_rand(&s) - 3, 6 * unit_rand(&s) - 3,
                             0));
        vec3 d = v3_norm(v3_sub(to, o));
        struct isect_list with, without;
        isect_list_init(&with);
        isect_list_init(&without);
        geom_extrude_hits(p, 2, o, d, 0, INFINITY, &with);
        int n_runs = p->n_runs;
        p->n_runs = 0;         /* the plain loop over every segment */
        geom_extrude_hits(p, 2, o, d, 0, INFINITY, &without);
        p->n_runs = n_runs;
        /* the same crossings, bit for bit, in the same order */
        assert_int_equal(with.n, without.n);
        for (int i = 0; i < with.n; i++) {
            assert_memory_equal(&with.v[i].t, &without.v[i].t,
                                sizeof(double));
            assert_memory_equal(&with.v[i].n, &without.v[i].n,
                                sizeof(vec3));
        }
        /* and those of the brute force: 1e-9 of the profile's size is a
        ** million times the rounding of either formula */
        int nb = brute_hits(p, o, d, ref);
        assert_int_equal(with.n, nb);
        for (int i = 0; i < with.n; i++)
            got[i] = with.v[i].t;
        qsort(got, (size_t)with.n, sizeof *got, by_t);
        for (int i = 0; i < nb; i++)
            assert_near(got[i], ref[i], 1e-9 * GLYPHS);
        total += nb;
        isect_list_fini(&with);
        isect_list_fini(&without);
    }
    /* the glyphs cover about a fifth of the window the rays aim at, and
    ** a ray that meets one crosses it twice or more: about 3750 */
    assert_true(total > 2000);
    geom_profile_free(p);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_inside_same),
        cmocka_unit_test(test_rays_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
