/* SPDX-License-Identifier: MIT */
/*
** imgcheck.c: image measurements for the stability tests.
**
**   imgcheck FILE        prints "bad maxc maxY meanY"
**   imgcheck same A B    exits 0 when A and B hold the same pixels, bit
**                        for bit (file metadata such as a DateTime is
**                        not compared), else prints the first difference
**   imgcheck colour FILE prints "meanR meanG meanB spread": the mean of
**                        each channel and the largest max - min of the
**                        channels of one pixel (0 for a grey image)
**
** over the linear r, g, b of every pixel: 'bad' counts NaN, Inf and
** negative values, 'maxc' is the largest channel value, 'maxY' and
** 'meanY' the largest and mean luminance Y = 0.2126 r + 0.7152 g +
** 0.0722 b (the Rec. 709 / sRGB weights). The energy bounds of
** stability.sh are stated on these numbers. Bad values are left out of
** the maxima and means so that one NaN does not hide the others.
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "iris/image.h"

static int load(iris_image *img, const char *path)
{
    char err[512];
    if (iris_image_read(img, path, err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "imgcheck: %s\n", err);
        return -1;
    }
    return 0;
}

/* Compares the pixels of two files exactly: 0 same, 1 different. */
static int same(const char *pa, const char *pb)
{
    iris_image a, b;
    if (load(&a, pa))
        return 1;
    if (load(&b, pb)) {
        iris_image_fini(&a);
        return 1;
    }
    int rc = 0;
    if (a.width != b.width || a.height != b.height) {
        printf("sizes differ: %dx%d, %dx%d\n", a.width, a.height, b.width,
               b.height);
        rc = 1;
    } else {
        size_t n = (size_t)a.width * (size_t)a.height * 4;
        for (size_t i = 0; i < n; i++)
            if (memcmp(&a.pixels[i], &b.pixels[i], sizeof(float))) {
                printf("pixel (%zu, %zu) channel %zu: %.9g, %.9g\n",
                       i / 4 % (size_t)a.width, i / 4 / (size_t)a.width,
                       i % 4, a.pixels[i], b.pixels[i]);
                rc = 1;
                break;
            }
    }
    iris_image_fini(&a);
    iris_image_fini(&b);
    return rc;
}

/* Mean colour and greyness (the 'colour' command). */
static int colour(const char *path)
{
    iris_image img;
    if (load(&img, path))
        return 1;
    double sum[3] = { 0, 0, 0 }, spread = 0;
    size_t n = (size_t)img.width * (size_t)img.height;
    for (size_t i = 0; i < n; i++) {
        const float *p = img.pixels + i * 4;
        for (int c = 0; c < 3; c++)
            sum[c] += p[c];
        spread = fmax(spread, fmax(p[0], fmax(p[1], p[2])) -
                                  fmin(p[0], fmin(p[1], p[2])));
    }
    double d = n ? (double)n : 1.0;
    printf("%.6g %.6g %.6g %.6g\n", sum[0] / d, sum[1] / d, sum[2] / d,
           spread);
    iris_image_fini(&img);
    return 0;
}

int main(int argc, char **argv)
{
    iris_image img;
    if (argc == 4 && !strcmp(argv[1], "same"))
        return same(argv[2], argv[3]);
    if (argc == 3 && !strcmp(argv[1], "colour"))
        return colour(argv[2]);
    if (argc != 2) {
        fputs("usage: imgcheck FILE | imgcheck same A B | imgcheck colour "
              "FILE\n", stderr);
        return 2;
    }
    if (load(&img, argv[1]))
        return 1;
    long bad = 0;
    double maxc = 0, maxy = 0, sumy = 0;
    size_t n = (size_t)img.width * (size_t)img.height;
    for (size_t i = 0; i < n; i++) {
        const float *p = img.pixels + i * 4;
        bool ok = true;
        for (int c = 0; c < 3; c++) {
            if (!isfinite(p[c]) || p[c] < 0) {
                bad++;
                ok = false;
            } else if (p[c] > maxc) {
                maxc = p[c];
            }
        }
        if (!ok)
            continue;
        double y = 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
        maxy = fmax(maxy, y);
        sumy += y;
    }
    printf("%ld %.6g %.6g %.6g\n", bad, maxc, maxy, n ? sumy / (double)n : 0.0);
    iris_image_fini(&img);
    return 0;
}
