/* SPDX-License-Identifier: MIT */
/*
** trace.c: the eye-pass tracer (see trace.h), following POV-Ray 3.7's
** Trace class (source/backend/render/trace.cpp): TraceRay,
** ComputeTextureColour, ComputeLightedTexture, ComputeOneDiffuseLight,
** the shadow-ray functions, ComputeRefraction, ComputeReflection,
** ComputeSky and ComputeFog, in that order below.
*/
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "render/trace.h"
#include "render/eyespectrum.h"
#include "render/media.h"
#include "render/rainbow.h"
#include "render/subsurface.h"
#include "render/gather.h"
#include "material/noise.h"
#include "math/transform.h"
#include "spectrum/ior.h"
#include "spectrum/spectrum.h"
#include "util/mem.h"

#define T_EPSILON 1e-10
#define HUGE_DEPTH 2.0e10        /* POV-Ray's BOUND_HUGE */
/* POV-Ray's shapes ignore intersections beyond MAX_DISTANCE = 1e7 (a plane
** seen near the horizon shows it). The limit grows with the scene's size
** (accel_epsilon is 1e-9 of it) so that a scene scaled up still renders. */
#define POV_MAX_DISTANCE 1.0e7
#define MAX_CACHED_LIGHTS 64

unsigned trace_quality_flags(int q)
{
    if (q < 0) q = 0;
    if (q > 9) q = 9;
    unsigned f = 0;
    if (q <= 1) f |= TQ_FULL_AMBIENT;
    if (q <= 5) f |= TQ_QUICK_COLOUR;
    if (q >= 4) f |= TQ_SHADOW;
    if (q >= 5) f |= TQ_AREA_LIGHT;
    if (q >= 6) f |= TQ_REFRACT;
    if (q >= 8) f |= TQ_REFLECT | TQ_NORMAL;
    if (q >= 9) f |= TQ_VOLUME | TQ_ADVANCED;
    return f;
}

static bool shadow_opaque_scene(const iris_scene *scene);
static bool rgb_zero(const double c[3]);

bool tracer_init(struct tracer *t, const iris_scene *scene,
                 const struct mat_ctx *mat, const struct rquery *q,
                 int quality)
{
    memset(t, 0, sizeof *t);
    t->scene = scene;
    t->mat = mat;
    t->q = *q;
    t->quality = trace_quality_flags(quality);
    t->max_level = scene->settings.max_trace_level > 0
                       ? scene->settings.max_trace_level : 5;
    if (t->max_level > 256)
        t->max_level = 256;
    t->adc = scene->settings.adc_bailout > 0 ? scene->settings.adc_bailout
                                             : 1.0 / 255.0;
    t->legacy = scene->version > 0 && scene->version < 3.7;
    t->max_area_grid = 1;
    t->max_distance = fmax(POV_MAX_DISTANCE, 1e6 * (q->eps / 1e-9));
    double gam = scene->settings.assumed_gamma;
    t->working_gamma = gam > 0 ? gam : 1.0;
    t->gamma_off = !(gam > 0) && t->legacy;
    /* the lights of light_groups follow the scene's in t->lights, beyond
    ** t->n_lights: only diffuse_light() asks for them, per object */
    int n_all = scene->n_lights + scene->n_group_lights;
    if (n_all > 0) {
        t->lights = iris_calloc((size_t)n_all, sizeof *t->lights);
        if (!t->lights)
            return false;
        for (int i = 0; i < n_all; i++) {
            light_prepare(i < scene->n_lights
                              ? scene->lights[i]
                              : scene->group_lights[i - scene->n_lights],
                          &t->lights[i]);
            t->lights[i].black = rgb_zero(t->lights[i].colour);
            if (t->lights[i].area) {
                long g = (long)t->lights[i].size1 * t->lights[i].size2;
                /* a point light, as the parser warned */
                if (g > IRIS_AREA_LIGHT_MAX_GRID)
                    t->lights[i].area = false;
                else if (g > t->max_area_grid)
                    t->max_area_grid = (int)g;
            }
        }
        t->n_lights = scene->n_lights;
    }
    t->shadow_cache = n_all > 0 && q->prim_hit && q->intersect_prim &&
                      shadow_opaque_scene(scene);
    return true;
}

void tracer_fini(struct tracer *t)
{
    iris_free(t->lights);
    t->lights = NULL;
}

bool trace_ctx_init(struct trace_ctx *c, const struct tracer *t)
{
    memset(c, 0, sizeof *c);
    c->t = t;
    c->grid = iris_calloc((size_t)t->max_area_grid, sizeof *c->grid);
    c->grid_set = iris_calloc((size_t)t->max_area_grid, sizeof *c->grid_set);
    rng_lazy_seed(&c->rng, t->seed, 0, 0);
    if (t->shadow_cache) {
        int n_all = t->scene->n_lights + t->scene->n_group_lights;
        c->shadow_prim = iris_calloc((size_t)n_all, sizeof *c->shadow_prim);
        if (!c->shadow_prim)
            return false;
    }
    return c->grid && c->grid_set;
}

void trace_ctx_fini(struct trace_ctx *c)
{
    gather_ctx_fini(c);
    iris_free(c->grid);
    iris_free(c->grid_set);
    iris_free(c->shadow_prim);
    c->grid = NULL;
    c->grid_set = NULL;
    c->shadow_prim = NULL;
}

/* ------------------------------------------------------------------ */
/* Small helpers                                                        */
/* ------------------------------------------------------------------ */

static bool rgb_zero(const double c[3])
{
    return fabs(c[0]) < T_EPSILON && fabs(c[1]) < T_EPSILON &&
           fabs(c[2]) < T_EPSILON;
}

static double ior_of(const iris_interior *in)
{
    return in && in->ior > 0 ? in->ior : 1.0;
}

/* The medium a hit's surface bounds. POV-Ray gives every object an
** interior (Parser::Post_Process): a CSG without interior{} gets one
** default interior that all its children without their own share, so
** the walls of a hole cut in glass (difference { glass knight }) bound
** one medium, not one per primitive of the knight. Keyed by the leaf,
** a ray entering the knight's prism and leaving through one of its
** cylinder cuts stayed "inside" the prism, and left the glass later
** unrefracted (advanced/glasschess). */
static const void *interior_key(const struct hit *h)
{
    if (h->interior)
        return h->interior;
    return h->top ? (const void *)h->top : (const void *)h->obj;
}

static int stack_find(const struct interior_stack *st, const void *key)
{
    for (int i = st->n - 1; i >= 0; i--)
        if (st->e[i].key == key)
            return i;
    return -1;
}

static void stack_remove(struct interior_stack *st, int i)
{
    for (; i + 1 < st->n; i++)
        st->e[i] = st->e[i + 1];
    st->n--;
}

static void stack_push(struct interior_stack *st, const void *key,
                       const iris_interior *in, bool hollow)
{
    if (st->n >= TRACE_MAX_INTERIORS)
        return;
    st->e[st->n].key = key;
    st->e[st->n].in = in;
    st->e[st->n].hollow = hollow;
    st->n++;
}

/* POV-Ray applies fog only to rays not inside a solid (non-hollow)
** object. */
static bool is_hollow_ray(const struct interior_stack *st)
{
    for (int i = 0; i < st->n; i++)
        if (!st->e[i].hollow)
            return false;
    return true;
}

/* POV-Ray's InitRayContainerState over one scene object. Every object
** has an interior there (a default one when none was given): a camera
** inside a plane that is not hollow sees no fog and no media. Unions are
** split into their children, as POV-Ray links them to the scene (not a
** merge, nor one clipped, bounded or with split_union off). An object
** without an interior{} is keyed by its top-level object 'top', as
** interior_key does. */
static bool containing_split(const iris_object *o)
{
    return (o->kind == IRIS_OBJ_UNION || o->kind == IRIS_OBJ_LIGHT_GROUP) &&
           o->split_union && o->n_clipped_by == 0 && !o->bounded_by;
}

static void containing_test(const struct tracer *t, const iris_object *o,
                            const iris_object *top, vec3 p,
                            struct interior_stack *st)
{
    if (t->q.inside(t->q.impl, o, p))
        stack_push(st, o->interior ? (const void *)o->interior
                                   : (const void *)top,
                   o->interior, o->hollow);
}

static void containing_rec(const struct tracer *t, const iris_object *o,
                           const iris_object *top, vec3 p,
                           struct interior_stack *st, int depth)
{
    if (!o || depth > 64)
        return;
    if (containing_split(o)) {
        for (int i = 0; i < o->u.csg.n_children; i++)
            containing_rec(t, o->u.csg.children[i], top, p, st, depth + 1);
        return;
    }
    containing_test(t, o, top, p, st);
}

/* Appends the objects containing_rec() would ask whose inside box meets
** cl's box; false when out of memory. */
static bool collect_rec(const struct tracer *t, const iris_object *o,
                        const iris_object *top, struct containing_list *cl,
                        int depth)
{
    if (!o || depth > 64)
        return true;
    if (containing_split(o)) {
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!collect_rec(t, o->u.csg.children[i], top, cl, depth + 1))
                return false;
        return true;
    }
    vec3 lo, hi;
    if (t->q.inside_bounds && t->q.inside_bounds(t->q.impl, o, &lo, &hi) &&
        !(lo.x <= cl->hi.x && hi.x >= cl->lo.x && lo.y <= cl->hi.y &&
          hi.y >= cl->lo.y && lo.z <= cl->hi.z && hi.z >= cl->lo.z))
        return true;
    if (cl->n == cl->cap) {
        int cap = cl->cap ? 2 * cl->cap : 16;
        const iris_object **nv =
            iris_realloc((void *)cl->o, (size_t)cap * sizeof *nv);
        if (!nv)
            return false;
        cl->o = nv;
        const iris_object **nt =
            iris_realloc((void *)cl->top, (size_t)cap * sizeof *nt);
        if (!nt)
            return false;
        cl->top = nt;
        cl->cap = cap;
    }
    cl->top[cl->n] = top;
    cl->o[cl->n++] = o;
    return true;
}

bool trace_containing_list(const struct tracer *t, vec3 lo, vec3 hi,
                           struct containing_list *cl)
{
    memset(cl, 0, sizeof *cl);
    cl->lo = lo;
    cl->hi = hi;
    for (int i = 0; i < t->scene->n_objects; i++)
        if (!collect_rec(t, t->scene->objects[i], t->scene->objects[i], cl,
                         0)) {
            trace_containing_list_free(cl);
            return false;
        }
    return true;
}

void trace_containing_list_free(struct containing_list *cl)
{
    iris_free((void *)cl->o);
    iris_free((void *)cl->top);
    memset(cl, 0, sizeof *cl);
}

void trace_containing_from(const struct tracer *t,
                           const struct containing_list *cl, vec3 p,
                           struct interior_stack *st)
{
    if (!(p.x >= cl->lo.x && p.x <= cl->hi.x && p.y >= cl->lo.y &&
          p.y <= cl->hi.y && p.z >= cl->lo.z && p.z <= cl->hi.z)) {
        trace_containing(t, p, st);
        return;
    }
    st->n = 0;
    if (!t->q.inside)
        return;
    for (int i = 0; i < cl->n; i++)
        containing_test(t, cl->o[i], cl->top[i], p, st);
}

void trace_containing(const struct tracer *t, vec3 p,
                      struct interior_stack *st)
{
    st->n = 0;
    if (!t->q.inside)
        return;
    for (int i = 0; i < t->scene->n_objects; i++)
        containing_rec(t, t->scene->objects[i], t->scene->objects[i], p,
                       st, 0);
}

/* The quality flags of the rays 'c' traces: a radiosity gather ray
** (gather.c) samples no area light (its centre instead) and no media
** unless radiosity{} has media on, as POV-Ray's radiosity rays. */
static unsigned ray_quality(const struct trace_ctx *c)
{
    unsigned q = c->t->quality;
    if (c->gi_depth > 0) {
        q &= ~(unsigned)TQ_AREA_LIGHT;
        if (!c->t->scene->settings.rad.media)
            q &= ~(unsigned)TQ_VOLUME;
    }
    return q;
}

/* The tmin of a ray leaving a hit with offset 'eps' (struct hit's eps,
** at most the scene's accel epsilon; docs/numerics.md §1). */
static double leave_eps(const struct tracer *t, double eps)
{
    return eps > 0.0 && eps < t->q.eps ? eps : t->q.eps;
}

static unsigned skip_flags(const struct tray *r)
{
    return r->reflected ? ACCEL_SKIP_NO_REFLECTION : ACCEL_SKIP_NO_IMAGE;
}

/* The texture seen at a hit: interior_texture on the back side. */
static const iris_texture *hit_texture(const struct hit *h, bool backface)
{
    if (backface && h->obj && h->obj->interior_texture)
        return h->obj->interior_texture;
    return h->texture;
}

/* The fade of 'in' over distance 'dist' (eye rays: applied even with
** fade_power 0, as POV-Ray's ComputeLightedTexture does). */
static void interior_fade(const iris_interior *in, double dist, bool eye,
                          double att[3])
{
    att[0] = att[1] = att[2] = 1.0;
    if (!in || !(fabs(in->fade_distance) > T_EPSILON))
        return;
    if (!eye && !(in->fade_power > 0.0))
        return;
    const double fc[3] = { in->fade_colour.r, in->fade_colour.g,
                           in->fade_colour.b };
    if (in->fade_power >= 1000) {
        double depth = dist / in->fade_distance;
        for (int k = 0; k < 3; k++)
            att[k] = exp(-(1.0 - fc[k]) * depth);
    } else {
        double a = 1.0 + pow(dist / in->fade_distance, in->fade_power);
        for (int k = 0; k < 3; k++)
            att[k] = fc[k] + (1.0 - fc[k]) / a;
    }
}

/* ------------------------------------------------------------------ */
/* Shadows                                                              */
/* ------------------------------------------------------------------ */

/*
** Whether 'tex' lets no light through anywhere: its top layer is a plain
** texture (no texture_map) whose pigment (pigment_opaque: a solid colour,
** or a pattern whose map entries all are, no image map) and quick
** colour have no filter or transmit. mat_eval_texture() would give every
** stack that layer on top, whose transmittance r*f + t is exactly 0, so
** shadow_colour()'s sum is exactly 0 whatever lies below: most shadow
** rays that meet something meet such an object, and the texture need
** not be evaluated (its patterns, normals, layers) to know it.
*/
static bool pigment_opaque(const iris_pigment *pg, int depth)
{
    if (!pg || depth > 8 || pg->quick_colour.f != 0.0 ||
        pg->quick_colour.t != 0.0)
        return false;
    if (pg->pattern.kind == IRIS_PAT_NONE)
        return pg->colour.f == 0.0 && pg->colour.t == 0.0;
    if (pg->pattern.kind == IRIS_PAT_IMAGE_MAP)
        return false;          /* texels carry filter, transmit, alpha */
    /* A pattern: pigment.c's mat_eval_pigment() gives one entry, or
    ** colour_lerp() of two neighbours at a finite fraction, or (average)
    ** a weighted mean: f and t stay exactly 0 when every entry's are, and
    ** it reports the layer valid (only image maps do not). Without
    ** entries it takes POV-Ray's default map, of opaque colours. */
    for (int i = 0; i < pg->n_entries; i++) {
        const iris_map_entry *e = &pg->entries[i];
        if (pg->is_pigment_map || e->pigment) {
            /* an entry without a pigment evaluates to 0 */
            if (e->pigment && !pigment_opaque(e->pigment, depth + 1))
                return false;
        } else if (e->colour.f != 0.0 || e->colour.t != 0.0) {
            return false;
        }
    }
    return true;
}

static inline bool texture_opaque(const iris_texture *tex)
{
    if (!tex ||
        (tex->map_pattern.kind != IRIS_PAT_NONE && tex->n_entries > 0))
        return false;
    const iris_pigment *pg = tex->pigment;
    /* a solid colour, the common case, inline (pigment_opaque's first
    ** tests) */
    if (pg && pg->pattern.kind == IRIS_PAT_NONE)
        return pg->colour.f == 0.0 && pg->colour.t == 0.0 &&
               pg->quick_colour.f == 0.0 && pg->quick_colour.t == 0.0;
    return pigment_opaque(pg, 0);
}

/*
** Whether every surface a shadow ray can meet in 'o' (top-level object
** 'top') shows only textures that texture_opaque() finds opaque, so that
** shadow_colour() makes the light black at any of them. The textures a
** hit can carry are those accel.c gives it (the leaf's own, a blob
** component's, a mesh triangle's) and the interior_texture of its back
** side; a CSG node's own texture is asked too, though its leaves carry
** resolved ones. Subtrees marked no_shadow are passed through by every
** shadow query (accel.c: the skip bits are inherited), so they do not
** count; clipped_by and bounded_by objects are never hit.
*/
static bool shadow_opaque_object(const iris_object *o, int depth)
{
    if (!o || o->no_shadow)
        return true;
    if (depth > 256)
        return false;
    if (o->texture && !texture_opaque(o->texture))
        return false;
    if (o->interior_texture && !texture_opaque(o->interior_texture))
        return false;
    if (mat_texture_blended(o))
        return false;
    switch (o->kind) {
    case IRIS_OBJ_UNION:
    case IRIS_OBJ_MERGE:
    case IRIS_OBJ_INTERSECTION:
    case IRIS_OBJ_DIFFERENCE:
    case IRIS_OBJ_LIGHT_GROUP:
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!shadow_opaque_object(o->u.csg.children[i], depth + 1))
                return false;
        return true;
    case IRIS_OBJ_BLOB:
        for (int i = 0; i < o->u.blob.n_components; i++) {
            const iris_texture *ct = o->u.blob.components[i].texture;
            if (ct && !texture_opaque(ct))
                return false;
        }
        return true;
    case IRIS_OBJ_MESH:
        for (int i = 0; i < o->u.mesh.n_textures; i++) {
            const iris_texture *mt = o->u.mesh.textures[i];
            if (mt && !texture_opaque(mt))
                return false;
        }
        return true;
    default:
        /* a leaf: the parser resolved its texture (never NULL) */
        return o->texture != NULL;
    }
}

/* shadow_opaque_object() of every object of the scene: then any surface
** in a shadow ray's way makes it black, whatever lies before or after. */
static bool shadow_opaque_scene(const iris_scene *scene)
{
    for (int i = 0; i < scene->n_objects; i++)
        if (!shadow_opaque_object(scene->objects[i], 0))
            return false;
    return true;
}

/* POV-Ray's ComputeShadowColour: the filter of the object at 'h' for a
** shadow ray along 'L'. */
static void shadow_colour(struct trace_ctx *c, const struct interior_stack *st,
                          const struct hit *h, vec3 L, double lc[3])
{
    const struct tracer *t = c->t;
    vec3 n = h->shading_n;
    double nd = v3_dot(n, L);
    const iris_texture *tex = hit_texture(h, nd > 0.0);
    if (texture_opaque(tex) && !mat_texture_blended(h->obj)) {
        /* lc times the sum below, which is +0 here */
        for (int k = 0; k < 3; k++)
            lc[k] *= 0.0;
        return;
    }
    if (nd > 0.0)
        n = v3_neg(n);
    struct mat_point pt = { h->p, n, L, h->uv, h->obj,
                            !(t->quality & TQ_NORMAL) };
    struct mat_eval ev;
    mat_eval_texture(t->mat, tex, &pt, &ev);
    const iris_interior *in = h->interior;
    double caustics = in ? in->caustics * 45.0 : 0.0;
    double fade[3] = { 1, 1, 1 };
    if (in && stack_find(st, interior_key(h)) >= 0)
        interior_fade(in, h->t, false, fade);
    double acc[3] = { 0, 0, 0 };
    for (int s = 0; s < ev.n_stacks; s++) {
        const struct mat_stack *sk = &ev.stacks[s];
        if (sk->weight < t->adc)
            continue;
        double tmp[3] = { 1, 1, 1 };
        for (int i = 0; i < sk->n; i++) {
            const struct mat_layer *l = &ev.layers[sk->first + i];
            if (l->valid) {
                double tr[3];
                mat_rgb_transm(&l->pigment, tr);
                for (int k = 0; k < 3; k++)
                    tmp[k] *= tr[k];
            }
            if (caustics != 0.0) {
                double k2 = 1.0 + pow(fabs(v3_dot(l->n, L)), caustics);
                for (int k = 0; k < 3; k++)
                    tmp[k] *= k2;
            }
        }
        for (int k = 0; k < 3; k++)
            acc[k] += sk->weight * tmp[k] * fade[k];
    }
    for (int k = 0; k < 3; k++)
        lc[k] *= acc[k];
}

static void apply_fog(struct trace_ctx *c, const ray *r, double depth,
                      bool shadow, double col[3]);

/* Media on a shadow ray's stretch of length 'len' from 'o' along 'L'
** (extinction only): at a surface ('at_surface'), the media of the
** interiors 'st' when no non-hollow one is among them (POV-Ray's
** ComputeShadowColour); on every stretch, the atmosphere's media and
** (on hollow rays) fog when the light has media_interaction and
** media_attenuation (ComputeShadowMedia; the last stretch, to the
** light, only when the ray is in hollow interiors and longer than
** POV-Ray's SHADOW_TOLERANCE). */
static void shadow_media_on(struct trace_ctx *c,
                            const struct interior_stack *st,
                            const iris_light *light, vec3 o, vec3 L,
                            double len, bool at_surface, double lc[3])
{
    const struct tracer *t = c->t;
    if (!(ray_quality(c) & TQ_VOLUME) || rgb_zero(lc))
        return;
    bool hollow = is_hollow_ray(st);
    bool stretch = light->media_interaction && light->media_attenuation &&
                   (at_surface || (hollow && len > 1e-3));
    bool atmos = stretch && t->scene->n_media > 0;
    bool fog = stretch && hollow && t->scene->n_fogs > 0;
    bool inner = at_surface && hollow && st->n > 0 && media_in_stack(st);
    if (!atmos && !inner && !fog)
        return;
    struct tray r;
    r.r.o = o;
    r.r.d = L;
    r.st.n = 0;                /* shadow media need no light tests */
    r.reflected = false;
    r.lambda = 0.0;
    r.tmin = 0.0;
    if (inner) {
        const iris_media *m[MEDIA_MAX_PER_RAY];
        int n = media_of_stack(st, m, MEDIA_MAX_PER_RAY);
        media_segment(c, m, n, &r, len, true, lc, NULL);
    }
    if (atmos)
        media_segment(c, (const iris_media *const *)t->scene->media,
                      t->scene->n_media, &r, len, true, lc, NULL);
    if (fog)
        apply_fog(c, &r.r, len, true, lc);
}

/* The common case inline: nothing in the air and no interior to ask, as
** for nearly every shadow ray (a call per shadow ray was 1 % of a simple
** scene's render). */
static inline void shadow_media(struct trace_ctx *c,
                                const struct interior_stack *st,
                                const iris_light *light, vec3 o, vec3 L,
                                double len, bool at_surface, double lc[3])
{
    const iris_scene *sc = c->t->scene;
    bool air = sc->n_media > 0 || sc->n_fogs > 0;
    if (air || (at_surface && st->n > 0))
        shadow_media_on(c, st, light, o, L, len, at_surface, lc);
}

/* True once the render was interrupted: the ray is not traced (black),
** so that a pixel of millions of rays (an area light with
** area_illumination, focal blur) ends within milliseconds of SIGTERM
** instead of minutes; the eye pass writes no pixel after it. The flag is
** read every 256 rays, not at every one (a volatile load). */
static inline bool trace_stopped(struct trace_ctx *c)
{
    if (!c->stopped && (c->rays & 255) == 0 && c->t->interrupt &&
        *c->t->interrupt)
        c->stopped = true;
    return c->stopped;
}

/*
** point_shadow() with POV-Ray's shadow cache (TracePointLightShadowRay's
** lightsource cache), for a scene whose every shadow-casting surface is
** opaque (t->shadow_cache, then c->shadow_prim exists): a shadow ray is
** black as soon as anything lies in (eps, depth - eps), whatever it is
** (shadow_colour() would make lc black at any hit, shadow_opaque_scene,
** as the photon rule would), so it has one stretch. accel_prim_hit()
** finding a crossing of the primitive that last blocked this light
** means the full query would find one too: the same counts and the same
** black without the query. A function of its own, which point_shadow()
** hands the ray to at its start, so that its own code stays as it was
** for every other scene (a test of the cache inside its loop, or a
** choice at its callers, cost 01_sphere_plane's eye pass 0.2 %).
*/
static void point_shadow_cached(struct trace_ctx *c,
                                const struct interior_stack *st,
                                const iris_light *light, vec3 origin,
                                double eps0, vec3 L, double depth,
                                double lc[3])
{
    const struct tracer *t = c->t;
    double eps = leave_eps(t, eps0);
    if (trace_stopped(c)) {
        lc[0] = lc[1] = lc[2] = 0.0;
        return;
    }
    c->rays++;
    c->n.shadow_tests++;
    ray r = { origin, L };
    /* the light's slot: its index in t->lights (few lights; only in
    ** scenes with the cache) */
    int li = 0, n_all = t->scene->n_lights + t->scene->n_group_lights;
    while (li < n_all - 1 && t->lights[li].src != light)
        li++;
    const void **slot = &c->shadow_prim[li];
    if (*slot) {
        double tc;
        if (t->q.prim_hit(t->q.impl, *slot, &r, eps, depth - eps,
                          ACCEL_SKIP_NO_SHADOW, &tc) &&
            tc > eps && tc < depth - eps) {
            c->n.shadow_hits++;
            lc[0] = lc[1] = lc[2] = 0.0;
            return;
        }
        /* Unlike POV-Ray, forgotten at the first miss: most shadow rays
        ** are not blocked, and with iris's cheap queries a test of the
        ** cached primitive before each of them cost more than the
        ** blocked ones saved (166_fopen_read_back +2.9 % instructions);
        ** shadows are coherent from one sample to the next, so the
        ** cache costs one test per way out of a shadow */
        *slot = NULL;
    }
    struct hit h;
    if (t->q.intersect_prim(t->q.impl, &r, eps, depth - eps,
                            ACCEL_SKIP_NO_SHADOW, &h) &&
        h.t > eps && h.t < depth - eps) {
        c->n.shadow_hits++;
        *slot = h.prim;
        lc[0] = lc[1] = lc[2] = 0.0;
        return;
    }
    shadow_media(c, st, light, origin, L, depth, false, lc);
}

/* POV-Ray's TracePointLightShadowRay: walks the segment to the light,
** filtering 'lc' by every object met, until it is black. The shadow ray
** starts with the eye ray's interiors and, as POV-Ray's ComputeShadowMedia
** does, toggles each object it crosses in and out of them, so the fade
** of a segment inside an object applies. */
static void point_shadow(struct trace_ctx *c, const struct interior_stack *eye_st,
                         const iris_light *light, const iris_object *lit,
                         vec3 origin, double eps0, vec3 L, double depth,
                         double lc[3])
{
    if (__builtin_expect(c->shadow_prim != NULL, 0)) {
        point_shadow_cached(c, eye_st, light, origin, eps0, L, depth, lc);
        return;
    }
    const struct tracer *t = c->t;
    double eps = leave_eps(t, eps0);
    /* The eye ray's stack is copied (its used part) only once the shadow
    ** ray crosses a surface: most shadow rays meet nothing or an opaque
    ** object first. */
    struct interior_stack stack;
    const struct interior_stack *st = eye_st;
    for (int guard = 0; guard < 1024; guard++) {
        ray r = { origin, L };
        struct hit h;
        if (trace_stopped(c)) {
            lc[0] = lc[1] = lc[2] = 0.0;
            return;
        }
        c->rays++;
        c->n.shadow_tests++;
        if (!t->q.intersect(t->q.impl, &r, eps, depth - eps,
                            ACCEL_SKIP_NO_SHADOW, &h) ||
            !(h.t > eps) || !(h.t < depth - eps)) {
            shadow_media(c, st, light, origin, L, depth, false, lc);
            return;
        }
        c->n.shadow_hits++;
        if (t->photon_shadow && t->photon_map &&
            t->photon_shadow(t->photon_map, h.obj, light, lit)) {
            lc[0] = lc[1] = lc[2] = 0.0;
            return;
        }
        shadow_colour(c, st, &h, L, lc);
        if (rgb_zero(lc)) {
            lc[0] = lc[1] = lc[2] = 0.0;
            return;
        }
        shadow_media(c, st, light, origin, L, h.t, true, lc);
        if (st != &stack) {
            stack.n = eye_st->n;
            for (int i = 0; i < eye_st->n; i++)
                stack.e[i] = eye_st->e[i];
            st = &stack;
        }
        int idx = stack_find(&stack, interior_key(&h));
        if (idx >= 0)
            stack_remove(&stack, idx);
        else
            stack_push(&stack, interior_key(&h), h.interior,
                       h.obj ? h.obj->hollow : true);
        depth -= h.t;
        origin = h.p;
        eps = leave_eps(t, h.eps);
    }
}

static double colour_distance(const double a[3], const double b[3])
{
    return fabs(a[0] - b[0]) + fabs(a[1] - b[1]) + fabs(a[2] - b[2]);
}

struct area_job {
    const struct rlight *l;
    const struct interior_stack *st;
    const iris_object *lit;
    vec3 p, a1, a2;
    double lc[3];              /* the light colour entering the test */
    double eps;                /* the lit hit's offset */
};

/* area_sample() of a grid point not yet tested: a point-light shadow
** test from a (jittered) position on the light, stored in the grid. */
static void area_sample_trace(struct trace_ctx *c, const struct area_job *j,
                              int u, int v, int idx, double out[3])
{
    const struct rlight *l = j->l;
    double ju = u, jv = v;
    if (l->src->jitter) {
        ju += rng_uniform(rng_lazy_get(&c->rng)) - 0.5;
        jv += rng_uniform(rng_lazy_get(&c->rng)) - 0.5;
    }
    vec3 off = light_area_offset(l, j->a1, j->a2, ju, jv);
    vec3 L;
    double depth;
    light_ray(l, j->p, off, &L, &depth);
    memcpy(out, j->lc, sizeof j->lc);
    if (light_through(l, j->p, leave_eps(c->t, j->eps), L, &depth))
        point_shadow(c, j->st, l->src, j->lit, j->p, j->eps, L, depth, out);
    else                       /* projected_through, per sample ray */
        out[0] = out[1] = out[2] = 0.0;
    memcpy(c->grid[idx], out, sizeof c->grid[idx]);
    c->grid_set[idx] = true;
}

/* One grid sample (u, v), cached in the grid. Inline: area_subset()
** asks for four corners, more than half of them already tested by a
** neighbouring subset (57 % in 06_area_light), and the call of a cache
** hit cost more than its lookup: 06's eye pass x0.953 instructions. */
static inline void area_sample(struct trace_ctx *c, const struct area_job *j,
                               int u, int v, double out[3])
{
    int idx = u * j->l->size2 + v;
    if (c->grid_set[idx])
        memcpy(out, c->grid[idx], sizeof c->grid[idx]);
    else
        area_sample_trace(c, j, u, v, idx, out);
}

/* POV-Ray's TraceAreaLightSubsetShadowRay: the four corners of the
** rectangle (u1,v1)-(u2,v2), subdivided while 'level' < adaptive or the
** corners differ, the result being the mean of the four parts. */
static void area_subset(struct trace_ctx *c, const struct area_job *j,
                        int u1, int v1, int u2, int v2, int level,
                        double out[3])
{
    double s[4][3];
    area_sample(c, j, u1, v1, s[0]);
    area_sample(c, j, u2, v1, s[1]);
    area_sample(c, j, u1, v2, s[2]);
    area_sample(c, j, u2, v2, s[3]);
    int adaptive = j->l->src->adaptive;
    if ((u2 - u1 > 1 || v2 - v1 > 1) && level < 64 && !c->stopped &&
        (level < adaptive || colour_distance(s[0], s[1]) > 0.1 ||
         colour_distance(s[1], s[3]) > 0.1 ||
         colour_distance(s[3], s[2]) > 0.1 ||
         colour_distance(s[2], s[0]) > 0.1)) {
        int um0 = (int)floor((u1 + u2) / 2.0), um1 = (int)ceil((u1 + u2) / 2.0);
        int vm0 = (int)floor((v1 + v2) / 2.0), vm1 = (int)ceil((v1 + v2) / 2.0);
        area_subset(c, j, u1, v1, um0, vm0, level + 1, s[0]);
        area_subset(c, j, um1, v1, u2, vm0, level + 1, s[1]);
        area_subset(c, j, u1, vm1, um0, v2, level + 1, s[2]);
        area_subset(c, j, um1, vm1, u2, v2, level + 1, s[3]);
    }
    for (int k = 0; k < 3; k++)
        out[k] = (s[0][k] + s[1][k] + s[2][k] + s[3][k]) * 0.25;
}

/* The area-light axes, rebuilt perpendicular to the light ray for
** 'orient' (both with axis1's length). */
static void area_axes(const struct rlight *l, vec3 p, vec3 *a1, vec3 *a2)
{
    *a1 = l->axis1;
    *a2 = l->axis2;
    if (!l->src->orient)
        return;
    vec3 L;
    double depth;
    light_ray(l, p, v3(0, 0, 0), &L, &depth);
    double len = v3_len(l->axis1);
    vec3 tmp = fabs(fabs(L.z) - 1.0) < 0.01 ? v3(0, 1, 0) : v3(0, 0, 1);
    *a1 = v3_scale(v3_norm(v3_cross(L, tmp)), len);
    *a2 = v3_scale(v3_norm(v3_cross(L, v3_norm(*a1))), len);
}

/* trace_shadow() of an area light (POV-Ray's TraceAreaLightShadowRay):
** out of line, as few lights are area lights, so that the shading of
** the usual light, which trace_shadow() is inlined into, stays smaller
** (01_sphere_plane's eye pass -0.13 % instructions). */
static __attribute__((noinline)) void area_shadow(
    struct trace_ctx *c, const struct interior_stack *st,
    const struct rlight *l, const iris_object *lit, vec3 p, double eps,
    double lc[3])
{
    struct area_job j = { l, st, lit, p, v3(0, 0, 0), v3(0, 0, 0),
                          { lc[0], lc[1], lc[2] }, eps };
    area_axes(l, p, &j.a1, &j.a2);
    memset(c->grid_set, 0,
           (size_t)(l->size1 * l->size2) * sizeof *c->grid_set);
    area_subset(c, &j, 0, 0, l->size1 - 1, l->size2 - 1, 0, lc);
}

/* POV-Ray's TraceShadowRay: past max_trace_level the light is black.
** Inline: its call passed two vectors on the stack per light and hit. */
static inline void trace_shadow(struct trace_ctx *c,
                                const struct interior_stack *st,
                                const struct rlight *l,
                                const iris_object *lit, vec3 p, double eps,
                                vec3 L, double depth, double lc[3])
{
    const struct tracer *t = c->t;
    if (c->level > t->max_level) {
        lc[0] = lc[1] = lc[2] = 0.0;
        return;
    }
    /* projected_through (light.h): an area light's samples test their
    ** own rays (area_sample), any other light the ray to its centre; a
    ** shadowless light stops after the test */
    bool area = l->area && (ray_quality(c) & TQ_AREA_LIGHT) && !l->fill;
    if (!area && l->through) {
        /* through a copy: 'depth' itself, never addressed, can stay in
        ** a register in the shading code this is inlined into (-0.1 %) */
        double d = depth;
        if (!light_through_object(l, p, leave_eps(t, eps), L, &d)) {
            lc[0] = lc[1] = lc[2] = 0.0;
            return;
        }
        depth = d;
    }
    if (l->fill)
        return;
    c->level++;
    if (area) {
        area_shadow(c, st, l, lit, p, eps, lc);
    } else {
        point_shadow(c, st, l->src, lit, p, eps, L, depth, lc);
    }
    c->level--;
}

/* POV-Ray's TestShadow for a media sample (media.h). */
bool trace_media_light(struct trace_ctx *c, const struct interior_stack *st,
                       int i, vec3 p, vec3 *L, double lc[3])
{
    const struct tracer *t = c->t;
    const struct rlight *l = &t->lights[i];
    double depth;
    light_ray(l, p, v3(0, 0, 0), L, &depth);
    double a = light_attenuation(l, p, *L, depth);
    lc[0] = l->colour[0] * a;
    lc[1] = l->colour[1] * a;
    lc[2] = l->colour[2] * a;
    if (rgb_zero(lc))
        return false;
    if ((t->quality & TQ_SHADOW) && (!l->fill || l->through)) {
        trace_shadow(c, st, l, NULL, p, 0.0, *L, depth, lc);
        if (rgb_zero(lc))
            return false;
    }
    return true;
}

/* ------------------------------------------------------------------ */
/* Local illumination                                                   */
/* ------------------------------------------------------------------ */

/* What the per-light shading of one layer needs. */
struct layer_shade {
    const struct mat_layer *l;
    const struct tray *eye;
    const struct hit *h;
    double att;                /* layer opacity */
};

static void irid_colour(const struct tracer *t, const iris_finish *f,
                        vec3 light, vec3 eye, vec3 n, vec3 p, double col[3])
{
    double thick = f->irid_thickness;
    if (f->irid_turbulence.x != 0) {
        struct noise_turb turb = { 5, 0.5, 2.0 };
        double nz = noise_turbulence(p, &turb, mat_noise_generator(t->mat));
        thick *= 1.0 + (2.0 * nz - 1.0) * f->irid_turbulence.x;
    }
    iris_vec3 wl = t->scene->settings.irid_wavelength;
    if (wl.x <= 0 || wl.y <= 0 || wl.z <= 0)
        wl = v3(0.70, 0.52, 0.48);
    double inter = 2.0 * M_PI * thick *
                   (fabs(v3_dot(n, light)) + fabs(v3_dot(n, eye)));
    col[0] *= 1.0 + f->irid * cos(inter / wl.x);
    col[1] *= 1.0 + f->irid * cos(inter / wl.y);
    col[2] *= 1.0 + f->irid * cos(inter / wl.z);
}

/* Diffuse, phong and specular of one light colour 'lc' along 'L'.
** Inline: called per light and layer of every hit. */
static inline void light_terms(struct trace_ctx *c,
                               const struct layer_shade *s, vec3 L,
                               const double lc[3], bool backside, bool fill,
                               double out[3])
{
    const iris_finish *f = s->l->finish;
    const iris_colour *P = &s->l->pigment;
    vec3 n = s->l->n, d = s->eye->r.d;
    double diffuse = backside ? f->diffuse_back : f->diffuse;
    if (diffuse > 0.0) {
        double cosi = v3_dot(n, L);
        double in = f->brilliance != 1.0 ? pow(fabs(cosi), f->brilliance)
                                         : fabs(cosi);
        in *= diffuse * s->att;
        if (f->crand > 0.0)
            in -= rng_uniform(rng_lazy_get(&c->rng)) * f->crand;
        out[0] += in * P->r * lc[0];
        out[1] += in * P->g * lc[1];
        out[2] += in * P->b * lc[2];
    }
    if (fill || backside || c->gi_depth > 0) /* radiosity rays: none */
        return;
    /* a finish without highlights (the usual diffuse one) ends here,
    ** before the tint is set up */
    if (!(f->phong > 0.0) && !(f->specular > 0.0))
        return;
    double tint[3] = { 1, 1, 1 };
    if (f->metallic > 0.0)
        mat_metallic_tint(f->metallic, v3_dot(n, L), P, tint);
    if (f->phong > 0.0) {
        vec3 R = v3_madd(d, n, -2.0 * v3_dot(d, n));
        double cr = v3_dot(R, L);
        if (cr > 0.0) {
            double in = (f->phong_size < 60 || cr > 0.0008)
                            ? f->phong * pow(cr, f->phong_size) : 0.0;
            for (int k = 0; k < 3; k++)
                out[k] += in * lc[k] * tint[k];
        }
    }
    if (f->specular > 0.0) {
        vec3 H = v3_scale(v3_add(v3_neg(d), L), 0.5);
        double hl = v3_len(H);
        if (hl > 0.0) {
            double ch = v3_dot(H, n) / hl;
            if (ch > 0.0) {
                double rough = f->roughness > 0 ? f->roughness : 0.05;
                double in = f->specular * pow(ch, 1.0 / rough);
                for (int k = 0; k < 3; k++)
                    out[k] += in * lc[k] * tint[k];
            }
        }
    }
}

/* Shadow colours of one intersection, shared by all its layers (POV-Ray's
** light colour cache). */
struct light_cache {
    bool tested[MAX_CACHED_LIGHTS];
    double colour[MAX_CACHED_LIGHTS][3];
};

/* area_illumination: every sub-light shades on its own with C_L/(n1 n2). */
static void full_area_light(struct trace_ctx *c, const struct layer_shade *s,
                            const struct rlight *l, double out[3])
{
    const double *col = l->colour;
    int n1 = l->size1, n2 = l->size2;
    vec3 a1, a2;
    area_axes(l, s->h->p, &a1, &a2);
    for (int u = 0; u < n1 && !c->stopped; u++)
        for (int v = 0; v < n2; v++) {
            double ju = u, jv = v;
            if (l->src->jitter) {
                ju += rng_uniform(rng_lazy_get(&c->rng)) - 0.5;
                jv += rng_uniform(rng_lazy_get(&c->rng)) - 0.5;
            }
            vec3 L;
            double depth;
            light_ray(l, s->h->p, light_area_offset(l, a1, a2, ju, jv), &L,
                      &depth);
            double a = light_attenuation(l, s->h->p, L, depth) / (n1 * n2);
            double lc[3] = { col[0] * a, col[1] * a, col[2] * a };
            if (rgb_zero(lc))
                continue;
            if ((c->t->quality & TQ_SHADOW) && !l->fill) {
                c->level++;
                point_shadow(c, &s->eye->st, l->src, s->h->obj, s->h->p,
                             s->h->eps,
                             L, depth, lc);
                c->level--;
            }
            if (rgb_zero(lc))
                continue;
            double tmp[3] = { 0, 0, 0 };
            bool back = v3_dot(s->l->n, L) < T_EPSILON;
            if (back && s->l->finish->diffuse_back == 0.0 &&
                !s->h->obj->double_illuminate)
                continue;
            light_terms(c, s, L, lc, back && !s->h->obj->double_illuminate,
                        l->fill, tmp);
            for (int k = 0; k < 3; k++)
                out[k] += tmp[k];
        }
}

/* POV-Ray's ComputeDiffuseLight over every light. 'cache' is NULL where
** the hit has one layer (no other layer could reuse a shadow test). */
static void diffuse_light(struct trace_ctx *c, const struct layer_shade *s,
                          struct light_cache *cache, double out[3])
{
    const struct tracer *t = c->t;
    const iris_finish *f = s->l->finish;
    vec3 p = s->h->p;
    bool dbl = s->h->obj && s->h->obj->double_illuminate;
    /* POV-Ray's ComputeDiffuseLight: the scene's lights unless the object
    ** is in a light_group without global_lights, then its group's */
    const iris_object *ob = s->h->obj;
    int j0 = ob && ob->no_global_lights ? t->n_lights : 0;
    int j1 = t->n_lights + (ob ? ob->light_group_count : 0);
    for (int j = j0; j < j1; j++) {
        int i = j < t->n_lights ? j : j + ob->light_group_first;
        const struct rlight *l = &t->lights[i];
        bool full_area = l->area && l->src->area_illumination &&
                         (ray_quality(c) & TQ_AREA_LIGHT);
        vec3 L;
        double depth;
        light_ray(l, p, v3(0, 0, 0), &L, &depth);
        double a = full_area ? 1.0 : light_attenuation(l, p, L, depth);
        double lc[3] = { l->colour[0] * a, l->colour[1] * a,
                         l->colour[2] * a };
        /* a = 1 (the usual light): lc is the colour, tested once */
        if (a == 1.0 ? l->black : rgb_zero(lc))
            continue;
        bool backside = false;
        if (!dbl && !full_area && v3_dot(s->l->n, L) < T_EPSILON) {
            if (f->diffuse_back != 0.0)
                backside = true;
            else
                continue;
        }
        if ((t->quality & TQ_SHADOW) && (!l->fill || l->through)) {
            if (cache && i < MAX_CACHED_LIGHTS && cache->tested[i]) {
                memcpy(lc, cache->colour[i], sizeof lc);
            } else {
                trace_shadow(c, &s->eye->st, l, s->h->obj, p, s->h->eps, L,
                             depth, lc);
                if (cache && i < MAX_CACHED_LIGHTS) {
                    cache->tested[i] = true;
                    memcpy(cache->colour[i], lc, sizeof lc);
                }
            }
        }
        if (rgb_zero(lc))
            continue;
        if (full_area) {
            full_area_light(c, s, l, out);
            continue;
        }
        double tmp[3] = { 0, 0, 0 };
        light_terms(c, s, L, lc, backside, l->fill, tmp);
        if (f->irid > 0.0) {
            /* through a copy: irid_colour() is a call, and tmp itself,
            ** never addressed, can stay in registers through the light
            ** loop (its address taken cost a simple scene's eye pass
            ** 0.3-0.4 % instructions) */
            double ic[3] = { tmp[0], tmp[1], tmp[2] };
            irid_colour(t, f, L, s->eye->r.d, s->l->n, p, ic);
            tmp[0] = ic[0];
            tmp[1] = ic[1];
            tmp[2] = ic[2];
        }
        for (int k = 0; k < 3; k++)
            out[k] += tmp[k];
    }
}

/* ------------------------------------------------------------------ */
/* Reflection and refraction                                            */
/* ------------------------------------------------------------------ */

/* POV-Ray's ComputeReflection: the mirror ray about 'n', kept above the
** surface with the raw normal. */
static void reflect(struct trace_ctx *c, const struct tray *eye,
                    const struct hit *h, const iris_finish *f, vec3 n,
                    vec3 raw, double weight, double out[3])
{
    vec3 d = eye->r.d;
    vec3 R = v3_madd(d, n, -2.0 * v3_dot(d, n));
    double k = v3_dot(R, raw);
    if (k < 0.0) {
        if (v3_dot(R, n) < 0.0)
            R = v3_madd(d, raw, -2.0 * v3_dot(d, raw));
        else
            R = v3_madd(R, raw, -2.0 * k);
    }
    struct tray nr;
    tray_copy(&nr, eye);
    nr.r.o = h->p;
    nr.r.d = v3_norm(R);
    nr.tmin = h->eps;
    nr.reflected = true;
    /* POV-Ray's reflected rays, and all they spawn, see the +UA
    ** background as opaque (sky_colour) */
    bool opaque_bg = c->opaque_bg;
    c->opaque_bg = true;
    c->n.reflected++;
    trace_ray(c, &nr, weight, false, out);
    c->opaque_bg = opaque_bg;
    if (f && f->irid > 0.0)
        irid_colour(c->t, f, nr.r.d, d, n, h->p, out);
}

bool trace_refract_dir(vec3 d, vec3 n, double eta, vec3 *out)
{
    double c = -v3_dot(d, n);
    double t2 = 1.0 + eta * eta * (c * c - 1.0);
    if (t2 < 0.0)
        return false;
    *out = v3_norm(v3_madd(v3_scale(d, eta), n, eta * c - sqrt(t2)));
    return true;
}

/* One refracted ray with relative index 'eta'; TIR reflects. */
static bool refract_one(struct trace_ctx *c, const struct tray *eye,
                        const struct tray *nr_in, const struct hit *h,
                        const iris_finish *f, vec3 n_top, vec3 raw,
                        vec3 local, double eta, double weight, double out[3])
{
    vec3 T;
    if (!trace_refract_dir(eye->r.d, local, eta, &T)) {
        double tmp[3] = { 0, 0, 0 };
        reflect(c, eye, h, f, n_top, raw, weight, tmp);
        for (int k = 0; k < 3; k++)
            out[k] += tmp[k];
        return true;
    }
    struct tray nr;
    tray_copy(&nr, nr_in);
    nr.r.o = h->p;
    nr.r.d = T;
    out[0] = out[1] = out[2] = 0.0;
    c->n.refracted++;
    trace_ray(c, &nr, weight, false, out);
    return false;
}

/* The wavelength-split refraction of a camera ray at a dispersive
** interface (DESIGN.md: chromatic aberration); eyespectrum.h says how the
** wavelengths are drawn and summed. */
static void refract_spectral(struct trace_ctx *c, const struct tray *eye,
                             const struct tray *nr, const struct hit *h,
                             const iris_finish *f, vec3 n_top, vec3 raw,
                             vec3 local, const iris_interior *from,
                             const iris_interior *to, int n_samples,
                             double weight, double out[3])
{
    struct eye_spectrum acc;
    eye_spectrum_init(&acc);
    double transm = 0.0;       /* the bands' c->transm, averaged */
    for (int i = 0; i < n_samples; i++) {
        double a[3];
        double u = rng_uniform(rng_lazy_get(&c->rng));
        double lambda = eye_lambda_sample(i, n_samples, u, a);
        double eta = ior_eval(from, lambda) / ior_eval(to, lambda);
        struct tray band;
        tray_copy(&band, nr);
        band.lambda = lambda;
        double col[3] = { 0, 0, 0 };
        (void)refract_one(c, eye, &band, h, f, n_top, raw, local, eta,
                          weight, col);
        eye_spectrum_add(&acc, a, spec_reflectance(col, lambda));
        transm += c->transm;
    }
    eye_spectrum_rgb(&acc, out);
    c->transm = transm / n_samples;
    c->spectral = true;        /* the eye pass maps the pixel's gamut */
}

/* POV-Ray's ComputeRefraction with the interior stack of §1.2. Returns
** whether total internal reflection happened. */
static bool refraction(struct trace_ctx *c, const struct tray *eye,
                       const struct hit *h, const iris_finish *f, vec3 n_top,
                       vec3 raw, double weight, double out[3])
{
    const struct tracer *t = c->t;
    const iris_interior *in = h->interior;
    const void *key = interior_key(h);
    bool hollow = h->obj ? h->obj->hollow : true;
    struct tray nr;
    tray_copy(&nr, eye);
    nr.tmin = h->eps;
    struct interior_stack *st = &nr.st;
    const iris_interior *from = NULL, *to = NULL;
    bool straight = false;
    int n_samples = in ? in->dispersion_samples : 7;
    if (st->n == 0) {
        stack_push(st, key, in, hollow);
        to = in;
    } else if (st->e[st->n - 1].key == key) {
        st->n--;
        from = in;
        if (st->n > 0) {
            to = st->e[st->n - 1].in;
            if (to && to->dispersion_samples > n_samples)
                n_samples = to->dispersion_samples;
        }
    } else {
        int idx = stack_find(st, key);
        if (idx >= 0) {
            stack_remove(st, idx);
            straight = true;
        } else {
            from = st->e[st->n - 1].in;
            stack_push(st, key, in, hollow);
            to = in;
        }
    }
    double eta = 1.0;
    bool dispersive = false;
    if (!straight) {
        if (eye->lambda > 0)
            eta = ior_eval(from, eye->lambda) / ior_eval(to, eye->lambda);
        else {
            eta = ior_of(from) / ior_of(to);
            dispersive = (from && ior_is_dispersive(from)) ||
                         (to && ior_is_dispersive(to));
        }
    }
    if (!isfinite(eta) || eta <= 0)
        eta = 1.0;
    if (fabs(eta - 1.0) < T_EPSILON && !dispersive) {
        nr.r.o = h->p;
        out[0] = out[1] = out[2] = 0.0;
        c->n.transmitted++;
        trace_ray(c, &nr, weight, true, out);
        return false;
    }
    vec3 local = v3_dot(eye->r.d, n_top) <= 0.0 ? n_top : v3_neg(n_top);
    if (!dispersive)
        return refract_one(c, eye, &nr, h, f, n_top, raw, local, eta, weight,
                           out);
    if (n_samples < 2)
        n_samples = 2;
    if (t->spectral_min > n_samples)
        n_samples = t->spectral_min;
    if (n_samples > 1000)
        n_samples = 1000;
    refract_spectral(c, eye, &nr, h, f, n_top, raw, local, from, to,
                     n_samples, weight, out);
    return false;
}

/* POV-Ray's ComputeRelativeIOR, the n of fresnel reflection. */
static double relative_ior(const struct tray *eye, const struct hit *h)
{
    const iris_interior *in = h->interior;
    if (!in)
        return 1.0;
    const struct interior_stack *st = &eye->st;
    double n = ior_of(in);
    if (st->n == 0)
        return n;
    if (stack_find(st, interior_key(h)) >= 0) {
        if (st->n == 1)
            return 1.0 / n;
        return ior_of(st->e[st->n - 1].in) / n;
    }
    return n / ior_of(st->e[st->n - 1].in);
}

/* ------------------------------------------------------------------ */
/* Texture colour                                                       */
/* ------------------------------------------------------------------ */

struct refl_entry {
    double weight, refl[3], exponent;
    vec3 n;
    const iris_finish *f;
};

/* Whether mat_layer_reflectivity() can give anything but 0: its first
** test, here without the call (most finishes reflect nothing, and the
** call per layer and hit was 2.6 % of a simple scene's eye pass). */
static inline uint64_t double_bits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}
static inline bool finish_reflects(const iris_finish *f)
{
    /* the bits of the six, or'ed: 0 only where all are +0 (six double
    ** compares cost twice this); a -0 answers true, and the call then
    ** finds the layer black, as it would anyway */
    const iris_colour *mx = &f->reflection_max, *mn = &f->reflection_min;
    return (double_bits(mx->r) | double_bits(mx->g) | double_bits(mx->b) |
            double_bits(mn->r) | double_bits(mn->g) | double_bits(mn->b)) != 0;
}

/* POV-Ray's ComputeLightedTexture for one stack of layers. */
static void lighted_texture(struct trace_ctx *c, const struct tray *eye,
                            const struct hit *h, const struct mat_eval *ev,
                            const struct mat_stack *sk, vec3 raw,
                            double weight, struct light_cache *cache,
                            double out[3])
{
    const struct tracer *t = c->t;
    const iris_scene *sc = t->scene;
    double filcol[3] = { 1, 1, 1 }, trans = 1.0;
    double stack_transm = 0.0; /* c->transm of this stack, see the end */
    bool one_found = false;
    struct refl_entry refl[MAT_MAX_LAYERS];
    int n_done = 0;
    vec3 n_top = raw;
    out[0] = out[1] = out[2] = 0.0;
    c->transm = 0.0;
    const double amb_light[3] = { sc->settings.ambient_light.r,
                                  sc->settings.ambient_light.g,
                                  sc->settings.ambient_light.b };
    /* POV-Ray 3.7 drops ambient only where radiosity runs (+Q9) */
    bool use_ambient = !sc->settings.radiosity || !gather_wanted(t) ||
                       t->legacy;
    /* fresnel's n, asked for by reflecting and subsurface layers only
    ** (most layers are neither): computed at the first that asks */
    double fres_n = 0.0;
    bool fres_known = false;
    bool any_refl = false;     /* some refl[] entry is not black */
    /* radiosity{}: an eye hit gathers (once for all layers) and reads
    ** the photon map without its global part; gather rays' hits read the
    ** global map only when recursion_limit allows a further bounce */
    bool gi_eye = t->gather && gather_at_depth(t->gather, c->gi_depth);
    bool gi_done = false;
    double gi_e[3] = { 0, 0, 0 };
    const void *pmap = !t->gather ? t->photon_map
                       : c->gi_depth == 0 ? t->photon_map_local : t->photon_map_gather;
    /* the pretrace's own eye hits only place samples (as in POV-Ray);
    ** deeper gathers beside a global map see no light source */
    bool lit = !t->gather || gather_lit(t->gather, c->gi_depth);

    for (int i = 0; i < sk->n && trans > t->adc; i++, n_done++) {
        const struct mat_layer *l = &ev->layers[sk->first + i];
        const iris_colour *P = &l->pigment;
        const iris_finish *f = l->finish;
        /* subsurface_shade() may point l into this (the layer without
        ** its diffuse term): it must live to the end of the iteration */
        struct subsurface_layer sss;
        if (i == 0)
            n_top = l->n;
        one_found = one_found || l->valid;
        double new_weight = weight * trans;
        if (t->quality & TQ_FULL_AMBIENT) {
            out[0] = P->r;
            out[1] = P->g;
            out[2] = P->b;
        } else {
            struct refl_entry *re = &refl[i];
            re->refl[0] = re->refl[1] = re->refl[2] = 0.0;
            if (finish_reflects(f)) {
                /* the rest of the entry is read only where refl is not
                ** black (the reflection loop below) */
                double cosi = -v3_dot(eye->r.d, l->n);
                if (!fres_known) {
                    fres_n = relative_ior(eye, h);
                    fres_known = true;
                }
                re->n = l->n;
                re->f = f;
                re->exponent = f->reflection_exponent > 0
                                   ? 1.0 / f->reflection_exponent : 1.0;
                double wf = 0.0;
                if (!mat_layer_reflectivity(l, cosi, fres_n, re->refl, &wf))
                    re->refl[0] = re->refl[1] = re->refl[2] = 0.0;
                re->weight = new_weight * wf;
                any_refl = any_refl || !rgb_zero(re->refl);
            }
            double att = mat_opacity(t->mat, P);
            double tmp[3] = { 0, 0, 0 };
            const double col[3] = { P->r, P->g, P->b };
            const double amb[3] = { f->ambient.r, f->ambient.g, f->ambient.b };
            const double emi[3] = { f->emission.r, f->emission.g,
                                    f->emission.b };
            for (int k = 0; k < 3; k++) {
                if (use_ambient)
                    tmp[k] += col[k] * amb[k] * amb_light[k] * att;
                tmp[k] += col[k] * emi[k] * att;
            }
            if (gi_eye && f->diffuse > 0.0) {
                /* POV-Ray's radiosity term: pigment x it x diffuse x att,
                ** gathered once the layer could show it above adc; the
                ** diffuse as written, not scaled by 'albedo' (RawDiffuse) */
                const double fc[3] = { filcol[0] * col[0], filcol[1] * col[1],
                                       filcol[2] * col[2] };
                double raw_d = iris_finish_raw_diffuse(f);
                double mx = mat_greyscale(fc) * att * raw_d;
                if (!gi_done && mx > t->adc) {
                    gather_irradiance(c, eye, h, raw, l->n, weight * mx,
                                      gi_e);
                    gi_done = true;
                }
                for (int k = 0; k < 3; k++)
                    tmp[k] += col[k] * gi_e[k] * raw_d * att;
            }
            /* subsurface{}: the BSSRDF stands for the diffuse term of
            ** the lights and photons below (subsurface.h) */
            if (f->subsurface && subsurface_enabled(t)) {
                if (!fres_known) {
                    fres_n = relative_ior(eye, h);
                    fres_known = true;
                }
                l = subsurface_shade(c, eye, h, l, raw, fres_n, lit, &sss,
                                     tmp);
                f = l->finish;
            }
            struct layer_shade s = { l, eye, h, att };
            if (lit && (f->diffuse != 0.0 || f->diffuse_back != 0.0 ||
                        f->specular != 0.0 || f->phong != 0.0))
                diffuse_light(c, &s, cache, tmp);
            if (lit && t->photon_shade && pmap &&
                !(h->obj && !h->obj->photon_collect)) {
                struct trace_photon_input pi = { h->p, l->n, raw, eye->r.d,
                                                 f, *P, att, h->obj };
                t->photon_shade(pmap, &pi, tmp);
            }
            for (int k = 0; k < 3; k++)
                out[k] += tmp[k] * filcol[k];
        }
        if (l->valid) {
            double tr[3];
            mat_rgb_transm(P, tr);
            for (int k = 0; k < 3; k++)
                filcol[k] *= tr[k];
            if (f->conserve_energy && !(t->quality & TQ_FULL_AMBIENT))
                for (int k = 0; k < 3; k++)
                    filcol[k] *= fmin(1.0, 1.0 - refl[i].refl[k]);
        }
        /* fmin(1, |grey|) without libm's call: a NaN gives 1 either way */
        double grey = fabs(mat_greyscale(filcol));
        trans = grey < 1.0 ? grey : 1.0;
    }
    if (t->quality & TQ_FULL_AMBIENT)
        return;

    /* Transmission: every object has an interior in POV-Ray (NULL here
    ** stands for the default one, ior 1). */
    bool tir = false;
    if (trans > t->adc && (t->quality & TQ_REFRACT)) {
        double w1 = fmax(fabs(filcol[0]), fmax(fabs(filcol[1]),
                                               fabs(filcol[2])));
        const iris_finish *ftop = sk->n > 0 ? ev->layers[sk->first].finish
                                            : NULL;
        double rfr[3] = { 0, 0, 0 };
        tir = refraction(c, eye, h, ftop, n_top, raw, weight * w1, rfr);
        double att[3] = { 1, 1, 1 };
        if (h->interior && stack_find(&eye->st, interior_key(h)) >= 0)
            interior_fade(h->interior, h->t, true, att);
        /* alpha: what the refracted ray saw of the background, through
        ** this surface (semantics §3.4) */
        stack_transm = fabs(mat_greyscale(att)) * c->transm * trans;
        for (int k = 0; k < 3; k++) {
            if (tir || !one_found)
                out[k] += att[k] * rfr[k];
            else
                out[k] += att[k] * rfr[k] * filcol[k];
        }
    }

    /* Reflection, unfiltered by the layers above. */
    if (any_refl && (t->quality & TQ_REFLECT)) {
        for (int i = 0; i < n_done; i++) {
            struct refl_entry *re = &refl[i];
            if (rgb_zero(re->refl))
                continue;
            if (tir && fabs(n_top.x - re->n.x) <= T_EPSILON &&
                fabs(n_top.y - re->n.y) <= T_EPSILON &&
                fabs(n_top.z - re->n.z) <= T_EPSILON)
                continue;
            double rfl[3] = { 0, 0, 0 };
            reflect(c, eye, h, re->f, re->n, raw, re->weight, rfl);
            for (int k = 0; k < 3; k++) {
                double v = re->exponent != 1.0 ? pow(fmax(rfl[k], 0.0),
                                                     re->exponent)
                                               : rfl[k];
                out[k] += re->refl[k] * v;
            }
        }
    }
    c->transm = stack_transm;  /* the reflected rays do not count */
}

/* POV-Ray's ComputeTextureColour: the texture stacks blended. */
static void texture_colour(struct trace_ctx *c, const struct tray *eye,
                           const struct hit *h, double weight, double out[3])
{
    const struct tracer *t = c->t;
    vec3 raw = h->shading_n;
    double nd = v3_dot(raw, eye->r.d);
    if (nd > 0.0)
        raw = v3_neg(raw);
    struct mat_point pt = { h->p, raw, eye->r.d, h->uv, h->obj,
                            !(t->quality & TQ_NORMAL) };
    /* On the stack: a heap block per hit costs more than the shading of
    ** a plain texture (the recursion depth is bounded by max_level). */
    struct mat_eval evs;
    struct mat_eval *ev = &evs;
    out[0] = out[1] = out[2] = 0.0;
    mat_eval_texture(t->mat, hit_texture(h, nd > 0.0), &pt, ev);
    /* the shadow colours are shared only between layers: a texture of
    ** one layer (the usual one) tests each light once anyway */
    struct light_cache cache, *cp = NULL;
    if (ev->n_layers > 1) {
        memset(cache.tested, 0, sizeof cache.tested);
        cp = &cache;
    }
    double transm = 0.0;       /* the stacks' c->transm, blended */
    for (int s = 0; s < ev->n_stacks; s++) {
        const struct mat_stack *sk = &ev->stacks[s];
        if (sk->weight < t->adc)
            continue;
        /* one stack of weight 1, every texture but a blend: its colour
        ** and c->transm are the hit's (1 x + 0 is x, but for the sign
        ** of a zero, which no pixel shows) */
        bool whole = ev->n_stacks == 1 && sk->weight == 1.0;
        double col[3];
        lighted_texture(c, eye, h, ev, sk, raw, weight, cp,
                        whole ? out : col);
        if (whole)
            return;
        for (int k = 0; k < 3; k++)
            out[k] += sk->weight * col[k];
        transm += sk->weight * c->transm;
    }
    c->transm = transm;
}

/* ------------------------------------------------------------------ */
/* Sky and fog                                                          */
/* ------------------------------------------------------------------ */

static void sky_colour(struct trace_ctx *c, vec3 d, double out[3])
{
    const struct tracer *t = c->t;
    const iris_scene *sc = t->scene;
    const iris_sky_sphere *sky = sc->sky_sphere;
    double col[3] = { 0, 0, 0 }, filcol[3] = { 1, 1, 1 };
    const iris_colour *bg = &sc->background;
    /* +UA: the background is transparent, except to reflected and
    ** radiosity rays, which POV-Ray lets see it opaque */
    bool alpha_bg = t->alpha && !c->opaque_bg && c->gi_depth == 0;
    if (t->legacy) {
        /* POV-Ray's pre-3.7 compositing: background shows through the
        ** sky by the accumulated filter and transmit. Under +UA the
        ** sky of an eye or refracted ray is transparent black (3.6's
        ** alpha background; the sky sphere is not drawn). */
        if (alpha_bg) {
            out[0] = out[1] = out[2] = 0.0;
            c->transm = 1.0;
            return;
        }
        out[0] = bg->r; out[1] = bg->g; out[2] = bg->b;
        if (!sky || sky->n_pigments == 0)
            return;
        iris_colour fc = { 1, 1, 1, 1, 1 };
        double trans = 1.0;
        vec3 p = sky->has_transform ? xf_inv_point(&sky->transform, d) : d;
        for (int i = sky->n_pigments - 1; i >= 0; i--) {
            iris_colour pc;
            struct mat_point pt = { p, v3(0, 0, 0), d, { 0, 0 }, NULL, true };
            mat_eval_pigment(t->mat, sky->pigments[i], &pt, &pc);
            double att = trans * (1.0 - pc.f - pc.t);
            col[0] += pc.r * att; col[1] += pc.g * att; col[2] += pc.b * att;
            fc.r *= pc.r; fc.g *= pc.g; fc.b *= pc.b; fc.f *= pc.f;
            fc.t *= pc.t;
            trans = fabs(fc.f) + fabs(fc.t);
        }
        double em = sky->emission != 0 ? sky->emission : 1.0;
        out[0] = col[0] * em + bg->r * (fc.r * fc.f + fc.t);
        out[1] = col[1] * em + bg->g * (fc.g * fc.f + fc.t);
        out[2] = col[2] * em + bg->b * (fc.b * fc.f + fc.t);
        return;
    }
    if (sky && sky->n_pigments > 0) {
        vec3 p = sky->has_transform ? xf_inv_point(&sky->transform, d) : d;
        double em = sky->emission != 0 ? sky->emission : 1.0;
        for (int i = sky->n_pigments - 1; i >= 0; i--) {
            iris_colour pc;
            struct mat_point pt = { p, v3(0, 0, 0), d, { 0, 0 }, NULL, true };
            mat_eval_pigment(t->mat, sky->pigments[i], &pt, &pc);
            double att = 1.0 - pc.f - pc.t;
            col[0] += pc.r * att * filcol[0] * em;
            col[1] += pc.g * att * filcol[1] * em;
            col[2] += pc.b * att * filcol[2] * em;
            double tr[3];
            mat_rgb_transm(&pc, tr);
            for (int k = 0; k < 3; k++)
                filcol[k] *= tr[k];
        }
    }
    /* The background is one more, uniform sky layer (POV-Ray 3.7's
    ** ComputeSky). With alpha output it shows by 1 - f - t and lets
    ** r*f + t through, which is the pixel's transmit; without, its f and
    ** t are dropped, and a background statement's colour was composed on
    ** black first: rgb * (1 - transmit) (POV-Ray does that as it parses
    ** 'background', so the default background and one a program sets
    ** directly are not scaled). Reflected rays see the alpha background
    ** opaque: f and t dropped, the colour not scaled. */
    iris_colour b = *bg;
    if (!alpha_bg) {
        /* the precomposition on black is the parser's without +UA only */
        double keep = !t->alpha && sc->has_background ? 1.0 - b.t : 1.0;
        b.r *= keep; b.g *= keep; b.b *= keep;
        b.f = b.t = 0.0;
    }
    double att = 1.0 - b.f - b.t, btr[3];
    mat_rgb_transm(&b, btr);
    out[0] = col[0] + b.r * att * filcol[0];
    out[1] = col[1] + b.g * att * filcol[1];
    out[2] = col[2] + b.b * att * filcol[2];
    for (int k = 0; k < 3; k++)
        filcol[k] *= btr[k];
    c->transm = fmin(1.0, fabs(mat_greyscale(filcol)));
}

static double fog_turbulence(const struct tracer *t, const iris_fog *fog,
                             vec3 p, double width)
{
    if (fog->turbulence.x == 0 && fog->turbulence.y == 0 &&
        fog->turbulence.z == 0)
        return width;
    /* the parser sets the defaults; 0 is meant literally (POV-Ray 3.7) */
    struct noise_turb turb = { fog->octaves < 1 ? 1 : fog->octaves > 10
                                   ? 10 : fog->octaves,
                               fog->omega, fog->lambda };
    p = v3_mul(p, fog->turbulence);
    double k = exp(-width / fog->distance);
    double depth = fog->turb_depth != 0 ? fog->turb_depth : 0.5;
    double n = noise_turbulence(p, &turb, mat_noise_generator(t->mat));
    return width * (1.0 - k * fmin(1.0, n * depth));
}

/* POV-Ray's ComputeFog over every fog of the scene; a 'shadow' ray is
** only attenuated (the fog adds no colour to light). */
static void apply_fog(struct trace_ctx *c, const ray *r, double depth,
                      bool shadow, double col[3])
{
    const struct tracer *t = c->t;
    const iris_scene *sc = t->scene;
    double sum_att[3] = { 1, 1, 1 }, sum_col[3] = { 0, 0, 0 };
    for (int i = 0; i < sc->n_fogs; i++) {
        const iris_fog *fog = sc->fogs[i];
        if (!(fabs(fog->distance) > T_EPSILON))
            continue;
        double width = depth, att;
        if (fog->kind == IRIS_FOG_GROUND) {
            vec3 up = v3_len2(fog->up) > 0 ? v3_norm(fog->up) : v3(0, 1, 0);
            vec3 p1 = r->o, p2 = v3_madd(r->o, r->d, width);
            double alt = fog->alt != 0 ? fog->alt : 1.0;
            double y1 = v3_dot(p1, up), y2 = v3_dot(p2, up);
            double s = (y1 - fog->offset) / alt, e = (y2 - fog->offset) / alt;
            double dens;
            if (s <= 0.0)
                dens = e <= 0.0 ? 1.0 : (atan(e) - s) / (e - s);
            else if (e <= 0.0)
                dens = (atan(s) - e) / (s - e);
            else {
                double dl = s - e;
                dens = fabs(dl) > T_EPSILON ? (atan(s) - atan(e)) / dl
                                            : 1.0 / (s * s + 1.0);
            }
            width = fog_turbulence(t, fog, v3_scale(v3_add(p1, p2), 0.5),
                                   width);
            att = exp(-width * dens / fog->distance);
        } else {
            width = fog_turbulence(t, fog, v3_madd(r->o, r->d, width / 2.0),
                                   width);
            att = exp(-width / fog->distance);
        }
        const iris_colour *fc = &fog->colour;
        if (att < fc->t)
            att = fc->t;
        const double rgb[3] = { fc->r, fc->g, fc->b };
        for (int k = 0; k < 3; k++) {
            sum_att[k] *= att * ((1.0 - fc->f) + fc->f * rgb[k]);
            if (!shadow)
                sum_col[k] += (1.0 - att) * rgb[k];
        }
    }
    for (int k = 0; k < 3; k++)
        col[k] = sum_col[k] + sum_att[k] * col[k];
    /* the fog hides the background as it hides colour: +UA's alpha
    ** (POV-Ray's ComputeFog scales the transmit channel alike) */
    if (!shadow)
        c->transm *= mat_greyscale(sum_att);
}

/* ------------------------------------------------------------------ */
/* TraceRay                                                             */
/* ------------------------------------------------------------------ */

/* POV-Ray's media of a ray not inside a non-hollow object: its
** interiors' media up to the hit (ComputeTextureColour), then the
** atmosphere's (TraceRay: up to the hit, or BOUND_HUGE on a miss). */
static void ray_media(struct trace_ctx *c, const struct tray *r, bool found,
                      double depth, double rgb[3])
{
    const iris_scene *sc = c->t->scene;
    if (!is_hollow_ray(&r->st))
        return;
    if (found && r->st.n > 0 && media_in_stack(&r->st)) {
        const iris_media *m[MEDIA_MAX_PER_RAY];
        int n = media_of_stack(&r->st, m, MEDIA_MAX_PER_RAY);
        media_segment(c, m, n, r, depth, false, rgb, &c->transm);
    }
    if (sc->n_media > 0)
        media_segment(c, (const iris_media *const *)sc->media, sc->n_media,
                      r, depth, false, rgb, &c->transm);
}

double trace_ray(struct trace_ctx *c, const struct tray *r, double weight,
                 bool continued, double rgb[3])
{
    const struct tracer *t = c->t;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    c->transm = 0.0;
    c->n.rays++;               /* before the bailouts, as POV-Ray counts */
    if (c->level >= t->max_level || weight < t->adc || trace_stopped(c))
        return HUGE_VAL;
    struct hit h;
    c->rays++;
    /* gather rays and what they spawn pass no_radiosity objects */
    unsigned skip = skip_flags(r) |
                    (c->gi_depth > 0 ? ACCEL_SKIP_NO_RADIOSITY : 0);
    double tmin = r->tmin > 0.0 ? leave_eps(t, r->tmin)
                                : accel_origin_epsilon(r->r.o, t->q.eps);
    bool found = t->q.intersect(t->q.impl, &r->r, tmin, t->max_distance,
                                skip, &h);
    if (found && !(h.t > 0.0 && h.t < HUGE_VAL)) /* positive, finite */
        found = false;
    if (c->imp_check) {
        /* a radiosity gather ray: an object less important than the
        ** ray's rank in its sample only gives its distance (POV-Ray) */
        c->imp_check = false;
        double imp = found && h.obj && h.obj->radiosity_importance > 0.0
                         ? h.obj->radiosity_importance
                         : t->scene->settings.rad_default_importance;
        c->imp_found = imp > 0.0 ? (float)imp : 1.0f;
        if (c->imp_found < c->imp_query)
            return found ? h.t : HUGE_VAL;
    }
    if (!continued)
        c->level++;
    if (found)
        texture_colour(c, r, &h, weight, rgb);
    else
        sky_colour(c, r->r.d, rgb);
    /* Rainbows, media and fog: a ray in no interior of a scene without
    ** rainbow, atmospheric media or fog has none of them (ray_media()'s
    ** interior media need an interior on the ray's stack), which one test
    ** tells, where the three below took ~30 instructions a ray. */
    const iris_scene *sc = t->scene;
    if (r->st.n > 0 || sc->n_rainbows > 0 || sc->n_media > 0 ||
        sc->n_fogs > 0) {
        if ((ray_quality(c) & TQ_VOLUME) && sc->n_rainbows > 0 &&
            is_hollow_ray(&r->st))
            rainbow_apply(sc, t->mat, r->r.d, found ? h.t : HUGE_DEPTH, rgb);
        if (ray_quality(c) & TQ_VOLUME)
            ray_media(c, r, found, found ? h.t : HUGE_DEPTH, rgb);
        if (sc->n_fogs > 0 && is_hollow_ray(&r->st))
            apply_fog(c, &r->r, found ? h.t : HUGE_DEPTH, false, rgb);
    }
    if (!continued)
        c->level--;
    return found ? h.t : HUGE_VAL;
}
