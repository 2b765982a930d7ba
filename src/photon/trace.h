/* SPDX-License-Identifier: MIT */
/*
** trace.h: the transport of one photon at one wavelength (trace.c).
*/
#ifndef IRIS_PHOTON_TRACE_H
#define IRIS_PHOTON_TRACE_H

#include <stdbool.h>
#include <stdint.h>

#include "photon/pmap.h"
#include "photon/pmedia.h"
#include "photon/targets.h"
#include "util/rng.h"

#define PTRACE_MAX_STACK 16

/* What stays fixed for all photons of one light x target pair. */
struct ptrace_combo {
    const iris_light *light;
    const iris_object *target;
    /* the target's leaves when it is a CSG that is not one of the
    ** scene's top-level objects (a child of a split union, or of a CSG
    ** that is no target: targets.c), sorted for ptrace_in_target();
    ** else NULL, 0 */
    const iris_object *const *target_leaves;
    int n_target_leaves;
    bool parallel;             /* no D^2 in the stored power */
    double fade_distance, fade_power; /* the light's fade */
    int max_level;             /* photon max_trace_level */
    bool chromatic;            /* the light's emission varies with lambda */
    bool no_dispersion;        /* no interior of the scene is dispersive
                                  (ior_is_dispersive): the per-interface
                                  test is skipped. false (unknown) keeps
                                  the test */
    bool global;               /* a global-map photon (global.c): any first
                                  hit, physical specular transport whatever
                                  the photon flags, Lambertian bounces by
                                  Russian roulette, stored after >= 1
                                  diffuse bounce; the D^2 and fade factors
                                  are applied where it first lands on a
                                  diffuse surface */
    int max_diffuse;           /* global: > 0 ends a photon after that many
                                  diffuse bounces (recursion_limit - 1) */
    const struct mat_ctx *mat; /* NULL: solid pigments (tests) */
    struct pmedia_path media;  /* media on the path (pmedia.h); zero:
                                  the scene has none */
    int n_stack;               /* interiors containing the light */
    const iris_object *stack[PTRACE_MAX_STACK];
};

/*
** Whether a first hit on leaf 'obj' of top-level object 'top' is on the
** pair's target, as POV-Ray's Trace::IsObjectInCSG asks (targets.c): the
** target is 'top' itself, or 'obj', or a CSG holding 'obj'.
*/
static inline bool ptrace_in_target(const struct ptrace_combo *c,
                                    const iris_object *obj,
                                    const iris_object *top)
{
    return top == c->target || obj == c->target ||
           (c->n_target_leaves > 0 &&
            ptargets_has(c->target_leaves, c->n_target_leaves, obj));
}

/*
** What a surface whose texture is one colour everywhere (solid pigments,
** no normal{}, no texture_map) gives a photon at every point, at every
** wavelength where 'transm_grey' (trace.c, eval_surface). Kept per batch:
** mat_eval_texture() of such a texture was 14% of a photon's instructions
** on the clear ball (callgrind), for the same answer at every hit.
*/
#define PTRACE_TEX_LAYERS 4
struct ptrace_tex {
    const iris_texture *key;   /* NULL: an empty slot */
    bool uniform;              /* false: evaluated at every hit */
    int n_layers;              /* the layers mat_eval_texture() used */
    iris_colour pigment[PTRACE_TEX_LAYERS];
    const iris_finish *fin;    /* the top layer's (psurf.fin) */
    double opacity;            /* the top layer's */
    double transm;             /* the layers' transmittance, if grey */
    bool transm_grey;          /* it does not depend on lambda */
    bool no_reflection;        /* the finish reflects nothing at any angle */
};

#define PTRACE_TEX_SLOTS 4
struct ptrace_tex_cache {
    struct ptrace_tex slot[PTRACE_TEX_SLOTS];
    int next;                  /* the slot to replace next */
    int64_t hits;              /* hits answered from a uniform slot */
};

/* The cache's slot of texture 'tex' (NULL: none), filled on first use:
** what a photon sees at every point of a texture one colour everywhere
** ('uniform'; wavefront.c resolves each primitive's surface with it). */
const struct ptrace_tex *ptrace_tex_get(const struct ptrace_combo *c,
                                        struct ptrace_tex_cache *tc,
                                        const iris_texture *tex);

/* The transmittance of uniform texture 'e' at 'lambda' (nm): the layers'
** product as eval_surface() takes it at every hit (wavefront.c tabulates
** a coloured filter's with it). */
double ptrace_tex_transm(const struct ptrace_tex *e, double lambda);

/* POV-Ray's photon flag rule (semantics §2.5): the object's refraction or
** reflection flag 'obj' with the light's 'light'. */
bool ptrace_allowed(enum iris_tristate obj, enum iris_tristate light);

/* A growable buffer of raw photons (one per batch). */
struct ptrace_out {
    struct pstore_raw *ph;
    size_t n, cap;
    bool failed;               /* an allocation failed */
    bool borrowed;             /* 'ph' is a slice of the caller's array
                                  (shoot.c): when full it is copied to a
                                  buffer of its own, never reallocated */
    struct ptrace_tex_cache *tex; /* the batch's texture cache, zeroed
                                  before its first photon (NULL: none);
                                  valid for one mat context */
};

/* Appends one record at 'p' to 'out' (grown as needed; out->failed on
** no memory). 'lambda_field' is the record's wavelength field as stored:
** a wavelength, -1 for a white photon, or pmedia.c's tagged value. */
void ptrace_out_push(struct ptrace_out *out, vec3 p, double power,
                     float lambda_field, vec3 from);

/* The level cap of a global photon: diffuse bounces end by Russian
** roulette on the albedo, this only guards an albedo-1 closed scene. */
#define PTRACE_GLOBAL_MAX_LEVEL 100

/*
** Traces one photon from 'o' along unit 'd' at 'lambda' with power
** 'power' (before the D^2 factor), depositing into 'out'. 'r' supplies
** the Russian-roulette numbers.
*/
void ptrace_photon(const struct pmap_world *w, const struct ptrace_combo *c,
                   vec3 o, vec3 d, double lambda, double power, rng *r,
                   struct ptrace_out *out);

/*
** Sibling wavelengths (issue 5). A photon carries PTRACE_SIBS wavelengths
** lambda_j = frac(u + j/S) of its lattice value u, each with 1/S of the
** power, along one path (through media too: Beer-Lambert per sibling,
** media photons one record per sibling on a chromatic path, pmedia.c).
** Every choice on the path is the same for all siblings, and each
** sibling's power is weighed so that its expectation is what a photon of
** its wavelength alone would carry: a spectral roulette (a coloured
** mirror) takes the siblings' mean probability and weighs each by its own
** over the mean; fades and spectral transmittances (coloured filters)
** multiply each by its own factor. A surface of a dispersive interior
** (or one met inside it) makes the path depend on lambda: there the
** siblings collapse to sibling 0 with S times its power (trace.c,
** sib_collapse). A chromatic path stores one record per sibling, so a
** gather of k records sees k/S paths but S wavelengths of each: the colour
** noise of a focusing mirror's caustic, whose neighbouring cells carry
** correlated lattice wavelengths, falls (docs/photons.md).
*/
#define PTRACE_SIBS 3
struct ptrace_sibs {
    int n;                     /* 1..PTRACE_SIBS */
    bool equal;                /* every sibling's power is power[0] (the
                                  others are then not kept up to date):
                                  a white light's siblings until a spectral
                                  event, one product instead of S */
    double lambda[PTRACE_SIBS];
    double power[PTRACE_SIBS]; /* before the D^2 factor */
};

/* ptrace_photon() with siblings 's' (changed: their powers) */
void ptrace_photon_sibs(const struct pmap_world *w,
                        const struct ptrace_combo *c, vec3 o, vec3 d,
                        struct ptrace_sibs *s, rng *r,
                        struct ptrace_out *out);

#endif
