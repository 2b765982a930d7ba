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
    int evals;
    double pol;  /* +1, or -1 while looking for the way out (POV's Inv3) */
    double tl;   /* the root root_r found */
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

/* g with the search's polarity: negative past the surface being sought */
static double f_t(struct iso *s, double t)
{
    return s->pol * g_t(s, t);
}

/* Outward normal as POV-Ray computes it (IsoSurface::Normal): forward
** differences of step 'accuracy' in object space. The step is part of
** the look: on a noisy function it smooths the normal the same way. */
static vec3 iso_normal(const iris_object *o, vec3 p, double h)
{
    double g0 = g_at(o, p);
    vec3 n = v3(g_at(o, v3(p.x + h, p.y, p.z)) - g0,
                g_at(o, v3(p.x, p.y + h, p.z)) - g0,
                g_at(o, v3(p.x, p.y, p.z + h)) - g0);
    return v3_len2(n) > 0 ? n : v3(1, 0, 0);
}

/*
** POV-Ray's Function_Find_Root_R (R. Suzuki's method): [t1, t2] with
** polarised values f1, f2 may hold a root unless f1 + f2 >= dt, where dt
** = max_gradient * |d| * (t2 - t1); such intervals are halved, front half
** first, until shorter than 'accuracy' (in ray units), and the first one
** whose far end is past the surface (f2 < 0) gives the root t2. The root
** is thus up to 'accuracy' inside the surface, on the halving grid of
** the container interval: the same points POV-Ray shades.
*/
static bool root_r(struct iso *s, double t1, double f1, double t2, double f2,
                   double dt, double t21)
{
    if (s->evals > MAX_EVALS)
        return false;
    if (t21 < s->acc) {
        if (f2 < 0) {
            s->tl = t2;
            return true;
        }
        return false;
    }
    if (f1 + f2 - dt >= 0)
        return false;
    t21 *= 0.5;
    dt *= 0.5;
    double tm = t1 + t21, fm = f_t(s, tm);
    return root_r(s, t1, f1, tm, fm, dt, t21) ||
           root_r(s, tm, fm, t2, f2, dt, t21);
}

/* POV-Ray's Function_Find_Root: the first root in [*tmin, tmax]. An open
** isosurface that starts inside turns its polarity to look for the way
** out. */
static bool find_root(struct iso *s, double *tmin, double tmax)
{
    double f1 = f_t(s, *tmin);
    if (s->o->open && f1 < 0) {
        s->pol = -s->pol;
        f1 = -f1;
    }
    double f2 = f_t(s, tmax), t21 = tmax - *tmin;
    if (!root_r(s, *tmin, f1, tmax, f2, s->G * s->dlen * t21, t21))
        return false;
    *tmin = s->tl;
    return true;
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

/*
** A ray starting on the surface (g0 = g at t = 0 under 4 max_gradient
** accuracy, as a reflected or shadow ray does) or inside the container:
** POV-Ray goes on from 5 accuracy and looks for the way out if it is
** inside there. (The points it shades lie up to 'accuracy' inside, so a
** ray leaving one at a grazing angle may find its own surface again; POV-
** Ray shadows such rays, and so does iris.)
*/
static double step_in(struct iso *s)
{
    double t = s->acc * 5.0;
    if (g_t(s, t) < 0)
        s->pol = -1;
    return t;
}

/* A crossing at 't' if it lies in the caller's range (t0, t1). */
static int push_in_range(struct isect_list *out, double t, vec3 n, double t0,
                         double t1)
{
    if (!(t > t0 && t < t1))
        return 0;
    isect_push(out, t, n, 0, 0);
    return 1;
}

/*
** The crossings along the ray, found as POV-Ray's All_Intersections
** finds them (isosurface.cpp), so that the points shaded are the same:
** the search runs over the whole container interval (from t = 0 when the
** ray starts inside it), whatever part of it the caller wants; a ray
** starting on the surface (|g| < 4 max_gradient accuracy) steps 5
** accuracy in and looks for the way out if it is inside; after a root
** the search goes on 5 accuracy further with the polarity turned.
*/
void geom_isosurface_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                          double t1, struct isect_list *out)
{
    if (!o->u.isosurface.fn)
        return;
    double a, b;
    if (!container(o, ro, rd, &a, &b))
        return;
    struct iso s = { .o = o, .ro = ro, .rd = rd, .pol = 1 };
    s.dlen = v3_len(rd);
    /* POV-Ray's defaults: max_gradient 1.1, accuracy 0.001 */
    s.G = o->u.isosurface.max_gradient > 0 ? o->u.isosurface.max_gradient
                                           : 1.1;
    s.acc = o->u.isosurface.accuracy > 0 ? o->u.isosurface.accuracy : 1e-3;
    int max_roots = o->u.isosurface.all_intersections ? 64
                    : o->u.isosurface.max_trace > 0 ? o->u.isosurface.max_trace
                                                    : 1;
    double near_surface = s.G * s.acc * 4.0;
    int n0 = out->n, itrace = 0;
    if (a < 0)
        a = 0;
    if (!o->open) {
        double ga = g_t(&s, a);
        if (a > s.acc) {
            if (ga < 0) {
                /* the container's wall, where the function is inside */
                push_in_range(out, a,
                              container_normal(o, v3_madd(ro, rd, a)), t0, t1);
                itrace++;
                s.pol = -1;
            }
        } else {
            if (ga < near_surface)
                a = step_in(&s);
            if (g_t(&s, b) < 0)
                push_in_range(out, b, container_normal(o, v3_madd(ro, rd, b)),
                              t0, t1);
        }
    }
    double tmax = b, tmin = fmin(a, b);
    if (tmax - tmin < s.acc) {
        out->n = n0; /* POV-Ray takes back the wall it found */
        return;
    }
    if (tmin < s.acc && s.pol > 0 && fabs(g_t(&s, tmin)) < near_surface)
        tmin = step_in(&s);
    for (; itrace < max_roots; itrace++) {
        if (!find_root(&s, &tmin, tmax))
            break;
        push_in_range(out, tmin,
                      iso_normal(o, v3_madd(ro, rd, tmin), s.acc), t0, t1);
        tmin += s.acc * 5.0;
        if (tmax - tmin < s.acc)
            break;
        s.pol = -s.pol;
    }
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
