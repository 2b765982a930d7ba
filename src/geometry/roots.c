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

/*
** Speed. The helpers below are forced inline so that the quartic's
** solver (quartic_roots: tori, blobs, the ovus) is compiled with its
** degree a constant, its loops unrolled: the same operations in the
** same order, hence the same roots to the bit, for a third fewer
** instructions in a torus's solve (callgrind, 02_shapes). Every other
** degree takes one out-of-line copy (any_degree_roots).
*/

/* Horner evaluation (roots_eval). */
static inline __attribute__((always_inline)) double
horner(const double *c, int deg, double t)
{
    double v = c[deg];
    for (int i = deg - 1; i >= 0; i--)
        v = v * t + c[i];
    return v;
}

double roots_eval(const double *c, int deg, double t)
{
    return horner(c, deg, t);
}

/* Value and derivative at 't'. */
static inline __attribute__((always_inline)) void
eval_d(const double *c, int deg, double t, double *f, double *df)
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
** taken while they stay inside the bracket and at least halve the step
** before (a Newton step crawling towards a flat end is no better),
** bisection otherwise; the bracket shrinks every iteration, so 200
** iterations always suffice to reach adjacent doubles. (Bisecting every
** fourth iteration whenever Newton moved by less than 1e-3 of the
** bracket, as before, broke Newton's convergence from one side, whose
** far end never moves: 16 iterations per cubic root on average, 6 now,
** the same roots to 3e-14.)
*/
static inline __attribute__((always_inline)) double
refine(const double *c, int deg, double a, double b, double fa)
{
    double x = 0.5 * (a + b), prev = HUGE_VAL;
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
        if (!(nx > a && nx < b) || !(fabs(step) <= 0.5 * prev)) {
            nx = 0.5 * (a + b);
            prev = fabs(b - a);
        } else {
            prev = fabs(step);
        }
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
** bernstein_coeffs() computes the b_k and the margin 1e-11·S (false when
** S is not finite and positive), bernstein_sign() returns their sign (+1
** or -1), or 0 when the b_k do not prove one; 'extra' is added to S
** (roots_surely_above()).
*/
static inline __attribute__((always_inline)) bool
bernstein_coeffs(const double *c, int deg, double lo, double hi, double extra,
                 double *b, double *margin)
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
        return false;
    for (int k = 0; k < deg; k++)        /* q(s) = p(lo + s) */
        for (int i = deg - 1; i >= k; i--)
            q[i] += lo * q[i + 1];
    double wp = w;
    for (int j = 1; j <= deg; j++) {     /* q(s) = p(lo + w·s) */
        q[j] *= wp;
        wp *= w;
    }
    /* 1 / (deg - j + 1), so that the weights below need no division */
    double inv[ROOTS_MAX_DEGREE + 1];
    for (int j = 1; j <= deg; j++)
        inv[j] = 1.0 / (double)(deg - j + 1);
    for (int k = 0; k <= deg; k++) {
        /* b_k; the weight C(k,j)/C(n,j) by its ratio to the previous j */
        double bk = q[0], wt = 1;
        for (int j = 1; j <= k; j++) {
            wt *= (double)(k - j + 1) * inv[j];
            bk += wt * q[j];
        }
        b[k] = bk;
    }
    *margin = 1e-11 * S;
    return true;
}

static inline __attribute__((always_inline)) int
bernstein_sign(const double *c, int deg, double lo, double hi, double extra)
{
    double b[ROOTS_MAX_DEGREE + 1], margin;
    if (!bernstein_coeffs(c, deg, lo, hi, extra, b, &margin))
        return 0;
    int sign = 0;
    for (int k = 0; k <= deg; k++) {
        int sg = b[k] > margin ? 1 : b[k] < -margin ? -1 : 0;
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

/*
** The roots in (lo, hi) of the quadratic c[0] + c[1] t + c[2] t² (c[2]
** != 0), ascending, in closed form: the critical points of a cubic, which
** only split its interval into monotone brackets (a root a few ulps off
** moves a bracket end, not the cubic's root that refine() finds in it).
** The recursion through degree 1 and refine() they replace was a third
** of the time of a prism's exact curves. The coefficients are scaled to
** a largest magnitude of 1 first, so that the discriminant neither
** overflows nor underflows; a double root (discriminant <= 0) is not
** reported, the cubic being monotone through it.
*/
static int quadratic_roots(const double *c, double lo, double hi, double *out)
{
    double m = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
    double a = c[2] / m, b = c[1] / m, k = c[0] / m;
    double disc = b * b - 4 * a * k;
    if (!(disc > 0))
        return 0;
    /* the stable pair: no cancellation between -b and the root */
    double q = -0.5 * (b + copysign(sqrt(disc), b));
    double r1 = q / a, r2 = k / q;   /* q != 0: disc > 0 */
    if (r1 > r2) {
        double t = r1;
        r1 = r2;
        r2 = t;
    }
    int n = 0;
    if (r1 > lo && r1 < hi)
        out[n++] = r1;
    if (r2 > lo && r2 < hi && r2 != r1)
        out[n++] = r2;
    return n;
}

/*
** The roots in (lo, hi) of c (degree >= 2, leading coefficient nonzero,
** finite interval) from its critical points: the derivative's roots
** (found recursively; in closed form for a cubic, and for a quartic by
** roots_cubic(): 8 % fewer instructions on the blob scene 185) split
** the interval into monotone brackets, each with one root where the
** values at its ends differ in sign. The brackets are taken in order and
** each is refined on its own, so the first 'cap' roots stored are those
** a larger cap gives, to the bit (a caller wanting the nearest root
** refines one bracket instead of every one).
*/
static inline __attribute__((always_inline)) int
derivative_roots(const double *c, int deg, double lo, double hi, double *out,
                 int cap)
{
    /* No sign change at the ends: there may be none inside either, and
    ** then the recursion below is not needed (a sign change means a
    ** root, so the test is not worth making). A cubic's two critical
    ** points cost less than the test. */
    double flo = horner(c, deg, lo);
    if (deg > 3 && (flo > 0) == (horner(c, deg, hi) > 0) &&
        bernstein_sign(c, deg, lo, hi, 0) != 0)
        return 0;

    /* Critical points isolate the roots */
    double dc[ROOTS_MAX_DEGREE], crit[ROOTS_MAX_DEGREE + 2];
    for (int i = 1; i <= deg; i++)
        dc[i - 1] = c[i] * i;
    int nc = deg == 3   ? quadratic_roots(dc, lo, hi, crit + 1)
             : deg == 4 ? roots_cubic(dc, lo, hi, crit + 1)
                        : roots_in_interval(dc, deg - 1, lo, hi, crit + 1);
    crit[0] = lo;
    crit[nc + 1] = hi;

    int n = 0;
    double fa = flo;
    for (int k = 0; k <= nc && n < cap; k++) {
        double a = crit[k], b = crit[k + 1];
        double fb = horner(c, deg, b);
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

/* derivative_roots() of a quartic, compiled for degree 4 (see Speed) */
static __attribute__((noinline)) int
quartic_roots(const double *c, double lo, double hi, double *out, int cap)
{
    return derivative_roots(c, 4, lo, hi, out, cap);
}

/* derivative_roots() of any degree, one copy */
static __attribute__((noinline)) int
any_degree_roots(const double *c, int deg, double lo, double hi, double *out,
                 int cap)
{
    return derivative_roots(c, deg, lo, hi, out, cap);
}

/*
** From degree ISOLATE_MIN_DEGREE the roots are isolated by subdividing
** the polynomial's Bernstein form (Descartes' rule of signs for
** Bernstein coefficients) instead: the derivative recursion refines
** every critical point of every derivative to full precision, about
** 16000 instructions for a sphere_sweep's degree-10 envelope, where a
** few de Casteljau splits usually separate the roots. Depth and margins
** below keep the answers those of derivative_roots(). Not below degree
** 7: a lathe's sextic, nearly a sum of squares for level rays, keeps
** sign changes through many splits and fell back to the derivatives
** after them (parity 144 took 13 % more instructions from degree 5).
*/
#define ISOLATE_MIN_DEGREE 7
#define ISOLATE_DEPTH 12

/* The sign changes of b[0..n], or -1 when a coefficient lies within
** 'margin' of 0 (its sign not sure). */
static int variations(const double *b, int n, double margin)
{
    int v = 0, prev = 0;
    for (int k = 0; k <= n; k++) {
        if (!(fabs(b[k]) > margin))
            return -1;
        int sg = b[k] > 0 ? 1 : -1;
        v += prev != 0 && sg != prev;
        prev = sg;
    }
    return v;
}

/* de Casteljau: the Bernstein coefficients of the same polynomial on
** [0, tau] ('l') and [tau, 1] ('r') from those on [0, 1] ('b'). */
static void split_at(const double *b, int n, double tau, double *l,
                     double *r)
{
    double w[ROOTS_MAX_DEGREE + 1];
    for (int i = 0; i <= n; i++)
        w[i] = b[i];
    for (int k = 0; k <= n; k++) {
        l[k] = w[0];
        r[n - k] = w[n - k];
        for (int i = 0; i < n - k; i++)
            w[i] += tau * (w[i + 1] - w[i]);
    }
}

/*
** The roots of c in (a, b), on which its Bernstein coefficients are 'bz'
** (all sure beyond 'margin', the whole interval's 1e-11·S: de Casteljau's
** convex combinations add rounding of a few ulps of the largest |b_k| per
** level, far below it). No sign change: no root. One: exactly one
** simple root, and the polynomial's values at a and b (those b_k's signs)
** bracket it for refine(). More, or a coefficient too near 0 to be sure:
** split where the value is surely nonzero (no root there to lose between
** the open halves); past ISOLATE_DEPTH levels (clustered or multiple
** roots), or without such a split point, derivative_roots() on (a, b).
** At most 'cap' roots are stored, ascending.
*/
static int isolate(const double *c, int deg, const double *bz,
                   double margin, double a, double b, int depth, double *out,
                   int cap)
{
    int v = variations(bz, deg, margin);
    if (v == 0 || cap <= 0)
        return 0;
    if (v == 1) {
        double fa = horner(c, deg, a), fb = horner(c, deg, b);
        if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
            out[0] = refine(c, deg, a, b, fa);
            return 1;
        }
    } else if (depth < ISOLATE_DEPTH) {
        static const double taus[] = { 0.5, 0.4375, 0.5625, 0.3125, 0.6875 };
        double l[ROOTS_MAX_DEGREE + 1], r[ROOTS_MAX_DEGREE + 1];
        for (int i = 0; i < (int)(sizeof taus / sizeof taus[0]); i++) {
            double m = a + taus[i] * (b - a);
            if (!(m > a && m < b))
                break;
            split_at(bz, deg, taus[i], l, r);
            if (!(fabs(l[deg]) > margin))
                continue;
            int n = isolate(c, deg, l, margin, a, m, depth + 1, out, cap);
            return n + isolate(c, deg, r, margin, m, b, depth + 1, out + n,
                               cap - n);
        }
    }
    double tmp[ROOTS_MAX_DEGREE];
    int n = any_degree_roots(c, deg, a, b, tmp, deg);
    if (n > cap)
        n = cap;
    for (int i = 0; i < n; i++)
        out[i] = tmp[i];
    return n;
}

int roots_in_interval(const double *c, int deg, double lo, double hi,
                      double *out)
{
    return roots_first_in_interval(c, deg, lo, hi, out, deg);
}

int roots_first_in_interval(const double *c_in, int deg, double lo,
                            double hi, double *out, int cap)
{
    double c[ROOTS_MAX_DEGREE + 1];
    if (deg > ROOTS_MAX_DEGREE || !(lo < hi) || cap <= 0)
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

    if (deg >= ISOLATE_MIN_DEGREE) {
        double b[ROOTS_MAX_DEGREE + 1], margin;
        if (bernstein_coeffs(c, deg, lo, hi, 0, b, &margin))
            return isolate(c, deg, b, margin, lo, hi, 0, out,
                           cap < deg ? cap : deg);
    }
    if (deg == 4)
        return quartic_roots(c, lo, hi, out, cap < deg ? cap : deg);
    return any_degree_roots(c, deg, lo, hi, out, cap < deg ? cap : deg);
}

/*
** Newton's method on the cubic c from '*x', a closed-form root whose
** error is a few ulps of 's', the size of the roots (|x| and the spread
** 2·sqrt|Q| + |a2/3| of roots_cubic()). Stops once a step is within 4
** ulps of x; rounding of p near its root can keep the steps a little
** above that, so after 6 steps a last step within 1e-12·s is accepted
** too. A step beyond 1e-6·s means the closed form was not near this
** root (it cannot be, by roots_cubic()'s conditioning test): false, and
** the caller takes the bracketing solver instead.
*/
static bool newton_polish(const double *c, double s, double *x)
{
    double t = *x, step = HUGE_VAL;
    for (int it = 0; it < 6; it++) {
        double f, df;
        eval_d(c, 3, t, &f, &df);
        if (f == 0)
            break;
        step = f / df;
        if (!(fabs(step) <= 1e-6 * s))   /* also df == 0, NaN */
            return false;
        t -= step;
        if (fabs(step) <= 4 * DBL_EPSILON * fabs(t))
            break;
        if (it == 5 && !(fabs(step) <= 1e-12 * s))
            return false;
    }
    *x = t;
    return true;
}

/*
** The closed form (roots.h). With the cubic made monic, t³ + a2 t² +
** a1 t + a0, Q = (a2² - 3 a1)/9 and R = (2 a2³ - 9 a2 a1 + 27 a0)/54:
** d = Q³ - R² > 0 gives three real roots -2√Q cos((θ + 2πk)/3) - a2/3
** with cos θ = R/√Q³, d < 0 one, A + Q/A - a2/3 with A = -sign(R)
** ∛(|R| + √-d) (as POV-Ray's solve_cubic, with ∛ for its pow(·, 1/3)).
** d is 1/108 of the discriminant, the product of the squared root
** differences: where |d| is within 1e-6 of max(|Q³|, R²), two roots lie
** within about 1e-3 of the roots' spread of each other (or Q³ and R²
** cancel to rounding and the sign of d, hence the number of real roots,
** is not sure; or a double or triple root, which roots_in_interval()
** does not report). Those, and overflowing or non-finite coefficients
** (every test below is false for NaN), go to roots_in_interval(); so do
** roots that Newton cannot polish. Otherwise acos's argument is at
** least 1e-6 from ±1, where its condition number is below 1e3, so each
** closed-form root is within about 1e-12 of the spread and two or three
** Newton steps bring it to the last few ulps.
*/
int roots_cubic(const double *c, double lo, double hi, double *out)
{
    if (!(c[3] != 0) || !(lo < hi))
        return roots_in_interval(c, 3, lo, hi, out);
    double inv = 1 / c[3];
    double a2 = c[2] * inv, a1 = c[1] * inv, a0 = c[0] * inv;
    double an = a2 / 3;
    double Q = (a2 * a2 - 3 * a1) / 9;
    double R = (a2 * (2 * a2 * a2 - 9 * a1) + 27 * a0) / 54;
    double Q3 = Q * Q * Q, R2 = R * R, d = Q3 - R2;
    double big = fabs(Q3) > R2 ? fabs(Q3) : R2;
    if (!(fabs(d) > 1e-6 * big) || !(big < HUGE_VAL))
        return roots_in_interval(c, 3, lo, hi, out);

    double x[3], s;
    int m;
    if (d > 0) {
        /* Q > 0 here (Q³ > R² >= 0); cos θ is inside [-1, 1] by the
        ** test above, up to rounding, which the clamp takes */
        double sq = sqrt(Q);
        /* The three roots lie within 2√Q of -a2/3 (|cos| <= 1); when
        ** that span, widened by far more than the closed form's error
        ** and the polish's moves, misses (lo, hi), so do they */
        s = 2 * sq + fabs(an);
        if (-an + (2 * sq + 1e-5 * s) <= lo || -an - (2 * sq + 1e-5 * s) >= hi)
            return 0;
        double ct = R / (Q * sq);
        ct = ct > 1 ? 1 : ct < -1 ? -1 : ct;
        double phi = acos(ct) / 3;   /* in [0, π/3] */
        double cp = cos(phi), sp = sin(phi);
        /* cos(φ ± 2π/3) = -cos φ / 2 ∓ sin φ √3/2: ascending roots */
        const double h3 = 0.86602540378443864676;   /* √3/2 */
        x[0] = -2 * sq * cp - an;
        x[1] = -2 * sq * (-0.5 * cp + h3 * sp) - an;
        x[2] = -2 * sq * (-0.5 * cp - h3 * sp) - an;
        m = 3;
    } else {
        double A = cbrt(fabs(R) + sqrt(-d));
        if (R > 0)
            A = -A;
        double B = A != 0 ? Q / A : 0;
        x[0] = A + B - an;
        m = 1;
        s = fabs(A) + fabs(B) + fabs(an);
    }
    int n = 0;
    for (int k = 0; k < m; k++) {
        double r = x[k], sr = fabs(r) > s ? fabs(r) : s;
        /* Six polishing steps move a root by at most 6e-6 of sr: one
        ** further than 1e-5 of it outside (lo, hi) stays outside */
        if (r + 1e-5 * sr <= lo || r - 1e-5 * sr >= hi)
            continue;
        if (!newton_polish(c, sr, &r))
            return roots_in_interval(c, 3, lo, hi, out);
        if (r > lo && r < hi)
            out[n++] = r;
    }
    /* Polishing moves a root by far less than the spacing the test
    ** above guarantees, so the order stays; kept sure anyway */
    for (int i = 1; i < n; i++)
        for (int j = i; j > 0 && out[j] < out[j - 1]; j--) {
            double t = out[j];
            out[j] = out[j - 1];
            out[j - 1] = t;
        }
    return n;
}
