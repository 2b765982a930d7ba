/* SPDX-License-Identifier: MIT */
/*
** pmedia.h: photons and participating media (docs/media.md, "Media
** photons").
**
** Two things POV-Ray 3.7 does with media in its photon pass
** (source/core/lighting/photons.cpp, PhotonTrace::ComputeLightedTexture
** and PhotonMediaFunction::DepositMediaPhotons), done here at each of
** the photon's sibling wavelengths (trace.h):
**
**  1. A photon crossing media loses power by their extinction: Beer-Lambert
**     along the segment, exp(-integral sigma_t(lambda, s) ds), by weighting
**     (the power is multiplied, no roulette). sigma_t(lambda) is the rgb
**     coefficient density·(absorption + extinction·scattering) upsampled
**     with Burns' curves (spec_reflectance(), linear in rgb: the same
**     upsampling as pigments, filters and fade).
**  2. With global_settings { photons { media MAX_STEPS [, FACTOR] } } a
**     photon that has been reflected or refracted at least once deposits
**     "media photons" along its path through scattering interior media,
**     stored in a map of their own (struct pmedia_map), which the eye
**     pass's media sampling gathers (pmedia_gather(), called by
**     render/media.c).
**
** Depends on: photon (pstore, trace.h's combo), spectrum, material.
** Used by: photon/trace.c (one call per segment), photon/shoot.c (set-up,
** the split of the raw photons), render/media.c (the gather).
*/
#ifndef IRIS_PHOTON_PMEDIA_H
#define IRIS_PHOTON_PMEDIA_H

#include <stdbool.h>
#include <stddef.h>

#include "iris/common.h"
#include "iris/scene.h"
#include "math/vec3.h"
#include "photon/pstore.h"
#include "util/rng.h"

struct ptrace_combo;
struct ptrace_out;
struct ptrace_sibs;
struct photon_map;

/*
** A raw photon whose 'lambda' is at least PMEDIA_TAG is a media photon:
** lambda - PMEDIA_TAG is its wavelength (negative: white, pstore.h).
** The transport writes both kinds into one batch buffer (trace.c's), and
** pmedia_take() moves the media photons out before the surface map is
** built. The tag keeps the photon path code to one call.
*/
#define PMEDIA_TAG 4096.0f

/* What one light x target pair needs for media (in struct ptrace_combo).
** Zeroed (scene NULL): the pair's photons never look at media. */
struct pmedia_path {
    const iris_scene *scene;   /* non-NULL: the scene has media */
    double spread;             /* POV-Ray's photonSpread: the angle between
                                  neighbouring photons (parallel lights:
                                  their distance), which sets the step
                                  between media photons */
    int max_steps;             /* media MAX_STEPS; 0: no media photons */
    double factor;             /* media FACTOR (spacing multiplier) */
};

/* Fills 'mp' for a combo of 'scene' whose photons are 'dtheta' apart
** (shoot.c's ring step; the world spacing for parallel lights). */
void pmedia_setup(struct pmedia_path *mp, const iris_scene *scene,
                  double dtheta);

/* True when 'scene' has media anywhere (interiors or atmosphere). */
bool pmedia_scene_has_media(const iris_scene *scene);

/* True when the scene asks for media photons: a photons{} block with
** media MAX_STEPS > 0 and some interior medium that scatters. */
bool pmedia_scene_wants_photons(const iris_scene *scene);

/*
** The photon segment from 'o' along unit 'd' of length 'len', which
** started 'depth0' along the photon's path from the light, with the
** interiors 'stack' (n_stack, innermost last) around it, at trace level
** 'level' (1: the segment leaving the light). Multiplies each sibling's
** power in 's' (trace.h: one or more wavelengths on one path) by the
** media's transmittance at its own wavelength (an 'equal' set is split
** when the media are not grey). When the photon is past its first
** bounce (level > 1) and the scene wants media photons, deposits them
** into 'out' (tagged): at each step one record per sibling at its own
** wavelength, or one white record of their summed power while the path
** is not chromatic. '*chroma' is set when the media made the photon's
** power depend on its wavelength. Media apply only when every interior
** on the stack is hollow (POV-Ray's IsHollowRay); the atmosphere's media
** dim the photon outside objects.
*/
void pmedia_segment(const struct ptrace_combo *c,
                    const iris_object *const *stack, int n_stack, vec3 o,
                    vec3 d, double len, double depth0, int level,
                    struct ptrace_sibs *s, bool *chroma, rng *r,
                    struct ptrace_out *out);

/* The media photon map: the records and the estimate's parameters. */
struct pmedia_map {
    struct pstore store;
    int gather_min, gather_max;
    double radius;             /* initial search radius (auto or given) */
    double expand_tol;
    int expand_min;
    double white[3][3];        /* pmap_white_matrix() */
};

/*
** Moves the media photons (tagged) of the 'n' raw photons 'all' into a
** new media map (*out; NULL when there are none), keeping the others in
** order at the front of 'all' (*n becomes their count). Does nothing
** (and costs nothing) when 'scene' wants no media photons. Returns
** IRIS_OK or IRIS_ENOMEM.
*/
IRIS_NODISCARD enum iris_status pmedia_take(const iris_scene *scene,
                                            struct pstore_raw *all,
                                            size_t *n, int threads,
                                            struct pmedia_map **out);

void pmedia_map_destroy(struct pmedia_map *m);

/* The media map of a photon map (NULL when none). */
const struct pmedia_map *pmedia_of(const struct photon_map *m);

/* POV-Ray's phase functions, unnormalised (isotropic 1): 'alpha' is the
** cosine between the eye ray's direction and the direction towards where
** the light comes from (media.cpp, ComputeMediaScatteringAttenuation). */
double pmedia_phase(const iris_media *m, double alpha);

/*
** The light the media photons scatter towards the eye at 'p' (eye ray
** direction 'dir'), added to 'emi' (rgb per unit length): for the k
** nearest media photons within the search radius (expanded as POV-Ray's
** gatherPhotonsAdaptive does), Σ phase·Φ_j·sigma_s(lambda_j)·rgb(lambda_j)
** / (4/3·pi·r^3), with phase the mean over the 'n' media 'm' (as
** POV-Ray's) and sigma_s the rgb scattering 'sca' at 'p' (densities
** included) upsampled at the photon's wavelength. With POV-Ray's
** unnormalised isotropic phase 1 a beam of irradiance E gives sigma_s·E,
** the same units as a light's direct in-scattering in media.c.
*/
void pmedia_gather(const struct pmedia_map *pm, const iris_media *const *m,
                   int n, vec3 p, vec3 dir, const double sca[3],
                   double emi[3]);

#endif
