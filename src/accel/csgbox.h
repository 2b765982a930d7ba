/* SPDX-License-Identifier: MIT */
/*
** csgbox.h: narrowing the box of a CSG intersection by its unbounded
** children (planes, quadrics without cross terms); see csgbox.c.
*/
#ifndef IRIS_ACCEL_CSGBOX_H
#define IRIS_ACCEL_CSGBOX_H

#include <stdbool.h>

#include "iris/scene.h"
#include "math/transform.h"
#include "math/vec3.h"

/*
** Narrows world box lo..hi (sides may be +-INFINITY) to a box holding
** every point of it inside 'o' (not inverted, world transform included).
** Kinds it cannot narrow leave the box as it is. Returns false when no
** point of the box is inside 'o'.
*/
bool csgbox_narrow(const iris_object *o, vec3 *lo, vec3 *hi);

#endif
