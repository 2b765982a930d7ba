/* SPDX-License-Identifier: MIT */
/*
** rainbow.c: rainbow{} over a ray's colour (rainbow.h).
**
** For each rainbow the ray's direction gives two angles: around the
** antisolar direction from the rainbow's up vector (beyond arc_angle there
** is no bow, and past falloff_angle it fades out smoothly), and away from
** the antisolar direction, which indexes the colour map across the bow's
** width. The map colour replaces the ray's colour by 1 - exp(-depth /
** distance), no less than the colour's transmit lets through. Several
** rainbows on one ray are averaged, as POV-Ray 3.7.0 does.
*/
#include "config.h"

#include <math.h>

#include "render/rainbow.h"

/* POV-Ray's EPSILON: the top of the map is left out. */
#define RB_EPSILON 1e-10

void rainbow_apply(const iris_scene *sc, const struct mat_ctx *mat, vec3 d,
                   double depth, double rgb[3])
{
    double sum[3] = { 0, 0, 0 };
    int n = 0;
    for (int i = 0; i < sc->n_rainbows; i++) {
        const iris_rainbow *rb = sc->rainbows[i];
        if (!rb->pigment || rb->distance == 0.0 || rb->width == 0.0)
            continue;
        double x = v3_dot(d, rb->right), y = v3_dot(d, rb->up);
        double l = x * x + y * y;
        if (l > 0.0)
            y /= sqrt(l);
        double angle = fabs(acos(fmin(fmax(y, -1.0), 1.0)));
        if (!(angle <= rb->arc_angle))
            continue;
        double dot = v3_dot(d, rb->antisolar);
        if (!(dot >= 0.0))
            continue;
        double index = (acos(fmin(dot, 1.0)) - rb->angle) / rb->width;
        if (!(index >= 0.0 && index <= 1.0 - RB_EPSILON))
            continue;
        struct mat_point pt = { .p = v3(index, 0.0, 0.0), .d = d };
        iris_colour cr;
        mat_eval_pigment(mat, rb->pigment, &pt, &cr);
        double fade = 0.0;
        if (rb->falloff_width > 0.0 && angle > rb->falloff_angle) {
            fade = (angle - rb->falloff_angle) / rb->falloff_width;
            fade = (3.0 - 2.0 * fade) * fade * fade;
        }
        double k = exp(-depth / rb->distance);
        k = fmax(k, fade * (1.0 - cr.t) + cr.t);
        double ki = 1.0 - k, f = cr.f * ki;
        const double c[3] = { cr.r, cr.g, cr.b };
        for (int j = 0; j < 3; j++)
            sum[j] += k * rgb[j] * ((1.0 - f) + f * c[j]) + ki * c[j];
        n++;
    }
    if (n > 0)
        for (int j = 0; j < 3; j++)
            rgb[j] = sum[j] / n;
}
