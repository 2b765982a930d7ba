/* SPDX-License-Identifier: MIT */
/*
** media.h: participating media along a ray segment, as POV-Ray 3.7's
** MediaFunction::ComputeMedia computes them (source/core/material/
** media.cpp; docs/media.md): absorption, emission and scattering scaled
** by density patterns, in-scattered light from the light sources (with
** their shadow rays), sampled in intervals by method 1, 2 or 3 (3: the
** adaptive subdivision of each interval).
**
** trace.c calls it for the media of the interiors a ray is inside (the
** segment ending at the hit), for the atmosphere on every ray outside
** non-hollow objects, and for shadow rays (extinction only).
**
** Depends on: render/trace.h (rays, the per-thread context, the light
** test), material. Used by: trace.c, tests.
*/
#ifndef IRIS_RENDER_MEDIA_H
#define IRIS_RENDER_MEDIA_H

#include <stdbool.h>

#include "iris/scene.h"
#include "render/trace.h"

/* At most this many media act on one segment (the rest are left out). */
#define MEDIA_MAX_PER_RAY 32

/*
** Applies the 'n' media 'm' on the segment [0, depth] of ray 'r' to the
** colour 'rgb' arriving at the segment's end: rgb = rgb·exp(-τ) + the
** light emitted and in-scattered along it, attenuated on the way. For a
** 'shadow' ray only the extinction counts. '*transm' (may be NULL) is
** scaled by the greyscale of exp(-τ), as POV-Ray's alpha channel is.
*/
void media_segment(struct trace_ctx *c, const iris_media *const *m, int n,
                   const struct tray *r, double depth, bool shadow,
                   double rgb[3], double *transm);

/* Collects the media of the interiors on 'st' into 'out' (at most 'max',
** innermost interior last); returns how many. */
int media_of_stack(const struct interior_stack *st, const iris_media **out,
                   int max);

/* True when 'st' holds an interior with media (cheap: the stack is short). */
bool media_in_stack(const struct interior_stack *st);

/*
** POV-Ray's TestShadow, defined in trace.c: the colour '*lc' of light
** 'i' (attenuated by spot/cylinder falloff and fade) reaching 'p', after
** its shadow ray from 'p' with the interiors 'st'; '*L' the unit
** direction towards the light. False when no light arrives.
*/
bool trace_media_light(struct trace_ctx *c, const struct interior_stack *st,
                       int i, vec3 p, vec3 *L, double lc[3]);

#endif
