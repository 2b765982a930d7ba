/* SPDX-License-Identifier: MIT */
/*
** gather.h: the final gather of `radiosity {}` with an irradiance cache,
** POV-Ray 3.7's radiosity as seen from the first diffuse eye hit.
**
** At an eye hit (any hit reached by camera, reflected or refracted rays,
** not by a gather ray) the irradiance is the mean radiance that 'count'
** cosine-distributed rays bring back: a ray that hits a surface takes
** what the tracer computes there (direct light without highlights,
** emission, ambient where POV-Ray counts it, caustics and the global
** photon map's diffuse interreflection); one that escapes takes the
** background or sky_sphere. The result is cached (Ward's irradiance
** cache with POV-Ray's error_bound, minimum_reuse, maximum_reuse and
** nearest_count) and filled by a pretrace in a fixed order, so that the
** image does not depend on the thread count; see gather.c.
**
** Depends on: render (trace, camera), photon (the caustic-only view of
** the photon map). Used by: trace.c, eyepass.c.
*/
#ifndef IRIS_RENDER_GATHER_H
#define IRIS_RENDER_GATHER_H

#include <stdbool.h>

#include "iris/render.h"
#include "render/trace.h"

/* True when 't' renders radiosity{} with a final gather: the block is
** present and the quality is 9 (POV-Ray's radiosity needs +Q9). */
bool gather_wanted(const struct tracer *t);

/*
** Sets up the final gather of one eye pass on 't' (t->gather,
** t->photon_map_local, t->photon_map_gather) and fills its cache by the pretrace over the
** window of 'opts', with 'threads' threads; 'cam' holds the interiors
** around the camera. Call after t->photon_map is set and before the eye
** pass; gather_end() frees it. Returns IRIS_OK or IRIS_ENOMEM.
*/
enum iris_status gather_begin(struct tracer *t,
                              const iris_render_options *opts, int threads,
                              const struct interior_stack *cam);
void gather_end(struct tracer *t);


/* True when a hit at gather level 'gi_depth' (0: eye hits, 1: the hits
** of their gather rays, ...) gathers: level 0 always, deeper levels when
** the gather recurses (a scene without light sources, recursion_limit
** >= 2; see gather_begin). */
bool gather_at_depth(const struct gather *g, int gi_depth);

/* False at a hit of level 'gi_depth' that takes no light from light
** sources: the pretrace's eye hits (they only place samples, as in
** POV-Ray) and, when the gather recurses beside a global map, the hits
** of deeper gathers (the map carries that light; see gather_begin). */
bool gather_lit(const struct gather *g, int gi_depth);

/* A new tile on 'c': forgets the records 'c' made for the last tile. */
void gather_tile_begin(struct trace_ctx *c);

/* Frees what the gather keeps in 'c' (trace_ctx_fini calls it). */
void gather_ctx_fini(struct trace_ctx *c);

/*
** POV-Ray's radiosity 'ambient colour' at eye hit 'h' with unit normal
** 'raw' facing the eye ray: the mean radiance over the cosine-weighted
** hemisphere, times brightness, gray_threshold applied. A surface adds
** pigment x it x diffuse x opacity. 'weight' is the ray's (adc_bailout).
** 'layer_n' is the layer's perturbed normal: with radiosity's 'normal
** on' the hemisphere is about it (cut off at raw's tangent plane) and
** the cache is searched and filled under it; otherwise it is not used.
*/
void gather_irradiance(struct trace_ctx *c, const struct tray *eye,
                       const struct hit *h, vec3 raw, vec3 layer_n,
                       double weight, double out[3]);

#endif
