/* SPDX-License-Identifier: MIT */
/*
** isosurface.c: the surface f(x,y,z) = threshold inside its container.
**
** f is a compiled SDL function (fn.h); the inside is where f < threshold.
** Roots are found as POV-Ray finds them, with 'max_gradient' as a
** Lipschitz bound: along the ray g(t) = f - threshold changes by at most
** G·|d| per unit t, so an interval [a, b] holds no root when |g(a)| +
** |g(b)| > G·|d|·(b - a); other intervals are halved until they are
** shorter than 'accuracy' and a sign change is refined by bisection. The
** container's own surface shows where the function is inside at its
** boundary (unless 'open'), as in POV-Ray.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>

#include "iris/fn.h"

/* Evaluations allowed per ray: a wrong max_gradient cannot stall a render */
#define MAX_EVALS 20000

struct iso {
    const iris_object *o;
    vec3 ro, rd;
    double G, acc, dlen;
    int evals, max_roots;
    double t0, t1;
    struct isect_list *out;
    int found;
};

static double g_at(const iris_object *o, vec3 p)
{
    double args[3] = { p.x, p.y, p.z };
    double v = iris_fn_eval(o->u.isosurface.fn, args, 3) -
               o->u.isosurface.threshold;
    return isfinite(v) ? v : 1.0; /* an undefined value counts as outside */
}

static double g_t(struct iso *s, double t)
{
    s->evals++;
    return g_at(s->o, v3_madd(s->ro, s->rd, t));
}

/* Outward normal: the gradient by central differences of step 'h'. */
static vec3 iso_normal(const iris_object *o, vec3 p, double h)
{
    return v3(g_at(o, v3(p.x + h, p.y, p.z)) - g_at(o, v3(p.x - h, p.y, p.z)),
              g_at(o, v3(p.x, p.y + h, p.z)) - g_at(o, v3(p.x, p.y - h, p.z)),
              g_at(o, v3(p.x, p.y, p.z + h)) - g_at(o, v3(p.x, p.y, p.z - h)));
}

static void search(struct iso *s, double a, double b, double ga, double gb)
{
    if (s->found >= s->max_roots || s->evals > MAX_EVALS)
        return;
    double len = (b - a) * s->dlen;
    if (fabs(ga) + fabs(gb) > s->G * len)
        return;
    if (len <= s->acc) {
        if ((ga < 0) == (gb < 0))
            return;
        /* Refine the sign change to double precision (60 halvings of an
        ** interval below 'accuracy'): a ray leaving the surface must not
        ** find the same root again beyond accel_epsilon() */
        for (int k = 0; k < 60 && b - a > 4e-16 * fmax(fabs(a), fabs(b));
             k++) {
            double m = 0.5 * (a + b), gm = g_t(s, m);
            if ((gm < 0) == (ga < 0)) {
                a = m;
                ga = gm;
            } else {
                b = m;
            }
        }
        double t = 0.5 * (a + b);
        if (t > s->t0 && t < s->t1) {
            vec3 p = v3_madd(s->ro, s->rd, t);
            isect_push(s->out, t, iso_normal(s->o, p, 1e-2 * s->acc), 0, 0);
            s->found++;
        }
        return;
    }
    double m = 0.5 * (a + b), gm = g_t(s, m);
    search(s, a, m, ga, gm);
    search(s, m, b, gm, gb);
}

/* Container interval along the ray and the container normal function. */
static bool container(const iris_object *o, vec3 ro, vec3 rd, double *a,
                      double *b)
{
    if (o->u.isosurface.contained_kind == 1) {
        vec3 oc = v3_sub(ro, o->u.isosurface.centre);
        double A = v3_len2(rd), r = o->u.isosurface.radius;
        double tc = -v3_dot(oc, rd) / A;
        double h2 = (r * r - v3_len2(v3_madd(oc, rd, tc))) / A;
        if (!(h2 > 0))
            return false;
        *a = tc - sqrt(h2);
        *b = tc + sqrt(h2);
        return true;
    }
    *a = -INFINITY;
    *b = INFINITY;
    return geom_clip_box(v3_min(o->u.isosurface.lo, o->u.isosurface.hi),
                         v3_max(o->u.isosurface.lo, o->u.isosurface.hi), ro,
                         rd, a, b);
}

static vec3 container_normal(const iris_object *o, vec3 p)
{
    if (o->u.isosurface.contained_kind == 1)
        return v3_sub(p, o->u.isosurface.centre);
    vec3 lo = v3_min(o->u.isosurface.lo, o->u.isosurface.hi);
    vec3 hi = v3_max(o->u.isosurface.lo, o->u.isosurface.hi);
    vec3 c = v3_scale(v3_add(lo, hi), 0.5), e = v3_scale(v3_sub(hi, lo), 0.5);
    /* The face whose relative distance is largest */
    double best = -1;
    vec3 n = v3(0, 1, 0);
    for (int k = 0; k < 3; k++) {
        double ek = v3_comp(e, k);
        double r = ek > 0 ? (v3_comp(p, k) - v3_comp(c, k)) / ek : 0;
        if (fabs(r) > best) {
            best = fabs(r);
            n = v3(k == 0 ? r : 0, k == 1 ? r : 0, k == 2 ? r : 0);
        }
    }
    return n;
}

void geom_isosurface_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                          double t1, struct isect_list *out)
{
    if (!o->u.isosurface.fn)
        return;
    double a, b;
    if (!container(o, ro, rd, &a, &b))
        return;
    struct iso s = { .o = o, .ro = ro, .rd = rd, .out = out, .t0 = t0,
                     .t1 = t1 };
    s.dlen = v3_len(rd);
    /* POV-Ray's defaults: max_gradient 1.1, accuracy 0.001 */
    s.G = o->u.isosurface.max_gradient > 0 ? o->u.isosurface.max_gradient
                                           : 1.1;
    s.acc = o->u.isosurface.accuracy > 0 ? o->u.isosurface.accuracy : 1e-3;
    s.max_roots = o->u.isosurface.all_intersections ? 64
                  : o->u.isosurface.max_trace > 0 ? o->u.isosurface.max_trace
                                                  : 1;
    double ga = g_t(&s, a), gb = g_t(&s, b);
    /* Container walls where the function is inside */
    if (!o->open) {
        if (ga < 0 && a > t0 && a < t1) {
            isect_push(out, a, container_normal(o, v3_madd(ro, rd, a)), 0, 0);
            s.found++;
        }
    }
    double sa = fmax(a, t0), sb = fmin(b, t1);
    if (sa < sb)
        search(&s, sa, sb, sa == a ? ga : g_t(&s, sa),
               sb == b ? gb : g_t(&s, sb));
    if (!o->open && gb < 0 && b > t0 && b < t1)
        isect_push(out, b, container_normal(o, v3_madd(ro, rd, b)), 0, 0);
}

bool geom_isosurface_inside(const iris_object *o, vec3 p)
{
    if (!o->u.isosurface.fn)
        return false;
    if (o->u.isosurface.contained_kind == 1) {
        double r = o->u.isosurface.radius;
        if (v3_len2(v3_sub(p, o->u.isosurface.centre)) >= r * r)
            return false;
    } else {
        vec3 lo = v3_min(o->u.isosurface.lo, o->u.isosurface.hi);
        vec3 hi = v3_max(o->u.isosurface.lo, o->u.isosurface.hi);
        if (!(p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y &&
              p.z > lo.z && p.z < hi.z))
            return false;
    }
    return g_at(o, p) < 0;
}
