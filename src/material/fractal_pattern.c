/* SPDX-License-Identifier: MIT */
/*
** fractal_pattern.c: POV-Ray's magnet patterns (magnet 1/2, mandel/julia).
**
** The magnet maps come from the renormalisation of the Ising model:
**   type 1: z <- ((z² + c - 1) / (2z + c - 2))²
**   type 2: z <- ((z³ + 3(c-1)z + (c-1)(c-2)) /
**                 (3z² + 3(c-2)z + (c-1)(c-2) + 1))²
** z = 1 is a superattracting fixed point, so an orbit stops either by
** escaping (|z|² > 10000) or by reaching 1 (|z - 1|² < 1e-4), as in
** POV-Ray 3.7 (pattern.cpp magnet1m_pattern ... magnet2j_pattern); both
** are coloured as exterior points. The mandel form starts from z = 0 with
** c = the point and the least |z|² starting at 10000; the julia form
** starts from the point with POV-Ray's constant c.
*/
#include "config.h"

#include "material/fractal_pattern.h"

typedef struct { double re, im; } cplx;

static cplx cmul(cplx p, cplx q)
{
    return (cplx){ p.re * q.re - p.im * q.im, p.re * q.im + p.im * q.re };
}

static cplx cadd(cplx p, cplx q) { return (cplx){ p.re + q.re, p.im + q.im }; }

static cplx cscale(cplx p, double s) { return (cplx){ p.re * s, p.im * s }; }

/* p / q; a zero q gives inf/NaN, which stops the orbit (pat_magnet) */
static cplx cdiv(cplx p, cplx q)
{
    double m = q.re * q.re + q.im * q.im;
    return (cplx){ (p.re * q.re + p.im * q.im) / m,
                   (p.im * q.re - p.re * q.im) / m };
}

bool pat_magnet(int type, bool julia, double x, double y, double cu,
                double cv, int it_max, int *k, double *a, double *b,
                double *mind2)
{
    cplx c = julia ? (cplx){ cu, cv } : (cplx){ x, y };
    cplx z = julia ? (cplx){ x, y } : (cplx){ 0, 0 };
    double m2 = julia ? x * x + y * y : 10000;
    cplx c1 = { c.re - 1, c.im }, c2 = { c.re - 2, c.im };
    cplx c12 = cmul(c1, c2);
    for (int i = 0; i < it_max; i++) {
        cplx num, den;
        if (type == 2) {
            cplx z2 = cmul(z, z);
            num = cadd(cadd(cmul(z2, z), cscale(cmul(c1, z), 3)), c12);
            den = cadd(cadd(cscale(z2, 3), cscale(cmul(c2, z), 3)),
                       (cplx){ c12.re + 1, c12.im });
        } else {
            num = cadd(cmul(z, z), c1);
            den = cadd(cscale(z, 2), c2);
        }
        cplx q = cdiv(num, den);
        z = cmul(q, q);
        double d2 = z.re * z.re + z.im * z.im;
        if (d2 < m2)
            m2 = d2;
        double dr = z.re - 1;
        /* !(d2 <= ..): a NaN from a zero denominator stops it too */
        if (!(d2 <= 10000.0) || dr * dr + z.im * z.im < 1e-4) {
            *k = i;
            *a = z.re;
            *b = z.im;
            *mind2 = m2;
            return true;
        }
    }
    *k = it_max;
    *a = z.re;
    *b = z.im;
    *mind2 = m2;
    return false;
}
