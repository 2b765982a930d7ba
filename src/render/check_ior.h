/* SPDX-License-Identifier: MIT */
/*
** check_ior.h: the scene's spectral indices checked before a render
** (spectrum/ior.c ior_check), reported with their scene location.
*/
#ifndef IRIS_RENDER_CHECK_IOR_H
#define IRIS_RENDER_CHECK_IOR_H

#include <stddef.h>
#include <stdio.h>

#include "iris/common.h"
#include "iris/scene.h"

/*
** Checks the interior of every object (CSG children included): writes
** "file:line:col: warning|error: ..." to 'log' for each interior whose
** index clamps (warning) or names a glass the catalogue lacks (error).
** Returns IRIS_EINVAL after the first error ('err' then refers to the
** message in the log, or holds it when 'log' is NULL); IRIS_OK otherwise.
*/
enum iris_status check_ior(const iris_scene *scene, FILE *log, char *err,
                           size_t errlen);

#endif
