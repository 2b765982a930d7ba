/* SPDX-License-Identifier: MIT */
/*
** indices.c: material_map texture numbers of an image (indices.h).
*/
#include "config.h"

#include "image/indices.h"

#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>

#include "image/gif_indices.h"
#include "image/png.h"
#include "iris/image.h"
#include "util/mem.h"

/* POV-Ray's (int)(red * 255.0) of a stored value in [0, 1]; the 1e-6
** keeps an 8-bit value k/255, which float arithmetic may leave a hair
** under k, at k. */
static int red_number(double red)
{
    if (!(red > 0))
        return 0;
    if (red > 1)
        red = 1;
    return (int)(red * 255.0 + 1e-6);
}

/* A PNG, keeping palette indices. Returns 0, 1 when the file is not a
** PNG, -1 on an error. */
static int png_indices(const char *path, int **out_i, int *width,
                       int *height, bool *palette, char *err, size_t errlen)
{
    struct png_samples s;
    int rc = png_read_samples(path, true, &s, err, errlen);
    if (rc != 0)
        return rc;
    size_t n = (size_t)s.width * s.height;
    int *out = iris_malloc(sizeof *out * (n ? n : 1));
    if (!out) {
        snprintf(err, errlen, "%s: out of memory", path);
        free(s.v);
        return -1;
    }
    double maxv = s.depth == 16 ? 65535.0 : 255.0;
    for (size_t i = 0; i < n; i++) {
        unsigned short v = s.v[i * (size_t)s.channels];
        out[i] = s.indexed ? (int)v : red_number(v / maxv);
    }
    *palette = s.indexed;
    free(s.v);
    *width = s.width;
    *height = s.height;
    *out_i = out;
    return 0;
}

enum iris_status iris_image_read_indices(const char *path, int **index,
                                         int *width, int *height,
                                         bool *palette, char *err,
                                         size_t errlen)
{
    *index = NULL;
    *width = *height = 0;
    *palette = false;
    int rc = png_indices(path, index, width, height, palette, err, errlen);
    if (rc < 0)
        return IRIS_EIO;
    if (rc == 0)
        return IRIS_OK;
    if (gif_is_gif(path)) {
        uint8_t *g = NULL;
        if (gif_read_indices(path, &g, width, height, err, errlen) != 0)
            return IRIS_EIO;
        size_t n = (size_t)*width * *height;
        int *out = iris_malloc(sizeof *out * (n ? n : 1));
        if (!out) {
            free(g);
            snprintf(err, errlen, "%s: out of memory", path);
            return IRIS_ENOMEM;
        }
        for (size_t i = 0; i < n; i++)
            out[i] = g[i];
        free(g);
        *index = out;
        *palette = true;
        return IRIS_OK;
    }
    /* Other formats come decoded from sRGB; palette files other than PNG
    ** and GIF (BMP) give their colours' red here, not their indices. */
    iris_image img;
    enum iris_status st = iris_image_read(&img, path, err, errlen);
    if (st != IRIS_OK)
        return st;
    size_t n = (size_t)img.width * img.height;
    int *out = iris_malloc(sizeof *out * (n ? n : 1));
    if (!out) {
        iris_image_fini(&img);
        snprintf(err, errlen, "%s: out of memory", path);
        return IRIS_ENOMEM;
    }
    for (size_t i = 0; i < n; i++)
        out[i] = red_number(iris_srgb_encode(img.pixels[4 * i]));
    *width = img.width;
    *height = img.height;
    *index = out;
    iris_image_fini(&img);
    return IRIS_OK;
}
