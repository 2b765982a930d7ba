/* SPDX-License-Identifier: MIT */
/*
** objpattern.h: the object pattern's inside test (POV-Ray 3.7's
** ObjectPattern: 1 where the pattern-space point is inside the object,
** else 0, so the second list entry shows inside it).
**
** The object of 'pigment { object { OBJ A, B } }' is in no scene list and
** so not in the accel; its leaves are prepared here once, when the
** material context is made (geom_prepare: the outlines of text, prism and
** lathe), and the test walks the object's own tree. Read-only afterwards,
** so any number of threads may ask.
**
** Depends on: math, util, geometry. Used by: texture.c, pattern.c.
*/
#ifndef IRIS_MATERIAL_OBJPATTERN_H
#define IRIS_MATERIAL_OBJPATTERN_H

#include <stdbool.h>
#include <stdio.h>

#include "iris/scene.h"
#include "iris/common.h"
#include "math/vec3.h"

struct objpat_leaf;

/* The prepared leaves of every object pattern of a scene. */
struct objpat_set {
    int n, cap;
    struct objpat_leaf *v;     /* sorted by object once objpat_seal ran */
};

/*
** Prepares every leaf of 'o' (children and clipped_by included) once;
** an object already added is skipped. A leaf that cannot be prepared is
** reported to 'log' with its location and counts as outside. IRIS_OK or
** IRIS_ENOMEM. 'sc' names the files of the locations (may be NULL).
*/
enum iris_status objpat_add(struct objpat_set *s, const iris_scene *sc,
                            const iris_object *o, FILE *log);

/* Sorts the set for lookups; call after the last objpat_add. */
void objpat_seal(struct objpat_set *s);

/*
** Whether point 'p' (in the space the object's transform maps to: the
** pattern's) is inside 'o', as POV-Ray's Inside_Object: CSG, inverse and
** clipped_by included. 's' may be NULL or lack 'o': prism, lathe and
** text leaves are then outside.
*/
bool objpat_inside(const struct objpat_set *s, const iris_object *o,
                   vec3 p);

void objpat_fini(struct objpat_set *s);

#endif
