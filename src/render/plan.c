/* SPDX-License-Identifier: MIT */
/*
** plan.c: the render plan (see plan.h). Photons follow POV-Ray's rules
** (semantics §2.1, §2.2b): a photons{} block with gather > 0, quality 9,
** and some non-shadowless light and photon target whose merged flags ask
** for refraction or reflection. A global photon map (diffuse
** interreflection, src/photon/global.c) when global_settings has
** radiosity{}, quality 9 and a light that is not shadowless. Spectral
** splitting is planned when some interior's index varies with the
** wavelength. Media (docs/media.md) are rendered at quality 9, as POV-Ray
** renders them; the plan only reports them (the tracer asks the ray's
** interiors, so a scene without media pays nothing).
*/
#include "config.h"

#include <string.h>

#include "photon/photon.h"
#include "photon/pmedia.h"
#include "render/plan.h"
#include "render/trace.h"
#include "spectrum/ior.h"

static bool flag_on(enum iris_tristate a, enum iris_tristate b)
{
    /* merged = light | target; shoot if ON and not OFF in the merge */
    return (a == IRIS_ON || b == IRIS_ON) && a != IRIS_OFF && b != IRIS_OFF;
}

struct walk {
    bool spectral;
    int spectral_samples;
    int n_objects;
    const iris_scene *scene;
    bool photon_ok;
    int n_media;               /* primitives whose interior has media */
};

static void walk_object(struct walk *w, const iris_object *o, int depth)
{
    if (!o || depth > 64)
        return;
    w->n_objects++;
    if (o->interior && o->interior->n_media > 0 &&
        o->kind < IRIS_OBJ_UNION)
        w->n_media++;
    if (o->interior && ior_is_dispersive(o->interior)) {
        w->spectral = true;
        int n = o->interior->dispersion_samples > 0
                    ? o->interior->dispersion_samples : 7;
        if (n > w->spectral_samples)
            w->spectral_samples = n;
    }
    if (o->photon_target && o->photon_density > 0) {
        for (int i = 0; i < w->scene->n_lights; i++) {
            const iris_light *l = w->scene->lights[i];
            if (l->shadowless)
                continue;
            if (flag_on(l->photon_refraction, o->photon_refraction) ||
                flag_on(l->photon_reflection, o->photon_reflection))
                w->photon_ok = true;
        }
    }
    if (o->kind >= IRIS_OBJ_UNION && o->kind <= IRIS_OBJ_LIGHT_GROUP)
        for (int i = 0; i < o->u.csg.n_children; i++)
            walk_object(w, o->u.csg.children[i], depth + 1);
}

void plan_compute(const iris_scene *scene, const iris_render_options *opts,
                  struct render_plan *p)
{
    memset(p, 0, sizeof *p);
    p->width = opts->width;
    p->height = opts->height;
    p->threads = opts->threads;
    p->quality = opts->quality < 0 ? 0 : opts->quality > 9 ? 9 : opts->quality;
    unsigned q = trace_quality_flags(p->quality);
    p->aa = opts->aa;
    p->aa_depth = opts->aa_depth < 1 ? 1 : opts->aa_depth > 9 ? 9 : opts->aa_depth;
    p->aa_threshold = opts->aa_threshold;
    p->n_lights = scene->n_lights;
    for (int i = 0; i < scene->n_lights; i++) {
        const iris_light *l = scene->lights[i];
        if (l->kind == IRIS_LIGHT_SPOT) p->n_spot++;
        else if (l->kind == IRIS_LIGHT_CYLINDER) p->n_cylinder++;
        else p->n_point++;
        if (l->parallel) p->n_parallel++;
        if (l->area && l->size1 * l->size2 > 1) p->n_area++;
        if (l->shadowless) p->n_shadowless++;
    }
    p->shadows = (q & TQ_SHADOW) && p->n_lights > p->n_shadowless;
    p->area_sampling = (q & TQ_AREA_LIGHT) && p->n_area > 0;
    p->refraction = (q & TQ_REFRACT) != 0;
    p->reflection = (q & TQ_REFLECT) != 0;
    p->normals = (q & TQ_NORMAL) != 0;
    struct walk w;
    memset(&w, 0, sizeof w);
    w.scene = scene;
    for (int i = 0; i < scene->n_objects; i++)
        walk_object(&w, scene->objects[i], 0);
    p->n_objects = w.n_objects;
    p->spectral = w.spectral && p->refraction;
    p->spectral_samples = w.spectral_samples;
    if (opts->spectral_samples_min > p->spectral_samples)
        p->spectral_samples = opts->spectral_samples_min;
    if (!opts->use_photons)
        p->photon_reason = "disabled by the options";
    else if (!scene->settings.photons.enabled)
        p->photon_reason = "no photons{} block with gather > 0";
    else if (p->quality < 9)
        p->photon_reason = "quality below 9";
    else if (!w.photon_ok)
        p->photon_reason = "no light and target ask for refraction or "
                           "reflection photons";
    else
        p->caustic_photons = true;
    bool lit = false;
    for (int i = 0; i < scene->n_lights; i++)
        lit = lit || !scene->lights[i]->shadowless;
    if (!opts->use_photons)
        p->global_reason = "disabled by the options";
    else if (!scene->settings.radiosity)
        p->global_reason = "no radiosity{} block";
    else if (p->quality < 9)
        p->global_reason = "quality below 9";
    else if (!lit)
        p->global_reason = "no light that casts shadows";
    else if (scene->settings.rad.recursion_limit == 1)
        p->global_reason = "recursion_limit 1: the final gather's bounce "
                           "only";
    else
        p->global_photons = true;
    p->photons = p->caustic_photons || p->global_photons;
    p->fog = scene->n_fogs > 0;
    p->n_media_objects = w.n_media;
    p->n_media_atmosphere = scene->n_media;
    p->media = (q & TQ_VOLUME) && (w.n_media > 0 || scene->n_media > 0);
    p->media_max_steps = scene->settings.photons.media_max_steps;
    p->media_factor = scene->settings.photons.media_factor;
    if (!p->caustic_photons)
        p->media_photon_reason = "no caustic photon pass";
    else if (p->media_max_steps <= 0)
        p->media_photon_reason = "no 'media MAX_STEPS' in photons{}";
    else if (!pmedia_scene_wants_photons(scene))
        p->media_photon_reason = "no interior media that scatter";
    else
        p->media_photons = true;
    p->sky_sphere = scene->sky_sphere && scene->sky_sphere->n_pigments > 0;
    p->max_trace_level = scene->settings.max_trace_level > 0
                             ? scene->settings.max_trace_level : 5;
    p->adc_bailout = scene->settings.adc_bailout > 0
                         ? scene->settings.adc_bailout : 1.0 / 255.0;
}

static const char *aa_name(enum iris_aa_method m)
{
    switch (m) {
    case IRIS_AA_POV1: return "POV-Ray method 1 (non-adaptive)";
    case IRIS_AA_POV2: return "POV-Ray method 2 (adaptive)";
    case IRIS_AA_STRATIFIED: return "stratified supersampling";
    default: return "none";
    }
}

void plan_print(const struct render_plan *p, FILE *out)
{
    if (!out)
        return;
    fprintf(out, "render plan:\n");
    fprintf(out, "  image: %d x %d, %d tiles, %d threads\n", p->width,
            p->height, p->tiles, p->threads);
    fprintf(out, "  quality: %d (shadows %s, refraction %s, reflection %s, "
            "normals %s)\n", p->quality, p->shadows ? "on" : "off",
            p->refraction ? "on" : "off", p->reflection ? "on" : "off",
            p->normals ? "on" : "off");
    fprintf(out, "  objects: %d; lights: %d (point %d, spot %d, cylinder %d, "
            "parallel %d, shadowless %d)\n", p->n_objects, p->n_lights,
            p->n_point, p->n_spot, p->n_cylinder, p->n_parallel,
            p->n_shadowless);
    fprintf(out, "  area-light sampling: %s", p->area_sampling ? "yes" : "no");
    if (p->n_area > 0 && !p->area_sampling)
        fprintf(out, " (quality below 5: area lights act as point lights)");
    fprintf(out, "\n");
    if (p->caustic_photons)
        fprintf(out, "  photon pass: yes\n");
    else
        fprintf(out, "  photon pass: no (%s)\n", p->photon_reason);
    if (p->global_photons)
        fprintf(out, "  global photon map (radiosity): yes, %d photons a "
                "pass, %d-nearest estimate at the final gather's "
                "hits\n", PMAP_GLOBAL_PHOTONS, PMAP_GLOBAL_GATHER);
    else
        fprintf(out, "  global photon map (radiosity): no (%s)\n",
                p->global_reason);
    if (p->spectral)
        fprintf(out, "  spectral splitting: yes, up to %d wavelengths at "
                "dispersive interiors\n", p->spectral_samples);
    else
        fprintf(out, "  spectral splitting: no (no dispersive interior)\n");
    fprintf(out, "  atmosphere: fog %s, sky_sphere %s\n", p->fog ? "yes" : "no",
            p->sky_sphere ? "yes" : "no");
    if (p->n_media_objects + p->n_media_atmosphere == 0)
        fprintf(out, "  media: none\n");
    else
        fprintf(out, "  media: %s, %d objects with interior media, %d "
                "atmospheric media%s\n", p->media ? "yes" : "no",
                p->n_media_objects, p->n_media_atmosphere,
                p->media ? "" : " (quality below 9: left out)");
    if (p->n_media_objects + p->n_media_atmosphere > 0) {
        if (p->media_photons)
            fprintf(out, "  media photons: yes, at most %d steps a "
                    "segment, spacing factor %g\n", p->media_max_steps,
                    p->media_factor > 0.0 ? p->media_factor : 1.0);
        else
            fprintf(out, "  media photons: no (%s)\n",
                    p->media_photon_reason);
    }
    fprintf(out, "  antialiasing: %s", aa_name(p->aa));
    if (p->aa != IRIS_AA_NONE)
        fprintf(out, ", depth %d, threshold %g", p->aa_depth, p->aa_threshold);
    fprintf(out, "\n  max_trace_level %d, adc_bailout %g\n", p->max_trace_level,
            p->adc_bailout);
}
