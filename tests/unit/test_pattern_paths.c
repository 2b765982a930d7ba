/* SPDX-License-Identifier: MIT */
/*
** test_pattern_paths.c: the short cuts of pattern.c and pigment.c give
** POV-Ray's numbers to the bit.
**
** POV-Ray 3.7 (pattern.cpp, Evaluate / Search_Blend_Map) computes a
** pattern value through fmod(value * frequency + phase, 1.00001), the
** gradient as fmod(x, 1) above 1, the onion as fmod(|p|, 1), and picks
** a colour map's entries by a linear search for the first entry >= the
** value. iris skips the library fmod where it cannot change the value
** and bisects long maps whose values ascend; the expectations below are
** those formulas, computed here with libm's fmod and a linear search, and
** compared bit for bit (the short cuts are exact, so no tolerance).
** Every point is checked, so a wrong short cut anywhere in the sweeps
** fails.
*/
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"

#include "material/mat_internal.h"
#include "material/material.h"
#include "parse_util.h"

/* A deterministic sweep of doubles (xorshift64*). */
static uint64_t rng_state = 0x9e3779b97f4a7c15u;
static double uniform(void)
{
    rng_state ^= rng_state >> 12;
    rng_state ^= rng_state << 25;
    rng_state ^= rng_state >> 27;
    return (double)((rng_state * 0x2545f4914f6cdd1du) >> 11) * 0x1p-53;
}

static void assert_same_bits(double got, double want)
{
    if (memcmp(&got, &want, sizeof got) != 0)
        fail_msg("got %.17g, want %.17g", got, want);
}

static iris_pattern gradient_x(void)
{
    iris_pattern pat;
    memset(&pat, 0, sizeof pat);
    pat.kind = IRIS_PAT_GRADIENT;
    pat.vector = v3(1, 0, 0);
    return pat;
}

/* gradient x, with and without frequency and phase, and onion, against
** POV-Ray's formulas with libm's fmod. */
static void test_gradient_onion_fmod(void **state)
{
    (void)state;
    iris_pattern g = gradient_x();
    iris_pattern f = gradient_x();
    f.frequency = 1.0;
    iris_pattern fp = gradient_x();
    fp.frequency = 3.0;
    fp.phase = 0.25;
    iris_pattern on;
    memset(&on, 0, sizeof on);
    on.kind = IRIS_PAT_ONION;
    /* 0, the integers, the values just off them and at 1.00001, then a
    ** spread of magnitudes up to 2^60 (fmod and the subtraction both
    ** exact there) */
    double xs[4000];
    int n = 0;
    const double fixed[] = { 0.0, 0.5, 1.0, 2.0, 3.0, 1.00001, 1.0000099999,
                             nextafter(1.0, 2.0), nextafter(1.0, 0.0),
                             nextafter(2.0, 3.0), 4503599627370496.0,
                             4503599627370497.0, 1e17 };
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; i++)
        xs[n++] = fixed[i];
    /* (below the pattern space's clamp at 1e17 > 2^56) */
    while (n < 4000)
        xs[n++] = ldexp(uniform(), (int)(uniform() * 58) - 2);
    for (int i = 0; i < n; i++) {
        double x = xs[i];
        vec3 p = v3(x, 0, 0);
        /* gradient: fmod(x, 1) above 1 (frequency 0: no further step) */
        double want = x > 1.0 ? fmod(x, 1.0) : x;
        assert_same_bits(pat_value(NULL, &g, p, NULL), want);
        /* frequency 1, phase 0: fmod(v * 1 + 0, 1.00001) (no negative
        ** value to wrap here) */
        assert_same_bits(pat_value(NULL, &f, p, NULL),
                         fmod(want * 1.0 + 0.0, 1.00001));
        double w = fmod(want * 3.0 + 0.25, 1.00001);
        assert_same_bits(pat_value(NULL, &fp, p, NULL), w);
        /* onion: fmod(|p|, 1) */
        assert_same_bits(pat_value(NULL, &on, p, NULL),
                         fmod(sqrt(x * x), 1.0));
        /* a negative gradient value: fmod(v * 1 + 0, 1.00001), then
        ** v - floor(v) below 0 */
        double neg = -x * 0.37;
        double wn = fmod(neg * 1.0 + 0.0, 1.00001);
        if (wn < 0.0)
            wn -= floor(wn);
        assert_same_bits(pat_value(NULL, &f, v3(neg, 0, 0), NULL), wn);
    }
    /* values about fmod's divisor, 1.00001, and 1: phase 0.5 moves the
    ** gradient's 0.50001 there */
    iris_pattern h = gradient_x();
    h.frequency = 1.0;
    h.phase = 0.5;
    for (int k = -200; k <= 200; k++) {
        for (int j = 0; j < 2; j++) {
            double x = (j ? 0.5 : 0.50001) + k * 1e-8;
            assert_same_bits(pat_value(NULL, &h, v3(x, 0, 0), NULL),
                             fmod(x * 1.0 + 0.5, 1.00001));
        }
    }
}

/* POV-Ray's Search_Blend_Map and blend, as written there: the entry
** pair for v and the colour between them. */
static iris_colour reference_blend(const iris_map_entry *e, int n, double v)
{
    int prev, cur;
    if (v >= e[n - 1].value) {
        prev = cur = n - 1;
    } else {
        int p = 0, c = 0;
        while (v > e[c].value) {
            p = c;
            c++;
        }
        if (v == e[c].value)
            p = c;
        prev = p;
        cur = c;
    }
    if (prev == cur)
        return e[cur].colour;
    double v0 = e[prev].value, v1 = e[cur].value;
    double t = v1 > v0 ? (v - v0) / (v1 - v0) : 1.0;
    iris_colour a = e[prev].colour, b = e[cur].colour, c = {
        a.r + t * (b.r - a.r), a.g + t * (b.g - a.g), a.b + t * (b.b - a.b),
        a.f + t * (b.f - a.f), a.t + t * (b.t - a.t) };
    return c;
}

#define MAP_N 40

/* MAP_N entries: ascending with repeated values (sharp steps) when
** 'ascending', else the same values with a stretch out of order. */
static void fill_map(iris_map_entry *e, bool ascending)
{
    memset(e, 0, MAP_N * sizeof *e);
    for (int i = 0; i < MAP_N; i++) {
        e[i].value = (i - i % 3 / 2) / (double)MAP_N; /* pairs repeat */
        /* random colours: a + 1 * (b - a) is then often not b, so the
        ** pair picked at an entry's own value shows */
        e[i].colour.r = uniform();
        e[i].colour.g = uniform() * 0.01;
        e[i].colour.b = uniform() * 100;
        e[i].colour.t = uniform();
    }
    if (!ascending) {
        double t = e[10].value;
        e[10].value = e[20].value;
        e[20].value = t;
    }
}

/* The pigment's colour at map value v against the linear search. */
static void check_map_at(const struct mat_ctx *ctx, const iris_pigment *pig,
                         double v)
{
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(v, 0, 0);
    iris_colour c;
    assert_true(mat_eval_pigment(ctx, pig, &pt, &c));
    iris_colour want = reference_blend(pig->entries, pig->n_entries, v);
    assert_memory_equal(&c, &want, sizeof c);
}

/* Every entry's value, the values just beside it, midpoints and random
** values across [0, 1) (gradient x gives v = x there). */
static void sweep_map(const struct mat_ctx *ctx, const iris_pigment *pig)
{
    for (int i = 0; i < pig->n_entries; i++) {
        double v = pig->entries[i].value;
        check_map_at(ctx, pig, v);
        if (v > 0)
            check_map_at(ctx, pig, nextafter(v, 0.0));
        check_map_at(ctx, pig, nextafter(v, 1.0));
        check_map_at(ctx, pig, v + 0.5 / MAP_N);
    }
    for (int k = 0; k < 2000; k++)
        check_map_at(ctx, pig, uniform());
}

/* A long colour map, bisected when ascending and given a context, searched
** linearly otherwise: the same entries either way; and a map changed
** in place after its context is gone is looked at afresh. */
static void test_long_colour_map(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with("#version 3.7;\nsphere { 0, 1 }\n", NULL);
    iris_map_entry e[MAP_N];
    iris_pigment pig;
    memset(&pig, 0, sizeof pig);
    pig.pattern = gradient_x();
    pig.entries = e;
    pig.n_entries = MAP_N;

    fill_map(e, true);
    struct mat_ctx *ctx = NULL;
    assert_int_equal(mat_ctx_create(sc, stderr, &ctx), IRIS_OK);
    sweep_map(ctx, &pig);  /* bisected */
    sweep_map(NULL, &pig); /* linear */
    mat_ctx_destroy(ctx);

    /* the same address and size, now out of order, in a new context: the
    ** remembered order must not be used (bisection would miss) */
    fill_map(e, false);
    assert_int_equal(mat_ctx_create(sc, stderr, &ctx), IRIS_OK);
    sweep_map(ctx, &pig);
    mat_ctx_destroy(ctx);
    iris_scene_destroy(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gradient_onion_fmod),
        cmocka_unit_test(test_long_colour_map),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
