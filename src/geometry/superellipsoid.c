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

double geom_superellipsoid_eval(const iris_object *o, vec3 p)
{
    double e = o->u.superellipsoid.e, n = o->u.superellipsoid.n;
    double s = pow(fabs(p.x), 2 / e) + pow(fabs(p.y), 2 / e);
    return pow(s, e / n) + pow(fabs(p.z), 2 / n) - 1;
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

/* Samples (a, b) and refines each sign change by 80 bisections. */
static void piece(const iris_object *o, vec3 ro, vec3 rd, double a, double b,
                  double t0, double t1, struct isect_list *out)
{
    double ta = a, fa = fat(o, ro, rd, a);
    for (int i = 1; i <= SAMPLES; i++) {
        double tb = a + (b - a) * i / SAMPLES, fb = fat(o, ro, rd, tb);
        if ((fa < 0) != (fb < 0)) {
            double l = ta, h = tb, fl = fa;
            for (int k = 0; k < 80 && h - l > 0; k++) {
                double m = 0.5 * (l + h), fm = fat(o, ro, rd, m);
                if ((fm < 0) == (fl < 0)) {
                    l = m;
                    fl = fm;
                } else {
                    h = m;
                }
            }
            double t = 0.5 * (l + h);
            if (t > t0 && t < t1)
                isect_push(out, t, grad(o, v3_madd(ro, rd, t)), 0, 0);
        }
        ta = tb;
        fa = fb;
    }
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
    for (int i = 0; i + 1 < nc; i++)
        if (cuts[i + 1] > cuts[i])
            piece(o, ro, rd, cuts[i], cuts[i + 1], t0, t1, out);
}
