/* SPDX-License-Identifier: MIT */
/*
** image.h: float images and image files (through OpenImageIO).
**
** Pixels are linear RGBA floats, row 0 at the top. Writing picks the
** format from the file name's extension: .png (8-bit, sRGB-encoded as
** POV-Ray writes it), .exr (linear, 32-bit float), .tif, .hdr, .jpg, .pfm.
** Writes are atomic: a temporary file in the same directory, then rename.
*/
#ifndef IRIS_IMAGE_H
#define IRIS_IMAGE_H

#include <stddef.h>

#include "iris/common.h"
#include "iris/scene.h"

#ifdef __cplusplus
extern "C" {
#endif


typedef struct iris_image {
    int width, height;
    float *pixels;             /* width*height*4 floats: r g b a */
} iris_image;

/* Allocates a black, transparent image. */
IRIS_NODISCARD enum iris_status iris_image_init(iris_image *img, int width,
                                                int height);
void iris_image_fini(iris_image *img);

/* Output pixel encoding for 8/16-bit formats. */
enum iris_encoding { IRIS_ENC_SRGB = 0, IRIS_ENC_LINEAR };

/*
** Writes 'img' to 'path'. 'bits' is 8 or 16 for integer formats (0 = the
** format's default). NaN and Inf never reach a file: they are written as 0
** and counted in '*n_bad' when not NULL. 'err' (may be NULL) receives a
** message of at most 'errlen' bytes on failure.
*/
IRIS_NODISCARD enum iris_status iris_image_write(const iris_image *img,
                                                 const char *path, int bits,
                                                 enum iris_encoding enc,
                                                 char *err, size_t errlen);

/*
** iris_image_write() with an alpha channel when 'alpha' (iris's +UA): the
** pixels hold colour premultiplied by alpha, as the renderer leaves them.
** Integer formats (PNG) get straight alpha as POV-Ray writes it: a pixel
** brighter than its alpha (a highlight on glass) has its alpha raised to
** its brightness, at most 1, then the colour is divided by the alpha
** (colour 0 where alpha is 0). Float formats (EXR) keep the premultiplied
** colour, OpenEXR's convention, with an A channel.
*/
IRIS_NODISCARD enum iris_status iris_image_write_alpha(const iris_image *img,
                                                       const char *path,
                                                       int bits,
                                                       enum iris_encoding enc,
                                                       bool alpha, char *err,
                                                       size_t errlen);

/* Reads any format OpenImageIO reads into linear RGBA floats (8-bit sRGB
** files are decoded to linear). */
IRIS_NODISCARD enum iris_status iris_image_read(iris_image *img,
                                                const char *path, char *err,
                                                size_t errlen);

/* The sRGB transfer function (IEC 61966-2-1). */
double iris_srgb_encode(double linear);
double iris_srgb_decode(double encoded);

#ifdef __cplusplus
}
#endif

#endif
