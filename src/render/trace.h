/* SPDX-License-Identifier: MIT */
/*
** trace.h: the recursive ray tracer of the eye pass, POV-Ray 3.7's RGB
** shading model (povray-3.7-semantics.md §3): layered textures, ambient,
** emission, diffuse, phong, specular, iridescence, reflection with
** fresnel and metallic, refraction through an interior stack with total
** internal reflection and fade, shadows through filtering objects with
** fake caustics, area lights sampled as POV-Ray samples them, fog,
** participating media (media.h), sky sphere and background,
** max_trace_level and adc_bailout.
**
** A 'tracer' is built once per render and shared read-only by all
** threads; a 'trace_ctx' is one thread's scratch space (area-light grid,
** random stream, counters). Camera rays that meet a dispersive interior
** split into wavelengths (DESIGN.md: chromatic aberration) and carry their
** wavelength from then on.
**
** Depends on: util, math, accel (through query.h), material, spectrum.
** Used by: render.c.
*/
#ifndef IRIS_RENDER_TRACE_H
#define IRIS_RENDER_TRACE_H

#include <stdbool.h>
#include <stdint.h>

#include "iris/scene.h"
#include "material/material.h"
#include "render/light.h"
#include "render/query.h"
#include "util/rng.h"

/* Quality switches of POV-Ray's +Q levels (povrayold.h). */
enum trace_quality {
    TQ_FULL_AMBIENT = 1, TQ_SHADOW = 2, TQ_AREA_LIGHT = 4, TQ_REFRACT = 8,
    TQ_REFLECT = 16, TQ_NORMAL = 32, TQ_VOLUME = 64, TQ_ADVANCED = 128,
    TQ_QUICK_COLOUR = 256
};

/* The quality flags of +Q 'q' (clipped to 0..9). */
unsigned trace_quality_flags(int q);

/* What the photon estimate needs at one texture layer (semantics §2.7). */
struct trace_photon_input {
    vec3 p;                    /* world point */
    vec3 layer_n, raw_n;       /* unit normals facing the eye ray */
    vec3 d;                    /* unit eye ray direction */
    const iris_finish *finish;
    iris_colour pigment;
    double att;                /* layer opacity */
    const iris_object *obj;
};

/* Adds the photon light of one layer to 'rgb'. Wired by render.c once a
** photon map exists; NULL when the plan has no photon pass. */
typedef void (*trace_photon_fn)(const void *map,
                                const struct trace_photon_input *in,
                                double rgb[3]);

/* POV-Ray's shadow rule for photon targets: true when the shadow ray from
** 'lit' to 'light' blocked by 'blocker' must be black (semantics §2.5). */
typedef bool (*trace_photon_shadow_fn)(const void *map,
                                       const iris_object *blocker,
                                       const iris_light *light,
                                       const iris_object *lit);

struct tracer {
    const iris_scene *scene;
    const struct mat_ctx *mat;
    struct rquery q;
    int n_lights;
    struct rlight *lights;
    int max_level;             /* max_trace_level */
    double adc;                /* adc_bailout */
    unsigned quality;          /* TQ_* flags */
    bool legacy;               /* #version < 3.7 paths */
    int spectral_min;          /* floor of dispersion samples */
    int max_area_grid;         /* largest size1*size2 of any area light */
    double max_distance;       /* hits farther than this are ignored */
    /* Every surface a shadow ray can meet is opaque (trace.c
    ** shadow_opaque_scene) and q.prim_hit exists: a shadow ray is black
    ** as soon as anything lies in its way, so each context keeps, per
    ** light, the primitive that last blocked one and tests it first
    ** (POV-Ray's per-light shadow cache, point_shadow) */
    bool shadow_cache;
    /* POV-Ray shades in the scene's working gamma space (assumed_gamma,
    ** semantics §3.9); the eye pass turns results into linear light with
    ** v^working_gamma, or, for a pre-3.7 scene without assumed_gamma
    ** (gamma handling off), with the sRGB decoding so that the file holds
    ** the values as computed. */
    double working_gamma;      /* 1 for assumed_gamma 1 */
    bool gamma_off;
    bool alpha;                /* +UA: the background's transmit counts */
    uint64_t seed;
    trace_photon_fn photon_shade;
    trace_photon_shadow_fn photon_shadow;
    const void *photon_map;
    /* radiosity{}: the final gather (gather.h); the photon map without
    ** its global map, which eye hits read when they gather; the one the
    ** gather rays' hits read (gather.c). NULL without */
    struct gather *gather;
    const void *photon_map_local, *photon_map_gather;
    /* iris_render_options.interrupt (SIGINT/SIGTERM), or NULL: read every
    ** 256 rays of a context, so that one pixel of millions of rays stops
    ** within milliseconds (trace.c trace_stopped) */
    volatile int *interrupt;
};

/* The interiors a ray is inside, innermost last (semantics §1.2). */
#define TRACE_MAX_INTERIORS 32
struct interior_entry {
    const void *key;           /* the interior, or the object without one */
    const iris_interior *in;   /* NULL: an interior with POV's defaults */
    bool hollow;
};
struct interior_stack {
    int n;
    struct interior_entry e[TRACE_MAX_INTERIORS];
};

/* A ray with what POV-Ray's Ray class carries besides geometry. */
struct tray {
    ray r;
    struct interior_stack st;
    bool reflected;            /* once reflected, no longer an image ray */
    double lambda;             /* wavelength in nm, 0 = RGB */
    double tmin;               /* the hit's eps a secondary ray leaves
                                  from (docs/numerics.md §1); 0 = the
                                  scene's accel epsilon */
};

/* Copies 'src' to 'dst' without the unused tail of the interior stack
** (most of the struct's size), as every secondary ray does. */
static inline void tray_copy(struct tray *dst, const struct tray *src)
{
    dst->r = src->r;
    dst->reflected = src->reflected;
    dst->lambda = src->lambda;
    dst->tmin = src->tmin;
    int n = src->st.n < 0 ? 0 : src->st.n > TRACE_MAX_INTERIORS
                                    ? TRACE_MAX_INTERIORS : src->st.n;
    dst->st.n = n;
    for (int i = 0; i < n; i++)
        dst->st.e[i] = src->st.e[i];
}

/* What a context's rays were, counted where POV-Ray's render statistics
** count them (trace.cpp), so that the two renderers' work can be compared
** ray for ray (tests/render/raycounts.sh, bench/ray-counts.sh). */
struct trace_counts {
    uint64_t rays;             /* trace_ray() calls, those that max_trace_
                                  level or adc_bailout stop included
                                  (POV-Ray's "Rays") */
    uint64_t camera;           /* camera rays ("Pixels" + "Samples") */
    uint64_t reflected, refracted, transmitted;
    uint64_t shadow_tests;     /* shadow ray queries */
    uint64_t shadow_hits;      /* ... that met an object before the light
                                  ("Succeeded") */
};

/* One thread's scratch space. */
struct trace_ctx {
    const struct tracer *t;
    rng_lazy rng;              /* re-keyed per pixel sample by the caller
                                  (rng_lazy_seed); drawn from through
                                  rng_lazy_get() */
    int level;                 /* current trace level */
    bool spectral;             /* a camera ray split into wavelengths since
                                  the caller last cleared it */
    double transm;             /* set by trace_ray: how much of the
                                  background the ray saw through
                                  transparent surfaces (POV-Ray's transmit
                                  channel; alpha = 1 - transm) */
    bool opaque_bg;            /* under a reflected ray: the +UA background
                                  is seen opaque (POV-Ray's ticket.
                                  alphaBackground, cleared by
                                  ComputeReflection) */
    uint64_t rays;
    struct trace_counts n;     /* POV-Ray's statistics of these rays */
    bool stopped;              /* the interrupt was seen: no more rays */
    const void **shadow_prim;  /* per light (t->lights), the primitive
                                  that last blocked a shadow ray from a
                                  surface, or NULL; allocated only when
                                  t->shadow_cache */
    double (*grid)[3];         /* area-light samples, max_area_grid */
    bool *grid_set;
    int gi_depth;              /* > 0 inside a radiosity gather ray */
    struct gather_local *gl;   /* the gather's tile-local records */
    /* radiosity importance (POV-Ray's radiosityImportanceQueried/Found):
    ** set by the gather for its next ray; trace_ray stores the hit
    ** object's importance in imp_found and does not shade the hit when
    ** it is below imp_query (the rays it spawns do not check) */
    bool imp_check;
    float imp_query, imp_found;
    /* Never touched: one cache line between this context's fields and
    ** the next one's in an array of contexts (one per thread). Without
    ** it thread 1's writes (rng, level, transm, rays at every ray) and
    ** thread 0's reads (gi_depth at every ray) could share a line,
    ** which then moves between the cores at every ray; whether they did
    ** depended on where malloc put the array. */
    char false_sharing_pad[64];
};

/* Prepares 't' (lights) for 'scene'; 'q', 'mat' borrowed. Returns false
** when memory runs out. */
bool tracer_init(struct tracer *t, const iris_scene *scene,
                 const struct mat_ctx *mat, const struct rquery *q,
                 int quality);
void tracer_fini(struct tracer *t);

bool trace_ctx_init(struct trace_ctx *c, const struct tracer *t);
void trace_ctx_fini(struct trace_ctx *c);

/* Fills 'st' with the interiors of the top-level objects containing 'p'
** (POV-Ray's InitRayContainerState). */
void trace_containing(const struct tracer *t, vec3 p,
                      struct interior_stack *st);

/*
** The objects trace_containing() asks (unions split), left out those
** whose inside box does not meet box lo..hi: for many rays starting in
** that box (focal blur's aperture), most objects are far away.
*/
struct containing_list {
    vec3 lo, hi;
    int n, cap;
    const iris_object **o;
    const iris_object **top;   /* o[i]'s top-level object (its key when
                                  o[i] has no interior{}) */
};
bool trace_containing_list(const struct tracer *t, vec3 lo, vec3 hi,
                           struct containing_list *cl);
void trace_containing_list_free(struct containing_list *cl);
/* trace_containing() through 'cl': the same interiors in the same order;
** a point outside the list's box asks every object. */
void trace_containing_from(const struct tracer *t,
                           const struct containing_list *cl, vec3 p,
                           struct interior_stack *st);

/*
** Traces 'r' and writes its linear colour to rgb[3]. 'continued' rays
** (straight through an ior-1 interface) do not count as a trace level.
** Returns the hit distance, or HUGE_VAL.
*/
double trace_ray(struct trace_ctx *c, const struct tray *r, double weight,
                 bool continued, double rgb[3]);

/* Refraction direction (Heckbert) of unit 'd' through unit normal 'n'
** facing the incident side, relative index 'eta' = n_from/n_to. Returns
** false on total internal reflection. */
bool trace_refract_dir(vec3 d, vec3 n, double eta, vec3 *out);

#endif
