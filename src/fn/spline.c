/* SPDX-License-Identifier: MIT */
/*
** spline.c: SDL splines (spline { ... }) for function calls S(t), spline
** functions and the parser, with POV-Ray 3.7's definitions (splines.cpp):
**
**   linear     straight lines between keys;
**   quadratic  the parabola through three keys: the segment's two and the
**              one before (the first segment uses keys 0, 1, 2);
**   cubic      Catmull-Rom (tangents are the mean of the neighbouring
**              slopes, times the segment length), defined only between
**              the second and the next-to-last keys: outside that range
**              the value is the nearest of those two keys; two keys give
**              their mean;
**   natural    the natural cubic spline (zero second derivative at the
**              ends) through all keys.
**
** Outside the keys every type but cubic returns the end key; too few keys
** lower the order (quadratic with two keys is linear). Degenerate keys
** (equal t) cannot occur: the parser keeps one entry per t, as POV-Ray.
*/
#include "config.h"

#include <stdbool.h>
#include <string.h>

#include "iris/fn.h"
#include "util/mem.h"

bool iris_fn_spline_coeffs(const iris_fn_spline *s, double (*out)[5])
{
    int n = s->n;
    if (n <= 0)
        return true;
    memset(out, 0, (size_t)n * sizeof *out);
    if (n < 3)
        return true;
    double *u = iris_malloc((size_t)n * 2 * sizeof *u);
    if (!u)
        return false;
    double *v = u + n;
    /* Tridiagonal solve for the second derivatives m[1..n-2] with
    ** m[0] = m[n-1] = 0; u, v are the eliminated diagonal and right side. */
    for (int k = 0; k < 5; k++) {
        double u_prev = 0, v_prev = 0;
        for (int i = 1; i <= n - 2; i++) {
            double h0 = s->t[i] - s->t[i - 1], h1 = s->t[i + 1] - s->t[i];
            double b0 = (s->p[i][k] - s->p[i - 1][k]) / h0;
            double b1 = (s->p[i + 1][k] - s->p[i][k]) / h1;
            if (i == 1) {
                u[i] = 2 * (h0 + h1);
                v[i] = 6 * (b1 - b0);
            } else {
                u[i] = 2 * (h1 + h0) - h0 * h0 / u_prev;
                v[i] = 6 * (b1 - b0) - h0 * v_prev / u_prev;
            }
            u_prev = u[i];
            v_prev = v[i];
        }
        for (int i = n - 2; i > 0; i--) {
            double h = s->t[i + 1] - s->t[i];
            out[i][k] = (v[i] - h * out[i + 1][k]) / u[i];
        }
    }
    iris_free(u);
    return true;
}

/* The index of the first key whose t is >= 'x' (0 below the first key,
** n at or above the last), as POV-Ray's findt. */
static int find_key(const iris_fn_spline *s, double x)
{
    if (x <= s->t[0])
        return 0;
    if (x >= s->t[s->n - 1])
        return s->n;
    int lo = 0, hi = s->n - 1; /* t[lo] < x <= t[hi] */
    while (hi - lo > 1) {
        int mid = lo + (hi - lo) / 2;
        if (x > s->t[mid])
            lo = mid;
        else
            hi = mid;
    }
    return hi;
}

static double linear(const iris_fn_spline *s, int i, int k, double x)
{
    double t1 = s->t[i], t2 = s->t[i + 1];
    double v1 = s->p[i][k], v2 = s->p[i + 1][k];
    return (x - t1) * (v2 - v1) / (t2 - t1) + v1;
}

/* The parabola through keys i-1, i, i+1 at x (Lagrange form). */
static double quadratic(const iris_fn_spline *s, int i, int k, double x)
{
    double t1 = s->t[i - 1], t2 = s->t[i], t3 = s->t[i + 1];
    double v1 = s->p[i - 1][k], v2 = s->p[i][k], v3 = s->p[i + 1][k];
    return v1 * (x - t2) * (x - t3) / ((t1 - t2) * (t1 - t3)) +
           v2 * (x - t1) * (x - t3) / ((t2 - t1) * (t2 - t3)) +
           v3 * (x - t1) * (x - t2) / ((t3 - t1) * (t3 - t2));
}

static double natural(const iris_fn_spline *s, int i, int k, double x)
{
    double h = s->t[i + 1] - s->t[i], d = x - s->t[i];
    double c0 = s->coeff ? s->coeff[i][k] : 0;
    double c1 = s->coeff ? s->coeff[i + 1][k] : 0;
    double q = c0 / 2 + d * (c1 - c0) / (6 * h);
    q = -(h / 6) * (c1 + 2 * c0) + (s->p[i + 1][k] - s->p[i][k]) / h + d * q;
    return s->p[i][k] + d * q;
}

/* Catmull-Rom on the segment [i, i+1] (keys i-1 and i+2 exist). */
static double catmull_rom(const iris_fn_spline *s, int i, int k, double x)
{
    double dt = s->t[i + 1] - s->t[i];
    double u = (x - s->t[i]) / dt;
    double s0 = (s->p[i][k] - s->p[i - 1][k]) / (s->t[i] - s->t[i - 1]);
    double s1 = (s->p[i + 1][k] - s->p[i][k]) / dt;
    double s2 = (s->p[i + 2][k] - s->p[i + 1][k]) /
                (s->t[i + 2] - s->t[i + 1]);
    double d0 = (s0 + s1) / 2 * dt, d1 = (s2 + s1) / 2 * dt;
    double u2 = u * u, u3 = u2 * u;
    return s->p[i][k] * (2 * u3 - 3 * u2 + 1) +
           s->p[i + 1][k] * (3 * u2 - 2 * u3) + d0 * (u3 - 2 * u2 + u) +
           d1 * (u3 - u2);
}

void iris_fn_spline_eval(const iris_fn_spline *s, double x, double out[5])
{
    memset(out, 0, 5 * sizeof *out);
    if (!s || s->n <= 0)
        return;
    int n = s->n;
    if (n == 1 || x != x) {
        memcpy(out, s->p[0], 5 * sizeof *out);
        return;
    }
    int i = find_key(s, x);
    for (int k = 0; k < 5; k++) {
        if (s->type == IRIS_FN_SPLINE_CUBIC) {
            if (n == 2)
                out[k] = (s->p[0][k] + s->p[1][k]) / 2;
            else if (i < 2)
                out[k] = s->p[1][k];
            else if (i >= n - 1)
                out[k] = s->p[n - 2][k];
            else
                out[k] = catmull_rom(s, i - 1, k, x);
            continue;
        }
        if (i == 0)
            out[k] = s->p[0][k];
        else if (i >= n)
            out[k] = s->p[n - 1][k];
        else if (s->type == IRIS_FN_SPLINE_QUADRATIC && n > 2)
            out[k] = quadratic(s, i > 1 ? i - 1 : 1, k, x);
        else if (s->type == IRIS_FN_SPLINE_NATURAL)
            out[k] = natural(s, i - 1, k, x);
        else
            out[k] = linear(s, i - 1, k, x);
    }
}
