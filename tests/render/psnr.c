/* SPDX-License-Identifier: MIT */
/*
** psnr.c: the peak signal-to-noise ratio of two images, for the POV-Ray
** parity suite (parity.sh).
**
** Usage: psnr A B. Prints "PSNR_dB MAX_ERROR" and exits 0, or 2 when an
** image cannot be read or the sizes differ. Both images are read with
** iris_image_read (8-bit sRGB decoded to linear), re-encoded to sRGB and
** compared over the RGB channels with peak 1, i.e. on the display values
** that a viewer compares; identical images give "inf".
*/
#include "config.h"

#include <math.h>
#include <stdio.h>

#include "iris/image.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: psnr A B\n");
        return 2;
    }
    iris_image a, b;
    char err[256];
    if (iris_image_read(&a, argv[1], err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "psnr: %s: %s\n", argv[1], err);
        return 2;
    }
    if (iris_image_read(&b, argv[2], err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "psnr: %s: %s\n", argv[2], err);
        iris_image_fini(&a);
        return 2;
    }
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "psnr: sizes differ: %dx%d and %dx%d\n", a.width,
                a.height, b.width, b.height);
        iris_image_fini(&a);
        iris_image_fini(&b);
        return 2;
    }
    double se = 0, maxe = 0;
    size_t n = (size_t)a.width * a.height;
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) {
            double x = iris_srgb_encode(a.pixels[i * 4 + k]);
            double y = iris_srgb_encode(b.pixels[i * 4 + k]);
            double d = fabs(fmin(fmax(x, 0), 1) - fmin(fmax(y, 0), 1));
            se += d * d;
            if (d > maxe)
                maxe = d;
        }
    double mse = se / (3.0 * n);
    if (mse == 0)
        printf("inf %.4f\n", maxe);
    else
        printf("%.2f %.4f\n", 10 * log10(1.0 / mse), maxe);
    iris_image_fini(&a);
    iris_image_fini(&b);
    return 0;
}
