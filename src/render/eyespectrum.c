/* SPDX-License-Identifier: MIT */
/*
** eyespectrum.c: wavelength sampling and the self-normalised XYZ estimate
** of a camera ray's dispersive split (see eyespectrum.h for why).
*/
#include "config.h"

#include "render/eyespectrum.h"

#include <math.h>
#include <pthread.h>

#include "spectrum/spectrum.h"

/* The sampling density is piecewise constant on 1 nm bins over the
** spectral domain: exact to sample from and to evaluate, and 1 nm is the
** resolution of the CIE tables. */
#define NBIN 400               /* SPEC_LAMBDA_RANGE nm */
/* (casts of the constants themselves: clang takes no cast of a sum here) */
_Static_assert(NBIN == (int)SPEC_LAMBDA_MAX - (int)SPEC_LAMBDA_MIN,
               "one bin per nm");

static double bin_p[NBIN];         /* density per nm in bin b */
static double bin_cdf[NBIN + 1];   /* cdf at the bin's left edge */
static double white_xyz[3];        /* XYZ of linear sRGB (1, 1, 1) */
static pthread_once_t table_once = PTHREAD_ONCE_INIT;

static double eye_sensitivity(double lambda)
{
    double xyz[3];
    spec_cmf(lambda, xyz);
    return (xyz[0] + xyz[1] + xyz[2]) * spec_d65(lambda);
}

static void init_table(void)
{
    double total = 0.0;
    for (int b = 0; b < NBIN; b++) {
        double l = SPEC_LAMBDA_MIN + b;
        /* the bin's mean by Simpson's rule; any positive value would do,
        ** as long as sampling and evaluation use the same one */
        bin_p[b] = (eye_sensitivity(l) + 4.0 * eye_sensitivity(l + 0.5) +
                    eye_sensitivity(l + 1.0)) / 6.0;
        total += bin_p[b];
    }
    bin_cdf[0] = 0.0;
    for (int b = 0; b < NBIN; b++) {
        bin_p[b] /= total;
        bin_cdf[b + 1] = bin_cdf[b] + bin_p[b];
    }
    bin_cdf[NBIN] = 1.0;
    const double one[3] = { 1.0, 1.0, 1.0 };
    spec_rgb_to_xyz(one, white_xyz);
}

double eye_lambda_sample(int i, int n, double u, double a[3])
{
    pthread_once(&table_once, init_table);
    if (n < 1)
        n = 1;
    double v = (i + u) / n;
    if (!(v >= 0.0))
        v = 0.0;
    if (v >= 1.0)
        v = nextafter(1.0, 0.0);
    /* the bin whose cdf interval holds v; bins of zero mass are never
    ** chosen since their interval is empty */
    int lo = 0, hi = NBIN;
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (bin_cdf[mid] <= v)
            lo = mid;
        else
            hi = mid;
    }
    double p = bin_p[lo];
    double f = p > 0.0 ? (v - bin_cdf[lo]) / p : 0.5;
    f = f < 0.0 ? 0.0 : f > 1.0 ? 1.0 : f;
    double lambda = SPEC_LAMBDA_MIN + lo + f;
    spec_cmf(lambda, a);
    double d65 = spec_d65(lambda);
    for (int k = 0; k < 3; k++)
        a[k] = p > 0.0 ? a[k] * d65 / p : 0.0;
    return lambda;
}

void eye_spectrum_init(struct eye_spectrum *s)
{
    for (int k = 0; k < 3; k++)
        s->num[k] = s->den[k] = 0.0;
    s->rsum = 0.0;
    s->n = 0;
}

void eye_spectrum_add(struct eye_spectrum *s, const double a[3], double r)
{
    for (int k = 0; k < 3; k++) {
        s->num[k] += r * a[k];
        s->den[k] += a[k];
    }
    s->rsum += r;
    s->n++;
}

void eye_spectrum_rgb(const struct eye_spectrum *s, double rgb[3])
{
    pthread_once(&table_once, init_table);
    double xyz[3];
    for (int k = 0; k < 3; k++) {
        /* a channel none of the wavelengths could see (zbar is 0 above
        ** 650 nm): the plain mean is the only estimate left */
        double m = s->den[k] > 0.0 ? s->num[k] / s->den[k]
                 : s->n > 0 ? s->rsum / s->n : 0.0;
        xyz[k] = m * white_xyz[k];
    }
    spec_xyz_to_rgb(xyz, rgb);
}

void eye_gamut_map(double rgb[3])
{
    if (rgb[0] >= 0.0 && rgb[1] >= 0.0 && rgb[2] >= 0.0)
        return;
    double xyz[3];
    spec_rgb_to_xyz(rgb, xyz);
    double y = xyz[1];
    if (!(y > 0.0)) {
        rgb[0] = rgb[1] = rgb[2] = 0.0;
        return;
    }
    /* c' = Y + t·(c - Y) keeps Y (the Y row sums to 1); the largest t in
    ** [0, 1] with every channel >= 0 */
    double t = 1.0;
    for (int k = 0; k < 3; k++)
        if (rgb[k] < 0.0) {
            double tk = y / (y - rgb[k]);
            if (tk < t)
                t = tk;
        }
    for (int k = 0; k < 3; k++) {
        rgb[k] = y + t * (rgb[k] - y);
        if (rgb[k] < 0.0)      /* rounding of the channel that hit 0 */
            rgb[k] = 0.0;
    }
}
