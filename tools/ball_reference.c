/* SPDX-License-Identifier: MIT */
/*
** ball_reference.c: the semi-analytic reference image of
** bench/caustic_ball.pov, for bench/error-vs-time.sh.
**
** The beam is parallel, straight down and exactly as wide as the ball, so
** the floor's light is the caustic alone and depends only on the distance
** r from the axis. A fan of rays in a meridional plane (impact parameter b
** in (0, R), each standing for its annulus 2·pi·b·db of the unit-irradiance
** beam) is traced through the ball with exact unpolarised Fresnel
** splitting (both branches, weights F and 1-F, up to the scene's
** max_trace_level, as the photons are), and what reaches the floor after
** at least one bounce is histogrammed by r (bins of 1e-3 R): energy per
** annulus area is the irradiance E(r), which is the pixel value (white
** diffuse 1 floor, light colour 1; POV-Ray's photon shading divides the
** photon's cosine out). Each pixel is the mean of E over its footprint on
** the floor (the orthographic camera 40 degrees up maps pixel columns to x
** and rows to z linearly over |x|, |z| <= 1.2), 24 x 24 samples a pixel:
** the converged image of jittered eye passes. The same fan is checked
** against photon estimates in tests/unit/test_photon.c.
**
** Not modelled: POV-Ray's clamp of the photon cosine at 0.1 (grazing
** photons; none land in the frame) and the direct light (none reaches the
** floor: the ball blocks the whole beam).
**
** Usage: ball_reference WIDTH HEIGHT out.exr
*/
#include "config.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#include "iris/image.h"

#define YC 2.5        /* ball centre height */
#define RAD 1.0       /* ball radius = beam radius */
#define IOR 1.5
#define MAX_LEVEL 6   /* the scene's max_trace_level */
#define HALF 1.2      /* the floor square seen: |x|, |z| <= HALF */
#define BIN 1e-3
#define N_BINS 1800   /* r up to 1.8 > HALF·sqrt(2) */
#define N_RAYS 2000000
#define SUB 24

static double energy[N_BINS];

static double fresnel(double n1, double n2, double ci)
{
    double si = sqrt(fmax(0, 1 - ci * ci)), st = n1 / n2 * si;
    if (st >= 1)
        return 1;
    double ct = sqrt(1 - st * st);
    double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
    double rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
    return 0.5 * (rs * rs + rp * rp);
}

/* Traces a ray of the meridional plane (x, y) with weight w. */
static void trace(double ox, double oy, double dx, double dy, double w,
                  int level, bool inside)
{
    if (w < 1e-9 || level > MAX_LEVEL)
        return;
    double px = ox, py = oy - YC;
    double b = px * dx + py * dy, c = px * px + py * py - RAD * RAD;
    double disc = b * b - c, t = INFINITY;
    if (disc >= 0) {
        double s = sqrt(disc);
        t = -b - s > 1e-9 ? -b - s : (-b + s > 1e-9 ? -b + s : INFINITY);
    }
    double tf = dy < 0 ? -oy / dy : INFINITY;
    if (!inside && tf < t) {
        if (level > 1) {
            double q = fabs(ox + tf * dx) / BIN;
            if (q < N_BINS)
                energy[(int)q] += w;
        }
        return;
    }
    if (!isfinite(t))
        return;
    double hx = ox + t * dx, hy = oy + t * dy;
    double nx = hx / RAD, ny = (hy - YC) / RAD;
    if (inside)
        nx = -nx, ny = -ny;
    double ci = -(dx * nx + dy * ny);
    double n1 = inside ? IOR : 1, n2 = inside ? 1 : IOR;
    double F = fresnel(n1, n2, ci);
    trace(hx, hy, dx + 2 * ci * nx, dy + 2 * ci * ny, w * F, level + 1,
          inside);
    if (F < 1) {
        double eta = n1 / n2, ct = sqrt(1 - eta * eta * (1 - ci * ci));
        trace(hx, hy, eta * dx + (eta * ci - ct) * nx,
              eta * dy + (eta * ci - ct) * ny, w * (1 - F), level + 1,
              !inside);
    }
}

/* E(r): the histogram's irradiance. */
static double irradiance(double r)
{
    int k = (int)(r / BIN);
    if (k >= N_BINS)
        return 0.0;
    double a = M_PI * BIN * BIN * ((k + 1.0) * (k + 1.0) - (double)k * k);
    return energy[k] / a;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: ball_reference WIDTH HEIGHT out.exr\n");
        return 2;
    }
    int w = atoi(argv[1]), h = atoi(argv[2]);
    if (w < 1 || h < 1 || w > 16384 || h > 16384) {
        fprintf(stderr, "ball_reference: bad image size\n");
        return 2;
    }
    double db = RAD / N_RAYS;
    for (int i = 0; i < N_RAYS; i++) {
        double b = (i + 0.5) * db;
        trace(b, 10, 0, -1, 2 * M_PI * b * db, 1, false);
    }
    iris_image img;
    if (iris_image_init(&img, w, h) != IRIS_OK)
        return 1;
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            double s = 0;
            for (int sj = 0; sj < SUB; sj++)
                for (int si = 0; si < SUB; si++) {
                    double x = -HALF + 2 * HALF * (i + (si + 0.5) / SUB) / w;
                    double z = HALF - 2 * HALF * (j + (sj + 0.5) / SUB) / h;
                    s += irradiance(sqrt(x * x + z * z));
                }
            float *px = &img.pixels[((size_t)j * w + i) * 4];
            px[0] = px[1] = px[2] = (float)(s / (SUB * SUB));
            px[3] = 1.0f;
        }
    char err[256] = "";
    enum iris_status st = iris_image_write(&img, argv[3], 0, IRIS_ENC_LINEAR,
                                           err, sizeof err);
    iris_image_fini(&img);
    if (st != IRIS_OK) {
        fprintf(stderr, "ball_reference: %s\n", err);
        return 1;
    }
    return 0;
}
