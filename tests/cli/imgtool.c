/* SPDX-License-Identifier: MIT */
/*
** imgtool.c: a small image inspector for shell tests.
**
**   imgtool size FILE          prints "W H"
**   imgtool pixel FILE X Y     prints the linear "r g b" at (X, Y)
**   imgtool stats FILE         prints "min max mean bad" over r, g, b,
**                              bad = NaN, Inf or negative values
**   imgtool psnr A B           prints the PSNR in dB of B against A on
**                              sRGB-encoded values clipped to [0,1]
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iris/image.h"

static int load(iris_image *img, const char *path)
{
    char err[512];
    if (iris_image_read(img, path, err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "imgtool: %s\n", err);
        return -1;
    }
    return 0;
}

static int run(int argc, char **argv, iris_image *a, iris_image *b);

static double enc(double v)
{
    v = iris_srgb_encode(v);
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

int main(int argc, char **argv)
{
    iris_image a = { 0, 0, NULL }, b = { 0, 0, NULL };
    int rc = run(argc, argv, &a, &b);
    iris_image_fini(&a);
    iris_image_fini(&b);
    return rc;
}

static int run(int argc, char **argv, iris_image *a, iris_image *b)
{
    if (argc == 3 && !strcmp(argv[1], "size")) {
        if (load(a, argv[2]))
            return 1;
        printf("%d %d\n", a->width, a->height);
    } else if (argc == 5 && !strcmp(argv[1], "pixel")) {
        if (load(a, argv[2]))
            return 1;
        int x = atoi(argv[3]), y = atoi(argv[4]);
        if (x < 0 || y < 0 || x >= a->width || y >= a->height)
            return 1;
        const float *p = a->pixels + ((size_t)y * a->width + x) * 4;
        printf("%.6f %.6f %.6f\n", p[0], p[1], p[2]);
    } else if (argc == 3 && !strcmp(argv[1], "stats")) {
        if (load(a, argv[2]))
            return 1;
        double lo = INFINITY, hi = -INFINITY, sum = 0;
        long bad = 0, n = 0;
        for (size_t i = 0; i < (size_t)a->width * a->height; i++)
            for (int c = 0; c < 3; c++) {
                double v = a->pixels[i * 4 + c];
                if (!isfinite(v) || v < 0) {
                    bad++;
                    continue;
                }
                lo = fmin(lo, v);
                hi = fmax(hi, v);
                sum += v;
                n++;
            }
        printf("%.6f %.6f %.6f %ld\n", lo, hi, n ? sum / n : 0.0, bad);
    } else if (argc == 4 && !strcmp(argv[1], "psnr")) {
        if (load(a, argv[2]) || load(b, argv[3]))
            return 1;
        if (a->width != b->width || a->height != b->height) {
            fprintf(stderr, "imgtool: sizes differ\n");
            return 1;
        }
        double se = 0;
        size_t n = (size_t)a->width * a->height;
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < 3; c++) {
                double d = enc(a->pixels[i * 4 + c]) - enc(b->pixels[i * 4 + c]);
                se += d * d;
            }
        double mse = se / (double)(n * 3);
        printf("%.2f\n", mse > 0 ? 10 * log10(1.0 / mse) : 99.0);
    } else {
        fputs("usage: imgtool size|pixel|stats|psnr ...\n", stderr);
        return 2;
    }
    return 0;
}
