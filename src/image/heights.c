/* SPDX-License-Identifier: MIT */
/*
** heights.c: height_field image heights as POV-Ray reads them (heights.h).
*/
#include "config.h"

#include "image/heights.h"
#include "image/gif_indices.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image/png.h"
#include "iris/image.h"
#include "util/mem.h"

/* POV-Ray keeps heights as unsigned 16-bit values (HF_VAL, truncated from
** its float computations) over a height of 65536 units. */
static double hf_val(double v16)
{
    if (!(v16 > 0))
        return 0.0;
    if (v16 > 65535.0)
        v16 = 65535.0;
    return floor(v16) / 65536.0;
}

/* The 8-bit colour rule: red the high byte, green the low byte. */
static double rg_height(double r, double g)
{
    return hf_val((r * 256.0 + g) * 255.0);
}

static double grey3_height(double r, double g, double b)
{
    return hf_val((0.297 * r + 0.589 * g + 0.114 * b) * 65535.0);
}

/*
** A PNG, keeping palette indices (which png.c's colour reader expands to
** colours). Returns 0, 1 when the file is not a PNG, -1 on an error.
*/
static int png_heights(const char *path, double **out_h, int *width,
                       int *height, char *err, size_t errlen)
{
    struct png_samples s;
    int rc = png_read_samples(path, true, &s, err, errlen);
    if (rc != 0)
        return rc;
    size_t n = (size_t)s.width * s.height;
    double *out = iris_malloc(sizeof *out * (n ? n : 1));
    if (!out) {
        snprintf(err, errlen, "%s: out of memory", path);
        free(s.v);
        return -1;
    }
    double maxv = s.depth == 16 ? 65535.0 : 255.0;
    int nch = s.channels;
    for (size_t i = 0; i < n; i++) {
        const unsigned short *px = s.v + i * (size_t)nch;
        if (s.indexed)
            out[i] = hf_val(px[0] * 256.0);
        else if (s.grey)
            out[i] = hf_val(px[0] / maxv * 65535.0);
        else if (s.depth == 16)
            out[i] = grey3_height(px[0] / maxv, px[1] / maxv, px[2] / maxv);
        else
            out[i] = rg_height(px[0] / maxv, px[1] / maxv);
    }
    free(s.v);
    *width = s.width;
    *height = s.height;
    *out_h = out;
    return 0;
}

/*
** Any other format, through iris_image_read (which decodes 8-bit files
** from sRGB: undone here, since POV-Ray takes a height field's values as
** stored). The reader does not say the file's bit depth; a file whose
** every value is a whole multiple of 1/255 is taken as 8-bit (JPEG, TGA,
** PPM, BMP), anything else as deeper. Palette files other than PNG (GIF,
** BMP) give their colours here, not their indices.
*/
static enum iris_status other_heights(const char *path, double **out_h,
                                      int *width, int *height, char *err,
                                      size_t errlen)
{
    iris_image img;
    enum iris_status st = iris_image_read(&img, path, err, errlen);
    if (st != IRIS_OK)
        return st;
    size_t n = (size_t)img.width * img.height;
    double *out = iris_malloc(sizeof *out * (n ? n : 1));
    if (!out) {
        iris_image_fini(&img);
        snprintf(err, errlen, "%s: out of memory", path);
        return IRIS_ENOMEM;
    }
    bool eight_bit = true;
    for (size_t i = 0; i < n * 4 && eight_bit; i++) {
        if (i % 4 == 3)
            continue;
        double v = iris_srgb_encode(img.pixels[i]) * 255.0;
        eight_bit = fabs(v - floor(v + 0.5)) < 1e-3;
    }
    for (size_t i = 0; i < n; i++) {
        double r = iris_srgb_encode(img.pixels[4 * i]);
        double g = iris_srgb_encode(img.pixels[4 * i + 1]);
        double b = iris_srgb_encode(img.pixels[4 * i + 2]);
        if (eight_bit)
            out[i] = rg_height(floor(r * 255.0 + 0.5) / 255.0,
                               floor(g * 255.0 + 0.5) / 255.0);
        else
            out[i] = grey3_height(r, g, b);
    }
    *width = img.width;
    *height = img.height;
    *out_h = out;
    iris_image_fini(&img);
    return IRIS_OK;
}

enum iris_status iris_image_read_heights(const char *path, double **heights,
                                         int *width, int *height, char *err,
                                         size_t errlen)
{
    *heights = NULL;
    *width = *height = 0;
    int rc = png_heights(path, heights, width, height, err, errlen);
    if (rc < 0)
        return IRIS_EIO;
    if (rc == 0)
        return IRIS_OK;
    if (gif_is_gif(path)) /* palette indices, which iris_image_read loses */
        return gif_read_heights(path, heights, width, height, err, errlen)
                   ? IRIS_EIO : IRIS_OK;
    return other_heights(path, heights, width, height, err, errlen);
}
