/* SPDX-License-Identifier: MIT */
/*
** photon.h: spectral caustic photon map: shooting, storage, estimate.
**
** photon_map_build() shoots photons from the scene's lights at its photon
** targets as POV-Ray 3.7 does (povray-3.7-semantics.md §2: spacing/count,
** target bounding spheres, the shooting rule, POV-Ray's power
** normalisation), but traces each photon at ONE wavelength with physical
** optics: exact unpolarised Fresnel with Russian roulette, n(lambda) from
** ior_eval(), total internal reflection, spectral filter and fade. Photons
** are stored only after at least one specular bounce (a caustic map, like
** POV-Ray's), on objects that collect photons.
**
** photon_map_shade() returns the photon contribution at a surface point in
** POV-Ray's shading model (§2.7): k nearest photons, the seed paper's cone
** filter, the surface reflectance applied per photon wavelength.
**
** With `radiosity {}` in global_settings the map also holds a global
** photon map (global.c): photons after at least one diffuse bounce, read
** at every diffuse eye hit as indirect light.
**
** Depends on: util, math, spectrum, accel. Used by: render.
** The map is immutable after the build; shade and the shadow query are
** thread-safe.
*/
#ifndef IRIS_PHOTON_PHOTON_H
#define IRIS_PHOTON_PHOTON_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "iris/common.h"
#include "iris/scene.h"
#include "math/vec3.h"

struct accel;
struct mat_ctx;
struct photon_map;

/* Global photons shot per pass (all lights), and the neighbours of their
** estimate (global.c). */
#define PMAP_GLOBAL_PHOTONS 400000
#define PMAP_GLOBAL_GATHER 400

struct photon_options {
    int threads;               /* worker threads (< 1: one) */
    uint64_t seed;             /* random streams: (seed, pass, photon) */
    int pass;                  /* progressive pass number, 0 first */
    double radius_scale;       /* progressive pass: the estimate radius is
                                  this times the k-nearest radius (0 = 1;
                                  estimate.c); progressive.c shrinks it */
    const struct mat_ctx *mat; /* texture evaluation (material.h); NULL:
                                  solid top-layer pigments only */
    int64_t max_photons;       /* > 0: clamp the photons shot to this many,
                                  with a warning; 0: fail with a located
                                  error past what the memory available
                                  holds (shoot.c, membudget.h) */
    FILE *log;                 /* warnings (NULL: stderr) */
    int64_t global_photons;    /* global map (radiosity{}): photons per
                                  pass, 0 = PMAP_GLOBAL_PHOTONS (pmap.h) */
    bool no_fastpath;          /* query accel even where the photon fast
                                  path applies (fastpath.h; benchmarks) */
    bool no_tex_cache;         /* evaluate every hit's texture, also those
                                  of one colour everywhere (trace.h,
                                  ptrace_tex; tests and benchmarks) */
    bool no_siblings;          /* one wavelength per photon, also where
                                  the path does not depend on it (trace.h,
                                  ptrace_sibs; tests and benchmarks) */
    bool no_wavefront;         /* trace every photon with the scalar tracer
                                  (trace.c), also in the scenes the
                                  wavefront tracer takes (wavefront.h;
                                  tests, benchmarks); so does the
                                  environment variable IRIS_NO_WAVEFRONT
                                  set to anything but 0 */
    volatile int *interrupt;   /* set non-zero (SIGINT, SIGTERM): the
                                  batches not started are skipped and the
                                  build returns IRIS_EINTR (last: the
                                  tests' positional initialisers) */
};

/* What a build did, for -v and the benchmarks. */
struct photon_stats {
    int64_t shot;              /* photons emitted */
    int64_t stored;            /* photons in the map */
    int64_t shot_global;       /* global map (radiosity{}): emitted, */
    int64_t stored_global;     /* and stored */
    int64_t bytes;             /* memory of the stored map */
    int n_combos;              /* light x target pairs that shot */
    double spacing;            /* the spacing used (after 'count' and
                                  the photon cap) */
    double gather_radius;      /* initial gather radius (auto or given) */
    double seconds_shoot, seconds_build;
    double cpu_shoot, cpu_build;   /* the same in CPU seconds of all the
                                      process's threads (a shared, loaded
                                      machine inflates wall time, not these) */
    int64_t tex_cached;        /* photons' surface hits (caustic and
                                  global) answered from the texture cache
                                  (trace.h) */
    int64_t wavefront;         /* caustic photons emitted by the wavefront
                                  tracer (wavefront.h), 0 when the scalar
                                  tracer shot them */
};

/*
** Builds the photon map of 'scene' (borrowed, like 'accel'; both must
** outlive the map). *out is NULL when the scene asks for no photons
** (no photons{} block, gather max 0, or no light x target pair with
** refraction or reflection on) and no global map is wanted. Returns
** IRIS_OK, IRIS_ENOMEM, or IRIS_EINVAL after a located error in the log.
*/
IRIS_NODISCARD enum iris_status
photon_map_build(const iris_scene *scene, const struct accel *accel,
                 const struct photon_options *opts, struct photon_map **out,
                 struct photon_stats *stats);

/* Frees the map. NULL does nothing. */
void photon_map_destroy(struct photon_map *m);

/* A surface point to shade with photons. */
struct photon_shade_input {
    vec3 p;                    /* world point */
    vec3 n_layer;              /* unit layer normal (perturbed), facing
                                  the viewer */
    vec3 n_raw;                /* unit raw normal, facing the viewer */
    vec3 view_dir;             /* unit direction of the incoming eye ray */
    double pigment_rgb[3];     /* layer pigment rgb (linear) */
    double opacity;            /* POV-Ray's att = 1 - filter - transmit */
    const iris_finish *finish; /* diffuse, brilliance, diffuse_back */
    const iris_object *obj;    /* the object hit; 'collect off' gives 0
                                  (NULL: assume it collects) */
};

/*
** The photon (caustic) light at 'in' in linear sRGB, to be added to the
** layer colour before POV-Ray's filter multiplication (semantics §2.7).
** It already includes diffuse, pigment (per wavelength), brilliance and
** opacity. 'm' NULL gives black.
*/
void photon_map_shade(const struct photon_map *m,
                      const struct photon_shade_input *in, double rgb_out[3]);

/*
** POV-Ray's shadow rule for photon targets (semantics §2.5, "Shadow
** consequence"): true when a shadow ray from 'lit' towards 'light' that
** is blocked by 'blocker' must be fully black because the caustic photons
** carry that light instead. False when 'm' is NULL or empty.
*/
bool photon_blocks_shadow(const struct photon_map *m,
                          const iris_object *blocker, const iris_light *light,
                          const iris_object *lit);

#endif
