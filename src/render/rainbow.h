/* SPDX-License-Identifier: MIT */
/*
** rainbow.h: the scene's rainbow{}s over a ray's colour (POV-Ray's
** ComputeRainbow, semantics: a colour_map looked up by the angle between
** the ray and the antisolar direction, faded with distance).
**
** Depends on: material (the colour map's pigment). Used by: trace.c, on
** hollow camera and secondary rays, never on shadow or photon rays.
*/
#ifndef IRIS_RENDER_RAINBOW_H
#define IRIS_RENDER_RAINBOW_H

#include "iris/scene.h"
#include "material/material.h"
#include "math/vec3.h"

/*
** Blends the rainbows of 'sc' into 'rgb', the colour of a ray going in
** unit direction 'd' that ended at 'depth' (POV-Ray's BOUND_HUGE, 2e10,
** on a miss, where a rainbow shows at full strength).
*/
void rainbow_apply(const iris_scene *sc, const struct mat_ctx *mat, vec3 d,
                   double depth, double rgb[3]);

#endif
