/* SPDX-License-Identifier: MIT */
/*
** imgprobe.c: reads an image's linear pixels for the optics checks
** (tests/optics/optics.sh), which do the physics in awk. Two reports:
**
**   imgprobe rows IMAGE X0 X1
**       one line per image row, top first: "row r g b", the sums of the
**       linear R, G, B over the columns X0..X1 (inclusive); a profile
**       along the image's height.
**   imgprobe mean IMAGE X0 Y0 X1 Y1
**       "r g b": the mean linear colour over the rectangle of columns
**       X0..X1 and rows Y0..Y1 (inclusive, row 0 at the top).
**   imgprobe range IMAGE X0 Y0 X1 Y1
**       "rmin gmin bmin rmax gmax bmax": the least and greatest linear
**       value of each channel over the rectangle (a uniform image's
**       spread, which a mean would hide); nan if any value is a NaN.
**   imgprobe radial IMAGE RMAX
**       one line per ring of pixels about the image's centre, "k r g b":
**       the mean linear colour of the pixels whose centres lie k..k+1
**       pixels from it, k = 0..RMAX-1; a radial profile.
**
** Coordinates outside the image are an error (exit 2), so a test whose
** scene and window disagree fails loudly instead of measuring nothing.
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iris/image.h"

static int arg_int(const char *s, int hi, int *out)
{
    char *end;
    long v = strtol(s, &end, 10);
    if (*s == '\0' || *end != '\0' || v < 0 || v >= hi)
        return 0;
    *out = (int)v;
    return 1;
}

/* The radial profile of imgprobe radial (see the top); frees the image. */
static int radial_profile(iris_image *a, const char *rmax_arg)
{
    int half = (a->width < a->height ? a->width : a->height) / 2, rmax;
    if (!arg_int(rmax_arg, half + 1, &rmax) || rmax < 1) {
        fprintf(stderr, "imgprobe: RMAX must be 1..%d for the %dx%d image\n",
                half, a->width, a->height);
        iris_image_fini(a);
        return 2;
    }
    double *sum = calloc((size_t)rmax * 4, sizeof *sum);
    if (!sum) {
        iris_image_fini(a);
        return 1;
    }
    double cx = a->width / 2.0, cy = a->height / 2.0;
    for (int y = 0; y < a->height; y++)
        for (int x = 0; x < a->width; x++) {
            double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
            int k = (int)sqrt(dx * dx + dy * dy);
            if (k >= rmax)
                continue;
            for (int c = 0; c < 3; c++)
                sum[4 * k + c] += a->pixels[4 * ((size_t)y * a->width + x) + c];
            sum[4 * k + 3] += 1;
        }
    for (int k = 0; k < rmax; k++) {
        double n = sum[4 * k + 3] > 0 ? sum[4 * k + 3] : 1;
        printf("%d %.9g %.9g %.9g\n", k, sum[4 * k] / n, sum[4 * k + 1] / n,
               sum[4 * k + 2] / n);
    }
    free(sum);
    iris_image_fini(a);
    return 0;
}

static int usage(void)
{
    fprintf(stderr, "usage: imgprobe rows IMAGE X0 X1\n"
                    "       imgprobe mean IMAGE X0 Y0 X1 Y1\n"
                    "       imgprobe range IMAGE X0 Y0 X1 Y1\n"
                    "       imgprobe radial IMAGE RMAX\n");
    return 2;
}

int main(int argc, char **argv)
{
    int rows = argc == 5 && strcmp(argv[1], "rows") == 0;
    int mean = argc == 7 && strcmp(argv[1], "mean") == 0;
    int range = argc == 7 && strcmp(argv[1], "range") == 0;
    int radial = argc == 4 && strcmp(argv[1], "radial") == 0;
    if (!rows && !mean && !range && !radial)
        return usage();
    iris_image a;
    char err[256] = "";
    if (iris_image_read(&a, argv[2], err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "imgprobe: %s\n", err);
        return 1;
    }
    if (radial)
        return radial_profile(&a, argv[3]);
    int x0, x1, y0 = 0, y1 = a.height - 1, ok;
    if (rows)
        ok = arg_int(argv[3], a.width, &x0) && arg_int(argv[4], a.width, &x1);
    else
        ok = arg_int(argv[3], a.width, &x0) &&
             arg_int(argv[4], a.height, &y0) &&
             arg_int(argv[5], a.width, &x1) &&
             arg_int(argv[6], a.height, &y1);
    if (!ok || x1 < x0 || y1 < y0) {
        fprintf(stderr, "imgprobe: window outside the %dx%d image\n",
                a.width, a.height);
        iris_image_fini(&a);
        return 2;
    }
    double tot[3] = { 0, 0, 0 };
    double lo[3] = { INFINITY, INFINITY, INFINITY };
    double hi[3] = { -INFINITY, -INFINITY, -INFINITY };
    for (int y = y0; y <= y1; y++) {
        double s[3] = { 0, 0, 0 };
        for (int x = x0; x <= x1; x++)
            for (int c = 0; c < 3; c++) {
                double v = a.pixels[4 * ((size_t)y * a.width + x) + c];
                s[c] += v;
                /* a NaN sticks (every comparison with it is false), so
                ** that range reports one instead of skipping it */
                lo[c] = v < lo[c] || v != v ? v : lo[c];
                hi[c] = v > hi[c] || v != v ? v : hi[c];
            }
        if (rows)
            printf("%d %.9g %.9g %.9g\n", y, s[0], s[1], s[2]);
        for (int c = 0; c < 3; c++)
            tot[c] += s[c];
    }
    if (mean) {
        double n = (double)(x1 - x0 + 1) * (y1 - y0 + 1);
        printf("%.9g %.9g %.9g\n", tot[0] / n, tot[1] / n, tot[2] / n);
    }
    if (range)
        printf("%.9g %.9g %.9g %.9g %.9g %.9g\n", lo[0], lo[1], lo[2], hi[0],
               hi[1], hi[2]);
    iris_image_fini(&a);
    return 0;
}
