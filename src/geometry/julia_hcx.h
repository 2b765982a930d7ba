/* SPDX-License-Identifier: MIT */
/*
** julia_hcx.h: the hypercomplex algebra of POV-Ray's julia_fractal.
*/
#ifndef IRIS_GEOMETRY_JULIA_HCX_H
#define IRIS_GEOMETRY_JULIA_HCX_H

#include <stdbool.h>

/* r = a b in the (commutative) hypercomplex algebra; r may alias a or b.
** Inline (as hcx_normal below): a julia_fractal ray calls them millions
** of times, and the call cost as much as the products (92's profile). */
static inline void hcx_mul(const double a[4], const double b[4], double r[4])
{
    /* i² = j² = -1, k² = +1, ij = k, ik = -j, jk = -i */
    double t[4] = {
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] + a[3] * b[3],
        a[1] * b[0] + a[0] * b[1] - a[3] * b[2] - a[2] * b[3],
        a[2] * b[0] - a[3] * b[1] + a[0] * b[2] - a[1] * b[3],
        a[3] * b[0] + a[2] * b[1] + a[1] * b[2] + a[0] * b[3]
    };
    for (int k = 0; k < 4; k++)
        r[k] = t[k];
}

/*
** r = f(q) for the julia_fractal function 'fn' (enum iris_julia_fn);
** 'e' is pwr's exponent. sqr and cube both square: POV-Ray 3.7's
** hypercomplex cube iterates q² (hcmplx.cpp), and iris renders what
** POV-Ray renders.
*/
void hcx_map(int fn, const double e[2], const double q[4], double r[4]);

/*
** The factor POV-Ray multiplies into its normal's derivative product per
** iterate: q for sqr and cube, -(1/q)² for reciprocal, f(q) itself for
** the other functions (POV-Ray's approximation, not f'(q)).
*/
void hcx_normal_factor(int fn, const double e[2], const double q[4],
                       double r[4]);

/*
** The 3-D normal from the derivative product 'dp' and the last iterate
** 'n' (already scaled): the gradient of n·(dp x) over x, y, z.
*/
static inline void hcx_normal(const double dp[4], const double n[4],
                              double out[3])
{
    /* n · (dp e) for e = 1, i, j: the x, y, z partials of n·(dp p) */
    out[0] = dp[0] * n[0] + dp[1] * n[1] + dp[2] * n[2] + dp[3] * n[3];
    out[1] = -dp[1] * n[0] + dp[0] * n[1] - dp[3] * n[2] + dp[2] * n[3];
    out[2] = -dp[2] * n[0] - dp[3] * n[1] + dp[0] * n[2] + dp[1] * n[3];
}

#endif
