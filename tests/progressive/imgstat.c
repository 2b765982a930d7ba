/* SPDX-License-Identifier: MIT */
/*
** imgstat.c: prints the mean and the standard deviation over the pixels
** of an image's linear R, G and B ("mean_r mean_g mean_b sd_r sd_g sd_b"),
** for tests that compare a render with an analytic value (radiosity.sh).
**
** Usage: imgstat image.exr
*/
#include "config.h"

#include <math.h>
#include <stdio.h>

#include "iris/image.h"

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: imgstat image.exr\n");
        return 2;
    }
    iris_image a;
    char err[256] = "";
    if (iris_image_read(&a, argv[1], err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "imgstat: %s\n", err);
        return 1;
    }
    size_t n = (size_t)a.width * a.height;
    double s[3] = { 0, 0, 0 }, s2[3] = { 0, 0, 0 };
    for (size_t i = 0; i < n; i++)
        for (int c = 0; c < 3; c++) {
            double v = a.pixels[4 * i + c];
            s[c] += v;
            s2[c] += v * v;
        }
    for (int c = 0; c < 3; c++)
        printf("%.6f ", n ? s[c] / n : 0.0);
    for (int c = 0; c < 3; c++) {
        double m = n ? s[c] / n : 0.0;
        double var = n ? s2[c] / n - m * m : 0.0;
        printf(c < 2 ? "%.6f " : "%.6f\n", var > 0 ? sqrt(var) : 0.0);
    }
    iris_image_fini(&a);
    return 0;
}
