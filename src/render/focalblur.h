/* SPDX-License-Identifier: MIT */
/*
** focalblur.h: POV-Ray 3.7's focal blur (camera aperture, blur_samples,
** focal_point, confidence, variance), as TracePixel's
** TraceRayWithFocalBlur and JitterCameraRay compute it (v3.7.0.10,
** source/backend/render/tracepixel.cpp).
**
** Each image sample (pixel centre or AA subsample) traces up to
** blur_samples rays. Ray k starts at the camera location moved within
** the aperture by the k-th point of a fixed pattern (POV-Ray's hexagonal
** grids of 7, 19 or 37 points, or its 4-point square, then Halton points
** on the disc), jittered by Jitter2d, and aims at the point where the
** pinhole ray meets the focal plane; its image position is jittered on a
** 16 x 16 sub-pixel grid. The rays come in batches (7, 6, 6, ... for the
** hexagonal grids, 4 otherwise); after each batch the sampling stops once
** at least blur_samples_min rays are in and the variance of the mean of
** every channel is below variance · chi2inv(n, confidence) /
** chi2inv(blur_samples - 1, confidence) (a chi-square confidence test).
**
** Depends on: math, render (camera, jitter), material (noise hash).
** Used by: eyepass.c.
*/
#ifndef IRIS_RENDER_FOCALBLUR_H
#define IRIS_RENDER_FOCALBLUR_H

#include <stdbool.h>

#include "accel/accel.h"
#include "iris/scene.h"

struct focal_blur {
    int samples;               /* blur_samples (the maximum) */
    int samples_min;
    const int *batches;        /* batch sizes ending in 0, or NULL: 4s */
    double *threshold;         /* [samples]: variance bound after n rays */
    double (*grid)[2];         /* [samples]: aperture points, radius 0.5 */
    double max_jitter;
    double radius;             /* aperture / 2 */
    vec3 xperp, yperp;         /* unit vectors spanning the aperture */
    double plane;              /* focal distance / |direction| */
};

/* True when the camera asks for focal blur (aperture != 0 and
** blur_samples > 0), as POV-Ray decides. */
bool focal_blur_wanted(const iris_camera *cam);

/* Prepares 'fb' for 'cam'; false when memory runs out. */
bool focal_blur_init(struct focal_blur *fb, const iris_camera *cam);
void focal_blur_fini(struct focal_blur *fb);

/* The pixel sample seed of POV-Ray's sub-pixel choice at (x, y). */
int focal_blur_seed(double x, double y);

/* The image position of blur ray 'nr' of the sample at (x, y): (x, y)
** moved within its pixel. */
void focal_blur_subpixel(int seed, int nr, double *dx, double *dy);

/* Turns the pinhole camera ray 'r' through image point (x, y), whose
** direction before normalisation was 'raw', into blur ray 'nr'. */
void focal_blur_ray(const struct focal_blur *fb, const iris_camera *cam,
                    double x, double y, int nr, vec3 raw, ray *r);

/* Whether the per-channel sums of n rays (s1 = sum c, s2 = sum c^2 over
** r, g, b and the transmit channel) pass the confidence test, so that no
** more rays are needed. */
bool focal_blur_converged(const struct focal_blur *fb, int n,
                          const double s1[4], const double s2[4]);

/* The x with P(chi^2_df > x) = p (Cephes' chdtri), for df > 0 and p in
** (0, 1). */
double chi2_upper_inv(double df, double p);

#endif
