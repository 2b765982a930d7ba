/* SPDX-License-Identifier: MIT */
/*
** testutil.h: what the cmocka unit tests share.
**
** cmocka (Debian libcmocka-dev) runs the tests and prints TAP for automake's
** tap-driver (CMOCKA_MESSAGE_OUTPUT=TAP is set by make check). It has no
** double-precision comparison, so assert_near() is here: it fails with
** file:line and both values when |a - b| > tol.
*/
#ifndef IRIS_TESTS_TESTUTIL_H
#define IRIS_TESTS_TESTUTIL_H

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>

#include <cmocka.h>

/* Fails unless |a - b| <= tol (and both are finite). */
#define assert_near(a, b, tol)                                              \
    do {                                                                    \
        double an_a_ = (double)(a), an_b_ = (double)(b);                    \
        double an_t_ = (double)(tol);                                       \
        if (!(fabs(an_a_ - an_b_) <= an_t_))                                \
            fail_msg("%s:%d: %s = %.9g, expected %s = %.9g within %.3g",    \
                     __FILE__, __LINE__, #a, an_a_, #b, an_b_, an_t_);      \
    } while (0)

/* Fails unless |a - b| <= rel * |b|. */
#define assert_rel(a, b, rel)                                               \
    do {                                                                    \
        double ar_a_ = (double)(a), ar_b_ = (double)(b);                    \
        double ar_r_ = (double)(rel);                                       \
        if (!(fabs(ar_a_ - ar_b_) <= ar_r_ * fabs(ar_b_)))                  \
            fail_msg("%s:%d: %s = %.9g, expected %s = %.9g within %.3g "    \
                     "relative", __FILE__, __LINE__, #a, ar_a_, #b, ar_b_,  \
                     ar_r_);                                                \
    } while (0)

#endif
