/* SPDX-License-Identifier: MIT */
/*
** heights.h: the heights of a height_field image, as POV-Ray 3.7 reads
** them (image_height_at in source/backend/support/imageutil.cpp).
**
** A height field is data, not a picture: POV-Ray takes no gamma and, for
** most files, not the grey level either. A palette image gives its
** palette indices (index * 256, so 255 reaches 0.996, not 1); a grey image
** its grey level; an 8-bit colour image its red channel as the high byte
** and green as the low byte of a 16-bit height (the old fractal and
** terrain generators' convention; blue is ignored); a 16-bit colour image
** the grey 0.297 R + 0.589 G + 0.114 B. A grey image read as colour (a
** JPEG) comes out the same by either rule.
*/
#ifndef IRIS_IMAGE_HEIGHTS_H
#define IRIS_IMAGE_HEIGHTS_H

#include <stddef.h>

#include "iris/common.h"

/*
** Reads 'path' and returns in '*heights' (iris_malloc'ed, iris_free)
** width x height heights in [0, 1) in image order (row 0 at the top),
** each POV-Ray's 16-bit height divided by 65536. PNG files are read with
** libpng (palette indices are only there); other formats through
** iris_image_read. On failure returns an error status with a message in
** 'err'.
*/
IRIS_NODISCARD enum iris_status iris_image_read_heights(const char *path,
                                                        double **heights,
                                                        int *width,
                                                        int *height,
                                                        char *err,
                                                        size_t errlen);

#endif
