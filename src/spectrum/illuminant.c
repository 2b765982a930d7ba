/* SPDX-License-Identifier: MIT */
/*
** illuminant.c: emission spectra of lights (spectrum.h): D65, A, F1-F12
** and blackbodies, normalised to Y = 1, and a light's emission relative
** to white D65.
*/
#include "config.h"

#include "spectrum/spectrum.h"

#include <math.h>
#include <pthread.h>

#include "spectrum/internal.h"
#include "spectrum/tables.h"

#define N_TABULATED (IRIS_SPEC_F12 + 1) /* D65, A, F1..F12 */

/* 1 / (integral of S·ybar over the domain) for each tabulated shape. */
static double inv_y[N_TABULATED];
static pthread_once_t inv_y_once = PTHREAD_ONCE_INIT;

/* Second radiation constant c2 = hc/k in nm·K (SI 2019 constants). */
#define PLANCK_C2_NM_K 1.438776877e7

static double clamp_kelvin(double t)
{
    if (!(t >= 100.0))
        return 100.0;
    return t > 1e6 ? 1e6 : t;
}

/*
** Planck's law relative to its value at 560 nm: computed through expm1 of
** the difference, so it neither overflows for cold bodies nor loses digits
** for hot ones.
*/
static double planck_rel(double lambda, double kelvin)
{
    double x = PLANCK_C2_NM_K / (lambda * kelvin);
    double x0 = PLANCK_C2_NM_K / (560.0 * kelvin);
    double ratio = pow(560.0 / lambda, 5.0);
    /* (e^x0 - 1)/(e^x - 1) = e^(x0-x)·(1 - e^-x0)/(1 - e^-x) */
    return ratio * exp(x0 - x) * (-expm1(-x0)) / (-expm1(-x));
}

/* The shape before normalisation; 0 outside its table. */
static double raw_shape(enum iris_light_spectrum s, double kelvin,
                        double lambda)
{
    int i;
    double t;
    if (s == IRIS_SPEC_BLACKBODY)
        return planck_rel(lambda, clamp_kelvin(kelvin));
    if (s == IRIS_SPEC_D65)
        return spec_d65(lambda);
    if (s == IRIS_SPEC_A) {
        if (!spec_locate(lambda, SPEC_TAB_FIRST, 1.0, SPEC_TAB_N, &i, &t))
            return 0.0;
        return spec_tab_a[i] + t * (spec_tab_a[i + 1] - spec_tab_a[i]);
    }
    if (s >= IRIS_SPEC_F1 && s <= IRIS_SPEC_F12) {
        int f = s - IRIS_SPEC_F1;
        if (!spec_locate(lambda, SPEC_TAB5_FIRST, 5.0, SPEC_TAB5_N, &i, &t))
            return 0.0;
        return spec_tab_f[i][f] + t * (spec_tab_f[i + 1][f] - spec_tab_f[i][f]);
    }
    return spec_d65(lambda); /* unknown value: the default shape */
}

struct shape_ctx {
    enum iris_light_spectrum s;
    double kelvin;
};

static void shape_y_cb(double lambda, void *ctx, double out[3])
{
    const struct shape_ctx *c = ctx;
    double xyz[3];
    spec_cmf(lambda, xyz);
    out[0] = raw_shape(c->s, c->kelvin, lambda) * xyz[1];
    out[1] = out[2] = 0.0;
}

/* 1 / integral of S·ybar: exact for the tables, Simpson (1 nm) for
** Planck, which is smooth enough for 1e-9 relative. */
static double compute_inv_y(enum iris_light_spectrum s, double kelvin)
{
    struct shape_ctx c = { s, kelvin };
    double sum[3];
    spec_integrate_1nm(shape_y_cb, &c, sum);
    return sum[0] > 0.0 ? 1.0 / sum[0] : 0.0;
}

static void init_inv_y(void)
{
    for (int s = 0; s < N_TABULATED; s++)
        inv_y[s] = compute_inv_y((enum iris_light_spectrum)s, 0.0);
}

static double shape_inv_y(enum iris_light_spectrum s, double kelvin)
{
    if (s == IRIS_SPEC_BLACKBODY)
        return compute_inv_y(s, clamp_kelvin(kelvin));
    pthread_once(&inv_y_once, init_inv_y);
    if (s < 0 || s >= N_TABULATED)
        s = IRIS_SPEC_D65;
    return inv_y[s];
}

double spec_illuminant(enum iris_light_spectrum s, double kelvin,
                       double lambda)
{
    return raw_shape(s, kelvin, lambda) * shape_inv_y(s, kelvin);
}

void spec_emitter_init(struct spec_emitter *e, const iris_light *l)
{
    e->shape = l->spectrum;
    if (e->shape < 0 || e->shape > IRIS_SPEC_BLACKBODY)
        e->shape = IRIS_SPEC_D65;
    e->kelvin = clamp_kelvin(l->blackbody_kelvin);
    e->scale = shape_inv_y(e->shape, e->kelvin) /
               shape_inv_y(IRIS_SPEC_D65, 0.0);
    e->rgb[0] = l->colour.r > 0.0 ? l->colour.r : 0.0;
    e->rgb[1] = l->colour.g > 0.0 ? l->colour.g : 0.0;
    e->rgb[2] = l->colour.b > 0.0 ? l->colour.b : 0.0;
}

double spec_emitter_eval(const struct spec_emitter *e, double lambda)
{
    double up = spec_reflectance(e->rgb, lambda);
    if (e->shape == IRIS_SPEC_D65)
        return up;
    double d65 = spec_d65(lambda);
    if (!(d65 > 0.0))
        return 0.0;
    return up * e->scale * raw_shape(e->shape, e->kelvin, lambda) / d65;
}

double spec_light(const iris_light *l, double lambda)
{
    struct spec_emitter e;
    spec_emitter_init(&e, l);
    return spec_emitter_eval(&e, lambda);
}

/*
** The colour a light gives a white diffuse surface, for the shading that
** stays RGB (direct light; DESIGN.md: camera rays are RGB). Without it a
** 'spectrum "A"' or 'blackbody' light lit surfaces directly in its plain
** colour (white) while its photons carried the coloured spectrum.
** D65 returns the colour itself, so POV-Ray scenes shade as in POV-Ray
** (the spectral round trip would differ by up to 1e-3); other shapes the
** mean over the domain of spec_emitter_eval x spec_lambda_rgb_weight,
** exactly what the photon estimate gives a white photon surface. The
** trapezoid rule on a 0.25 nm grid: the curves are linear between 1 nm
** (5 nm for F1-F12) table rows, so the error is below 1e-6 of the value.
*/
void spec_light_rgb(const iris_light *l, double rgb[3])
{
    struct spec_emitter e;
    spec_emitter_init(&e, l);
    if (e.shape == IRIS_SPEC_D65) {
        rgb[0] = l->colour.r;
        rgb[1] = l->colour.g;
        rgb[2] = l->colour.b;
        return;
    }
    enum { STEPS = 1600 };
    double sum[3] = { 0, 0, 0 };
    for (int i = 0; i <= STEPS; i++) {
        double lambda = SPEC_LAMBDA_MIN + SPEC_LAMBDA_RANGE * i / STEPS;
        double w[3], s = spec_emitter_eval(&e, lambda);
        spec_lambda_rgb_weight(lambda, w);
        double f = (i == 0 || i == STEPS) ? 0.5 : 1.0;
        for (int c = 0; c < 3; c++)
            sum[c] += f * s * w[c];
    }
    for (int c = 0; c < 3; c++)
        rgb[c] = sum[c] / STEPS;
}
