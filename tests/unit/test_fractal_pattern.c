/* SPDX-License-Identifier: MIT */
/*
** test_fractal_pattern.c: the magnet patterns (fractal_pattern.c) on the
** real axis with c = 0, where both maps reduce to real recurrences worked
** out here by hand:
**   type 1: ((z² - 1)/(2z - 2))² = ((z + 1)/2)²
**   type 2: (z - 1)²(z + 2) / (3(z - 1)²), squared = ((z + 2)/3)²
** and the parser's magnet syntax and its errors.
*/
#include "config.h"

#include "testutil.h"

#include <string.h>

#include "iris/parse.h"
#include "parse_util.h"
#include "material/fractal_pattern.h"

/*
** Type 1, mandel, the point 0: c = 0, z from 0, so w = 1 - z follows
** w <- w - w²/4 from w = 1 (a parabolic approach to z = 1). The orbit
** stops at the first step whose w is below 0.01 (|z - 1|² < 1e-4).
*/
static void test_magnet1_parabolic(void **state)
{
    (void)state;
    int want = -1;
    double w = 1;
    for (int i = 0; i < 2000 && want < 0; i++) {
        w -= w * w / 4;
        if (w * w < 1e-4)
            want = i;
    }
    assert_true(want > 300); /* w_n ~ 4/n: about 400 steps */
    int k;
    double a, b, m2;
    assert_true(pat_magnet(1, false, 0, 0, 0, 0, 2000, &k, &a, &b, &m2));
    assert_int_equal(k, want);
    assert_near(b, 0, 1e-12);
    assert_true((a - 1) * (a - 1) < 1e-4);
    /* the least |z|² of a mandel orbit: z_1 = 0.25 */
    assert_near(m2, 0.0625, 1e-15);
    /* fewer steps than that: interior, the last z still short of 1 */
    assert_false(pat_magnet(1, false, 0, 0, 0, 0, 50, &k, &a, &b, &m2));
    assert_int_equal(k, 50);
    assert_true(a < 0.99);
}

/*
** Julia forms with c = 0 from real starts (an orbit leaves once
** |z|² > 10000, i.e. |z| > 100): type 1 from 5 runs 9, 25, 169 (stops at
** step 2); type 2 from 10 runs 16, 36, 160.4 (step 2); type 2 from 4
** stays at its repelling fixed point 4 = ((4 + 2)/3)²: interior, least
** |z|² 16.
*/
static void test_magnet_julia(void **state)
{
    (void)state;
    int k;
    double a, b, m2;
    assert_true(pat_magnet(1, true, 5, 0, 0, 0, 20, &k, &a, &b, &m2));
    assert_int_equal(k, 2);
    assert_near(a, 169, 1e-12);
    assert_near(m2, 25, 0); /* the start, 5² */
    assert_true(pat_magnet(2, true, 10, 0, 0, 0, 20, &k, &a, &b, &m2));
    assert_int_equal(k, 2);
    assert_rel(a, pow(38.0 / 3, 2), 1e-12);
    assert_false(pat_magnet(2, true, 4, 0, 0, 0, 20, &k, &a, &b, &m2));
    assert_int_equal(k, 20);
    assert_near(a, 4, 1e-12);
    assert_near(m2, 16, 1e-12);
    /* a zero denominator (type 1 julia, c = 2 + 0i, z = 0: 2z + c - 2 = 0)
    ** stops the orbit instead of carrying a NaN into the colour */
    assert_true(pat_magnet(1, true, 0, 0, 2, 0, 20, &k, &a, &b, &m2));
    assert_int_equal(k, 0);
}

/* magnet parses without a warning; a bad type or form is a located error */
static void test_magnet_parse(void **state)
{
    (void)state;
    unsigned line = 0, col = 0;
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0 pigment { magnet 1 mandel 30 interior 1, 200 "
        "exterior 5, 1 } }\n"
        "plane { y, 0 normal { magnet 2 julia <0.3, 0.4>, 30 0.2 } }\n",
        &line, &col), 0);
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0\n pigment { magnet 3 mandel 30 } }\n", &line, &col),
        -1);
    assert_int_equal(line, 2);
    assert_int_equal(col, 12);
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0 pigment { magnet 1 bozo 30 } }\n", &line, &col), -1);
    assert_int_equal(line, 1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_magnet1_parabolic),
        cmocka_unit_test(test_magnet_julia),
        cmocka_unit_test(test_magnet_parse),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
