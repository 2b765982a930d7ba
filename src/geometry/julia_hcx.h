/* SPDX-License-Identifier: MIT */
/*
** julia_hcx.h: the hypercomplex algebra of POV-Ray's julia_fractal.
*/
#ifndef IRIS_GEOMETRY_JULIA_HCX_H
#define IRIS_GEOMETRY_JULIA_HCX_H

#include <stdbool.h>

/* r = a b in the (commutative) hypercomplex algebra; r may alias a or b */
void hcx_mul(const double a[4], const double b[4], double r[4]);

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
void hcx_normal(const double dp[4], const double n[4], double out[3]);

#endif
