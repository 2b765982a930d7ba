/* SPDX-License-Identifier: MIT */
/*
** ovus.c: POV-Ray 3.7's egg shape, ovus { bottom_radius, top_radius }.
**
** As POV-Ray 3.7.0 defines it (parse.cpp Parse_Ovus, ovus.cpp): a bottom
** sphere of radius Rb at the origin, a top sphere of radius Rt centred at
** the bottom sphere's zenith (0, Rb, 0), and between them the inner
** ("lemon") part of a spindle torus about the y axis whose tube circle, in
** the (rho, y) half-plane, has radius C (twice the larger radius) and
** centre (-H, V) on the far side of the axis. That circle is internally
** tangent to both sphere outlines; the tangent heights yb < yt split the
** surface into bottom sphere (y < yb), connection (yb < y < yt) and top
** sphere (y > yt). When Rt >= 2·Rb no such circle exists and POV-Ray
** substitutes the sphere of radius Rt at (0, Rb, 0); so do we.
**
** The connection is solved as the full torus quartic (roots.c, shifted to
** the ray's closest approach like torus.c) by geom_spindle_hits(), which
** lemon.c shares; a root belongs to the lemon part, not the outer
** "apple", when |p|² + H² - C² <= 0 (the squared torus equation merges
** (rho - H)² and (rho + H)²; the sign tells them apart exactly, where
** POV-Ray tests a residual against a tolerance).
** The solid (for CSG) is the union of both balls and the connection
** region, POV-Ray's Inside().
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/roots.h"

#include <math.h>

/* The derived dimensions of an ovus (POV-Ray's names in comments). */
struct ovus_dims {
    double rb, rt;        /* BottomRadius, TopRadius */
    double c;             /* ConnectingRadius */
    double h, v;          /* HorizontalPosition, VerticalPosition */
    double yb, yt;        /* BottomVertical, TopVertical */
    bool sphere;          /* Rt >= 2·Rb: the top sphere alone */
};

static struct ovus_dims ovus_dims(const iris_object *o)
{
    struct ovus_dims d = { 0 };
    double rb = o->u.ovus.r1, rt = o->u.ovus.r2;
    d.rb = rb;
    d.rt = rt;
    if (!(rt < 2 * rb)) {
        d.sphere = true;
        return d;
    }
    if (rb > rt) {
        d.c = 2 * rb;
        d.v = 2 * rt - rb - rt * rt / (2 * rb);
        d.h = sqrt(fmax(0, rb * rb - d.v * d.v));
        d.yb = -d.v;
        d.yt = (rb - d.v) * rt / (d.c - rt) + rb;
    } else {
        d.c = 2 * rt;
        d.v = -2 * rt + rb + 1.5 * rt * rt / rb;
        d.h = sqrt(fmax(0, rt * rt - (d.v - rb) * (d.v - rb)));
        d.yt = 2 * rb - d.v;
        d.yb = -d.v * rb / (d.c - rb);
    }
    return d;
}

const char *geom_ovus_check(const iris_object *o)
{
    double rb = o->u.ovus.r1, rt = o->u.ovus.r2;
    /* POV-Ray rejects negative radii; a zero bottom radius would divide
    ** by zero in its own formulas, and a zero top radius is no egg */
    if (!(rb > 0) || !(rt > 0) || !isfinite(rb) || !isfinite(rt))
        return "ovus radii must be positive";
    return NULL;
}

/* POV-Ray's ovus uv: a sphere mapping about (0, Rt/2, 0). */
static void ovus_uv(const struct ovus_dims *d, vec3 p, double *u, double *v)
{
    vec3 q = v3(p.x, p.y - d->rt / 2, p.z);
    double len = v3_len(q);
    *u = *v = 0;
    if (!(len > 0))
        return;
    q = v3_scale(q, 1 / len);
    *v = 0.5 + asin(fmax(-1, fmin(1, q.y))) / M_PI;
    double th = atan2(q.z, q.x);
    *u = (th < 0 ? th + 2 * M_PI : th) / (2 * M_PI);
}

static void push(struct isect_list *out, const struct ovus_dims *d, vec3 ro,
                 vec3 rd, double t, vec3 n)
{
    double u, v;
    ovus_uv(d, v3_madd(ro, rd, t), &u, &v);
    isect_push(out, t, n, u, v);
}

/*
** Ray hits with the sphere (centre c, radius r) in (t0, t1) whose point
** satisfies sign·(y - ycut) > 0; measured at the closest approach for
** precision (as quadrics.c does).
*/
static void sphere_part(const struct ovus_dims *d, vec3 c, double r,
                        double ycut, double sign, vec3 ro, vec3 rd,
                        double t0, double t1, struct isect_list *out)
{
    double a = v3_len2(rd);
    vec3 oc = v3_sub(ro, c);
    double tc = -v3_dot(oc, rd) / a;
    vec3 pc = v3_madd(oc, rd, tc);
    double h2 = (r * r - v3_len2(pc)) / a;
    if (!(h2 > 0))
        return;
    double h = sqrt(h2);
    for (int k = 0; k < 2; k++) {
        double t = k ? tc + h : tc - h;
        if (!(t > t0 && t < t1))
            continue;
        vec3 p = v3_madd(ro, rd, t);
        if (ycut == INFINITY || sign * (p.y - ycut) > 0)
            push(out, d, ro, rd, t, v3_sub(p, c));
    }
}

/*
** The part of ray ro + t·rd, t in (*t0, *t1), that can meet the part of
** the spindle that geom_spindle_hits() reports: the points with
** ylo < y < yhi on the inner surface, whose distance from the axis is
** rho = sqrt(C² - (y - yc)²) - H <= C - H. The ray is cut to that slab
** and to the cylinder rho <= C - H; 'tol' widens both, so that a root
** the solver would find and keep is never cut off by rounding. False
** when nothing is left: most rays through an ovus's box miss the
** connection's slab or cylinder. Solving the quartic on the cut span
** only also drops most roots on the outer "apple" part (which the
** caller would drop), and with them most of the solver's work.
*/
static bool spindle_span(double H, double C, double ylo, double yhi,
                         vec3 ro, vec3 rd, double *t0, double *t1,
                         double tol)
{
    double a = *t0, b = *t1;
    if (rd.y != 0) {
        double ta = (ylo - tol - ro.y) / rd.y, tb = (yhi + tol - ro.y) / rd.y;
        if (ta > tb) {
            double tmp = ta;
            ta = tb;
            tb = tmp;
        }
        if (ta > a)
            a = ta;
        if (tb < b)
            b = tb;
        if (!(a <= b))
            return false;
    } else if (!(ro.y >= ylo - tol && ro.y <= yhi + tol)) {
        return false;
    }
    if (!(C > H) || !isfinite(a) || !isfinite(b)) {
        *t0 = a;
        *t1 = b;
        return true;
    }
    /* rho² along the ray: dd t² + 2 e t + f, convex */
    double dd = rd.x * rd.x + rd.z * rd.z;
    double e = ro.x * rd.x + ro.z * rd.z;
    double f = ro.x * ro.x + ro.z * ro.z;
    double rmax = C - H + tol;
    if (!(dd > 0)) {
        if (!(f <= rmax * rmax))
            return false;
    } else {
        double disc = e * e - dd * (f - rmax * rmax);
        if (!(disc >= 0))
            return false;
        /* the stable pair of roots, then widened by 'tol' along the ray */
        double q = -(e + copysign(sqrt(disc), e));
        double ca = q / dd, cb = q != 0 ? (f - rmax * rmax) / q : ca;
        if (ca > cb) {
            double tmp = ca;
            ca = cb;
            cb = tmp;
        }
        double pad = tol / sqrt(dd);
        if (ca - pad > a)
            a = ca - pad;
        if (cb + pad < b)
            b = cb + pad;
        if (!(a <= b))
            return false;
    }
    *t0 = a;
    *t1 = b;
    return true;
}

void geom_spindle_hits(double H, double C, double yc, double ylo,
                       double yhi, vec3 ro, vec3 rd, double t0, double t1,
                       struct isect_list *out)
{
    double dl = v3_len(rd);
    if (!(dl > 0))
        return;
    /* 1e-7 of the size: far beyond the rounding of the roots' points */
    if (!spindle_span(H, C, ylo, yhi, ro, rd, &t0, &t1, 1e-7 * (C + H)))
        return;
    vec3 dir = v3_scale(rd, 1 / dl);
    vec3 o = v3_sub(ro, v3(0, yc, 0));
    double R = H, r = C;
    /* the spindle is the inner part of the torus quartic whose major
    ** radius H is below its minor radius C (a spindle torus) */
    double s, w[4];
    vec3 p;
    int n = geom_torus_roots(R, r, o, dir, t0 * dl, t1 * dl, &s, &p, w);
    for (int i = 0; i < n; i++) {
        vec3 q = v3_madd(p, dir, w[i]);
        double y = q.y + yc;
        if (!(y > ylo && y < yhi))
            continue;
        /* (rho + H)² + y² = C² has |q|² + H² - C² = -2·H·rho <= 0 */
        if (v3_len2(q) + R * R - r * r > 0)
            continue;
        double rho = sqrt(q.x * q.x + q.z * q.z);
        /* Outward normal: from the tube circle's centre, which lies on
        ** the far side of the axis at distance H */
        vec3 nn = rho > 0 ? v3(q.x + R * q.x / rho, q.y, q.z + R * q.z / rho)
                          : v3(0, q.y, 0);
        isect_push(out, (s + w[i]) / dl, nn, 0, 0);
    }
}

void geom_ovus_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out)
{
    if (!(v3_len2(rd) > 0))
        return;
    struct ovus_dims d = ovus_dims(o);
    if (d.sphere) {
        sphere_part(&d, v3(0, d.rb, 0), d.rt, INFINITY, 1, ro, rd, t0, t1,
                    out);
        return;
    }
    sphere_part(&d, v3(0, 0, 0), d.rb, d.yb, -1, ro, rd, t0, t1, out);
    sphere_part(&d, v3(0, d.rb, 0), d.rt, d.yt, 1, ro, rd, t0, t1, out);
    int first = out->n;
    geom_spindle_hits(d.h, d.c, d.v, d.yb, d.yt, ro, rd, t0, t1, out);
    for (int i = first; i < out->n; i++)
        ovus_uv(&d, v3_madd(ro, rd, out->v[i].t), &out->v[i].uv.u,
                &out->v[i].uv.v);
}

bool geom_ovus_inside(const iris_object *o, vec3 p)
{
    struct ovus_dims d = ovus_dims(o);
    vec3 top = v3_sub(p, v3(0, d.rb, 0));
    if (v3_len2(top) < d.rt * d.rt)
        return true;
    if (d.sphere)
        return false;
    if (v3_len2(p) < d.rb * d.rb)
        return true;
    if (p.y > d.yb && p.y < d.yt) {
        double rho = sqrt(p.x * p.x + p.z * p.z);
        double dy = p.y - d.v;
        return (rho + d.h) * (rho + d.h) + dy * dy < d.c * d.c;
    }
    return false;
}

void geom_ovus_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    struct ovus_dims d = ovus_dims(o);
    if (d.sphere) {
        *lo = v3(-d.rt, d.rb - d.rt, -d.rt);
        *hi = v3(d.rt, d.rb + d.rt, d.rt);
        return;
    }
    /* POV-Ray's box: the widest of the connection's equator (C - H, when
    ** its centre height V lies in the band) and the two radii */
    double w = fmax(d.c - d.h, fmax(d.rb, d.rt));
    *lo = v3(-w, -d.rb, -w);
    *hi = v3(w, d.rb + d.rt, w);
}
