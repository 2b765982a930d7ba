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
**
** psnr --rgba A B compares the alpha channel too (as stored, 0..1) beside
** the three sRGB values; psnr --alpha A B the alpha channel alone (for an
** EXR, whose colour is premultiplied, against a PNG, whose is not).
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iris/image.h"

int main(int argc, char **argv)
{
    int k0 = 0, k1 = 3;        /* channels compared: [k0, k1) */
    if (argc == 4 && !strcmp(argv[1], "--rgba")) {
        k1 = 4;
        argv++;
        argc--;
    } else if (argc == 4 && !strcmp(argv[1], "--alpha")) {
        k0 = 3;
        k1 = 4;
        argv++;
        argc--;
    }
    if (argc != 3) {
        fprintf(stderr, "usage: psnr [--rgba | --alpha] A B\n");
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
        for (int k = k0; k < k1; k++) {
            double x = a.pixels[i * 4 + k], y = b.pixels[i * 4 + k];
            if (k < 3) {
                x = iris_srgb_encode(x);
                y = iris_srgb_encode(y);
            }
            double d = fabs(fmin(fmax(x, 0), 1) - fmin(fmax(y, 0), 1));
            se += d * d;
            if (d > maxe)
                maxe = d;
        }
    double mse = se / ((double)(k1 - k0) * n);
    if (mse == 0)
        printf("inf %.4f\n", maxe);
    else
        printf("%.2f %.4f\n", 10 * log10(1.0 / mse), maxe);
    iris_image_fini(&a);
    iris_image_fini(&b);
    return 0;
}
