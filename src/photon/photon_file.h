/* SPDX-License-Identifier: MIT */
/*
** photon_file.h: photons { save_file "f" } and { load_file "f" } (issue
** 8): the caustic photon map written to a file after it is built, and
** read back instead of shooting (POV-Ray: "load skips shooting").
**
** What is saved is the built store (pstore.h): the 16-byte records in
** kd-tree order with their quantisation box, so a loaded map is the saved
** one bit for bit and renders the same image. The estimate's parameters
** (gather, radius, expand_thresholds) come from the scene that loads it,
** as in POV-Ray. The global map of radiosity{} is not saved: it is built
** as usual. File format: photon_file.c.
**
** Depends on: photon (pmap.h), accel. Used by: render.c.
*/
#ifndef IRIS_PHOTON_PHOTON_FILE_H
#define IRIS_PHOTON_PHOTON_FILE_H

#include <stddef.h>

#include "photon/photon.h"

/*
** Writes the caustic store of 'm' (its global map is left out) to 'path',
** with 'shot', the photons emitted to build it. Returns IRIS_OK, or
** IRIS_EIO with a message in 'err'. An empty or NULL map writes a file of
** no photons.
*/
IRIS_NODISCARD enum iris_status
photon_file_save(const struct photon_map *m, long long shot, const char *path,
                 char *err, size_t errlen);

/*
** The photon map of 'scene' with its caustic store read from 'path'
** instead of shot; the global map (radiosity{}) is built as by
** photon_map_build(). *out and 'stats' as photon_map_build's (stats->shot
** is the count saved in the file). Returns IRIS_OK, IRIS_ENOMEM, or
** IRIS_EIO with a message in 'err' (missing, truncated, damaged or
** foreign file, or another record layout or version).
*/
IRIS_NODISCARD enum iris_status
photon_file_load(const iris_scene *scene, const struct accel *accel,
                 const struct photon_options *opts, const char *path,
                 struct photon_map **out, struct photon_stats *stats,
                 char *err, size_t errlen);

#endif
