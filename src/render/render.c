/* SPDX-License-Identifier: MIT */
/*
** render.c: iris_render(): the render plan, the Embree scene and the
** materials, the photon pass when the plan has one, then the eye pass
** (eyepass.c).
**
** The scene reaches the tracer only through the query table (query.h),
** filled here from src/accel.
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "accel/accel.h"
#include "iris/render.h"
#include "material/material.h"
#include "photon/photon.h"
#include "photon/photon_file.h"
#include "render/check_ior.h"
#include "render/eyepass.h"
#include "render/mpi_passes.h"
#include "render/plan.h"
#include "render/progressive.h"
#include "render/trace.h"
#include "util/mem.h"
#include "util/thread.h"

void iris_render_defaults(iris_render_options *o)
{
    memset(o, 0, sizeof *o);
    o->width = 160;
    o->height = 120;
    o->quality = 9;
    o->aa = IRIS_AA_NONE;
    o->aa_threshold = 0.3;
    o->aa_depth = 3;
    o->jitter = true;
    o->jitter_amount = 1.0;
    o->aa_gamma = 2.5;
    o->use_photons = true;
}

/* ------------------------------------------------------------------ */
/* The scene query through src/accel                                    */
/* ------------------------------------------------------------------ */

static bool accel_isect(const void *impl, const ray *r, double tmin,
                        double tmax, unsigned skip, struct hit *h)
{
    return accel_intersect(impl, r, tmin, tmax, skip, h);
}

static bool accel_in(const void *impl, const iris_object *obj, vec3 p)
{
    return accel_inside(impl, obj, p);
}

/* ------------------------------------------------------------------ */
/* Photons                                                              */
/* ------------------------------------------------------------------ */

/* The tracer's photon hooks, on src/photon's map. */
static void shade_photons(const void *map, const struct trace_photon_input *in,
                          double rgb[3])
{
    struct photon_shade_input si = {
        in->p, in->layer_n, in->raw_n, in->d,
        { in->pigment.r, in->pigment.g, in->pigment.b }, in->att,
        in->finish, in->obj };
    double add[3] = { 0, 0, 0 };
    photon_map_shade(map, &si, add);
    for (int k = 0; k < 3; k++)
        if (isfinite(add[k]))
            rgb[k] += add[k];
}

static bool photon_shadow(const void *map, const iris_object *blocker,
                          const iris_light *light, const iris_object *lit)
{
    return photon_blocks_shadow(map, blocker, light, lit);
}

/* err = "file:line:col: " of 'loc' in 'scene' followed by 'msg'. */
static void located(const iris_scene *scene, iris_loc loc, const char *msg,
                    char *err, size_t errlen)
{
    const char *file = "<unknown>";
    if (loc.file > 0 && (int)loc.file < scene->n_files && scene->files &&
        scene->files[loc.file])
        file = scene->files[loc.file];
    if (err && errlen)
        snprintf(err, errlen, "%s:%u:%u: error: %s", file, (unsigned)loc.line,
                 (unsigned)loc.col, msg);
}

/*
** The map of the photon pass: shot, or read from photons { load_file }
** (POV-Ray: loading skips shooting); with save_file written once built,
** by rank 0 alone under MPI. File errors are IRIS_EIO with the
** keyword's location in 'err'.
*/
static enum iris_status build_or_load(const iris_scene *scene,
                                      const struct accel *acc,
                                      const struct photon_options *po,
                                      struct photon_map **map,
                                      struct photon_stats *ps, char *err,
                                      size_t errlen)
{
    const iris_photon_settings *set = &scene->settings.photons;
    char msg[400] = "";
    enum iris_status st;
    if (set->enabled && set->load_file && set->load_file[0])
        st = photon_file_load(scene, acc, po, set->load_file, map, ps, msg,
                              sizeof msg);
    else
        st = photon_map_build(scene, acc, po, map, ps);
    if (st == IRIS_OK && set->enabled && set->save_file &&
        set->save_file[0] && mpi_passes_rank() == 0)
        st = photon_file_save(*map, (long long)ps->shot, set->save_file, msg,
                              sizeof msg);
    if (st != IRIS_OK && msg[0])
        located(scene, set->file_loc, msg, err, errlen);
    return st;
}

/* The photon pass, when the plan has one: the caustic map the tracer reads
** at every texture layer and in shadows. */
static enum iris_status photon_pass(const struct render_plan *plan,
                                    struct tracer *t, const struct accel *acc,
                                    const struct mat_ctx *mat, int threads,
                                    const iris_render_options *opts,
                                    struct photon_map **map,
                                    iris_render_stats *stats, char *err,
                                    size_t errlen)
{
    *map = NULL;
    t->photon_shade = NULL;
    t->photon_shadow = NULL;
    t->photon_map = NULL;
    if (!plan->photons)
        return IRIS_OK;
    if (progressive_wanted(opts) && mpi_passes_rank() != 0) {
        /* MPI: pass 0 is rank 0's; this rank builds only its own passes'
        ** maps (progressive.c) */
        t->photon_shade = shade_photons;
        t->photon_shadow = photon_shadow;
        return IRIS_OK;
    }
    struct photon_options po;
    memset(&po, 0, sizeof po);
    po.threads = threads;
    po.seed = opts->seed;
    po.mat = mat;
    po.log = opts->log; /* the spacing-cap warning goes with the others */
    po.interrupt = opts->interrupt;
    struct photon_stats ps;
    memset(&ps, 0, sizeof ps);
    enum iris_status st = build_or_load(t->scene, acc, &po, map, &ps, err,
                                        errlen);
    if (st != IRIS_OK)
        return st;
    if (stats) {
        stats->photons_emitted = (uint64_t)ps.shot;
        stats->photons_stored = (uint64_t)ps.stored;
        stats->photon_bytes = (uint64_t)ps.bytes;
    }
    if (*map) {
        t->photon_shade = shade_photons;
        t->photon_shadow = photon_shadow;
        t->photon_map = *map;
    }
    return IRIS_OK;
}

/*
** A light's looks_like object is rendered as an ordinary object (the
** parser has moved it to the light and made it no_shadow) but the parser
** keeps it on the light only. The render therefore works on a shallow
** copy of the scene whose object list has those objects appended; every
** node stays the caller's. Returns 'scene' itself when no light has one,
** NULL when memory runs out.
*/
static const iris_scene *with_looks_like(const iris_scene *scene,
                                         iris_scene *copy,
                                         iris_object ***objects)
{
    *objects = NULL;
    int n = 0;
    for (int i = 0; i < scene->n_lights; i++)
        if (scene->lights[i] && scene->lights[i]->looks_like)
            n++;
    if (n == 0)
        return scene;
    iris_object **o = iris_calloc((size_t)(scene->n_objects + n), sizeof *o);
    if (!o)
        return NULL;
    for (int i = 0; i < scene->n_objects; i++)
        o[i] = scene->objects[i];
    int k = scene->n_objects;
    for (int i = 0; i < scene->n_lights; i++)
        if (scene->lights[i] && scene->lights[i]->looks_like)
            o[k++] = scene->lights[i]->looks_like;
    *copy = *scene;
    copy->objects = o;
    copy->n_objects = k;
    *objects = o;
    return copy;
}

/*
** projected_through: a light with such an object shines only where the
** ray to it meets that object (light_through(), light.h). The object is
** not part of the scene (POV-Ray does not render it), so each such light
** gets a query of its own on an accel built from a one-object copy of the
** scene.
*/
struct through {
    int n;
    struct accel **acc;
    struct rquery *q;
    iris_scene *sc;
};

static void through_free(struct through *th)
{
    for (int i = 0; i < th->n; i++)
        accel_destroy(th->acc[i]);
    iris_free(th->acc);
    iris_free(th->q);
    iris_free(th->sc);
    memset(th, 0, sizeof *th);
}

static enum iris_status through_build(const iris_scene *scene,
                                      struct tracer *tr, FILE *log,
                                      char *err, size_t errlen,
                                      struct through *th)
{
    int n = 0;
    for (int i = 0; i < tr->n_lights; i++)
        if (tr->lights[i].src && tr->lights[i].src->projected_through)
            n++;
    if (n == 0)
        return IRIS_OK;
    th->acc = iris_calloc((size_t)n, sizeof *th->acc);
    th->q = iris_calloc((size_t)n, sizeof *th->q);
    th->sc = iris_calloc((size_t)n, sizeof *th->sc);
    if (!th->acc || !th->q || !th->sc)
        return IRIS_ENOMEM;
    for (int i = 0; i < tr->n_lights; i++) {
        const iris_light *l = tr->lights[i].src;
        if (!l || !l->projected_through)
            continue;
        iris_scene *s = &th->sc[th->n];
        *s = *scene;
        s->objects = (iris_object **)&l->projected_through;
        s->n_objects = 1;
        enum iris_status st = accel_build(s, &th->acc[th->n], log, err,
                                          errlen);
        if (st != IRIS_OK)
            return st;
        th->q[th->n] = (struct rquery){ th->acc[th->n], accel_isect,
                                        accel_in,
                                        accel_epsilon(th->acc[th->n]),
                                        accel_inside_bounds, NULL, NULL };
        tr->lights[i].through = &th->q[th->n];
        th->n++;
    }
    return IRIS_OK;
}

static void set_err(char *err, size_t errlen, const char *msg)
{
    if (err && errlen) {
        strncpy(err, msg, errlen - 1);
        err[errlen - 1] = '\0';
    }
}

enum iris_status iris_render(const iris_scene *scene,
                             const iris_render_options *opts, iris_image *out,
                             iris_render_stats *stats, char *err,
                             size_t errlen)
{
    if (stats)
        memset(stats, 0, sizeof *stats);
    if (!scene || !opts || !out || !out->pixels) {
        set_err(err, errlen, "iris_render: missing scene, options or image");
        return IRIS_EINVAL;
    }
    if (opts->width <= 0 || opts->height <= 0 || out->width != opts->width ||
        out->height != opts->height) {
        set_err(err, errlen, "iris_render: the image size does not match "
                             "the options");
        return IRIS_EINVAL;
    }
    FILE *log = opts->log ? opts->log : stderr;
    iris_scene scene_copy;
    iris_object **extra_objects = NULL;
    scene = with_looks_like(scene, &scene_copy, &extra_objects);
    if (!scene) {
        set_err(err, errlen, "iris_render: out of memory");
        return IRIS_ENOMEM;
    }
    double t0 = par_now();
    int threads = opts->threads > 0 ? opts->threads : par_cores();
    if (threads > 256)
        threads = 256;
    struct render_plan plan;
    plan_compute(scene, opts, &plan);
    plan.threads = threads;
    plan.tiles = ((opts->width + 31) / 32) * ((opts->height + 31) / 32);
    if (opts->plan_out)
        plan_print(&plan, opts->plan_out);
    if (opts->plan_only) { /* --plan: nothing to build or render */
        iris_free(extra_objects);
        return IRIS_OK;
    }

    struct accel *acc = NULL;
    /* unknown glass names (an error) and clamping indices, located */
    enum iris_status st = check_ior(scene, log, err, errlen);
    if (st == IRIS_OK)
        st = accel_build(scene, &acc, log, err, errlen);
    if (st != IRIS_OK) {
        iris_free(extra_objects);
        return st;
    }
    struct mat_ctx *mat = NULL;
    st = mat_ctx_create(scene, log, &mat);
    if (st != IRIS_OK) {
        accel_destroy(acc);
        iris_free(extra_objects);
        set_err(err, errlen, "iris_render: out of memory building materials");
        return st;
    }
    mat_ctx_set_quick_colour(mat, (trace_quality_flags(plan.quality) &
                                   TQ_QUICK_COLOUR) != 0);
    struct rquery q = { acc, accel_isect, accel_in, accel_epsilon(acc),
                        accel_inside_bounds, NULL, NULL };
    if (accel_prim_cache_pays(acc)) {
        q.prim_hit = accel_prim_hit;
        q.intersect_prim = accel_intersect_prim;
    }
    struct tracer tr;
    struct through th;
    memset(&th, 0, sizeof th);
    if (!tracer_init(&tr, scene, mat, &q, plan.quality)) {
        st = IRIS_ENOMEM;
        goto done;
    }
    st = through_build(scene, &tr, log, err, errlen, &th);
    if (st != IRIS_OK)
        goto done;
    tr.seed = opts->seed;
    tr.spectral_min = opts->spectral_samples_min;
    tr.alpha = opts->alpha;
    tr.interrupt = opts->interrupt; /* a slow pixel stops too (trace.c) */
    double t1 = par_now();
    struct photon_map *pmap = NULL;
    st = photon_pass(&plan, &tr, acc, mat, threads, opts, &pmap, stats, err,
                     errlen);
    if (st == IRIS_EINVAL) /* the located error went to the log */
        set_err(err, errlen, "the photon settings ask for more than memory holds");
    double t2 = par_now();
    double more_photon_s = 0.0; /* maps of progressive passes after the first */
    /* MPI: rank 0's failed pass 0 must still stop the other ranks,
    ** which are rendering their passes (progressive.h) */
    if (progressive_wanted(opts) &&
        (st == IRIS_OK || (plan.photons && mpi_passes_size() > 1)))
        st = progressive_run(&tr, acc, mat, threads, opts, t0, st, &pmap,
                             out, stats, &more_photon_s, err, errlen);
    else if (st == IRIS_OK)
        st = eyepass_run(&tr, opts, threads, out, stats);
    if (stats) {
        stats->time_build_s = t1 - t0;
        stats->time_photon_s = t2 - t1 + more_photon_s;
        stats->time_render_s = par_now() - t2 - more_photon_s;
    }
    if (st == IRIS_ENOMEM)
        set_err(err, errlen, "iris_render: out of memory");
    else if (st == IRIS_EINTR)
        set_err(err, errlen, "iris_render: interrupted");
    else if (st == IRIS_EINVAL && !(err && err[0]))
        set_err(err, errlen, "iris_render: empty render window");
    photon_map_destroy(pmap);
done:
    through_free(&th);
    tracer_fini(&tr);
    mat_ctx_destroy(mat);
    accel_destroy(acc);
    iris_free(extra_objects);
    return st;
}
