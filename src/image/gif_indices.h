/* SPDX-License-Identifier: MIT */
/*
** gif_indices.h: the palette indices of a GIF file's first image.
**
** A height_field from a GIF is data: POV-Ray takes each pixel's palette
** index (index * 256 of 65536), and a POT file (Fractint's 16-bit
** "potential" format, a GIF twice as wide as the field) has the high
** bytes in its left half and the low bytes in its right half. The colour
** image readers expand palettes to colours and lose the indices, so the
** height reader decodes GIF's LZW stream itself.
*/
#ifndef IRIS_IMAGE_GIF_INDICES_H
#define IRIS_IMAGE_GIF_INDICES_H

#include <stddef.h>
#include <stdint.h>

/* True when the file starts with a GIF signature ("GIF87a"/"GIF89a"). */
int gif_is_gif(const char *path);

/*
** Decodes the first image of GIF file 'path' into '*idx' (malloc'ed,
** free with free(), row 0 at the top, rows in stored order: POV-Ray 3.7
** does not undo interlacing), 'width' x
** 'height' palette indices. Pixels the LZW stream does not reach are 0.
** Returns 0, or -1 with a message in 'err' (never crashes on a truncated
** or corrupt file).
*/
int gif_read_indices(const char *path, uint8_t **idx, int *width,
                     int *height, char *err, size_t errlen);

/*
** The heights POV-Ray's height_field takes from GIF file 'path', each
** its 16-bit HF_VAL / 65536, row 0 at the top: index * 256 for a GIF; for
** a file named *.pot (POV-Ray's 'pot' keyword; iris tells it by the name)
** half the width, with height (left index << 8 | right index). Returns 0,
** or -1 with a message in 'err'. '*heights' is freed with iris_free.
*/
int gif_read_heights(const char *path, double **heights, int *width,
                     int *height, char *err, size_t errlen);

#endif
