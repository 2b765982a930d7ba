/* SPDX-License-Identifier: MIT */
/*
** focalblur.c: POV-Ray 3.7's focal blur (see focalblur.h).
**
** The aperture patterns below are the sample positions POV-Ray 3.7.0.10
** uses (tracepixel.cpp: Grid1, HexGrid2-4 and their jitter radii), so
** that a blurred image has the same structure as POV-Ray's; the order of
** the points matters, since the confidence test may stop after any batch.
*/
#include "config.h"

#include "render/focalblur.h"

#include <math.h>
#include <string.h>

#include "material/noise.h"
#include "render/jitter.h"
#include "util/mem.h"

static const double grid4[4][2] = {
    { -0.25, 0.25 }, { 0.25, 0.25 }, { -0.25, -0.25 }, { 0.25, -0.25 } };

static const int hex7_batches[] = { 7, 0 };
static const double hex7[7][2] = {
    { -0.288675, 0.0 }, { 0.0, 0.0 }, { 0.288675, 0.0 },
    { -0.144338, 0.25 }, { -0.144338, -0.25 }, { 0.144338, 0.25 },
    { 0.144338, -0.25 } };

static const int hex19_batches[] = { 7, 6, 6, 0 };
static const double hex19[19][2] = {
    { -0.192450, 0.333333 }, { -0.192450, -0.333333 },
    { 0.192450, 0.333333 }, { 0.192450, -0.333333 }, { 0.384900, 0.0 },
    { -0.384900, 0.0 }, { 0.0, 0.0 },
    { 0.0, 0.333333 }, { 0.0, -0.333333 }, { -0.288675, 0.166667 },
    { -0.288675, -0.166667 }, { 0.288675, 0.166667 },
    { 0.288675, -0.166667 },
    { -0.096225, 0.166667 }, { -0.096225, -0.166667 },
    { 0.096225, 0.166667 }, { 0.096225, -0.166667 }, { -0.192450, 0.0 },
    { 0.192450, 0.0 } };

static const int hex37_batches[] = { 7, 6, 6, 4, 4, 4, 4, 2, 0 };
static const double hex37[37][2] = {
    { 0.0, 0.0 }, { -0.216506, 0.375 }, { 0.216506, -0.375 },
    { -0.216506, -0.375 }, { 0.216506, 0.375 }, { -0.433013, 0.0 },
    { 0.433013, 0.0 },
    { -0.144338, 0.25 }, { 0.144338, -0.25 }, { -0.144338, -0.25 },
    { 0.144338, 0.25 }, { -0.288675, 0.0 }, { 0.288675, 0.0 },
    { -0.072169, 0.125 }, { 0.072169, -0.125 }, { -0.072169, -0.125 },
    { 0.072169, 0.125 }, { -0.144338, 0.0 }, { 0.144338, 0.0 },
    { -0.360844, 0.125 }, { -0.360844, -0.125 }, { 0.360844, 0.125 },
    { 0.360844, -0.125 },
    { -0.288675, 0.25 }, { -0.288675, -0.25 }, { 0.288675, 0.25 },
    { 0.288675, -0.25 },
    { -0.072169, 0.375 }, { -0.072169, -0.375 }, { 0.072169, 0.375 },
    { 0.072169, -0.375 },
    { -0.216506, 0.125 }, { -0.216506, -0.125 }, { 0.216506, 0.125 },
    { 0.216506, -0.125 },
    { 0.0, 0.25 }, { 0.0, -0.25 } };

/* Sub-pixel grid of the image-position jitter (POV-Ray's
** SUB_PIXEL_GRID_SIZE). */
#define SUBPIXEL 16

bool focal_blur_wanted(const iris_camera *cam)
{
    return cam->aperture != 0.0 && cam->blur_samples > 0;
}

/* ------------------------------------------------------------------ */
/* The chi-square quantile of the confidence test                       */
/* ------------------------------------------------------------------ */

/* The regularised upper incomplete gamma function Q(a, x), a > 0: the
** power series of P below a + 1, a continued fraction (modified Lentz)
** above, the textbook split where each converges fast. */
static double gamma_q(double a, double x)
{
    if (!(x > 0.0))
        return 1.0;
    double lg = lgamma(a);
    if (x < a + 1.0) {
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < 1000; n++) {
            term *= x / (a + n);
            sum += term;
            if (fabs(term) < fabs(sum) * 1e-16)
                break;
        }
        double p = sum * exp(-x + a * log(x) - lg);
        return p >= 1.0 ? 0.0 : 1.0 - p;
    }
    const double tiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
    for (int i = 1; i < 1000; i++) {
        double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (fabs(d) < tiny)
            d = tiny;
        c = b + an / c;
        if (fabs(c) < tiny)
            c = tiny;
        d = 1.0 / d;
        double del = d * c;
        h *= del;
        if (fabs(del - 1.0) < 1e-16)
            break;
    }
    return exp(-x + a * log(x) - lg) * h;
}

/* The quantile by bisection: Q(df/2, x/2) falls from 1 to 0 as x grows,
** so bracket, then bisect to the last bit. */
static double chi2_solve(double df, double p)
{
    double a = 0.5 * df, lo = 0.0, hi = df + 1.0;
    while (gamma_q(a, 0.5 * hi) > p && hi < 1e300)
        hi *= 2.0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; i++) {
        double mid = 0.5 * (lo + hi);
        if (gamma_q(a, 0.5 * mid) > p)
            lo = mid;
        else
            hi = mid;
    }
    return 0.5 * (lo + hi);
}

/* Quantiles already solved, per thread (so without locks): media's
** adaptive sampling asks for df = 1 .. max_samples at one confidence
** after every sample of every interval, and each solve costs a hundred
** incomplete gamma functions; the cache returns the same bits. */
#define CHI2_CACHE 64
static _Thread_local struct chi2_entry {
    double df, p, x;
} chi2_cache[CHI2_CACHE];

double chi2_upper_inv(double df, double p)
{
    if (!(df > 0.0) || !(p > 0.0 && p < 1.0))
        return 0.0;
    if (!isfinite(df))
        return chi2_solve(df, p);
    struct chi2_entry *e =
        &chi2_cache[(unsigned)fmod(df, (double)CHI2_CACHE)];
    if (e->df == df && e->p == p)
        return e->x;
    double x = chi2_solve(df, p);
    e->df = df;
    e->p = p;
    e->x = x;
    return x;
}

/* ------------------------------------------------------------------ */
/* Set-up                                                               */
/* ------------------------------------------------------------------ */

/* Point 'i' (from 0) of the Halton sequence in 'base', in [0, 1). */
static double halton(unsigned long i, unsigned base)
{
    double h = 0.0, q = 1.0 / base;
    for (unsigned long k = i + 1; k > 0; k /= base) {
        h += (double)(k % base) * q;
        q /= base;
    }
    return h;
}

/* Point 'i' of POV-Ray's sub-random sequence on the disc of radius 0.5:
** radius from the base-2, angle from the base-3 Halton sequence, uniform
** in area. */
static void disc_point(unsigned long i, double v[2])
{
    double r = sqrt(0.25 * halton(i, 2)), th = 2.0 * M_PI * halton(i, 3);
    v[0] = r * cos(th);
    v[1] = r * sin(th);
}

static int grid_cell(double c, int size)
{
    int k = (int)((c + 0.5) * size);
    return k < 0 ? 0 : k > size - 1 ? size - 1 : k;
}

/* Fills fb->grid: the standard pattern, then Halton points on the disc,
** each in a cell of a coarse grid not yet taken where possible, so that
** the points cover the aperture evenly. */
static bool fill_grid(struct focal_blur *fb, const double (*std)[2],
                      int n_std)
{
    int n = fb->samples;
    for (int i = 0; i < n_std && i < n; i++) {
        fb->grid[i][0] = std[i][0];
        fb->grid[i][1] = std[i][1];
    }
    if (n <= n_std)
        return true;
    int size = 2 * (int)ceil(sqrt(n / M_PI)) + 1;
    unsigned char *taken = iris_calloc((size_t)size * size, 1);
    if (!taken)
        return false;
    for (int i = 0; i < n_std; i++)
        taken[grid_cell(std[i][1], size) * size +
              grid_cell(std[i][0], size)] = 1;
    long remain = 10L * n;
    unsigned long next = 0;
    for (int i = n_std; i < n; i++) {
        double v[2];
        disc_point(next++, v);
        remain--;
        int xi = grid_cell(v[0], size), yi = grid_cell(v[1], size);
        while ((taken[yi * size + xi] || v[0] * v[0] + v[1] * v[1] > 0.25) &&
               remain > n - i) {
            disc_point(next++, v);
            remain--;
            xi = grid_cell(v[0], size);
            yi = grid_cell(v[1], size);
        }
        fb->grid[i][0] = v[0];
        fb->grid[i][1] = v[1];
        taken[yi * size + xi] = 1;
    }
    iris_free(taken);
    return true;
}

bool focal_blur_init(struct focal_blur *fb, const iris_camera *cam)
{
    memset(fb, 0, sizeof *fb);
    int n = cam->blur_samples > 0 ? cam->blur_samples : 1;
    fb->samples = n;
    fb->samples_min = cam->blur_samples_min > 0 && cam->blur_samples_min <= n
                          ? cam->blur_samples_min : 0;
    /* POV-Ray's parser keeps its defaults for values out of range */
    double conf = cam->confidence > 0.0 && cam->confidence < 1.0
                      ? cam->confidence : 0.9;
    double var = cam->variance >= 0.0 && cam->variance <= 1.0
                     ? cam->variance : 1.0 / 10000.0;
    fb->threshold = iris_calloc((size_t)n, sizeof *fb->threshold);
    fb->grid = iris_calloc((size_t)n, sizeof *fb->grid);
    if (!fb->threshold || !fb->grid) {
        focal_blur_fini(fb);
        return false;
    }
    if (n > 1) {
        double t1 = var / chi2_upper_inv(n - 1, conf);
        for (int i = 0; i < n; i++)
            fb->threshold[i] = t1 * chi2_upper_inv(i + 1, conf);
    }
    const double (*std)[2] = grid4;
    int n_std = 4;
    if (n >= 37) {
        std = hex37; n_std = 37; fb->batches = hex37_batches;
    } else if (n >= 19) {
        std = hex19; n_std = 19; fb->batches = hex19_batches;
    } else if (n >= 7) {
        std = hex7; n_std = 7; fb->batches = hex7_batches;
    }
    /* the jitter radius: half a lattice step for the full hexagonal
    ** grids, else half the spacing of n points on the unit square */
    fb->max_jitter = n == 7 ? 0.144338 : n == 19 ? 0.096225
                   : n == 37 ? 0.0721688 : 0.5 / sqrt((double)n);
    if (!fill_grid(fb, std, n_std)) {
        focal_blur_fini(fb);
        return false;
    }
    fb->radius = 0.5 * cam->aperture;
    /* the aperture's axes: across the image's up and direction */
    fb->xperp = v3_norm(v3_cross(cam->up, cam->direction));
    fb->yperp = v3_norm(v3_cross(cam->direction, fb->xperp));
    /* POV-Ray focuses at focal_distance, which the parser resolved
    ** (|focal_point - location|, or the length of direction); a camera
    ** built without the parser (-1) falls back to the direction's length */
    double dlen = v3_len(cam->direction);
    double fd = cam->focal_distance;
    if (!(fd > 0.0) || !isfinite(fd))
        fd = dlen;
    fb->plane = dlen > 0.0 ? fd / dlen : 1.0;
    return true;
}

void focal_blur_fini(struct focal_blur *fb)
{
    iris_free(fb->threshold);
    iris_free(fb->grid);
    fb->threshold = NULL;
    fb->grid = NULL;
}

/* ------------------------------------------------------------------ */
/* Per sample                                                           */
/* ------------------------------------------------------------------ */

int focal_blur_seed(double x, double y)
{
    return (int)(x * 313.0 + 11.0) + (int)(y * 311.0 + 17.0);
}

void focal_blur_subpixel(int seed, int nr, double *dx, double *dy)
{
    int xi = noise_hash_entry((seed + nr) & 0xfff) % SUBPIXEL;
    int yi = noise_hash_entry((seed + nr + 1) & 0xfff) % SUBPIXEL;
    double sx = (2.0 * xi + 1.0) / (2.0 * SUBPIXEL) - 0.5;
    double sy = (2.0 * yi + 1.0) / (2.0 * SUBPIXEL) - 0.5;
    double jx, jy;
    jitter2d(sx, sy, &jx, &jy);
    /* POV-Ray subtracts 0.5 from a jitter already centred on 0: the
    ** offset lies in [-1/16, 0) cells, kept for the same positions */
    *dx = sx + (jx - 0.5) / SUBPIXEL;
    *dy = sy + (jy - 0.5) / SUBPIXEL;
}

void focal_blur_ray(const struct focal_blur *fb, const iris_camera *cam,
                    double x, double y, int nr, vec3 raw, ray *r)
{
    if (nr < 0 || nr >= fb->samples)
        nr = 0;
    /* POV-Ray jitters with the pixel corner coordinates its camera uses */
    double jx, jy;
    jitter2d(x + 0.5, y - 0.5, &jx, &jy);
    jx *= 2.0 * fb->max_jitter;
    jy *= 2.0 * fb->max_jitter;
    double xl = fb->radius * (fb->grid[nr][0] + jx);
    double yl = fb->radius * (fb->grid[nr][1] + jy);
    vec3 defl = v3_sub(v3_scale(fb->xperp, xl), v3_scale(fb->yperp, yl));
    /* the ray still meets the pinhole ray on the focal plane */
    vec3 d = v3_sub(v3_scale(raw, fb->plane), defl);
    double len = v3_len(d);
    if (!(len > 0.0) || !isfinite(len))
        return;
    /* POV-Ray restarts every camera's ray at the location; an
    ** orthographic camera keeps its own origin here (POV-Ray's would
    ** collapse the image to one point) */
    r->o = v3_add(cam->kind == IRIS_CAM_ORTHOGRAPHIC ? r->o : cam->location,
                  defl);
    r->d = v3_scale(d, 1.0 / len);
}

bool focal_blur_converged(const struct focal_blur *fb, int n,
                          const double s1[4], const double s2[4])
{
    if (n < 1 || n < fb->samples_min)
        return false;
    double thr = fb->threshold[n - 1 < fb->samples ? n - 1 : fb->samples - 1];
    /* the transmit channel too, as POV-Ray: under +UA a blurred edge
    ** against the background takes more rays (without +UA it is 0, whose
    ** variance 0 passes only when the bound is positive) */
    for (int k = 0; k < 4; k++) {
        double m = s1[k] / n;
        double v = (s2[k] / n - m * m) / n;
        if (!(v < thr))
            return false;
    }
    return true;
}
