/* SPDX-License-Identifier: MIT */
/*
** wavefront.h: the photon tracer of scenes of spheres, planes and convex
** objects in lockstep, eight photons a step in single precision
** (wavefront.c, wf_kernel.h).
**
** shoot.c lays out the rings and numbers the photons as for the scalar
** tracer (trace.c); for a scene this path accepts (wf_build) it hands each
** batch's photons to wf_trace() as a run of one light x target pair, in
** structure-of-arrays form, and gets the same 32-byte raw records. The
** estimator is the scalar one (the same emission rule, Fresnel roulette,
** refraction by n(lambda), mirror and filter rules, deposit), with other
** random numbers and float arithmetic: the maps agree in distribution,
** not record for record (docs/photons.md, Session 8).
*/
#ifndef IRIS_PHOTON_WAVEFRONT_H
#define IRIS_PHOTON_WAVEFRONT_H

#include <stdbool.h>
#include <stdint.h>

#include "photon/pmap.h"
#include "photon/trace.h"

/* Photons in one run (a shooter batch, shoot.c's PHOTON_BATCH), and its
** lanes: a photon of a chromatic light takes one lane per sibling
** wavelength (trace.h), as the scalar tracer's one path per sibling. */
#define WF_MAX 4096
#define WF_RUN_LANES (WF_MAX * PTRACE_SIBS)

/* The light of one light x target pair as shoot.c aims it (its struct
** combo): rings about 'axis' (basis a, b), a photon's direction cell
** (theta, phi) jittered or, in passes > 0, drawn uniformly inside it. */
enum wf_atten { WF_ATTEN_ONE, WF_ATTEN_SPOT, WF_ATTEN_CYLINDER };
struct wf_light {
    bool parallel;             /* parallel or cylinder: one direction */
    vec3 origin;               /* point and spot lights: the location */
    vec3 axis, a, b;           /* ring axis and the basis around it */
    vec3 base;                 /* parallel: the rings' centre on the
                                  light's plane */
    double dtheta, jitter;
    int pass;                  /* progressive pass (0: POV-Ray's jitter) */
    uint64_t seed;
    bool chromatic;            /* the emission varies with lambda: every
                                  record is chromatic (struct wf_run's
                                  'emission' per lane) */
    enum wf_atten atten;       /* tightness 0 only (wf_build) */
    vec3 beam, location;       /* unit light->point_at; the light */
    double spot_cr, spot_cf;   /* spot: cos of radius and falloff */
    double radius, falloff;    /* cylinder */
};

/* One run of photons of one pair, filled by shoot.c, one entry a lane:
** per photon its ring centre theta, the ring's phi step, its column, the
** cell's measure, its wavelength (nm), the emission there relative to
** D65 (divided by the siblings a chromatic light's photon shares its
** power with) and its index (random streams). A chromatic light's photon
** fills one entry per sibling wavelength with the same index: the same
** random numbers, so the same direction and the same choices as long as
** nothing on the path depends on lambda (the scalar siblings' one path). */
struct wf_run {
    int n;
    int combo;
    float theta[WF_RUN_LANES], dphi[WF_RUN_LANES], kphi[WF_RUN_LANES];
    float cell[WF_RUN_LANES], lambda[WF_RUN_LANES], emission[WF_RUN_LANES];
    float white[WF_RUN_LANES]; /* a white record's factor: 1 for a photon
                                  of one lane; of a flat light's sibling
                                  lanes S for sibling 0 and 0 for the
                                  others (the scalar tracer's one white
                                  record of their summed power) */
    uint32_t idx_lo[WF_RUN_LANES], idx_hi[WF_RUN_LANES];
};

struct wf_scene;
struct wf_state;               /* one thread's lanes (wavefront.c) */

/*
** The wavefront tracer of the caustic photons of 'scene' through world
** 'w', for the 'n' pairs 'tc' (shoot.c's combos) with lights 'L', or NULL
** when any pair or the scene is outside what it handles (then shoot.c
** traces with trace.c): a world answering from the scene's geometry
** (pmap_world_is_scene()) of at most 8 objects photons meet, each a
** sphere, a plane, or a convex object: a box, a linear prism of one
** convex polygon, a capped cylinder, or an intersection of those, planes
** (also inverse) and spheres, with at most 32 half-spaces, balls and
** cylinders in all; transforms affine for planes, boxes and prisms, a
** similarity for spheres and cylinders; no clipped_by or bounded_by, the
** parts of an intersection of one surface; no media, lights outside
** every interior, no area-light grid, no light fade, tightness 0; every
** texture one colour everywhere, a coloured filter's transmittance > 0
** at every wavelength; mirrors of a constant grey reflection (no
** falloff, fresnel or metallic); no pass_through; interiors without
** fade; refracting spheres and convex objects clear of every object a
** photon can pass (by their boxes; an opaque one may cut into them), or
** one refracting plane; every primitive and the light within 1e4 target
** sizes of the origin (float's rounding far below the target).
** 'why' (may be NULL) gets the first reason refused. 'L' is copied.
*/
struct wf_scene *wf_build(const iris_scene *scene, const struct pmap_world *w,
                          const struct ptrace_combo *const *tc,
                          const struct wf_light *L, int n, const char **why);

void wf_destroy(struct wf_scene *ws);

/* Whether a photon of pair 'combo' under a light of flat emission takes a
** lane per sibling wavelength (a coloured filter on its way can make its
** path chromatic: then the scalar tracer stores a record per sibling). */
bool wf_sibling_lanes(const struct wf_scene *ws, int combo);

/* A thread's scratch lanes (about 250 kB), NULL on no memory. */
struct wf_state *wf_state_new(void);
void wf_state_free(struct wf_state *st);

/* Emits and traces the photons of 'run', appending their records to
** 'out' (out->failed on no memory). */
void wf_trace(const struct wf_scene *ws, struct wf_state *st,
              const struct wf_run *run, struct ptrace_out *out);

/* Which kernel runs: "avx2" (AVX2 and FMA, __builtin_cpu_supports) or
** "generic" (any CPU; also with IRIS_WAVEFRONT_KERNEL=generic). Both do
** the same float operations (no contraction: -std=c11), so they give the
** same map. */
const char *wf_kernel_name(void);

/*
** For the tests: the lanes' exact unpolarised Fresnel reflectance and
** refraction cosine (the kernel's own arithmetic) of 'n' cosines cos_i
** and relative indices eta: f[i] and cos_t[i] (f 1 past the critical
** angle, cos_t 0 there).
*/
void wf_fresnel_lanes(const float *cos_i, const float *eta, float *f,
                      float *cos_t, int n);

#endif
