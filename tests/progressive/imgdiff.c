/* SPDX-License-Identifier: MIT */
/*
** imgdiff.c: prints the largest absolute difference between two images'
** linear RGBA values (0 when they are identical), for progressive.sh's
** exact comparisons (imgtool's PSNR clamps values above 1).
**
** Usage: imgdiff a.exr b.exr
*/
#include "config.h"

#include <math.h>
#include <stdio.h>

#include "iris/image.h"

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: imgdiff a.exr b.exr\n");
        return 2;
    }
    iris_image a, b;
    char err[256] = "";
    if (iris_image_read(&a, argv[1], err, sizeof err) != IRIS_OK ||
        iris_image_read(&b, argv[2], err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "imgdiff: %s\n", err);
        return 1;
    }
    if (a.width != b.width || a.height != b.height) {
        fprintf(stderr, "imgdiff: sizes differ\n");
        return 1;
    }
    double d = 0;
    for (size_t i = 0; i < (size_t)a.width * a.height * 4; i++) {
        double x = fabs((double)a.pixels[i] - b.pixels[i]);
        d = isfinite(x) ? fmax(d, x) : INFINITY;
    }
    printf("%g\n", d);
    iris_image_fini(&a);
    iris_image_fini(&b);
    return 0;
}
