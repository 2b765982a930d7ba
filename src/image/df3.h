/* SPDX-License-Identifier: MIT */
/*
** df3.h: POV-Ray's density files (.df3), for the density_file pattern.
**
** The format: three big-endian 16-bit sizes nx, ny, nz, then nx*ny*nz
** voxels, x fastest, then y, then z, each 1, 2 or 4 bytes big-endian;
** which one is told by the file's length alone (POV-Ray's
** Read_Density_File). A voxel's density is its value over the type's
** maximum (255, 65535, 4294967295).
*/
#ifndef IRIS_IMAGE_DF3_H
#define IRIS_IMAGE_DF3_H

#include <stddef.h>

#include "iris/common.h"

typedef struct iris_df3 {
    int nx, ny, nz;
    float *v;                  /* nx*ny*nz densities in [0, 1] (iris_free) */
} iris_df3;

/*
** Checks a .df3 file's header against its length: IRIS_OK with the voxel
** size in bytes (1, 2 or 4) in '*bytes', else IRIS_EIO (unreadable) or
** IRIS_EINVAL (truncated, or a length no voxel size explains) with a
** message in 'err'. Reads 6 bytes, whatever the file's size.
*/
IRIS_NODISCARD enum iris_status iris_df3_check(const char *path, int *nx,
                                               int *ny, int *nz, int *bytes,
                                               char *err, size_t errlen);

/* Reads the whole file into 'out' (iris_df3_fini frees it). */
IRIS_NODISCARD enum iris_status iris_df3_read(const char *path,
                                              iris_df3 *out, char *err,
                                              size_t errlen);
void iris_df3_fini(iris_df3 *d);

/*
** POV-Ray 3.7.0's density_pattern at pattern-space point (x, y, z): 0
** outside the unit cube [0, 1)^3; inside, the voxel grid stretched over
** the cube, read with no interpolation (interpolate 0), trilinearly (1,
** wrapping at the far faces) or tricubically (2, POV-Ray's Catmull-Rom
** intp3 in single precision and its unsigned index wrap at the near
** faces); interpolate is taken modulo 10. Never negative.
*/
double iris_df3_density(const iris_df3 *d, int interpolate, double x,
                        double y, double z);

#endif
