/* SPDX-License-Identifier: MIT */
/*
** render.h: rendering a scene into an image.
**
** iris_render() plans the work the scene needs (render plan), builds the
** Embree scene and the materials, shoots photons when the scene asks for
** them, traces the eye pass over tiles on a pool of threads, and fills an
** iris_image with linear RGBA. The scene is only read; it may be shared.
*/
#ifndef IRIS_RENDER_H
#define IRIS_RENDER_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "iris/image.h"
#include "iris/common.h"
#include "iris/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Antialiasing as POV-Ray's +AM switch, plus stratified supersampling. */
enum iris_aa_method { IRIS_AA_NONE = 0, IRIS_AA_POV1 = 1, IRIS_AA_POV2 = 2,
                      IRIS_AA_STRATIFIED = 3 };

/* Called now and then from one thread with the fraction done in [0,1]. */
typedef void (*iris_progress_fn)(void *user, const char *phase,
                                  double fraction);

/* Progressive mode: where the accumulation stands after a pass. */
typedef struct iris_pass_info {
    int passes;                /* passes averaged so far (resumed ones too) */
    double time_s;             /* wall seconds since the render started,
                                  plus those of a resumed accumulation */
    uint64_t photons;          /* photons emitted, summed over the passes */
    double radius_scale;       /* the last pass's estimate radius / first's */
} iris_pass_info;

/* Called from the rendering thread after every progressive pass with the
** average so far (avg, linear RGBA; valid during the call only). */
typedef void (*iris_pass_fn)(void *user, const iris_image *avg,
                             const iris_pass_info *info);

/* Options of one render; iris_render_defaults() fills POV-Ray's. */
typedef struct iris_render_options {
    int width, height;         /* 160 x 120 as POV-Ray's code default */
    int threads;               /* 0 = number of cores */
    uint64_t seed;             /* 0 is a valid seed */
    int quality;               /* +Q, 9 */
    enum iris_aa_method aa;    /* +A: POV1 when threshold given */
    double aa_threshold;       /* 0.3 */
    int aa_depth;              /* +R, 3 */
    bool jitter;               /* +J, on */
    double jitter_amount;      /* 1.0 */
    double aa_gamma;           /* 2.5 */
    /* part of the image: +SR/+ER/+SC/+EC (1-based, inclusive; 0 = all) */
    int start_row, end_row, start_col, end_col;
    /* Progressive photon mapping (issue 6) */
    int passes;                /* 0 = one ordinary render */
    double time_limit;         /* seconds, 0 = none */
    const char *checkpoint;    /* save the accumulation here (atomic), or
                                  NULL; see src/render/progressive.c */
    const char *resume;        /* continue the accumulation saved here */
    iris_pass_fn on_pass;      /* after every progressive pass, or NULL */
    void *on_pass_user;
    int spectral_samples_min;  /* dispersion_samples floor, 0 = scene's */
    bool alpha;                /* +UA: alpha = 1 - what the pixel sees of a
                                  transmitting background; the colour is
                                  then premultiplied by it */
    bool use_photons;          /* false disables photons whatever the scene */
    iris_progress_fn progress;
    void *progress_user;
    volatile int *interrupt;   /* when set non-zero, stop soon */
    FILE *plan_out;            /* where --plan/-v prints the plan, or NULL */
    bool plan_only;            /* --plan: print the plan, render nothing */
    FILE *log;                 /* warnings during building, NULL = stderr */
    FILE *rank_times;          /* MPI: rank 0 prints each rank's times
                                  here (progressive.c); NULL = not; the
                                  same on every rank (a collective) */
} iris_render_options;

/* Fills 'o' with the defaults. */
void iris_render_defaults(iris_render_options *o);

/* What a render did and how long each phase took (for --stats). */
typedef struct iris_render_stats {
    double time_build_s, time_photon_s, time_render_s;
    double time_render_cpu_s;  /* CPU seconds of the eye pass's tile loop,
                                  summed over the threads (and the
                                  passes of a progressive render) */
    uint64_t photons_emitted, photons_stored, photon_bytes;
    uint64_t rays_traced;
    int threads, passes;
    uint64_t nan_pixels;       /* non-finite values caught and zeroed */
    /* The eye pass's rays as POV-Ray's render statistics count them
    ** (its "Rays", "Pixels" + "Samples", reflected, refracted,
    ** transmitted rays, shadow ray tests and those that succeeded):
    ** rays counts every trace, those max_trace_level or adc_bailout stop
    ** included; rays_traced above counts the ray queries. */
    uint64_t rays, rays_camera, rays_reflected, rays_refracted,
             rays_transmitted, shadow_tests, shadow_hits;
} iris_render_stats;

/*
** Renders 'scene' into 'out', which must be initialised at the options'
** width and height. Returns IRIS_OK, IRIS_ENOMEM, IRIS_EINVAL,
** IRIS_EUNSUPPORTED or IRIS_EINTR (the image holds what was done).
** 'err' receives a message on failure. Thread-safe for distinct outputs.
*/
IRIS_NODISCARD enum iris_status iris_render(const iris_scene *scene,
                                            const iris_render_options *opts,
                                            iris_image *out,
                                            iris_render_stats *stats,
                                            char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
