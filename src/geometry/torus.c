/* SPDX-License-Identifier: MIT */
/*
** torus.c: the torus about the y axis (POV-Ray's orientation).
**
** The quartic (|p|² + R² - r²)² = 4R²(x² + z²) is set up in a parameter
** measured from the ray's closest approach to the centre, along a unit
** direction: far ray origins would otherwise make the coefficients span
** many orders of magnitude and cancel (POV-Ray moves the origin for the
** same reason). Roots come from roots.c, which refines to full precision.
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/roots.h"

#include <math.h>

/*
** Whether the segment p + u d, u in [lo, hi], surely misses the torus,
** so that the quartic need not be solved (POV-Ray tests a thick cylinder
** for the same reason). Every point of the torus has |y| <= r and a
** distance from the y axis of at least R - r, R = |major|: the quartic
** factors as (rho -+ R)^2 + y^2 = r^2, rho = sqrt(x^2 + z^2). The
** segment is cut to the slab |y| <= r; as rho^2 is convex along a line,
** the cut segment lies in the hole when both its ends do. 'tol' widens
** both tests, so rays that graze the torus are still solved. The solve
** itself keeps [lo, hi], so the roots found do not change.
*/
static bool torus_missed(double R, double r, vec3 p, vec3 d, double lo,
                         double hi, double tol)
{
    double ry = r + tol;
    if (d.y != 0) {
        double a = (-ry - p.y) / d.y, b = (ry - p.y) / d.y;
        if (a > b) {
            double tmp = a;
            a = b;
            b = tmp;
        }
        lo = fmax(lo, a);
        hi = fmin(hi, b);
        if (!(lo <= hi))
            return true;
    } else if (!(fabs(p.y) <= ry)) {
        return true;
    }
    double hole = R - r - tol;
    if (!(hole > 0))
        return false;
    double xa = p.x + lo * d.x, za = p.z + lo * d.z;
    double xb = p.x + hi * d.x, zb = p.z + hi * d.z;
    return xa * xa + za * za < hole * hole && xb * xb + zb * zb < hole * hole;
}

/* geom_torus_roots() storing at most 'cap' roots, the first ones
** (roots_first_in_interval). */
static int torus_roots(double R, double r, vec3 o, vec3 d, double t0,
                       double t1, double *s_out, vec3 *p_out, double u[4],
                       int cap)
{
    /* Shift the origin to the closest approach; reject outside the
    ** bounding sphere of radius |R| + r */
    double s = -v3_dot(o, d);
    vec3 p = v3_madd(o, d, s);
    double rb = fabs(R) + r;
    double h2 = rb * rb - v3_len2(p);
    if (h2 <= 0)
        return 0;
    /* Widen by 1e-9 so that roots on the sphere itself (a ray through the
    ** equator meets the outer rim exactly at distance R + r) stay inside
    ** the open interval the solver searches */
    double h = sqrt(h2) + 1e-9 * rb;
    double lo = fmax(-h, t0 - s), hi = fmin(h, t1 - s);
    if (!(lo < hi))
        return 0;
    if (torus_missed(fabs(R), r, p, d, lo, hi, 1e-6 * rb))
        return 0;

    double beta = 2 * v3_dot(p, d);
    double gamma = v3_len2(p) + R * R - r * r;
    double c[5];
    c[4] = 1;
    c[3] = 2 * beta;
    c[2] = beta * beta + 2 * gamma - 4 * R * R * (d.x * d.x + d.z * d.z);
    c[1] = 2 * beta * gamma - 8 * R * R * (p.x * d.x + p.z * d.z);
    c[0] = gamma * gamma - 4 * R * R * (p.x * p.x + p.z * p.z);
    *s_out = s;
    *p_out = p;
    return roots_first_in_interval(c, 4, lo, hi, u, cap);
}

int geom_torus_roots(double R, double r, vec3 o, vec3 d, double t0,
                     double t1, double *s_out, vec3 *p_out, double u[4])
{
    return torus_roots(R, r, o, d, t0, t1, s_out, p_out, u, 4);
}

/*
** The crossing at root u of the torus with the unit ray p + u·d (p the
** closest approach, at s along the ray of length dl): its t, and the
** point q and its distance rxz from the axis, from which come the normal
** and the uv.
*/
static void torus_cross(double R, vec3 p, vec3 d, double s, double dl,
                        double u, struct geom_torus_cross *c)
{
    vec3 q = v3_madd(p, d, u);
    double rxz = sqrt(q.x * q.x + q.z * q.z);
    /* Outward normal: from the nearest point of the core circle */
    c->n = rxz > 0 ? v3(q.x - R * q.x / rxz, q.y, q.z - R * q.z / rxz)
                   : v3(0, q.y, 0);
    c->t = (s + u) / dl;
    c->q = q;
    c->rxz = rxz;
    c->R = R;
}

iris_vec2 geom_torus_uv(const struct geom_torus_cross *c)
{
    double uu = atan2(c->q.z, c->q.x) / (2 * M_PI);
    double vv = atan2(c->q.y, c->rxz - c->R) / (2 * M_PI);
    uu = uu < 0 ? uu + 1 : uu;
    vv = vv < 0 ? vv + 1 : vv;
    /* isect_push()'s rule for a uv that is not finite */
    iris_vec2 uv = { isfinite(uu) ? uu : 0, isfinite(vv) ? vv : 0 };
    return uv;
}

int geom_torus_first(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct geom_torus_cross *c)
{
    double R = o->u.torus.major, r = o->u.torus.minor;
    double dl = v3_len(rd);
    if (!(dl > 0))
        return 0;
    vec3 d = v3_scale(rd, 1.0 / dl);
    double s, u[4];
    vec3 p;
    if (torus_roots(R, r, ro, d, t0 * dl, t1 * dl, &s, &p, u, 1) == 0)
        return 0;
    torus_cross(R, p, d, s, dl, u[0], c);
    /* isect_push() would drop this crossing: the caller must see the
    ** others */
    if (!isfinite(c->t) || !isfinite(c->n.x) || !isfinite(c->n.y) ||
        !isfinite(c->n.z) || (c->n.x == 0 && c->n.y == 0 && c->n.z == 0))
        return -1;
    return 1;
}

void geom_torus_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out)
{
    double R = o->u.torus.major, r = o->u.torus.minor;
    double dl = v3_len(rd);
    if (!(dl > 0))
        return;
    vec3 d = v3_scale(rd, 1.0 / dl);
    double s, u[4];
    vec3 p;
    int n = geom_torus_roots(R, r, ro, d, t0 * dl, t1 * dl, &s, &p, u);
    for (int i = 0; i < n; i++) {
        struct geom_torus_cross c;
        torus_cross(R, p, d, s, dl, u[i], &c);
        iris_vec2 uv = geom_torus_uv(&c);
        isect_push(out, c.t, c.n, uv.u, uv.v);
    }
}
