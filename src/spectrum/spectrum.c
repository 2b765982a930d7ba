/* SPDX-License-Identifier: MIT */
/*
** spectrum.c: colour matching functions, the sRGB matrices, Burns'
** reflectance curves and the per-wavelength RGB weight (spectrum.h).
**
** Illuminant shapes and light emission are in illuminant.c.
*/
#include "config.h"

#include "spectrum/spectrum.h"

#include <math.h>
#include <pthread.h>

#include "spectrum/internal.h"
#include "spectrum/tables.h"

/* Full-precision D65 sRGB matrices (data/srgb.md, = CSS Color 4). */
static const double M_XYZ_TO_RGB[3][3] = {
    { 3.2409699419045235, -1.5373831775700944, -0.4986107602930036 },
    { -0.9692436362808797, 1.8759675015077204, 0.0415550574071756 },
    { 0.0556300796969936, -0.2039769588889765, 1.0569715142428786 },
};
static const double M_RGB_TO_XYZ[3][3] = {
    { 0.4123907992659592, 0.3575843393838780, 0.1804807884018343 },
    { 0.2126390058715102, 0.7151686787677560, 0.0721923153607337 },
    { 0.0193308187155918, 0.1191947797946260, 0.9505321522496607 },
};

/* Per-channel constants k_c of spec_lambda_rgb_weight(). */
static double weight_k[3];
static pthread_once_t weight_once = PTHREAD_ONCE_INIT;

/*
** Position of 'lambda' in a table of 'n' rows starting at 'first' with
** 'step' nm: row index *i (so that i and i+1 are valid) and fraction *t.
** Returns 0 when lambda lies outside the table (the caller yields 0).
*/
int spec_locate(double lambda, double first, double step, int n, int *i,
                double *t)
{
    double x = (lambda - first) / step;
    if (!(x >= 0.0) || x > (double)(n - 1))
        return 0;
    int k = (int)x;
    if (k >= n - 1)
        k = n - 2;
    *i = k;
    *t = x - k;
    return 1;
}

void spec_cmf(double lambda, double xyz[3])
{
    int i;
    double t;
    if (!spec_locate(lambda, SPEC_TAB_FIRST, 1.0, SPEC_TAB_N, &i, &t)) {
        xyz[0] = xyz[1] = xyz[2] = 0.0;
        return;
    }
    for (int c = 0; c < 3; c++)
        xyz[c] = spec_tab_cmf[i][c] +
                 t * (spec_tab_cmf[i + 1][c] - spec_tab_cmf[i][c]);
}

double spec_d65(double lambda)
{
    int i;
    double t;
    if (!spec_locate(lambda, SPEC_TAB_FIRST, 1.0, SPEC_TAB_N, &i, &t))
        return 0.0;
    return spec_tab_d65[i] + t * (spec_tab_d65[i + 1] - spec_tab_d65[i]);
}

static void mat_apply(const double m[3][3], const double a[3], double b[3])
{
    double r[3];
    for (int k = 0; k < 3; k++)
        r[k] = m[k][0] * a[0] + m[k][1] * a[1] + m[k][2] * a[2];
    b[0] = r[0];
    b[1] = r[1];
    b[2] = r[2];
}

void spec_xyz_to_rgb(const double xyz[3], double rgb[3])
{
    mat_apply(M_XYZ_TO_RGB, xyz, rgb);
}

void spec_rgb_to_xyz(const double rgb[3], double xyz[3])
{
    mat_apply(M_RGB_TO_XYZ, rgb, xyz);
}

double spec_reflectance(const double rgb[3], double lambda)
{
    int i = 0;
    double t = 0.0;
    if (lambda < SPEC_LAMBDA_MIN)
        lambda = SPEC_LAMBDA_MIN;
    if (lambda > SPEC_LAMBDA_MAX || lambda != lambda)
        lambda = SPEC_LAMBDA_MAX;
    spec_locate(lambda, SPEC_TAB5_FIRST, 5.0, SPEC_TAB5_N, &i, &t);
    double r = 0.0;
    for (int c = 0; c < 3; c++) {
        double a = spec_tab_burns[i][c], b = spec_tab_burns[i + 1][c];
        r += rgb[c] * (a + t * (b - a));
    }
    return r;
}

/* M·cmf(lambda)·D65(lambda), before the per-channel balance. */
static void raw_weight(double lambda, double w[3])
{
    double xyz[3];
    spec_cmf(lambda, xyz);
    double s = spec_d65(lambda);
    for (int c = 0; c < 3; c++)
        xyz[c] *= s;
    spec_xyz_to_rgb(xyz, w);
}

/*
** The integral over the domain of f(lambda), where f is a product of two
** functions each linear on every 1 nm interval: Simpson's rule on each
** interval is then exact (the product is quadratic there).
*/
void spec_integrate_1nm(void (*f)(double lambda, void *ctx, double out[3]),
                        void *ctx, double sum[3])
{
    sum[0] = sum[1] = sum[2] = 0.0;
    for (int l = (int)SPEC_LAMBDA_MIN; l < (int)SPEC_LAMBDA_MAX; l++) {
        double a[3], m[3], b[3];
        f(l, ctx, a);
        f(l + 0.5, ctx, m);
        f(l + 1.0, ctx, b);
        for (int c = 0; c < 3; c++)
            sum[c] += (a[c] + 4.0 * m[c] + b[c]) / 6.0;
    }
}

static void raw_weight_cb(double lambda, void *ctx, double out[3])
{
    (void)ctx;
    raw_weight(lambda, out);
}

static void init_weights(void)
{
    double sum[3];
    spec_integrate_1nm(raw_weight_cb, NULL, sum);
    for (int c = 0; c < 3; c++)
        weight_k[c] = SPEC_LAMBDA_RANGE / sum[c];
}

void spec_lambda_rgb_weight(double lambda, double w[3])
{
    pthread_once(&weight_once, init_weights);
    raw_weight(lambda, w);
    for (int c = 0; c < 3; c++)
        w[c] *= weight_k[c];
}
