/* SPDX-License-Identifier: MIT */
/*
** indices.h: the texture numbers of a material_map image, as POV-Ray 3.7
** reads them (material_map in source/core/support/imageutil.cpp).
**
** A material_map picks one of its textures per texel: a palette image
** gives the texel's palette index, any other image the red channel's
** stored value times 255, truncated (so an 8-bit grey or colour image
** gives its red byte). The number is taken modulo the texture count by
** the caller.
*/
#ifndef IRIS_IMAGE_INDICES_H
#define IRIS_IMAGE_INDICES_H

#include <stdbool.h>
#include <stddef.h>

#include "iris/common.h"

/*
** Reads 'path' and returns in '*index' (iris_malloc'ed, iris_free)
** width x height numbers >= 0 in image order (row 0 at the top). PNG
** files are read with libpng, GIF files with gif_indices.c (the palette
** indices are only there); other
** formats through iris_image_read, their 8-bit values taken as stored
** (the sRGB decoding undone). '*palette' tells whether the numbers are
** palette indices (a palette PNG or a GIF). On failure returns an error
** status with a message in 'err'.
*/
IRIS_NODISCARD enum iris_status iris_image_read_indices(const char *path,
                                                        int **index,
                                                        int *width,
                                                        int *height,
                                                        bool *palette,
                                                        char *err,
                                                        size_t errlen);

#endif
