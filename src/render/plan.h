/* SPDX-License-Identifier: MIT */
/*
** plan.h: the render plan (DESIGN.md): what this scene needs, decided
** before any work starts, so that a scene pays only for what it uses.
**
** Depends on: iris/scene.h, iris/render.h, spectrum (dispersion test).
** Used by: render.c.
*/
#ifndef IRIS_RENDER_PLAN_H
#define IRIS_RENDER_PLAN_H

#include <stdbool.h>
#include <stdio.h>

#include "iris/render.h"
#include "iris/scene.h"

struct render_plan {
    int width, height, threads, tiles;
    int quality;
    enum iris_aa_method aa;
    int aa_depth;
    double aa_threshold;
    int n_objects, n_lights;
    int n_point, n_spot, n_cylinder, n_parallel, n_area, n_shadowless;
    bool shadows, area_sampling, refraction, reflection, normals;
    bool photons;              /* a photon pass before the eye pass */
    bool caustic_photons;      /* ... with a caustic map (photons{}) */
    const char *photon_reason; /* why no caustic map */
    bool global_photons;       /* ... with a global map (radiosity{}) */
    const char *global_reason; /* why no global map */
    bool spectral;             /* camera rays split at dispersive interiors */
    int spectral_samples;      /* the largest split */
    bool fog, sky_sphere;
    /* media (docs/media.md): objects whose interior has media, the
    ** atmosphere's media blocks; 'media' = some of them are rendered
    ** (quality 9) */
    int n_media_objects, n_media_atmosphere;
    bool media;
    /* media photons (photon/pmedia.h): deposited in scattering interior
    ** media by the caustic photons and gathered by the media sampling;
    ** photons are dimmed by media whenever the photon pass runs */
    bool media_photons;
    const char *media_photon_reason; /* why not */
    int media_max_steps;
    double media_factor;
    int max_trace_level;
    double adc_bailout;
};

/* Computes the plan of rendering 'scene' with 'opts'. */
void plan_compute(const iris_scene *scene, const iris_render_options *opts,
                  struct render_plan *plan);

/* Prints the plan, one item a line. */
void plan_print(const struct render_plan *plan, FILE *out);

#endif
