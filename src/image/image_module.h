/* SPDX-License-Identifier: MIT */
/*
** image_module.h: the interface between libiris and its image module.
**
** OpenImageIO lives in a loadable module (iris-oiio.so, built from
** oiio.cc) that image_io.c opens with dlopen() on first use, because
** linking it into every program costs a third of a second of start-up
** relocations. The module only moves pixels between files and memory;
** every conversion (sRGB, quantisation, NaN handling) stays in image_io.c.
*/
#ifndef IRIS_IMAGE_MODULE_H
#define IRIS_IMAGE_MODULE_H

#include <stddef.h>

#define IRIS_OIIO_ABI 1

/* Pixel types of the module's write(). */
enum oiio_type { OIIO_UINT8 = 0, OIIO_UINT16 = 1, OIIO_FLOAT = 2 };

struct iris_oiio_api {
    int abi; /* IRIS_OIIO_ABI */
    /* Writes interleaved pixels to 'path' (the format from its extension),
    ** through a temporary file renamed into place. Returns 0, or -1 with a
    ** message in 'err'. 'colorspace' is "sRGB" or "Linear". */
    int (*write)(const char *path, int width, int height, int channels,
                 enum oiio_type type, const void *pixels,
                 const char *colorspace, char *err, size_t errlen);
    /* Reads the first subimage as floats into a malloc'ed buffer ('*pixels',
    ** freed with free()). '*srgb' is set when integer data is sRGB-encoded
    ** (integer files not tagged linear). Returns 0, or -1 with 'err'. */
    int (*read)(const char *path, int *width, int *height, int *channels,
                float **pixels, int *srgb, char *err, size_t errlen);
};

/* The module's only exported symbol. */
#define IRIS_OIIO_ENTRY "iris_oiio_module"
typedef const struct iris_oiio_api *(*iris_oiio_entry_fn)(void);

#endif
