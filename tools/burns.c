/* SPDX-License-Identifier: MIT */
/*
** burns.c: computes Burns' three reflectance curves (src/spectrum/
** burns_table.c) by his constrained optimisation, as the seed paper does
** with scipy.
**
** Problem (Burns 2020, "Numerical methods for smoothest reflectance
** reconstruction", the three-curve form of the seed paper). Unknowns are
** z_c = ln rho_c at the 81 wavelengths 380, 385, ..., 780 nm, c = R, G, B:
**
**   minimise   sum_c sum_i (z_c[i+1] - z_c[i])^2
**   subject to T·exp(z_R) = (1,0,0),  T·exp(z_G) = (0,1,0),
**              exp(z_R) + exp(z_G) + exp(z_B) = 1 at every node.
**
** The sum constraint is Burns' "rho <= 1" inequality taken as active (it is
** at the optimum: the three curves of his published set sum to one), so
** any rgb in [0,1]^3 gives a reflectance in [0,1]. T·exp(z_B) = (0,0,1)
** then follows and is left out (it would make the KKT matrix singular):
** T·1 = (1,1,1) holds exactly because T is white-balanced.
**
** T[c][i] = (1/400) ∫ hat_i(lambda)·w_c(lambda) dlambda, where hat_i is the
** linear-interpolation basis function of node i (spec_reflectance
** interpolates the curves linearly) and w is spec_lambda_rgb_weight(), the
** per-wavelength RGB of D65 light. The integral is exact (Simpson on 1 nm
** pieces of a piecewise cubic), so the curves reproduce pure r, g, b exactly
** in the renderer's own continuous integration.
**
** Solver: Newton's method on the KKT conditions, damped by backtracking on
** the norm of the KKT residual; each step is one dense solve of the
** (4N+6)-square system with LAPACKE_dgesv. It converges in about a dozen
** iterations. Usage: burns > src/spectrum/burns_table.c
*/
#include "config.h"

#include <lapacke.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "spectrum/internal.h"
#include "spectrum/spectrum.h"

#define N 81                   /* nodes, 380..780 nm every 5 nm */
#define NX (3 * N)             /* unknowns z_R, z_G, z_B */
#define NC (6 + N)             /* constraints */
#define NK (NX + NC)           /* KKT system size */

static double T[3][N];

struct hat_ctx {
    int node;
};

/* hat_i(lambda)·w(lambda)/400 */
static void hat_weight_cb(double lambda, void *ctx, double out[3])
{
    const struct hat_ctx *h = ctx;
    double centre = SPEC_LAMBDA_MIN + 5.0 * h->node;
    double hat = 1.0 - fabs(lambda - centre) / 5.0;
    if (hat < 0.0)
        hat = 0.0;
    spec_lambda_rgb_weight(lambda, out);
    for (int c = 0; c < 3; c++)
        out[c] *= hat / SPEC_LAMBDA_RANGE;
}

static void build_t(void)
{
    for (int i = 0; i < N; i++) {
        struct hat_ctx h = { i };
        double s[3];
        spec_integrate_1nm(hat_weight_cb, &h, s);
        for (int c = 0; c < 3; c++)
            T[c][i] = s[c];
    }
}

/* (K z)[i] for K = D^T D, D the first-difference matrix. */
static double kz(const double *z, int i)
{
    double r = 0.0;
    if (i > 0)
        r += z[i] - z[i - 1];
    if (i < N - 1)
        r += z[i] - z[i + 1];
    return r;
}

/*
** The KKT residual at (x, y): gradient of the Lagrangian, then the
** constraint values. y = (lambda_R[3], lambda_G[3], mu[N]).
*/
static double residual(const double *x, const double *y, double *res)
{
    double e[NX];
    for (int k = 0; k < NX; k++)
        e[k] = exp(x[k]);
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < N; i++) {
            double s = y[6 + i];
            if (c < 2)
                for (int k = 0; k < 3; k++)
                    s += T[k][i] * y[3 * c + k];
            res[c * N + i] = 2.0 * kz(x + c * N, i) + e[c * N + i] * s;
        }
    for (int c = 0; c < 2; c++)
        for (int k = 0; k < 3; k++) {
            double s = 0.0;
            for (int i = 0; i < N; i++)
                s += T[k][i] * e[c * N + i];
            res[NX + 3 * c + k] = s - (k == c ? 1.0 : 0.0);
        }
    for (int i = 0; i < N; i++)
        res[NX + 6 + i] = e[i] + e[N + i] + e[2 * N + i] - 1.0;
    double n2 = 0.0;
    for (int k = 0; k < NK; k++)
        n2 += res[k] * res[k];
    return sqrt(n2);
}

/* Fills the KKT matrix (row-major) at (x, y). */
static void kkt_matrix(const double *x, const double *y, double *m)
{
    memset(m, 0, sizeof(double) * NK * NK);
    for (int c = 0; c < 3; c++)
        for (int i = 0; i < N; i++) {
            int r = c * N + i;
            double e = exp(x[r]), s = y[6 + i];
            if (c < 2)
                for (int k = 0; k < 3; k++)
                    s += T[k][i] * y[3 * c + k];
            /* Hessian of the Lagrangian: 2K + diag(e ∘ s) */
            m[r * NK + r] = 2.0 * ((i > 0) + (i < N - 1)) + e * s;
            if (i > 0)
                m[r * NK + r - 1] = -2.0;
            if (i < N - 1)
                m[r * NK + r + 1] = -2.0;
            /* Constraint Jacobian A and its transpose */
            if (c < 2)
                for (int k = 0; k < 3; k++) {
                    int q = NX + 3 * c + k;
                    m[q * NK + r] = m[r * NK + q] = T[k][i] * e;
                }
            int q = NX + 6 + i;
            m[q * NK + r] = m[r * NK + q] = e;
        }
}

int main(void)
{
    static double x[NX], y[NC], m[NK * NK], rhs[NK], res[NK];
    static double xt[NX], yt[NC];
    static lapack_int piv[NK];
    build_t();
    for (int k = 0; k < NX; k++)
        x[k] = log(1.0 / 3.0);
    double r = residual(x, y, res);
    int it;
    for (it = 0; it < 100 && r > 1e-13; it++) {
        /* Newton step: [H A^T; A 0][dx; y+] = [-2Kz; -c] */
        kkt_matrix(x, y, m);
        for (int c = 0; c < 3; c++)
            for (int i = 0; i < N; i++)
                rhs[c * N + i] = -2.0 * kz(x + c * N, i);
        for (int k = 0; k < NC; k++)
            rhs[NX + k] = -res[NX + k];
        if (LAPACKE_dgesv(LAPACK_ROW_MAJOR, NK, 1, m, NK, piv, rhs, 1) != 0) {
            fprintf(stderr, "burns: singular KKT matrix at iteration %d\n",
                    it);
            return 1;
        }
        /* Backtrack until the KKT residual decreases */
        double alpha = 1.0, rt = r;
        for (int tries = 0; tries < 40; tries++) {
            for (int k = 0; k < NX; k++)
                xt[k] = x[k] + alpha * rhs[k];
            for (int k = 0; k < NC; k++)
                yt[k] = y[k] + alpha * (rhs[NX + k] - y[k]);
            rt = residual(xt, yt, res);
            if (rt < (1.0 - 1e-4 * alpha) * r)
                break;
            alpha *= 0.5;
        }
        memcpy(x, xt, sizeof x);
        memcpy(y, yt, sizeof y);
        r = residual(x, y, res);
        fprintf(stderr, "burns: iteration %2d step %.4g residual %.3e\n",
                it + 1, alpha, r);
    }
    if (r > 1e-10) {
        fprintf(stderr, "burns: no convergence (residual %.3e)\n", r);
        return 1;
    }

    printf("/* SPDX-License-Identifier: MIT */\n"
           "/*\n"
           "** burns_table.c: GENERATED by tools/burns (`make regen-burns`);\n"
           "** do not edit. Burns' smoothest log-reflectance curves rho_R,\n"
           "** rho_G, rho_B for D65 and linear sRGB, 380..780 nm every 5 nm;\n"
           "** they sum to 1. Newton/KKT converged in %d iterations to a\n"
           "** residual of %.1e.\n"
           "*/\n"
           "#include \"config.h\"\n\n"
           "#include \"spectrum/tables.h\"\n\n"
           "const double spec_tab_burns[SPEC_TAB5_N][3] = {\n", it, r);
    for (int i = 0; i < N; i++)
        printf("    { %.17g, %.17g, %.17g }, /* %d */\n", exp(x[i]),
               exp(x[N + i]), exp(x[2 * N + i]), 380 + 5 * i);
    printf("};\n");
    return 0;
}
