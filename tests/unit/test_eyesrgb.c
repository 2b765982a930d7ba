/* SPDX-License-Identifier: MIT */
/*
** test_eyesrgb.c: the eye pass's sRGB decode of legacy-gamma pixels
** (eye_srgb_decode, eyepass.h). It replaces (float)iris_srgb_decode(v)
** in put_pixel, so it must give that float exactly, every time: the
** image of a legacy scene may not change by a bit. The expectation is
** IEC 61966-2-1's formula as image.c computes it with pow().
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "testutil.h"

#include "iris/image.h"
#include "render/eyepass.h"
#include "util/mem.h"
#include "util/rng.h"

static struct eye_srgb *table(void)
{
    struct eye_srgb *s = iris_malloc(sizeof *s);
    assert_non_null(s);
    eye_srgb_init(s);
    return s;
}

static void expect_same(const struct eye_srgb *s, double v)
{
    float want = (float)iris_srgb_decode(v);
    float got = eye_srgb_decode(s, v);
    /* bitwise: == would let -0 pass for +0 */
    if (memcmp(&want, &got, sizeof want) != 0) {
        print_error("v = %.17g: %.9g, iris_srgb_decode %.9g\n", v, got, want);
        fail();
    }
}

/* The same float as (float)iris_srgb_decode(v): on a regular sweep of
** (0, 1] (every 2^-20, so each of the 1024 segments at 1024 points),
** on 2 million random values, at the ends of every segment and around
** the linear part's end 0.04045, at 0, -0 and 1 (every clipped channel). */
static void test_decode_exact(void **state)
{
    (void)state;
    struct eye_srgb *s = table();
    for (int i = 0; i <= 1 << 20; i++)
        expect_same(s, ldexp(i, -20));
    rng r;
    rng_seed(&r, 7, 0, 0);
    for (int i = 0; i < 2000000; i++)
        expect_same(s, rng_uniform(&r));
    for (int i = 1; i <= EYE_SRGB_N; i++) {
        double v = (double)i / EYE_SRGB_N;
        expect_same(s, v);
        expect_same(s, nextafter(v, 0.0));
        expect_same(s, nextafter(v, 2.0));
    }
    double v = 0.04045;
    for (int i = 0; i < 50; i++) {
        expect_same(s, v);
        expect_same(s, 0.04045 - (v - 0.04045));
        v = nextafter(v, 1.0);
    }
    expect_same(s, 0.0);
    expect_same(s, -0.0);
    expect_same(s, 1.0);
    /* IEC 61966-2-1 at mid-grey: ((0.5 + 0.055) / 1.055)^2.4 = 0.214041
    ** (to 1e-6, the printed digits) */
    assert_true(fabs(eye_srgb_decode(s, 0.5) - 0.214041) < 1e-6);
    iris_free(s);
}

/* The bound the exactness rests on: the cubic lies within EYE_SRGB_REL
** (relative) of pow()'s value everywhere on (0.04045, 1). Checked on a
** sweep denser than the segments; the worst error seen must also come
** within a factor 10 of the bound (eyepass.c derives 3.7e-10 at the low
** end), else the bound is loose and needlessly sends pixels to pow().
** And so that the fast path is the one taken, under 5 % of the values
** may fall back to pow() (a rel of 1e-9 is 1/60 of a float's ulp). */
static void test_cubic_bound(void **state)
{
    (void)state;
    struct eye_srgb *s = table();
    double worst = 0.0;
    int n = 0, fallback = 0;
    for (int i = 0; i < 4000000; i++) {
        double v = 0.04045 + (1.0 - 0.04045) * (i + 0.5) / 4000000.0;
        double want = iris_srgb_decode(v);
        double y = eye_srgb_cubic(s, v);
        double rel = fabs(y - want) / want;
        assert_true(rel <= EYE_SRGB_REL);
        worst = fmax(worst, rel);
        n++;
        if ((float)(y * (1.0 - EYE_SRGB_REL)) !=
            (float)(y * (1.0 + EYE_SRGB_REL)))
            fallback++;
    }
    assert_true(worst > 0.1 * EYE_SRGB_REL);
    assert_true(fallback < n / 20);
    iris_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_decode_exact),
        cmocka_unit_test(test_cubic_bound),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
