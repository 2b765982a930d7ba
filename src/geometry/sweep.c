/* SPDX-License-Identifier: MIT */
/*
** sweep.c: surfaces made from a 2-D profile: revolved about the y axis
** (lathe, sor) or extruded along an axis (prism along y, text along z).
**
** The profile is made of straight segments (profile.c), so every piece is
** a cone, cylinder, annulus or plane strip with a closed-form crossing.
** Normals use the spline tangents kept by profile.c, interpolated along
** the segment, so flattened curves still shade smoothly. Inside tests use
** the even-odd rule on the profile, as POV-Ray's Inside() for these
** shapes does.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>

/* Outward 2-D normal of segment 'i' at parameter 's' in [0,1]. */
static iris_vec2 seg_normal(const struct geom_profile *p, int i, double s)
{
    iris_vec2 t = { p->ta[i].u + s * (p->tb[i].u - p->ta[i].u),
                    p->ta[i].v + s * (p->tb[i].v - p->ta[i].v) };
    if (t.u == 0 && t.v == 0) {
        t.u = p->b[i].u - p->a[i].u;
        t.v = p->b[i].v - p->a[i].v;
    }
    iris_vec2 n = { p->side[i] * t.v, -p->side[i] * t.u };
    return n;
}

void geom_lathe_hits(const struct geom_profile *p, vec3 ro, vec3 rd,
                     double t0, double t1, struct isect_list *out)
{
    /* Work from the closest approach to the origin along a unit direction
    ** (coefficients stay well scaled for far-away ray origins) */
    double dl = v3_len(rd);
    if (!(dl > 0))
        return;
    vec3 d = v3_scale(rd, 1.0 / dl);
    double sh = -v3_dot(ro, d);
    vec3 o = v3_madd(ro, d, sh);
    double lo = t0 * dl - sh, hi = t1 * dl - sh;

    /*
    ** Every crossing lies within the cylinder of the profile's largest
    ** radius R, where the ray spans heights [ylo, yhi]: a segment wholly
    ** above or below cannot be met. The cylinder is grown by 1e-7 of R
    ** (a crossing's radius is rounded by ~1e-16 of it; near a grazing
    ** ray the span's ends move fast with the radius) and the band padded
    ** by 1e-9 of the scale, so only segments that give no crossing are
    ** skipped.
    */
    double R = fmax(fabs(p->lo.u), fabs(p->hi.u)) * (1 + 1e-7);
    double ylo = -INFINITY, yhi = INFINITY;
    double hd2 = d.x * d.x + d.z * d.z;
    if (hd2 > 0) {
        double tc = -(o.x * d.x + o.z * d.z) / hd2;
        double cx = o.x + tc * d.x, cz = o.z + tc * d.z;
        double h2 = (R * R - (cx * cx + cz * cz)) / hd2;
        if (h2 >= 0) {
            double h = sqrt(h2);
            double ya = o.y + (tc - h) * d.y, yb = o.y + (tc + h) * d.y;
            double pad = 1e-9 * (R + fabs(ya) + fabs(yb) + fabs(p->lo.v) +
                                 fabs(p->hi.v)) + 1e-300;
            ylo = fmin(ya, yb) - pad;
            yhi = fmax(ya, yb) + pad;
        }
        /* h2 < 0 by rounding alone is possible at a grazing ray: no band */
    }

    for (int i = 0; i < p->n_seg; i++) {
        double r0 = p->a[i].u, y0 = p->a[i].v, r1 = p->b[i].u, y1 = p->b[i].v;
        if (fmax(y0, y1) < ylo || fmin(y0, y1) > yhi)
            continue;
        double ts[2];
        int nt = 0;
        if (y0 == y1) {
            /* An annulus in the plane y = y0 */
            if (d.y == 0)
                continue;
            double t = (y0 - o.y) / d.y;
            double x = o.x + t * d.x, z = o.z + t * d.z;
            double rho = sqrt(x * x + z * z);
            if (rho >= fmin(fabs(r0), fabs(r1)) &&
                rho <= fmax(fabs(r0), fabs(r1)))
                ts[nt++] = t;
        } else {
            /* x² + z² = (A0 + k·y)² between y0 and y1 */
            double k = (r1 - r0) / (y1 - y0), A0 = r0 - k * y0;
            double ry = A0 + k * o.y;
            double qa = d.x * d.x + d.z * d.z - k * k * d.y * d.y;
            double qb = 2 * (o.x * d.x + o.z * d.z - ry * k * d.y);
            double qc = o.x * o.x + o.z * o.z - ry * ry;
            if (fabs(qa) <= 1e-14 * (d.x * d.x + d.z * d.z + k * k * d.y * d.y)) {
                if (qb != 0)
                    ts[nt++] = -qc / qb;
            } else {
                double disc = qb * qb - 4 * qa * qc;
                if (disc >= 0) {
                    double q = -0.5 * (qb + copysign(sqrt(disc), qb));
                    ts[nt++] = q / qa;
                    if (q != 0)
                        ts[nt++] = qc / q;
                }
            }
            /* keep the nappe where the signed radius matches the profile */
            for (int j = 0; j < nt; j++) {
                double y = o.y + ts[j] * d.y;
                double r = A0 + k * y;
                double s = (y - y0) / (y1 - y0);
                /* Half-open, so a crossing at a shared end counts once */
                if (s < 0 || s >= 1 || (r0 >= 0 && r1 >= 0 && r < 0))
                    ts[j] = NAN;
            }
        }
        for (int j = 0; j < nt; j++) {
            double t = ts[j];
            if (!(t > lo && t < hi))
                continue;
            vec3 q = v3_madd(o, d, t);
            double rho = sqrt(q.x * q.x + q.z * q.z);
            double s = y0 == y1 ? (r1 != r0 ? (rho - r0) / (r1 - r0) : 0)
                                : (q.y - y0) / (y1 - y0);
            iris_vec2 n2 = seg_normal(p, i, fmax(0, fmin(1, s)));
            vec3 n = rho > 0 ? v3(n2.u * q.x / rho, n2.v, n2.u * q.z / rho)
                             : v3(0, n2.v != 0 ? n2.v : 1, 0);
            double u = atan2(q.z, q.x) / (2 * M_PI);
            isect_push(out, (t + sh) / dl, n, u < 0 ? u + 1 : u,
                       (i + s) / p->n_seg);
        }
    }
}

bool geom_lathe_inside(const struct geom_profile *p, vec3 q)
{
    return geom_profile_inside2d(p, sqrt(q.x * q.x + q.z * q.z), q.y);
}

void geom_lathe_bounds(const struct geom_profile *p, vec3 *lo, vec3 *hi)
{
    double R = fmax(fabs(p->lo.u), fabs(p->hi.u));
    *lo = v3(-R, p->lo.v, -R);
    *hi = v3(R, p->hi.v, R);
}

/* 2-D coordinates (u, v) and height of 'q' for extrusion 'axis'. */
static void split(vec3 q, int axis, double *u, double *v, double *h)
{
    *u = q.x;
    *v = axis == 1 ? q.z : q.y;
    *h = axis == 1 ? q.y : q.z;
}

/* 3-D vector from 2-D (u, v) and height component 'h'. */
static vec3 join(double u, double v, double h, int axis)
{
    return axis == 1 ? v3(u, h, v) : v3(u, v, h);
}

bool geom_extrude_inside(const struct geom_profile *p, int axis, vec3 q)
{
    double u, v, h;
    split(q, axis, &u, &v, &h);
    if (!(h > p->h1 && h < p->h2))
        return false;
    if (p->conic) {
        if (!(h > 0))
            return false;
        return geom_profile_inside2d(p, u / h, v / h);
    }
    return geom_profile_inside2d(p, u, v);
}

void geom_extrude_bounds(const struct geom_profile *p, int axis, vec3 *lo,
                         vec3 *hi)
{
    double ulo = p->lo.u, uhi = p->hi.u, vlo = p->lo.v, vhi = p->hi.v;
    if (p->conic) {
        /* The outline scales with the height: extremes at h1 or h2 */
        double a[4] = { ulo * p->h1, ulo * p->h2, uhi * p->h1, uhi * p->h2 };
        double b[4] = { vlo * p->h1, vlo * p->h2, vhi * p->h1, vhi * p->h2 };
        ulo = fmin(fmin(a[0], a[1]), fmin(a[2], a[3]));
        uhi = fmax(fmax(a[0], a[1]), fmax(a[2], a[3]));
        vlo = fmin(fmin(b[0], b[1]), fmin(b[2], b[3]));
        vhi = fmax(fmax(b[0], b[1]), fmax(b[2], b[3]));
    }
    *lo = join(ulo, vlo, p->h1, axis);
    *hi = join(uhi, vhi, p->h2, axis);
}

/* The caps at h1 and h2. */
static void cap_hits(const struct geom_profile *p, int axis, vec3 ro,
                     vec3 rd, double t0, double t1, struct isect_list *out)
{
    double ou, ov, oh, du, dv, dh;
    split(ro, axis, &ou, &ov, &oh);
    split(rd, axis, &du, &dv, &dh);
    if (dh == 0)
        return;
    for (int k = 0; k < 2; k++) {
        double h = k ? p->h2 : p->h1;
        double t = (h - oh) / dh;
        if (!(t > t0 && t < t1))
            continue;
        double u = ou + t * du, v = ov + t * dv;
        if (p->conic) {
            if (!(h > 0))
                continue;
            u /= h;
            v /= h;
        }
        if (geom_profile_inside2d(p, u, v))
            isect_push(out, t, join(0, 0, k ? 1 : -1, axis), 0, 0);
    }
}

void geom_extrude_hits(const struct geom_profile *p, int axis, vec3 ro,
                       vec3 rd, double t0, double t1, struct isect_list *out)
{
    double ou, ov, oh, du, dv, dh;
    split(ro, axis, &ou, &ov, &oh);
    split(rd, axis, &du, &dv, &dh);

    /* The part of the ray between the two heights */
    double ta = t0, tb = t1;
    if (dh == 0) {
        if (!(oh > p->h1 && oh < p->h2))
            return;
    } else {
        double x = (p->h1 - oh) / dh, y = (p->h2 - oh) / dh;
        ta = fmax(ta, fmin(x, y));
        tb = fmin(tb, fmax(x, y));
        if (!(ta <= tb))
            return;
    }
    if (!p->open)
        cap_hits(p, axis, ro, rd, t0, t1, out);

    for (int g = 0; g < p->n_groups; g++) {
        int f = p->group_first[g], end = f + p->group_count[g];
        if (!p->conic) {
            /* Skip groups whose 2-D box the ray's shadow misses */
            double a = ta, b = tb;
            vec3 blo = v3(p->group_lo[g].u, p->group_lo[g].v, 0);
            vec3 bhi = v3(p->group_hi[g].u, p->group_hi[g].v, 0);
            if (!geom_clip_box(blo, bhi, v3(ou, ov, 0), v3(du, dv, 0), &a, &b))
                continue;
        }
        for (int i = f; i < end; i++) {
            iris_vec2 A = p->a[i], B = p->b[i];
            double eu = B.u - A.u, ev = B.v - A.v;
            double t, s;
            if (!p->conic) {
                double den = du * ev - dv * eu;
                if (den == 0)
                    continue;
                t = -((ou - A.u) * ev - (ov - A.v) * eu) / den;
                double pu = ou + t * du - A.u, pv = ov + t * dv - A.v;
                s = (pu * eu + pv * ev) / (eu * eu + ev * ev);
            } else {
                /* The plane through the apex and the segment at h = 1 */
                vec3 a3 = join(A.u, A.v, 1, axis), b3 = join(B.u, B.v, 1, axis);
                vec3 N = v3_cross(a3, b3);
                double den = v3_dot(N, rd);
                if (den == 0)
                    continue;
                t = -v3_dot(N, ro) / den;
                double h = oh + t * dh;
                if (!(h > 0))
                    continue;
                double pu = (ou + t * du) / h - A.u, pv = (ov + t * dv) / h - A.v;
                s = (pu * eu + pv * ev) / (eu * eu + ev * ev);
            }
            /* Half-open, so a crossing at a shared corner counts once */
            if (!(t > ta && t < tb) || s < 0 || s >= 1)
                continue;
            iris_vec2 n2 = seg_normal(p, i, s);
            vec3 n = join(n2.u, n2.v, 0, axis);
            if (p->conic) {
                vec3 a3 = join(A.u, A.v, 1, axis), b3 = join(B.u, B.v, 1, axis);
                vec3 N = v3_cross(a3, b3);
                /* Smooth tangent direction is lost on the cone: use the
                ** plane, turned to the outward side */
                n = v3_dot(N, n) < 0 ? v3_neg(N) : N;
            }
            isect_push(out, t, n, s, 0);
        }
    }
}
