/* SPDX-License-Identifier: MIT */
/*
** test_fractal_cap.c: the iteration cap of the mandel, julia and magnet
** patterns (IRIS_PATTERN_MAX_ITERATIONS, src/material/pattern.c).
**
** 'pigment { mandel 1e9 }' iterated every interior point 1e9 times (4 s of
** CPU per evaluation, minutes per pixel). Each evaluation now stops at the
** cap while the colouring keeps the count the scene gave, so a point that
** escapes before the cap gets exactly the value an uncapped run gives:
** k / iterations, with k counted here by iterating z <- z² + c by hand.
** Only points escaping after the cap change (they become interior), and
** the parser warns at the count.
*/
#include "config.h"

#include "testutil.h"

#include <string.h>
#include <time.h>

#include "iris/parse.h"
#include "parse_util.h"
#include "material/mat_internal.h"

/* The step at which z <- z² + c, z0 = c, first has |z|² > 4, or -1
** within 'limit' steps (the recurrence of POV-Ray's mandel_pattern). */
static long escape_step(double ca, double cb, long limit)
{
    double a = ca, b = cb;
    for (long k = 0; k < limit; k++) {
        double t = a * a - b * b + ca;
        b = a * b + b * a + cb;
        a = t;
        if (a * a + b * b > 4.0)
            return k;
    }
    return -1;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static iris_pattern fractal_pattern(enum iris_pattern_kind kind, int n)
{
    iris_pattern p;
    memset(&p, 0, sizeof p); /* POV-Ray's default colouring */
    p.kind = kind;
    p.iterations = n;
    return p;
}

/*
** Near the neck of the Mandelbrot set, c = -0.75 + εi escapes after about
** π/ε steps: ε = 0.01 after a few hundred (below the cap: the value of a
** 1e9-iteration pattern is exactly k / 1e9), ε = 1e-5 after about 314000
** (beyond the cap of 100000: interior, 1, where an uncapped run gives
** k / 1e9 = 3e-4: the one departure, a boundary sliver).
*/
static void test_mandel_capped_values(void **state)
{
    (void)state;
    const int n = 1000000000;
    iris_pattern m = fractal_pattern(IRIS_PAT_MANDEL, n);
    long k = escape_step(-0.75, 0.01, 10000);
    assert_true(k > 100 && k < 1000);
    /* exact: the same operations in the same order */
    assert_true(pat_eval_at(NULL, &m, v3(-0.75, 0.01, 0), NULL) ==
                (double)k / n);
    /* below the cap nothing changed: 500 iterations give k / 500 */
    iris_pattern m500 = fractal_pattern(IRIS_PAT_MANDEL, 500);
    assert_true(pat_eval_at(NULL, &m500, v3(-0.75, 0.01, 0), NULL) ==
                (double)k / 500);
    long far = escape_step(-0.75, 1e-5, 1000000);
    assert_true(far > IRIS_PATTERN_MAX_ITERATIONS);
    assert_near(pat_eval_at(NULL, &m, v3(-0.75, 1e-5, 0), NULL), 1, 0);
    /* a count of exactly the cap runs all of it: the point at ε = 1e-4
    ** escapes after about 31400 steps, within it */
    long mid = escape_step(-0.75, 1e-4, IRIS_PATTERN_MAX_ITERATIONS);
    assert_true(mid > 10000);
    iris_pattern mc = fractal_pattern(IRIS_PAT_MANDEL,
                                      IRIS_PATTERN_MAX_ITERATIONS);
    assert_true(pat_eval_at(NULL, &mc, v3(-0.75, 1e-4, 0), NULL) ==
                (double)mid / IRIS_PATTERN_MAX_ITERATIONS);
}

/*
** The cost: an interior point (the origin) of mandel, julia (c = 0, from
** 0.5: |z| shrinks to 0) and magnet 2 julia (c = 0 from 4, its repelling
** fixed point: interior forever, test_fractal_pattern.c) with 1e9
** iterations. Each stops at the cap: 1e5 steps of a few ns, under 1 ms
** (10 ms under ASan or valgrind), where 1e9 steps take 4 s. The bound,
** 0.5 s of CPU for all three, is 25 times under the uncapped cost and far
** above the capped one whatever the load (thread CPU time).
*/
static void test_interior_cost_bounded(void **state)
{
    (void)state;
    const int n = 1000000000;
    iris_pattern m = fractal_pattern(IRIS_PAT_MANDEL, n);
    iris_pattern j = fractal_pattern(IRIS_PAT_JULIA, n);
    iris_pattern g = fractal_pattern(IRIS_PAT_JULIA, n);
    g.params[7] = 2; /* magnet 2 */
    g.params[1] = 1; /* interior factor 1, exterior type 1 factor 1, given */
    g.params[2] = 1;
    g.params[3] = 1;
    g.params[5] = 1;
    double t0 = cpu_now();
    assert_near(pat_eval_at(NULL, &m, v3(0, 0, 0), NULL), 1, 0);
    assert_near(pat_eval_at(NULL, &j, v3(0.5, 0, 0), NULL), 1, 0);
    assert_near(pat_eval_at(NULL, &g, v3(4, 0, 0), NULL), 1, 0);
    double dt = cpu_now() - t0;
    print_message("# three interior points of 1e9 iterations: %.4f s CPU\n",
                  dt);
    assert_true(dt < 0.5);
}

/* Counts above the cap are warned about at the count, in all three
** forms; the cap itself and POV-Ray's examples' counts are not. */
static void test_parser_warns_at_count(void **state)
{
    (void)state;
    unsigned line = 0, col = 0;
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0 pigment { mandel 100000 } }\n"
        "plane { y, 0 pigment { julia <0.3, 0.4>, 10000 } }\n"
        "plane { y, 0 pigment { magnet 2 mandel 300 } }\n", &line, &col), 0);
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0\n  pigment { mandel 1e9 } }\n", &line, &col), 1);
    assert_int_equal(line, 2);
    assert_int_equal(col, 20);
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0 pigment { julia <0.3, 0.4>, 100001 } }\n", &line,
        &col), 1);
    assert_int_equal(line, 1);
    assert_int_equal(col, 42);
    assert_int_equal(pt_parse_warnings(
        "plane { y, 0 pigment { magnet 1 julia <0.3, 0.4>, 2e8 } }\n",
        &line, &col), 1);
    assert_int_equal(col, 51);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_mandel_capped_values),
        cmocka_unit_test(test_interior_cost_bounded),
        cmocka_unit_test(test_parser_warns_at_count),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
