/* SPDX-License-Identifier: MIT */
/*
** image.c: float RGBA images and the sRGB transfer function.
**
** File input and output are in oiio.cc (OpenImageIO is a C++ library);
** this file holds what needs no library.
*/
#include "config.h"

#include <math.h>
#include <stdint.h>

#include "iris/image.h"
#include "util/mem.h"

enum iris_status iris_image_init(iris_image *img, int width, int height)
{
    img->width = img->height = 0;
    img->pixels = NULL;
    if (width <= 0 || height <= 0 || width > 1 << 16 || height > 1 << 16)
        return IRIS_EINVAL;
    img->pixels = iris_calloc((size_t)width * (size_t)height * 4, sizeof(float));
    if (!img->pixels)
        return IRIS_ENOMEM;
    img->width = width;
    img->height = height;
    return IRIS_OK;
}

void iris_image_fini(iris_image *img)
{
    iris_free(img->pixels);
    img->pixels = NULL;
    img->width = img->height = 0;
}

/* IEC 61966-2-1; constants from ../shared/data/srgb.md. */
double iris_srgb_encode(double l)
{
    if (!(l > 0.0))
        return 0.0;
    if (l <= 0.0031308)
        return 12.92 * l;
    return 1.055 * pow(l, 1.0 / 2.4) - 0.055;
}

double iris_srgb_decode(double v)
{
    if (!(v > 0.0))
        return 0.0;
    if (v <= 0.04045)
        return v / 12.92;
    return pow((v + 0.055) / 1.055, 2.4);
}
