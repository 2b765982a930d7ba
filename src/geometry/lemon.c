/* SPDX-License-Identifier: MIT */
/*
** lemon.c: lemon { <base>, base_radius, <cap>, cap_radius, inner_radius },
** as POV-Ray 3.8 defines it (lemon.cpp; POV-Ray 3.7.0 has no lemon, and
** iris's parser does not read one yet: a program may build it).
**
** In the unit frame where base is the origin and cap is (0, 0, 1) (all
** lengths divided by |cap - base|), the surface is the arc of the circle
** of radius r (the inner radius) through the base rim (a, 0) and the cap
** rim (b, 0, 1), revolved about the axis: the circle's centre (H, V) has
** H <= 0, i.e. lies on the far side of the axis, which makes the surface
** the inner ("lemon") part of a spindle torus of major radius -H. POV-Ray
** raises r to the smallest that reaches both rims,
**     r_min = sqrt(a^4 - 2a²(b² - 1) + (b² + 1)²) / 2,
** where the centre is on the axis (H = 0) and the surface a sphere's
** zone. Unless 'open', flat discs of radius a and b close the ends.
**
** The spindle is solved by ovus.c's geom_spindle_hits(), whose axis is y:
** the unit frame here maps the lemon's axis to y for it.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>

struct lemon {
    vec3 base, e1, e2, w;  /* frame: e1, e2, w orthonormal, w along axis */
    double len;            /* |cap - base| */
    double a, b, r;        /* radii in the unit frame */
    double H, V;           /* the arc's centre in the unit frame */
};

static bool lemon_of(const iris_object *o, struct lemon *L)
{
    vec3 axis = v3_sub(o->u.lemon.cap, o->u.lemon.base);
    L->len = v3_len(axis);
    if (!(L->len > 0) || !isfinite(L->len))
        return false;
    L->base = o->u.lemon.base;
    L->w = v3_scale(axis, 1 / L->len);
    v3_basis(L->w, &L->e1, &L->e2);
    double a = fabs(o->u.lemon.base_radius) / L->len;
    double b = fabs(o->u.lemon.cap_radius) / L->len;
    double r = fabs(o->u.lemon.inner_radius) / L->len;
    double lo = sqrt(a * a * a * a - 2 * a * a * (b * b - 1) +
                     (b * b + 1) * (b * b + 1)) / 2;
    if (r < lo)
        r = lo;
    double ab2 = (a - b) * (a - b);
    double f = sqrt(fmax(0, (4 * r * r - ab2 - 1) / (ab2 + 1)));
    L->a = a;
    L->b = b;
    L->r = r;
    L->H = fmin(0, (a + b - f) / 2);
    L->V = ((b - a) * f + 1) / 2;
    return true;
}

/* World (object) point or direction into the unit frame, with the axis
** on y as geom_spindle_hits() wants it: (e1, w, e2). */
static vec3 to_unit(const struct lemon *L, vec3 v, bool point)
{
    if (point)
        v = v3_sub(v, L->base);
    return v3_scale(v3(v3_dot(v, L->e1), v3_dot(v, L->w), v3_dot(v, L->e2)),
                    1 / L->len);
}

static vec3 from_unit_normal(const struct lemon *L, vec3 n)
{
    return v3_add(v3_add(v3_scale(L->e1, n.x), v3_scale(L->w, n.y)),
                  v3_scale(L->e2, n.z));
}

void geom_lemon_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out)
{
    struct lemon L;
    if (!lemon_of(o, &L))
        return;
    /* A linear map keeps the ray parameter */
    vec3 p = to_unit(&L, ro, true), d = to_unit(&L, rd, false);
    struct isect_list tmp;
    isect_list_init(&tmp);
    if (L.H < -1e-10) {
        geom_spindle_hits(-L.H, L.r, L.V, 0, 1, p, d, t0, t1, &tmp);
    } else {
        /* centre on the axis: the zone 0 < y < 1 of a sphere */
        vec3 oc = v3_sub(p, v3(0, L.V, 0));
        double A = v3_len2(d), B = v3_dot(oc, d);
        double C = v3_len2(oc) - L.r * L.r, disc = B * B - A * C;
        if (disc > 0) {
            double q = -(B + copysign(sqrt(disc), B));
            double ts[2] = { q / A, C / q };
            for (int k = 0; k < 2; k++) {
                vec3 x = v3_madd(p, d, ts[k]);
                if (ts[k] > t0 && ts[k] < t1 && x.y > 0 && x.y < 1)
                    isect_push(&tmp, ts[k], v3_sub(x, v3(0, L.V, 0)), 0, 0);
            }
        }
    }
    if (!o->open && d.y != 0) {
        /* the end discs */
        const double ys[2] = { 0, 1 }, rad[2] = { L.a, L.b };
        for (int k = 0; k < 2; k++) {
            double t = (ys[k] - p.y) / d.y;
            vec3 x = v3_madd(p, d, t);
            if (t > t0 && t < t1 && x.x * x.x + x.z * x.z <= rad[k] * rad[k])
                isect_push(&tmp, t, v3(0, k ? 1 : -1, 0), 0, 0);
        }
    }
    for (int i = 0; i < tmp.n; i++)
        isect_push(out, tmp.v[i].t, from_unit_normal(&L, tmp.v[i].n), 0, 0);
    isect_list_fini(&tmp);
}

bool geom_lemon_inside(const iris_object *o, vec3 p)
{
    struct lemon L;
    if (!lemon_of(o, &L))
        return false;
    vec3 q = to_unit(&L, p, true);
    if (!(q.y >= 0 && q.y <= 1))
        return false;
    double rho = sqrt(q.x * q.x + q.z * q.z);
    return (rho - L.H) * (rho - L.H) + (q.y - L.V) * (q.y - L.V) < L.r * L.r;
}

void geom_lemon_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    struct lemon L;
    if (!lemon_of(o, &L)) {
        *lo = *hi = o->u.lemon.base;
        return;
    }
    /* Widest at the arc's centre height when that lies between the
    ** ends, else at the nearer end (POV-Ray's Compute_BBox) */
    double m = L.V < 0 ? L.a : L.V > 1 ? L.b : L.r + L.H;
    m *= L.len;
    /* The box of the cylinder of radius m from base to cap */
    vec3 c = o->u.lemon.cap;
    vec3 e = v3(sqrt(fmax(0, 1 - L.w.x * L.w.x)),
                sqrt(fmax(0, 1 - L.w.y * L.w.y)),
                sqrt(fmax(0, 1 - L.w.z * L.w.z)));
    *lo = v3_min(v3_sub(L.base, v3_scale(e, m)), v3_sub(c, v3_scale(e, m)));
    *hi = v3_max(v3_add(L.base, v3_scale(e, m)), v3_add(c, v3_scale(e, m)));
}

const char *geom_lemon_check(const iris_object *o)
{
    vec3 a = o->u.lemon.base, c = o->u.lemon.cap;
    double r[3] = { o->u.lemon.base_radius, o->u.lemon.cap_radius,
                    o->u.lemon.inner_radius };
    if (!isfinite(a.x) || !isfinite(a.y) || !isfinite(a.z) ||
        !isfinite(c.x) || !isfinite(c.y) || !isfinite(c.z))
        return "lemon end is not finite";
    for (int k = 0; k < 3; k++)
        if (!isfinite(r[k]) || r[k] < 0)
            return "lemon radii must be finite and not negative";
    if (!(v3_len(v3_sub(c, a)) > 0))
        return "degenerate lemon: base and cap coincide";
    return NULL;
}
