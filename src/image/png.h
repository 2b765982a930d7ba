/* SPDX-License-Identifier: MIT */
/*
** png.h: PNG files through libpng, the fast path for the default format.
**
** Loading the OpenImageIO module costs 0.3 s of CPU (0.8 s of wall time on
** a busy machine) in relocations, more than a whole small render. PNG is
** iris's and POV-Ray's default output and the usual image_map input, so it
** is written and read with libpng directly; every other format goes
** through the module. The pixel conversions are the caller's (image_io.c).
*/
#ifndef IRIS_IMAGE_PNG_H
#define IRIS_IMAGE_PNG_H

#include <stdbool.h>
#include <stddef.h>

/* Writes 8- or 16-bit RGB ('nch' 3) or RGBA ('nch' 4, straight alpha as
** PNG defines it) to 'path' (sRGB chunk when 'srgb', as POV-Ray writes),
** through a temporary file renamed into place. Returns 0, or -1 with a
** message in 'err'. 'pixels' holds bytes or native uint16s. */
int png_write_rgb(const char *path, int width, int height, int bits, int nch,
                  const void *pixels, int srgb, char *err, size_t errlen);

/* A PNG's samples as stored, row 0 (the top) first, 'channels' per
** pixel, 8- or 16-bit values by 'depth'. */
struct png_samples {
    int width, height, channels, depth;
    bool indexed;              /* one channel of palette indices */
    bool grey;                 /* the file is grey (plus alpha) */
    unsigned short *v;         /* malloc'ed (free()) */
};

/* Reads a PNG's samples: palette images as their indices when
** 'keep_indices' (POV-Ray's height fields read them so), else as colours,
** and low bit depths expanded to 8. Returns 0, 1 when the file is not a
** PNG (try another reader), or -1 with a message in 'err'. */
int png_read_samples(const char *path, bool keep_indices,
                     struct png_samples *s, char *err, size_t errlen);

/* Reads a PNG as floats in [0,1], 1 to 4 channels as stored (palette and
** low bit depths expanded). '*pixels' is malloc'ed (free()). Returns 0,
** 1 when the file is not a PNG (try another reader), or -1 with 'err'. */
int png_read_float(const char *path, int *width, int *height, int *channels,
                   float **pixels, char *err, size_t errlen);

#endif
