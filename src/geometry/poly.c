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

    double lo = t0 * dl - s, hi = t1 * dl - s;
    double u[MAXO];
    int m = roots_in_interval(poly, n, lo, hi, u);
    for (int i = 0; i < m; i++) {
        vec3 q = v3_madd(p, d, u[i]);
        isect_push(out, (s + u[i]) / dl, poly_grad(o, q), 0, 0);
    }
}
