/* SPDX-License-Identifier: MIT */
/*
** superellipsoid.c: POV-Ray's superellipsoid { <e, n> }.
**
** The surface is f = (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) - 1 = 0
** inside the box [-1,1]³. f is not a polynomial, so the ray segment in the
** box is cut where it crosses the planes x=0, y=0, z=0 (where f is not
** smooth), each piece is sampled and every sign change is refined by
** bisection. Approximation: two crossings closer together than one sample
** step (a ray grazing an edge) can be missed; 48 samples per piece keep
** that to a sliver.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>

#define SAMPLES 48

/* x^k for x >= 0. Whole powers up to 64 (e or n 1, 0.5, 0.1, 0.05; e/n
** 1) by squaring: a few roundings (log2 k + 1 products, at most ~14 ulp
** with pow's own half ulp), far inside group_sign()'s 1e-6 margin, and
** many times faster than pow, which dominated scenes of such shapes. */
static inline double upow(double x, double k)
{
    if (k == 1)
        return x;
    if (k == 2)
        return x * x;
    if (k > 2 && k <= 64 && k == (double)(int)k) {
        double r = 1, b = x;
        for (int m = (int)k;; b *= b) {
            if (m & 1)
                r *= b;
            if (!(m >>= 1))
                break;
        }
        return r;
    }
    return pow(x, k);
}

double geom_superellipsoid_eval(const iris_object *o, vec3 p)
{
    double e = o->u.superellipsoid.e, n = o->u.superellipsoid.n;
    double s = upow(fabs(p.x), 2 / e) + upow(fabs(p.y), 2 / e);
    return upow(s, e / n) + upow(fabs(p.z), 2 / n) - 1;
}

static vec3 grad(const iris_object *o, vec3 p)
{
    double e = o->u.superellipsoid.e, n = o->u.superellipsoid.n;
    double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
    double s = pow(ax, 2 / e) + pow(ay, 2 / e);
    double f = s > 0 ? (2 / n) * pow(s, e / n - 1) : 0;
    vec3 g = v3(copysign(f * pow(ax, 2 / e - 1), p.x),
                copysign(f * pow(ay, 2 / e - 1), p.y),
                copysign((2 / n) * pow(az, 2 / n - 1), p.z));
    if (isfinite(g.x) && isfinite(g.y) && isfinite(g.z) && v3_len2(g) > 0)
        return g;
    /* At the creases the analytic form divides by zero: use central
    ** differences with a step of 1e-7 of the unit shape */
    const double h = 1e-7;
    return v3(geom_superellipsoid_eval(o, v3(p.x + h, p.y, p.z)) -
                  geom_superellipsoid_eval(o, v3(p.x - h, p.y, p.z)),
              geom_superellipsoid_eval(o, v3(p.x, p.y + h, p.z)) -
                  geom_superellipsoid_eval(o, v3(p.x, p.y - h, p.z)),
              geom_superellipsoid_eval(o, v3(p.x, p.y, p.z + h)) -
                  geom_superellipsoid_eval(o, v3(p.x, p.y, p.z - h)));
}

static double fat(const iris_object *o, vec3 ro, vec3 rd, double t)
{
    return geom_superellipsoid_eval(o, v3_madd(ro, rd, t));
}

/* Samples per group whose sign group_sign() may settle at once. */
#define GROUP 8

/*
** Smallest and largest |x| over the samples between x0 = o + d·ta and
** x1 = o + d·tb, widened by 'pad': a sample's coordinate is rounded
** (a few ulps of |o| + |d·t|), and where the power 2/e or 2/n is below 1
** f changes fast near 0, so even that must stay inside the range.
*/
static void abs_range(double o, double d, double ta, double tb, double *lo,
                      double *hi)
{
    double x0 = o + d * ta, x1 = o + d * tb;
    double pad = 1e-12 + 1e-14 * (fabs(o) + fabs(d) * fmax(fabs(ta),
                                                          fabs(tb)));
    double a = fmin(x0, x1) - pad, b = fmax(x0, x1) + pad;
    *lo = (a <= 0 && b >= 0) ? 0 : fmin(fabs(a), fabs(b));
    *hi = fmax(fabs(a), fabs(b));
}

/*
** +1 when f > 0 on the whole segment t in [ta, tb], -1 when f < 0 there,
** 0 when unknown. f grows with each of |x|, |y|, |z| (positive powers), so
** f at the smallest |x|, |y|, |z| over the segment bounds it below and at
** the largest above (abs_range() covers the rounding of the points on
** the segment, the margin of 1e-6 that of pow), so a settled sign is the
** sign of every sample in it.
*/
static int group_sign(const iris_object *o, vec3 ro, vec3 rd, double ta,
                      double tb)
{
    vec3 lo, hi;
    abs_range(ro.x, rd.x, ta, tb, &lo.x, &hi.x);
    abs_range(ro.y, rd.y, ta, tb, &lo.y, &hi.y);
    abs_range(ro.z, rd.z, ta, tb, &lo.z, &hi.z);
    if (geom_superellipsoid_eval(o, lo) > 1e-6)
        return 1;
    if (geom_superellipsoid_eval(o, hi) < -1e-6)
        return -1;
    return 0;
}

/* Samples (a, b) and refines each sign change by bisection to the last
** bit. Groups of samples whose sign group_sign() settles, the same as
** the sign at the group's start, hold no change and are not sampled:
** the samples looked at, their signs and so the roots are the same.
** Sample steps ending at or before t0 are skipped (their roots lie
** before t0), and with out->first_only the first root kept ends the
** search. Returns whether it did. */
static bool piece(const iris_object *o, vec3 ro, vec3 rd, double a, double b,
                  double t0, double t1, struct isect_list *out)
{
    int i0 = 1;
    double ta = a;
    while (i0 < SAMPLES && a + (b - a) * i0 / SAMPLES <= t0)
        ta = a + (b - a) * i0++ / SAMPLES;
    double fa = fat(o, ro, rd, ta);
    for (int i = i0; i <= SAMPLES; i++) {
        if ((i - 1) % GROUP == 0) {
            int last = i + GROUP - 1 < SAMPLES ? i + GROUP - 1 : SAMPLES;
            double tg = a + (b - a) * last / SAMPLES;
            int sg = group_sign(o, ro, rd, ta, tg);
            if (sg != 0 && (sg < 0) == (fa < 0)) {
                /* only fa's sign is used below: sg stands for it */
                ta = tg;
                fa = sg;
                i = last;
                continue;
            }
        }
        double tb = a + (b - a) * i / SAMPLES, fb = fat(o, ro, rd, tb);
        if ((fa < 0) != (fb < 0)) {
            double l = ta, h = tb, fl = fa;
            for (int k = 0; k < 80 && h - l > 0; k++) {
                double m = 0.5 * (l + h);
                /* l and h adjacent: further steps change neither */
                if (m <= l || m >= h)
                    break;
                double fm = fat(o, ro, rd, m);
                if ((fm < 0) == (fl < 0)) {
                    l = m;
                    fl = fm;
                } else {
                    h = m;
                }
            }
            double t = 0.5 * (l + h);
            if (t > t0 && t < t1) {
                int had = out->n;
                isect_push(out, t, grad(o, v3_madd(ro, rd, t)), 0, 0);
                if (out->first_only && out->n > had)
                    return true;
            }
        }
        ta = tb;
        fa = fb;
    }
    return false;
}

void geom_superellipsoid_hits(const iris_object *o, vec3 ro, vec3 rd,
                              double t0, double t1, struct isect_list *out)
{
    /* The box is padded by 1e-9 so that roots on its faces are bracketed */
    double a = -INFINITY, b = INFINITY, pad = 1 + 1e-9;
    if (!geom_clip_box(v3(-pad, -pad, -pad), v3(pad, pad, pad), ro, rd, &a,
                       &b))
        return;
    double cuts[5];
    int nc = 0;
    cuts[nc++] = a;
    double ts[3];
    int nt = 0;
    for (int k = 0; k < 3; k++) {
        double dk = v3_comp(rd, k);
        if (dk != 0) {
            double t = -v3_comp(ro, k) / dk;
            if (t > a && t < b)
                ts[nt++] = t;
        }
    }
    /* Sort the few plane crossings */
    for (int i = 0; i < nt; i++)
        for (int j = i + 1; j < nt; j++)
            if (ts[j] < ts[i]) {
                double s = ts[i];
                ts[i] = ts[j];
                ts[j] = s;
            }
    for (int i = 0; i < nt; i++)
        cuts[nc++] = ts[i];
    cuts[nc++] = b;
    /* pieces in t order: the first root kept is the nearest; a piece
    ** ending by t0 or starting at t1 has no root to keep */
    for (int i = 0; i + 1 < nc; i++)
        if (cuts[i + 1] > cuts[i] && cuts[i + 1] > t0 && cuts[i] < t1 &&
            piece(o, ro, rd, cuts[i], cuts[i + 1], t0, t1, out))
            return;
}
