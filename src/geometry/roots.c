/* SPDX-License-Identifier: MIT */
/*
** roots.c: polynomial root isolation by derivative recursion plus
** safeguarded Newton (see roots.h for why this method).
*/
#include "config.h"

#include "geometry/roots.h"

#include <float.h>
#include <stdbool.h>
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
        /* Stop when the bracket is a few ulps wide (a comparison, not
        ** fmax(), a library call in the innermost loop; a and b are
        ** finite, so the two agree) */
        double aa = fabs(a), ab = fabs(b);
        if (fabs(b - a) <= 4 * DBL_EPSILON * (aa > ab ? aa : ab) ||
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

/*
** Whether c (degree deg) surely keeps one sign on [lo, hi] by a
** margin larger than the rounding of any Horner evaluation there, so that
** roots_in_interval() would evaluate no sign change and no zero on it and
** return no root: the same answer, without the derivative recursion and
** its refinements (most of the cost of a ray that misses a quartic or a
** sphere_sweep segment).
**
** The test: with t = lo + w·s (w = hi - lo), the coefficients q_j of
** p(lo + w·s) in s (a Taylor shift, then scaling by w^j) give the
** Bernstein coefficients b_k = sum_{j <= k} C(k,j)/C(n,j) q_j on s in
** [0, 1], and p lies between the smallest and largest b_k there (convex
** hull property). Every rounding error involved, of the shift, of the
** Bernstein sums and of Horner's evaluation at |t| <= |lo| + w, is at
** most a few times n·DBL_EPSILON·S with S = sum |c_i|·(|lo| + w)^i
** (Higham, Accuracy and Stability of Numerical Algorithms, 5.1; the
** shift's error sums the same binomial terms as S). All b_k beyond
** 1e-11·S, hundreds of times those errors for degree 35, make every
** evaluation the solver could do nonzero with the sign of the b_k.
** Returns that sign (+1 or -1), or 0 when the b_k do not prove one;
** 'extra' is added to S (roots_surely_above()).
*/
static int bernstein_sign(const double *c, int deg, double lo, double hi,
                          double extra)
{
    double w = hi - lo, m = fabs(lo) + w;
    double q[ROOTS_MAX_DEGREE + 1];
    double S = extra, mp = 1;
    for (int i = 0; i <= deg; i++) {
        q[i] = c[i];
        S += fabs(c[i]) * mp;
        mp *= m;
    }
    if (!isfinite(S) || !(S > 0))
        return 0;
    for (int k = 0; k < deg; k++)        /* q(s) = p(lo + s) */
        for (int i = deg - 1; i >= k; i--)
            q[i] += lo * q[i + 1];
    double wp = w;
    for (int j = 1; j <= deg; j++) {     /* q(s) = p(lo + w·s) */
        q[j] *= wp;
        wp *= w;
    }
    double margin = 1e-11 * S;
    int sign = 0;
    for (int k = 0; k <= deg; k++) {
        /* b_k; the weight C(k,j)/C(n,j) by its ratio to the previous j */
        double b = q[0], wt = 1;
        for (int j = 1; j <= k; j++) {
            wt *= (double)(k - j + 1) / (double)(deg - j + 1);
            b += wt * q[j];
        }
        int sg = b > margin ? 1 : b < -margin ? -1 : 0;
        if (sg == 0 || (sign != 0 && sg != sign))
            return 0;
        sign = sg;
    }
    return sign;
}

bool roots_surely_above(const double *c, int deg, double lo, double hi,
                        double v)
{
    double d[ROOTS_MAX_DEGREE + 1];
    if (deg < 0 || deg > ROOTS_MAX_DEGREE || !(lo <= hi) || !isfinite(lo) ||
        !isfinite(hi) || !isfinite(v))
        return false;
    for (int i = 0; i <= deg; i++)
        d[i] = c[i];
    /* p - v > margin·(S + |v|) covers the rounding of c[0] - v and of
    ** comparing a Horner value of p itself with v */
    d[0] -= v;
    return bernstein_sign(d, deg, lo, hi, fabs(v)) > 0;
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
    for (int i = 0; i < deg; i++) {
        double q = fabs(c[i] / c[deg]);   /* finite c: never NaN */
        if (q > bound)
            bound = q;
    }
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

    /* No sign change at the ends: there may be none inside either, and
    ** then the recursion below is not needed (a sign change means a
    ** root, so the test is not worth making) */
    double flo = roots_eval(c, deg, lo);
    if ((flo > 0) == (roots_eval(c, deg, hi) > 0) &&
        bernstein_sign(c, deg, lo, hi, 0) != 0)
        return 0;

    /* Critical points isolate the roots */
    double dc[ROOTS_MAX_DEGREE], crit[ROOTS_MAX_DEGREE + 2];
    for (int i = 1; i <= deg; i++)
        dc[i - 1] = c[i] * i;
    int nc = roots_in_interval(dc, deg - 1, lo, hi, crit + 1);
    crit[0] = lo;
    crit[nc + 1] = hi;

    int n = 0;
    double fa = flo;
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
