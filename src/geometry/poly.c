/* SPDX-License-Identifier: MIT */
/*
** poly.c: quadric, cubic, quartic and poly surfaces.
**
** A poly of order n has (n+1)(n+2)(n+3)/6 coefficients in POV-Ray's term
** order: x powers from n down to 0, then y powers, then z powers, each
** descending (order 2: x², xy, xz, x, y², yz, y, z², z, 1). A quadric's
** ten are in the order of its SDL instead (see coeffs()). The surface is
** p(x,y,z) = 0 and the inside is p < 0. Along a ray the polynomial becomes
** univariate in t, solved by roots.c; the parameter is measured from the
** closest approach to the origin along a unit direction to keep the
** coefficients well scaled.
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/roots.h"

#include <math.h>

#define MAXO 15

/*
** The coefficients in poly order. A quadric keeps them as written in
** quadric { <A,B,C>, <D,E,F>, <G,H,I>, J } (x², y², z², xy, xz, yz, x, y,
** z, 1), which 'buf' reorders.
*/
static const double *coeffs(const iris_object *o, double buf[10])
{
    if (o->kind != IRIS_OBJ_QUADRIC)
        return o->u.poly.coeffs;
    const double *k = o->u.poly.coeffs;
    static const int from[10] = { 0, 3, 4, 6, 1, 5, 7, 2, 8, 9 };
    for (int i = 0; i < 10; i++)
        buf[i] = k[from[i]];
    return buf;
}

double geom_poly_eval(const iris_object *o, vec3 p)
{
    int n = o->u.poly.order, idx = 0;
    double buf[10];
    const double *c = coeffs(o, buf);
    if (n == 2) /* written out: CSG inside tests call this per crossing */
        return c[0] * p.x * p.x + c[1] * p.x * p.y + c[2] * p.x * p.z +
               c[3] * p.x + c[4] * p.y * p.y + c[5] * p.y * p.z +
               c[6] * p.y + c[7] * p.z * p.z + c[8] * p.z + c[9];
    double px[MAXO + 1], py[MAXO + 1], pz[MAXO + 1];
    px[0] = py[0] = pz[0] = 1;
    for (int i = 1; i <= n; i++) {
        px[i] = px[i - 1] * p.x;
        py[i] = py[i - 1] * p.y;
        pz[i] = pz[i - 1] * p.z;
    }
    double v = 0;
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--)
            for (int k = n - i - j; k >= 0; k--)
                v += c[idx++] * px[i] * py[j] * pz[k];
    return v;
}

/* Gradient of the polynomial at 'p' (the unnormalised normal). */
static vec3 poly_grad(const iris_object *o, vec3 p)
{
    int n = o->u.poly.order, idx = 0;
    double buf[10];
    const double *c = coeffs(o, buf);
    if (n == 2)
        return v3(2 * c[0] * p.x + c[1] * p.y + c[2] * p.z + c[3],
                  c[1] * p.x + 2 * c[4] * p.y + c[5] * p.z + c[6],
                  c[2] * p.x + c[5] * p.y + 2 * c[7] * p.z + c[8]);
    double px[MAXO + 1], py[MAXO + 1], pz[MAXO + 1];
    px[0] = py[0] = pz[0] = 1;
    for (int i = 1; i <= n; i++) {
        px[i] = px[i - 1] * p.x;
        py[i] = py[i - 1] * p.y;
        pz[i] = pz[i - 1] * p.z;
    }
    vec3 g = v3(0, 0, 0);
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--)
            for (int k = n - i - j; k >= 0; k--) {
                double a = c[idx++];
                if (i)
                    g.x += a * i * px[i - 1] * py[j] * pz[k];
                if (j)
                    g.y += a * j * px[i] * py[j - 1] * pz[k];
                if (k)
                    g.z += a * k * px[i] * py[j] * pz[k - 1];
            }
    return g;
}

/* out = a·b for polynomials in u of degrees na and nb. */
static void pmul(const double *a, int na, const double *b, int nb, double *out)
{
    for (int i = 0; i <= na + nb; i++)
        out[i] = 0;
    for (int i = 0; i <= na; i++)
        for (int j = 0; j <= nb; j++)
            out[i + j] += a[i] * b[j];
}

/*
** Order 2 (quadric, and poly of order 2): the same polynomial in u as the
** general expansion below, written out directly, and its roots by the
** numerically stable quadratic formula. It reports what
** roots_in_interval() would: exact-zero leading terms drop the degree,
** a negative discriminant has no root, a double root (discriminant
** exactly zero) is the one critical point that is a root. The general
** path costs ~20 polynomial products per ray, and quadrics (paraboloids,
** hyperboloids) are common in POV-Ray's scenes.
*/
static int quadric_roots(const double *c, vec3 p, vec3 d, double lo,
                         double hi, double u[2])
{
    /* c: x², xy, xz, x, y², yz, y, z², z, 1 */
    double a2 = c[0] * d.x * d.x + c[1] * d.x * d.y + c[2] * d.x * d.z +
                c[4] * d.y * d.y + c[5] * d.y * d.z + c[7] * d.z * d.z;
    double a1 = 2 * c[0] * p.x * d.x + c[1] * (p.x * d.y + p.y * d.x) +
                c[2] * (p.x * d.z + p.z * d.x) + c[3] * d.x +
                2 * c[4] * p.y * d.y + c[5] * (p.y * d.z + p.z * d.y) +
                c[6] * d.y + 2 * c[7] * p.z * d.z + c[8] * d.z;
    double a0 = c[0] * p.x * p.x + c[1] * p.x * p.y + c[2] * p.x * p.z +
                c[3] * p.x + c[4] * p.y * p.y + c[5] * p.y * p.z +
                c[6] * p.y + c[7] * p.z * p.z + c[8] * p.z + c[9];
    if (!isfinite(a0) || !isfinite(a1) || !isfinite(a2))
        return 0;
    double r[2];
    int m = 0;
    if (a2 == 0) {
        if (a1 == 0)
            return 0;
        r[m++] = -a0 / a1;
    } else {
        double disc = a1 * a1 - 4 * a2 * a0;
        if (disc < 0)
            return 0;
        if (disc == 0) {
            r[m++] = -a1 / (2 * a2);
        } else {
            double q = -0.5 * (a1 + copysign(sqrt(disc), a1));
            double x0 = q / a2, x1 = a0 / q;
            r[m++] = fmin(x0, x1);
            r[m++] = fmax(x0, x1);
        }
    }
    int n = 0;
    for (int i = 0; i < m; i++)
        if (r[i] > lo && r[i] < hi)
            u[n++] = r[i];
    return n;
}

void geom_poly_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out)
{
    int n = o->u.poly.order, idx = 0;
    double buf[10];
    const double *c = coeffs(o, buf);
    double dl = v3_len(rd);
    if (!(dl > 0) || n > MAXO)
        return;
    vec3 d = v3_scale(rd, 1.0 / dl);
    double s = -v3_dot(ro, d);
    vec3 p = v3_madd(ro, d, s);
    /* POV-Ray's Poly::All_Intersections drops roots closer than its
    ** DEPTH_TOLERANCE, 1e-4 along the unit object-space direction: a
    ** shadow ray leaving the surface then cannot find it again at a
    ** root the solver puts a hair away (the speckles of shapesq.inc's
    ** Sinsurf). quadric{} has its own test (1e-6), kept as t0. */
    double t_lo = o->kind == IRIS_OBJ_POLY ? fmax(t0 * dl, 1e-4) : t0 * dl;

    if (n == 2) {
        double u[2];
        int m = quadric_roots(c, p, d, t_lo - s, t1 * dl - s, u);
        for (int i = 0; i < m; i++) {
            vec3 q = v3_madd(p, d, u[i]);
            isect_push(out, (s + u[i]) / dl, poly_grad(o, q), 0, 0);
        }
        return;
    }

    /* Powers of (p_k + u·d_k) as polynomials in u */
    double X[MAXO + 1][MAXO + 1], Y[MAXO + 1][MAXO + 1], Z[MAXO + 1][MAXO + 1];
    X[0][0] = Y[0][0] = Z[0][0] = 1;
    double lx[2] = { p.x, d.x }, ly[2] = { p.y, d.y }, lz[2] = { p.z, d.z };
    for (int i = 1; i <= n; i++) {
        pmul(X[i - 1], i - 1, lx, 1, X[i]);
        pmul(Y[i - 1], i - 1, ly, 1, Y[i]);
        pmul(Z[i - 1], i - 1, lz, 1, Z[i]);
    }
    double poly[MAXO + 1] = { 0 }, xy[MAXO + 1], xyz[MAXO + 1];
    for (int i = n; i >= 0; i--)
        for (int j = n - i; j >= 0; j--) {
            /* the terms x^i y^j z^k of this (i, j) are often all zero
            ** (a torus quartic has 8 of its 35): no product for them */
            bool any = false;
            for (int k = 0; k <= n - i - j && !any; k++)
                any = c[idx + k] != 0;
            if (!any) {
                idx += n - i - j + 1;
                continue;
            }
            pmul(X[i], i, Y[j], j, xy);
            for (int k = n - i - j; k >= 0; k--) {
                double a = c[idx++];
                if (a == 0)
                    continue;
                pmul(xy, i + j, Z[k], k, xyz);
                for (int e = 0; e <= i + j + k; e++)
                    poly[e] += a * xyz[e];
            }
        }

    double lo = t_lo - s, hi = t1 * dl - s;
    double u[MAXO];
    int m = roots_in_interval(poly, n, lo, hi, u);
    for (int i = 0; i < m; i++) {
        vec3 q = v3_madd(p, d, u[i]);
        isect_push(out, (s + u[i]) / dl, poly_grad(o, q), 0, 0);
    }
}
