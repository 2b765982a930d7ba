/* SPDX-License-Identifier: MIT */
/*
** gather_sources.h: whether a scene holds light that does not come from
** a light source (emission, ambient where POV-Ray counts it, a non-black
** background, sky_sphere, fog, rainbow, media that gather rays see).
**
** WHY: beside a global photon map the deeper levels of a recursive
** final gather (gather.c) see no light source; in a scene without such
** light every one of them returns exactly 0, and a cheap walk over the
** scene proves it before the render, so the gather does not trace them.
**
** Depends on: include/iris/scene.h. Used by: gather.c.
*/
#ifndef IRIS_RENDER_GATHER_SOURCES_H
#define IRIS_RENDER_GATHER_SOURCES_H

#include <stdbool.h>

#include "iris/scene.h"

/* True unless 'sc' provably has no light but its light sources' for a
** ray that sees no light source: false only when no finish reachable
** from an object (layers, texture and material maps, interior textures,
** mesh and blob textures, CSG children, lights' looks_like) has emission,
** nor ambient with 'ambient_counts' (#version < 3.7) and a non-black
** ambient_light; the background is black; there is no sky_sphere, fog
** or rainbow; and, when 'media_seen' (radiosity{ media on }), no media
** at all. Errs towards true (a shared or cyclic texture walk is cut at a
** depth limit and counts as light). */
bool gather_scene_has_unlit_light(const iris_scene *sc, bool ambient_counts,
                                  bool media_seen);

#endif
