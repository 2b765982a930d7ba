/* SPDX-License-Identifier: MIT */
/*
** imgcheck.c: image measurements for the stability tests.
**
**   imgcheck FILE   prints "bad maxc maxY meanY"
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

#include "iris/image.h"

int main(int argc, char **argv)
{
    iris_image img;
    char err[512];
    if (argc != 2) {
        fputs("usage: imgcheck FILE\n", stderr);
        return 2;
    }
    if (iris_image_read(&img, argv[1], err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "imgcheck: %s\n", err);
        return 1;
    }
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
