/* SPDX-License-Identifier: MIT */
/*
** test_noise_exact.c: noise_value() and noise_vector() bit for bit against
** POV-Ray's Noise() and DNoise() written out the plain way.
**
** noise.c regroups POV-Ray's random coefficients into per-hash blocks and
** sums dnoise()'s x and y components in SSE2 lanes, for speed. The parity
** suite and test_material compare with POV-Ray's images within tolerances
** that would hide a last-bit change, yet such a change moves pattern edges
** (colour map entries, crackle borders) and breaks the promise that iris
** computes POV-Ray's noise exactly. So the tolerance here is zero: the
** reference below is POV-Ray 3.7's algorithm (source/backend/texture/
** texture.cpp: RTable with value k at 2k and half of it at 2k+1, the
** Hash2d/Hash1dRTableIndex lookups, INCRSUM/INCRSUMP order of the eight
** corners), written with the same C operations in the same order and
** reading the hash table through noise_hash_entry() and the coefficients
** through noise_coefficient(), and the two must
** agree in every bit (memcmp, so -0 and +0 differ) at 20,000 points:
** random ones, lattice points, points 1e-12 either side of lattice planes
** (the negative-side epsilon of the cell floor), -0, and points beyond the
** +-1e9 clip.
*/
#include "config.h"

#include <string.h>

#include "testutil.h"

#include "material/noise.h"

/* POV-Ray's layout of the coefficients (noise_coefficient() gives its
** RTable values, the input both sides share). */
static double rtable[267 * 2];

static void build_rtable(void)
{
    for (int i = 0; i < 267; i++) {
        rtable[2 * i] = noise_coefficient(i);
        rtable[2 * i + 1] = noise_coefficient(i) * 0.5;
    }
}

static int hash2d(int a, int b)
{
    return noise_hash_entry(noise_hash_entry(a) ^ b);
}

static const double *rt(int h, int iz)
{
    return &rtable[(noise_hash_entry(h ^ iz) & 0xFF) * 2];
}

static double clip(double v)
{
    const double lim = 1e9;
    if (!(fabs(v) < lim))
        return isnan(v) ? 0 : copysign(lim, v);
    return v;
}

/* POV-Ray's floor with its epsilon for negatives; cells from -10000. */
static void cell(double x, int *ix, double *fx)
{
    int c = x >= 0 ? (int)x : (int)(x - (1 - 1e-10));
    *ix = (c + 10000) & 0xFFF;
    *fx = x - c;
}

static double sc(double a)
{
    return a * a * (3.0 - 2.0 * a);
}

struct ref_cell {
    int ix, iy, iz;
    double x, y, z, x1, y1, z1, sz, tz, txty, sxty, txsy, sxsy;
};

static void ref_setup(vec3 p, struct ref_cell *c)
{
    cell(clip(p.x), &c->ix, &c->x);
    cell(clip(p.y), &c->iy, &c->y);
    cell(clip(p.z), &c->iz, &c->z);
    c->x1 = c->x - 1;
    c->y1 = c->y - 1;
    c->z1 = c->z - 1;
    double sx = sc(c->x), sy = sc(c->y);
    c->sz = sc(c->z);
    double tx = 1 - sx, ty = 1 - sy;
    c->tz = 1 - c->sz;
    c->txty = tx * ty;
    c->sxty = sx * ty;
    c->txsy = tx * sy;
    c->sxsy = sx * sy;
}

static double term(const double *mp, double s, double x, double y, double z)
{
    return s * (mp[1] + mp[2] * x + mp[4] * y + mp[6] * z);
}

/* POV-Ray's Noise() for generators 1 and 2. */
static double ref_noise(vec3 p, int gen)
{
    struct ref_cell c;
    ref_setup(p, &c);
    int h00 = hash2d(c.ix, c.iy), h10 = hash2d(c.ix + 1, c.iy);
    int h01 = hash2d(c.ix, c.iy + 1), h11 = hash2d(c.ix + 1, c.iy + 1);
    double sum = term(rt(h00, c.iz), c.txty * c.tz, c.x, c.y, c.z);
    sum += term(rt(h10, c.iz), c.sxty * c.tz, c.x1, c.y, c.z);
    sum += term(rt(h01, c.iz), c.txsy * c.tz, c.x, c.y1, c.z);
    sum += term(rt(h11, c.iz), c.sxsy * c.tz, c.x1, c.y1, c.z);
    sum += term(rt(h00, c.iz + 1), c.txty * c.sz, c.x, c.y, c.z1);
    sum += term(rt(h10, c.iz + 1), c.sxty * c.sz, c.x1, c.y, c.z1);
    sum += term(rt(h01, c.iz + 1), c.txsy * c.sz, c.x, c.y1, c.z1);
    sum += term(rt(h11, c.iz + 1), c.sxsy * c.sz, c.x1, c.y1, c.z1);
    sum = gen == 2 ? (sum + 1.05242) * 0.48985582 : sum + 0.5;
    return fmin(fmax(sum, 0.0), 1.0);
}

static void dterm(double r[3], const double *mp, double s, double x, double y,
                  double z)
{
    r[0] += term(mp, s, x, y, z);
    r[1] += term(mp + 8, s, x, y, z);
    r[2] += term(mp + 16, s, x, y, z);
}

/* POV-Ray's DNoise(), corners in its order. */
static vec3 ref_dnoise(vec3 p)
{
    struct ref_cell c;
    ref_setup(p, &c);
    int h00 = hash2d(c.ix, c.iy), h10 = hash2d(c.ix + 1, c.iy);
    int h01 = hash2d(c.ix, c.iy + 1), h11 = hash2d(c.ix + 1, c.iy + 1);
    double r[3] = {0, 0, 0};
    dterm(r, rt(h00, c.iz), c.txty * c.tz, c.x, c.y, c.z);
    dterm(r, rt(h10, c.iz), c.sxty * c.tz, c.x1, c.y, c.z);
    dterm(r, rt(h11, c.iz), c.sxsy * c.tz, c.x1, c.y1, c.z);
    dterm(r, rt(h01, c.iz), c.txsy * c.tz, c.x, c.y1, c.z);
    dterm(r, rt(h01, c.iz + 1), c.txsy * c.sz, c.x, c.y1, c.z1);
    dterm(r, rt(h11, c.iz + 1), c.sxsy * c.sz, c.x1, c.y1, c.z1);
    dterm(r, rt(h10, c.iz + 1), c.sxty * c.sz, c.x1, c.y, c.z1);
    dterm(r, rt(h00, c.iz + 1), c.txty * c.sz, c.x, c.y, c.z1);
    return v3(r[0], r[1], r[2]);
}

/* The test points: kind 0 random in [-60, 60], 1 lattice points, 2 and
** 3 1e-12 below and above them, 4 large (up to 3e9, past the clip),
** 5 random with a -0 coordinate. */
static uint32_t lcg_state = 12345u;

static double urand(void)
{
    lcg_state = lcg_state * 1664525u + 1013904223u;
    return (lcg_state >> 8) * (1.0 / 16777216.0);
}

static double coord(int kind)
{
    double u = 120 * urand() - 60;
    switch (kind) {
    case 1: return floor(u);
    case 2: return floor(u) - 1e-12;
    case 3: return floor(u) + 1e-12;
    case 4: return (urand() - 0.5) * 6e9;
    default: return u;
    }
}

static vec3 test_point(int i)
{
    int kind = i % 6;
    vec3 p = v3(coord(kind), coord(kind), coord(kind));
    if (kind == 5)
        p.y = -0.0;
    return p;
}

#define N_POINTS 20000

static void test_scalar_noise_bits(void **state)
{
    (void)state;
    int bad = 0;
    for (int i = 0; i < N_POINTS; i++) {
        vec3 p = test_point(i);
        for (int gen = 1; gen <= 2; gen++) {
            double a = noise_value(p, gen), b = ref_noise(p, gen);
            if (memcmp(&a, &b, sizeof a) != 0 && bad++ < 5)
                print_error("gen %d at (%.17g, %.17g, %.17g): %.17g vs "
                            "%.17g\n", gen, p.x, p.y, p.z, a, b);
        }
    }
    assert_int_equal(bad, 0);
}

static void test_vector_noise_bits(void **state)
{
    (void)state;
    int bad = 0;
    for (int i = 0; i < N_POINTS; i++) {
        vec3 p = test_point(i);
        vec3 a = noise_vector(p), b = ref_dnoise(p);
        double av[3] = {a.x, a.y, a.z}, bv[3] = {b.x, b.y, b.z};
        if (memcmp(av, bv, sizeof av) != 0 && bad++ < 5)
            print_error("at (%.17g, %.17g, %.17g): (%.17g %.17g %.17g) vs "
                        "(%.17g %.17g %.17g)\n", p.x, p.y, p.z, a.x, a.y, a.z,
                        b.x, b.y, b.z);
    }
    assert_int_equal(bad, 0);
}

/* The reference itself is anchored to POV-Ray by test_material's rendered
** values; this checks that the points exercise the whole range, so the
** comparisons above are not all between clamped zeros or ones. */
static void test_points_cover_range(void **state)
{
    (void)state;
    int low = 0, high = 0, mid = 0;
    for (int i = 0; i < N_POINTS; i++) {
        double v = ref_noise(test_point(i), 2);
        low += v < 0.25;
        high += v > 0.75;
        mid += v > 0.25 && v < 0.75;
    }
    assert_true(low > 100 && high > 100 && mid > N_POINTS / 4);
}

int main(void)
{
    build_rtable();
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scalar_noise_bits),
        cmocka_unit_test(test_vector_noise_bits),
        cmocka_unit_test(test_points_cover_range),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
