/* SPDX-License-Identifier: MIT */
/*
** test_fn.c: the function evaluator (src/fn) on hand-assembled programs,
** and the internal functions of functions.inc against their analytic
** definitions. (Their values against POV-Ray's own output are checked by
** the golden case tests/parse/cases/fn_povray.)
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <string.h>

#include "iris/fn.h"

static iris_fn_insn ins(enum iris_fn_op op, int arg, int nargs, double v)
{
    iris_fn_insn i;
    memset(&i, 0, sizeof i);
    i.op = op;
    i.arg = arg;
    i.nargs = nargs;
    i.value = v;
    return i;
}

/* (x + 2) * y with x = 3, y = 4 is 20; missing arguments are 0. */
static void test_arith(void **state)
{
    (void)state;
    iris_fn_insn code[] = {
        ins(IRIS_FN_PARAM, 0, 0, 0), ins(IRIS_FN_CONST, 0, 0, 2),
        ins(IRIS_FN_ADD, 0, 0, 0), ins(IRIS_FN_PARAM, 1, 0, 0),
        ins(IRIS_FN_MUL, 0, 0, 0),
    };
    iris_fn fn = { 3, NULL, 5, code, 2, 1 };
    double a[2] = { 3, 4 };
    assert_near(iris_fn_eval(&fn, a, 2), 20, 0);
    assert_near(iris_fn_eval(&fn, a, 1), 0, 0);
}

/* Division by zero and domain errors give 0, never NaN or Inf. */
static void test_no_nan(void **state)
{
    (void)state;
    iris_fn_insn div0[] = {
        ins(IRIS_FN_CONST, 0, 0, 1), ins(IRIS_FN_CONST, 0, 0, 0),
        ins(IRIS_FN_DIV, 0, 0, 0),
    };
    iris_fn f1 = { 0, NULL, 3, div0, 2, 1 };
    assert_near(iris_fn_eval(&f1, NULL, 0), 0, 0);
    iris_fn_insn sq[] = {
        ins(IRIS_FN_CONST, 0, 0, -1), ins(IRIS_FN_BUILTIN, IRIS_FB_SQRT, 1, 0),
    };
    iris_fn f2 = { 0, NULL, 2, sq, 1, 1 };
    assert_near(iris_fn_eval(&f2, NULL, 0), 0, 0);
    iris_fn_insn big[] = {
        ins(IRIS_FN_CONST, 0, 0, 1e300), ins(IRIS_FN_CONST, 0, 0, 1e300),
        ins(IRIS_FN_MUL, 0, 0, 0),
    };
    iris_fn f3 = { 0, NULL, 3, big, 2, 1 };
    assert_near(iris_fn_eval(&f3, NULL, 0), 0, 0);
    /* a stack underflow in a malformed program is caught */
    iris_fn_insn bad[] = { ins(IRIS_FN_ADD, 0, 0, 0) };
    iris_fn f4 = { 0, NULL, 1, bad, 0, 1 };
    assert_near(iris_fn_eval(&f4, NULL, 0), 0, 0);
}

/* select, comparisons, calls; a self-call is cut at the depth limit. */
static void test_select_call(void **state)
{
    (void)state;
    iris_fn_insn s[] = {
        ins(IRIS_FN_PARAM, 0, 0, 0), ins(IRIS_FN_CONST, 0, 0, 10),
        ins(IRIS_FN_CONST, 0, 0, 20), ins(IRIS_FN_CONST, 0, 0, 30),
        ins(IRIS_FN_SELECT4, 0, 4, 0),
    };
    iris_fn sel = { 1, NULL, 5, s, 4, 1 };
    double m = -1, z = 0, p = 1;
    assert_near(iris_fn_eval(&sel, &m, 1), 10, 0);
    assert_near(iris_fn_eval(&sel, &z, 1), 20, 0);
    assert_near(iris_fn_eval(&sel, &p, 1), 30, 0);
    iris_fn_insn c[] = {
        ins(IRIS_FN_CONST, 0, 0, 1), ins(IRIS_FN_CALL, 0, 1, 0),
        ins(IRIS_FN_CONST, 0, 0, 5), ins(IRIS_FN_ADD, 0, 0, 0),
    };
    iris_fn caller = { 0, NULL, 4, c, 2, 1 };
    c[1].callee = &sel;
    assert_near(iris_fn_eval(&caller, NULL, 0), 35, 0);
    iris_fn_insn r[] = { ins(IRIS_FN_CALL, 0, 0, 0) };
    iris_fn rec = { 0, NULL, 1, r, 1, 1 };
    r[0].callee = &rec;
    assert_near(iris_fn_eval(&rec, NULL, 0), 0, 0);
}

/* select(x, 10, 20, 30) as the compiler emits it: a branch and jumps.
** Only the arm chosen runs: each other arm holds an ADD on an empty
** stack, which would make the whole function 0. Jumps backwards or past
** the end are refused (0), so that every function ends. */
static void test_branch(void **state)
{
    (void)state;
    iris_fn_insn s[] = {
        ins(IRIS_FN_PARAM, 0, 0, 0),
        ins(IRIS_FN_BRANCH, 5, 9, 0),     /* == 0: 5, > 0: 9 */
        ins(IRIS_FN_CONST, 0, 0, 10),
        ins(IRIS_FN_JUMP, 12, 0, 0),
        ins(IRIS_FN_ADD, 0, 0, 0),        /* never reached */
        ins(IRIS_FN_CONST, 0, 0, 20),
        ins(IRIS_FN_JUMP, 12, 0, 0),
        ins(IRIS_FN_ADD, 0, 0, 0),
        ins(IRIS_FN_ADD, 0, 0, 0),
        ins(IRIS_FN_CONST, 0, 0, 30),
        ins(IRIS_FN_JUMP, 12, 0, 0),
        ins(IRIS_FN_ADD, 0, 0, 0),
    };
    iris_fn sel = { 1, NULL, 12, s, 1, 1 };
    double m = -1, z = 0, p = 1;
    assert_near(iris_fn_eval(&sel, &m, 1), 10, 0);
    assert_near(iris_fn_eval(&sel, &z, 1), 20, 0);
    assert_near(iris_fn_eval(&sel, &p, 1), 30, 0);
    /* x ? 7 : 8 */
    iris_fn_insn c[] = {
        ins(IRIS_FN_PARAM, 0, 0, 0), ins(IRIS_FN_BRANCH_ZERO, 4, 0, 0),
        ins(IRIS_FN_CONST, 0, 0, 7), ins(IRIS_FN_JUMP, 5, 0, 0),
        ins(IRIS_FN_CONST, 0, 0, 8),
    };
    iris_fn cond = { 1, NULL, 5, c, 1, 1 };
    assert_near(iris_fn_eval(&cond, &p, 1), 7, 0);
    assert_near(iris_fn_eval(&cond, &z, 1), 8, 0);
    /* a jump to itself, and one past the end: 0 */
    iris_fn_insn loop[] = {
        ins(IRIS_FN_CONST, 0, 0, 5), ins(IRIS_FN_JUMP, 1, 0, 0),
    };
    iris_fn lf = { 0, NULL, 2, loop, 1, 1 };
    assert_near(iris_fn_eval(&lf, NULL, 0), 0, 0);
    loop[1].arg = 3;
    assert_near(iris_fn_eval(&lf, NULL, 0), 0, 0);
    loop[1].arg = 2;  /* to the end: the 5 stays */
    assert_near(iris_fn_eval(&lf, NULL, 0), 5, 0);
}

/* functions.inc internals against their definitions: f_sphere = |p| - r,
** f_torus = distance to the tube circle - minor, f_r = |p|,
** f_th = atan2(x, z), f_ph = atan2(sqrt(x^2 + z^2), y). */
static void test_internals(void **state)
{
    (void)state;
    double a[6] = { 3, 0, 4, 1, 0, 0 };
    assert_near(iris_fn_internal(61, a, 4), 4, 1e-15);
    assert_near(iris_fn_internal(57, a, 3), 5, 1e-15);
    assert_near(iris_fn_internal(69, a, 3), atan2(3, 4), 1e-15);
    assert_near(iris_fn_internal(47, a, 3), M_PI / 2, 1e-15);
    double t[5] = { 2, 0.5, 0, 2, 0.25 };   /* on the tube's top: 0.25 */
    assert_near(iris_fn_internal(70, t, 5), 0.25, 1e-15);
    double b[7] = { 1.5, 0, 0, 0.1, 1, 1, 1 }; /* 0.5 outside the x face */
    assert_near(iris_fn_internal(60, b, 7), 0.5 - 1e-6, 1e-12);
    double e[6] = { 0, 2, 0, 1, 0.5, 1 };   /* ellipsoid: |(0, 2*0.5, 0)| */
    assert_near(iris_fn_internal(17, e, 6), 1, 1e-15);
    assert_near(iris_fn_internal(999, a, 3), 0, 0);
}

/* sum(i, 1, 4, i * x) with x = 0.5 is 0.5 * (1+2+3+4) = 5; bounds are
** inclusive (POV-Ray). A huge bound stops at the term cap instead of
** hanging; a product over an empty range is 1. */
static void test_sum(void **state)
{
    (void)state;
    iris_fn_insn body[] = {
        ins(IRIS_FN_PARAM, 3, 0, 0), ins(IRIS_FN_PARAM, 0, 0, 0),
        ins(IRIS_FN_MUL, 0, 0, 0),
    };
    iris_fn b = { 4, NULL, 3, body, 2, 1 };
    iris_fn_insn code[] = {
        ins(IRIS_FN_CONST, 0, 0, 1), ins(IRIS_FN_CONST, 0, 0, 4),
        ins(IRIS_FN_SUM, 0, 3, 0),
    };
    code[2].callee = &b;
    iris_fn fn = { 3, NULL, 3, code, 2, 1 };
    double a[3] = { 0.5, 0, 0 };
    assert_near(iris_fn_eval(&fn, a, 3), 5, 0);
    code[1].value = 1e12;       /* capped at 1e6 terms: sum 0.5 * n(n+1)/2 */
    assert_near(iris_fn_eval(&fn, a, 3), 0.5 * 1e6 * (1e6 + 1) / 2, 1);
    code[1].value = 0;
    code[2].arg = 1;            /* prod over 1..0: empty */
    assert_near(iris_fn_eval(&fn, a, 3), 1, 0);
}

/* Parameters that drive loops (octaves, tube counts) cannot hang: a
** billion octaves of f_ridged_mf/f_hetero_mf and a billion tubes of
** f_polytubes return finite values (they stop at 1000). */
static void test_internal_limits(void **state)
{
    (void)state;
    double r[9] = { 0.3, 0.7, -0.4, 0.5, 2, 1e9, 1, 2, 2 };
    assert_true(isfinite(iris_fn_internal(59, r, 9)));
    assert_true(isfinite(iris_fn_internal(29, r, 9)));
    double t[9] = { 0.3, 0.7, -0.4, 1e9, 0.5, 0.1, 0, 0, 0 };
    assert_true(isfinite(iris_fn_internal(52, t, 9)));
    double n[4] = { 1e300, -1e300, NAN, 7 };
    assert_true(isfinite(iris_fn_internal(78, n, 4)));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arith),
        cmocka_unit_test(test_no_nan),
        cmocka_unit_test(test_select_call),
        cmocka_unit_test(test_branch),
        cmocka_unit_test(test_internals),
        cmocka_unit_test(test_sum),
        cmocka_unit_test(test_internal_limits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
