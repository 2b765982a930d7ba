/* SPDX-License-Identifier: MIT */
/*
** roots.c: polynomial root isolation by derivative recursion plus
** safeguarded Newton (see roots.h for why this method).
*/
#include "config.h"

#include "geometry/roots.h"

#include <float.h>
#include <math.h>

double roots_eval(const double *c, int deg, double t)
{
    double v = c[deg];
    for (int i = deg - 1; i >= 0; i--)
        v = v * t + c[i];
    return v;
}

/* Value and derivative at 't'. */
static void eval_d(const double *c, int deg, double t, double *f, double *df)
{
    double v = c[deg], d = 0;
    for (int i = deg - 1; i >= 0; i--) {
        d = d * t + v;
        v = v * t + c[i];
    }
    *f = v;
    *df = d;
}

/*
** Refines a root bracketed by [a, b] with f(a)·f(b) < 0. Newton steps are
** taken while they stay inside the bracket, bisection otherwise; the
** bracket shrinks every iteration, so 200 iterations always suffice to
** reach adjacent doubles.
*/
static double refine(const double *c, int deg, double a, double b, double fa)
{
    double x = 0.5 * (a + b);
    for (int it = 0; it < 200; it++) {
        double f, df;
        eval_d(c, deg, x, &f, &df);
        if (f == 0)
            return x;
        if ((f < 0) == (fa < 0)) {
            a = x;
            fa = f;
        } else {
            b = x;
        }
        /* Stop when the bracket is a few ulps wide */
        if (fabs(b - a) <= 4 * DBL_EPSILON * fmax(fabs(a), fabs(b)) ||
            fabs(b - a) < DBL_MIN)
            break;
        double step = df != 0 ? f / df : HUGE_VAL;
        double nx = x - step;
        /* Newton converging to one side never shrinks the far end of the
        ** bracket: stop once its step is a few ulps of x, the precision
        ** the bracket test above would reach (quadratic convergence makes
        ** the next step far smaller still) */
        if (nx > a && nx < b && fabs(step) <= 4 * DBL_EPSILON * fabs(nx))
            return nx;
        if (!(nx > a && nx < b))
            nx = 0.5 * (a + b);
        /* Newton that barely moves near an endpoint stalls: bisect */
        if (fabs(nx - x) < 1e-3 * fabs(b - a) && it % 4 == 3)
            nx = 0.5 * (a + b);
        x = nx;
    }
    return x;
}

int roots_in_interval(const double *c_in, int deg, double lo, double hi,
                      double *out)
{
    double c[ROOTS_MAX_DEGREE + 1];
    if (deg > ROOTS_MAX_DEGREE || !(lo < hi))
        return 0;
    for (int i = 0; i <= deg; i++) {
        if (!isfinite(c_in[i]))
            return 0;
        c[i] = c_in[i];
    }

    /* Drop leading coefficients that are exactly zero */
    while (deg > 0 && c[deg] == 0)
        deg--;
    if (deg <= 0)
        return 0;

    /* Cauchy's bound: every root has |t| <= 1 + max |c[i] / c[deg]| */
    double bound = 0;
    for (int i = 0; i < deg; i++)
        bound = fmax(bound, fabs(c[i] / c[deg]));
    bound = 1 + bound;
    if (!isfinite(bound))
        bound = DBL_MAX / 4;
    lo = fmax(lo, -bound);
    hi = fmin(hi, bound);
    if (!(lo < hi))
        return 0;

    if (deg == 1) {
        double t = -c[0] / c[1];
        if (t > lo && t < hi) {
            out[0] = t;
            return 1;
        }
        return 0;
    }

    /* Critical points isolate the roots */
    double dc[ROOTS_MAX_DEGREE], crit[ROOTS_MAX_DEGREE + 2];
    for (int i = 1; i <= deg; i++)
        dc[i - 1] = c[i] * i;
    int nc = roots_in_interval(dc, deg - 1, lo, hi, crit + 1);
    crit[0] = lo;
    crit[nc + 1] = hi;

    int n = 0;
    double fa = roots_eval(c, deg, crit[0]);
    for (int k = 0; k <= nc; k++) {
        double a = crit[k], b = crit[k + 1];
        double fb = roots_eval(c, deg, b);
        if (fa == 0 && k > 0) {
            /* Exact root at a critical point: report it once */
            if (n == 0 || out[n - 1] != a)
                out[n++] = a;
        } else if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
            out[n++] = refine(c, deg, a, b, fa);
        }
        fa = fb;
    }
    return n;
}
