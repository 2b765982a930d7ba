/* SPDX-License-Identifier: MIT */
/*
** povbox.h: the bounding box POV-Ray 3.7 gives a photon target that
** holds a blob, for the photon count estimate (povbox.c).
*/
#ifndef IRIS_PHOTON_POVBOX_H
#define IRIS_PHOTON_POVBOX_H

#include <stdbool.h>

#include "iris/scene.h"
#include "math/vec3.h"

/* A leaf's world box as iris bounds it (pmap_world.object_bounds). */
typedef bool (*povbox_leaf_fn)(const void *ctx, const iris_object *o,
                               vec3 *lo, vec3 *hi);

/*
** POV-Ray's box of target 't' into *lo, *hi when it differs from iris's
** by rule: 't' holds a blob (POV-Ray bounds a blob by its components'
** bounding spheres, wider than the blob). Other leaves take 'leaf's
** box, CSG nodes combine them as POV-Ray's CSG::Compute_BBox does.
** Returns false (iris's own box stands) when 't' holds no blob, or a
** node clipped or bounded by another object, or a leaf without a box.
*/
bool povbox_target(const iris_object *t, povbox_leaf_fn leaf,
                   const void *ctx, vec3 *lo, vec3 *hi);

/*
** POV-Ray's world box of blob 'o' (Blob::Compute_BBox: its positive
** components' bounding spheres, then the blob's transform by the box's
** corners): what POV-Ray's min_extent/max_extent return for a blob.
** False when 'o' is not a blob or has no positive component.
*/
bool povbox_blob(const iris_object *o, vec3 *lo, vec3 *hi);

#endif
