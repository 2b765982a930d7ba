/* SPDX-License-Identifier: MIT */
/*
** julia_hcx.c: the hypercomplex algebra of POV-Ray's julia_fractal.
**
** Hypercomplex numbers x + yi + zj + wk (ij = k, i² = j² = -1, k² = 1)
** form a commutative algebra isomorphic to pairs of complex numbers: the
** "duplex" form a = (x - w) + (y + z)i, b = (x + w) + (y - z)i multiplies
** component-wise. Any complex function f therefore extends to
** hypercomplexes as (f(a), f(b)) mapped back, which is how POV-Ray 3.7
** defines exp, ln, sin, ..., pwr for julia_fractal. The complex functions
** below follow the formulas POV-Ray documents for each (its branch choices:
** acos(z) = -i ln(z + sqrt(z² - 1)), not C's cacos).
*/
#include "config.h"

#include "geometry/julia_hcx.h"

#include "iris/scene.h"

#include <math.h>

typedef struct { double re, im; } cplx;

static cplx cx(double re, double im) { return (cplx){ re, im }; }
static cplx cadd(cplx a, cplx b) { return cx(a.re + b.re, a.im + b.im); }
static cplx cmul(cplx a, cplx b)
{
    return cx(a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re);
}

/* a / b; 0 when b is 0 (POV-Ray leaves its result unset there) */
static cplx cdiv(cplx a, cplx b)
{
    double m = b.re * b.re + b.im * b.im;
    if (m == 0)
        return cx(0, 0);
    return cx((a.re * b.re + a.im * b.im) / m,
              (a.im * b.re - a.re * b.im) / m);
}

/* Principal logarithm and square root */
static cplx cln(cplx z)
{
    return cx(log(hypot(z.re, z.im)), atan2(z.im, z.re));
}

static cplx csqrt_p(cplx z)
{
    if (z.re == 0 && z.im == 0)
        return cx(0, 0);
    double m = sqrt(hypot(z.re, z.im)), t = 0.5 * atan2(z.im, z.re);
    return cx(m * cos(t), m * sin(t));
}

/* -i z */
static cplx cmul_mi(cplx z) { return cx(z.im, -z.re); }

/* atanh(z) = ½ ln((1 + z)/(1 - z)), with POV-Ray's special cases */
static cplx catanh_p(cplx z)
{
    if (z.re == 0)
        return cx(0, atan(z.im));
    if (fabs(z.re) == 1 && z.im == 0)
        return cx(0, 0); /* a pole: POV-Ray leaves the value unset */
    if (fabs(z.re) < 1 && z.im == 0)
        return cx(0.5 * log((1 + z.re) / (1 - z.re)), 0);
    cplx l = cln(cdiv(cx(1 + z.re, z.im), cx(1 - z.re, -z.im)));
    return cx(0.5 * l.re, 0.5 * l.im);
}

/* atan(z) = (i/2) ln((1 - iz)/(1 + iz)), with POV-Ray's special cases */
static cplx catan_p(cplx z)
{
    if (z.re == 0 && z.im == 0)
        return cx(0, 0);
    if (z.im == 0)
        return cx(atan(z.re), 0);
    if (z.re == 0) {
        cplx t = catanh_p(cx(z.im, 0));
        return cx(-t.im, t.re);
    }
    cplx iz = cx(-z.im, z.re);
    cplx l = cln(cdiv(cx(1 - iz.re, -iz.im), cx(1 + iz.re, iz.im)));
    return cx(-0.5 * l.im, 0.5 * l.re);
}

static cplx cfunc(int fn, const double e[2], cplx z)
{
    double x = z.re, y = z.im;
    switch (fn) {
    case IRIS_JULIA_EXP:
        return cx(exp(x) * cos(y), exp(x) * sin(y));
    case IRIS_JULIA_LN:
        return cln(z);
    case IRIS_JULIA_SIN:
        return cx(sin(x) * cosh(y), cos(x) * sinh(y));
    case IRIS_JULIA_SINH:
        return cx(sinh(x) * cos(y), cosh(x) * sin(y));
    case IRIS_JULIA_COS:
        return cx(cos(x) * cosh(y), -sin(x) * sinh(y));
    case IRIS_JULIA_COSH:
        return cx(cosh(x) * cos(y), sinh(x) * sin(y));
    case IRIS_JULIA_TAN: {
        double d = cos(2 * x) + cosh(2 * y);
        return d == 0 ? cx(0, 0) : cx(sin(2 * x) / d, sinh(2 * y) / d);
    }
    case IRIS_JULIA_TANH: {
        double d = cosh(2 * x) + cos(2 * y);
        return d == 0 ? cx(0, 0) : cx(sinh(2 * x) / d, sin(2 * y) / d);
    }
    case IRIS_JULIA_ASIN: {
        /* -i ln(iz + sqrt(1 - z²)) */
        cplx s = cmul(z, z);
        s = csqrt_p(cx(1 - s.re, -s.im));
        return cmul_mi(cln(cadd(cx(-y, x), s)));
    }
    case IRIS_JULIA_ACOS: {
        /* -i ln(z + sqrt(z² - 1)) */
        cplx s = cmul(z, z);
        s = csqrt_p(cx(s.re - 1, s.im));
        return cmul_mi(cln(cadd(z, s)));
    }
    case IRIS_JULIA_ASINH: {
        /* ln(z + sqrt(z² + 1)) */
        cplx s = cmul(z, z);
        return cln(cadd(z, csqrt_p(cx(s.re + 1, s.im))));
    }
    case IRIS_JULIA_ACOSH: {
        /* ln(z + sqrt(z² - 1)) */
        cplx s = cmul(z, z);
        return cln(cadd(z, csqrt_p(cx(s.re - 1, s.im))));
    }
    case IRIS_JULIA_ATAN:
        return catan_p(z);
    case IRIS_JULIA_ATANH:
        return catanh_p(z);
    case IRIS_JULIA_PWR: {
        /* exp(e ln z); 0 at 0, and 0 where exp would underflow */
        if (x == 0 && y == 0)
            return cx(0, 0);
        cplx t = cmul(cln(z), cx(e[0], e[1]));
        double m = t.re < -690 ? 0 : exp(t.re);
        return cx(m * cos(t.im), m * sin(t.im));
    }
    default:
        return cmul(z, z);
    }
}

/* 1/q; 0 where q is a zero divisor (POV-Ray leaves it unset) */
static void hcx_reciprocal(const double q[4], double r[4])
{
    cplx a = cx(q[0] - q[3], q[1] + q[2]), b = cx(q[0] + q[3], q[1] - q[2]);
    cplx ra = cdiv(cx(1, 0), a), rb = cdiv(cx(1, 0), b);
    if ((a.re == 0 && a.im == 0) || (b.re == 0 && b.im == 0))
        ra = rb = cx(0, 0);
    r[0] = 0.5 * (ra.re + rb.re);
    r[1] = 0.5 * (ra.im + rb.im);
    r[2] = 0.5 * (ra.im - rb.im);
    r[3] = 0.5 * (rb.re - ra.re);
}

void hcx_map(int fn, const double e[2], const double q[4], double r[4])
{
    if (fn == IRIS_JULIA_SQR || fn == IRIS_JULIA_CUBE) {
        hcx_mul(q, q, r);
        return;
    }
    if (fn == IRIS_JULIA_RECIPROCAL) {
        hcx_reciprocal(q, r);
        return;
    }
    /* Duplex form, f on each half, and back */
    cplx a = cfunc(fn, e, cx(q[0] - q[3], q[1] + q[2]));
    cplx b = cfunc(fn, e, cx(q[0] + q[3], q[1] - q[2]));
    r[0] = 0.5 * (a.re + b.re);
    r[1] = 0.5 * (a.im + b.im);
    r[2] = 0.5 * (a.im - b.im);
    r[3] = 0.5 * (b.re - a.re);
}

void hcx_normal_factor(int fn, const double e[2], const double q[4],
                       double r[4])
{
    if (fn == IRIS_JULIA_SQR || fn == IRIS_JULIA_CUBE) {
        for (int k = 0; k < 4; k++)
            r[k] = q[k];
    } else if (fn == IRIS_JULIA_RECIPROCAL) {
        double inv[4];
        hcx_reciprocal(q, inv);
        hcx_mul(inv, inv, r);
        for (int k = 0; k < 4; k++)
            r[k] = -r[k];
    } else {
        hcx_map(fn, e, q, r);
    }
}
