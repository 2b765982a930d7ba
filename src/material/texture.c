/* SPDX-License-Identifier: MIT */
/*
** texture.c: the material context, texture evaluation into layer stacks,
** and the optical helpers of material.h (transmittance, opacity, Fresnel
** and layer reflectivity as POV-Ray's ComputeLightedTexture computes them).
**
** DESIGN. POV-Ray shades a texture_map by shading each of the two
** neighbouring textures completely and mixing the colours. So that the
** tracer and the photon shooter need not recurse through textures, a
** texture is flattened here into weighted stacks of plain layers: a
** layered texture is one stack; a texture_map layer splits every stack
** into one per neighbouring entry, weighted by the blend fraction.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "material/mat_internal.h"
#include "image/df3.h"
#include "image/indices.h"
#include "material/noise.h"
#include "util/mem.h"

/* ------------------------------------------------------------------ */
/* Context                                                              */
/* ------------------------------------------------------------------ */

/* What a file is read for (a mask: one file may serve several). */
enum { USE_COLOURS = 1, USE_INDICES = 2, USE_DF3 = 4 };

struct image_list {
    int n, cap;
    const iris_image_ref **refs;
    unsigned char *use;        /* USE_* of each file */
    /* the walk also prepares the objects of object patterns */
    struct objpat_set *objpats;
    const iris_scene *scene;
    FILE *log;
};

static bool add_ref_as(struct image_list *l, const iris_image_ref *ref,
                       unsigned char use)
{
    if (!ref || !ref->path)
        return true;
    for (int i = 0; i < l->n; i++)
        if (l->refs[i] == ref || strcmp(l->refs[i]->path, ref->path) == 0) {
            l->use[i] |= use;
            return true;
        }
    if (l->n == l->cap) {
        int cap = l->cap ? 2 * l->cap : 8;
        const iris_image_ref **r = iris_realloc((void *)l->refs,
                                                (size_t)cap * sizeof *r);
        if (!r)
            return false;
        l->refs = r;
        unsigned char *x = iris_realloc(l->use, (size_t)cap * sizeof *x);
        if (!x)
            return false;
        l->use = x;
        l->cap = cap;
    }
    l->use[l->n] = use;
    l->refs[l->n++] = ref;
    return true;
}

/* Visiting guard: textures and pigments may be shared, and a malformed
** scene could even make them cyclic; a depth limit ends any walk. */
#define WALK_DEPTH 64

static bool walk_texture(struct image_list *l, const iris_texture *t,
                         int depth);

static bool walk_pattern(struct image_list *l, const iris_pattern *p)
{
    if (p->kind == IRIS_PAT_OBJECT && p->object)
        return objpat_add(l->objpats, l->scene, p->object, l->log) ==
               IRIS_OK;
    if (p->kind == IRIS_PAT_DENSITY_FILE)
        return add_ref_as(l, p->image, USE_DF3);
    /* per-index filter/transmit needs the palette indices */
    return add_ref_as(l, p->image, USE_COLOURS |
                      (p->image && p->image->n_palette_ft > 0 ? USE_INDICES
                                                               : 0));
}

static bool walk_pigment(struct image_list *l, const iris_pigment *p,
                         int depth)
{
    if (!p || depth > WALK_DEPTH)
        return true;
    if (!walk_pattern(l, &p->pattern))
        return false;
    for (int i = 0; i < p->n_entries; i++)
        if (!walk_pigment(l, p->entries[i].pigment, depth + 1))
            return false;
    return true;
}

static bool walk_normal(struct image_list *l, const iris_normal *n, int depth)
{
    if (!n || depth > WALK_DEPTH)
        return true;
    if (!walk_pattern(l, &n->pattern) ||
        !add_ref_as(l, n->bump_map, USE_COLOURS |
                    (n->bump_map && n->bump_map->use_index ? USE_INDICES
                                                           : 0)))
        return false;
    for (int i = 0; i < n->n_entries; i++)
        if (!walk_normal(l, n->entries[i].normal, depth + 1))
            return false;
    return true;
}

static bool walk_texture(struct image_list *l, const iris_texture *t,
                         int depth)
{
    for (; t && depth <= WALK_DEPTH; t = t->next, depth++) {
        if (!walk_pigment(l, t->pigment, depth) ||
            !walk_normal(l, t->normal, depth) ||
            !(t->map_pattern.kind == IRIS_PAT_IMAGE_MAP
                  ? add_ref_as(l, t->map_pattern.image, USE_INDICES)
                  : walk_pattern(l, &t->map_pattern)))
            return false;
        for (int i = 0; i < t->n_entries; i++)
            if (!walk_texture(l, t->entries[i].texture, depth + 1))
                return false;
    }
    return true;
}

/* The density pigments of media blocks (density_file reads a .df3). */
static bool walk_media(struct image_list *l, iris_media *const *m, int n)
{
    for (int i = 0; i < n; i++)
        for (int j = 0; m[i] && j < m[i]->n_densities; j++)
            if (!walk_pigment(l, m[i]->densities[j], 0))
                return false;
    return true;
}

static bool walk_object(struct image_list *l, const iris_object *o, int depth)
{
    if (!o || depth > WALK_DEPTH)
        return true;
    if (!walk_texture(l, o->texture, 0) ||
        !walk_texture(l, o->interior_texture, 0))
        return false;
    if (o->interior &&
        !walk_media(l, o->interior->media, o->interior->n_media))
        return false;
    if (o->kind >= IRIS_OBJ_UNION && o->kind <= IRIS_OBJ_LIGHT_GROUP)
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!walk_object(l, o->u.csg.children[i], depth + 1))
                return false;
    if (o->kind == IRIS_OBJ_MESH)
        for (int i = 0; i < o->u.mesh.n_textures; i++)
            if (!walk_texture(l, o->u.mesh.textures[i], 0))
                return false;
    return true;
}

enum iris_status mat_ctx_create(const iris_scene *scene, FILE *log,
                                struct mat_ctx **out)
{
    *out = NULL;
    noise_init();
    struct mat_ctx *ctx = iris_calloc(1, sizeof *ctx);
    if (!ctx)
        return IRIS_ENOMEM;
    ctx->scene = scene;
    ctx->noise_generator = 2;
    ctx->n_waves = 10;
    if (scene) {
        int g = scene->settings.noise_generator;
        ctx->noise_generator = g >= 1 && g <= 3 ? g : 2;
        if (scene->settings.number_of_waves > 0)
            ctx->n_waves = scene->settings.number_of_waves;
        ctx->head.legacy_opacity = scene->version > 0 && scene->version < 3.7;
    }
    struct image_list l = { 0, 0, NULL, NULL, &ctx->objpats, scene, log };
    bool ok = true;
    if (scene) {
        for (int i = 0; ok && i < scene->n_objects; i++)
            ok = walk_object(&l, scene->objects[i], 0);
        if (scene->sky_sphere)
            for (int i = 0; ok && i < scene->sky_sphere->n_pigments; i++)
                ok = walk_pigment(&l, scene->sky_sphere->pigments[i], 0);
        ok = ok && walk_media(&l, scene->media, scene->n_media);
    }
    if (ok && l.n > 0) {
        ctx->images = iris_calloc((size_t)l.n, sizeof *ctx->images);
        ok = ctx->images != NULL;
    }
    for (int i = 0; ok && i < l.n; i++) {
        struct mat_image *mi = &ctx->images[ctx->n_images++];
        mi->ref = l.refs[i];
        char err[256] = "";
        if ((l.use[i] & USE_COLOURS) && mi->ref->pixels) {
            /* an image the parser computed from a function */
            const iris_image_ref *r = mi->ref;
            ok = iris_image_init(&mi->img, r->pixels_w, r->pixels_h) ==
                 IRIS_OK;
            if (ok)
                memcpy(mi->img.pixels, r->pixels, (size_t)r->pixels_w *
                       (size_t)r->pixels_h * 4 * sizeof(float));
        } else if ((l.use[i] & USE_COLOURS) &&
            iris_image_read(&mi->img, mi->ref->path, err, sizeof err) !=
            IRIS_OK) {
            fprintf(log ? log : stderr,
                    "warning: cannot read image '%s'%s%s; it renders black\n",
                    mi->ref->path, err[0] ? ": " : "", err);
            memset(&mi->img, 0, sizeof mi->img);
        }
        if ((l.use[i] & USE_DF3) &&
            iris_df3_read(mi->ref->path, &mi->df3, err, sizeof err) !=
            IRIS_OK)
            fprintf(log ? log : stderr, "warning: cannot read the density "
                    "file '%s'%s%s; its density is 0\n", mi->ref->path,
                    err[0] ? ": " : "", err);
        if ((l.use[i] & USE_INDICES) && iris_image_read_indices(mi->ref->path,
                                                    &mi->index, &mi->index_w,
                                                    &mi->index_h,
                                                    &mi->index_palette, err,
                                                    sizeof err) != IRIS_OK) {
            fprintf(log ? log : stderr, "warning: cannot read the material_map "
                    "image '%s'%s%s; its first texture is used everywhere\n",
                    mi->ref->path, err[0] ? ": " : "", err);
            mi->index = NULL;
        }
    }
    iris_free((void *)l.refs);
    iris_free(l.use);
    objpat_seal(&ctx->objpats);
    if (!ok) {
        mat_ctx_destroy(ctx);
        return IRIS_ENOMEM;
    }
    *out = ctx;
    return IRIS_OK;
}

void mat_ctx_destroy(struct mat_ctx *ctx)
{
    if (!ctx)
        return;
    /* before the images go: no texel of theirs may be remembered */
    mat_texel_memo_forget();
    for (int i = 0; i < ctx->n_images; i++) {
        if (ctx->images[i].img.width > 0)
            iris_image_fini(&ctx->images[i].img);
        iris_free(ctx->images[i].index);
        iris_df3_fini(&ctx->images[i].df3);
    }
    iris_free(ctx->images);
    objpat_fini(&ctx->objpats);
    iris_free(ctx);
}

void mat_ctx_set_quick_colour(struct mat_ctx *ctx, bool on)
{
    if (ctx)
        ctx->quick_colour = on;
}

int mat_noise_generator(const struct mat_ctx *ctx)
{
    return ctx ? ctx->noise_generator : 2;
}

/* ------------------------------------------------------------------ */
/* Texture evaluation                                                   */
/* ------------------------------------------------------------------ */

/* The finish of a texture that has none (never happens with the parser,
** but a hand-built scene may omit it). */
static const iris_finish *default_finish(void)
{
    /* POV-Ray's defaults (semantics §3.1). */
    static const iris_finish f = {
        .ambient = { 0.1, 0.1, 0.1, 0, 0 },
        .diffuse = 0.6, .brilliance = 1, .phong_size = 40,
        .roughness = 0.05, .reflection_falloff = 1,
        .reflection_exponent = 1, .legacy_refraction = 1,
    };
    return &f;
}

/*
** 'pn' is POV-Ray's Intersection->PNormal: the normal the patterns see
** (slope). It starts as the raw normal at each hit, and every layer with
** a normal{} leaves its perturbed normal there (Perturb_Normal), for the
** layers and the texture_map entries evaluated after it: a slope map
** whose first entry has bumps sees them in the next entry's slope
** (textures/patterns/slopemt_37). Each layer still perturbs the raw
** normal.
*/
static inline void layer_at(const struct mat_ctx *ctx,
                            const iris_texture *t,
                            const struct mat_point *ppt, vec3 raw,
                            struct mat_layer *l)
{
    l->valid = mat_eval_pigment(ctx, t->pigment, ppt, &l->pigment);
    l->finish = t->finish ? t->finish : default_finish();
    l->n = raw;
    if (t->normal && !ppt->skip_normals)
        /* POV-Ray keeps a perturbed normal as it comes, even where it
        ** tips below the surface (the light then falls on its back). */
        l->n = mat_perturb_normal(ctx, t->normal, ppt, raw);
}

static void eval_layer(const struct mat_ctx *ctx, const iris_texture *t,
                       const struct mat_point *pt, struct mat_layer *l,
                       vec3 *pn)
{
    struct mat_point ppt = *pt;
    ppt.n = *pn;
    layer_at(ctx, t, &ppt, pt->n, l);
    if (t->normal && !pt->skip_normals)
        *pn = l->n;
}

static void set_empty(struct mat_eval *e)
{
    e->n_layers = 0;
    e->n_stacks = 1;
    e->stacks[0].weight = 1.0;
    e->stacks[0].first = 0;
    e->stacks[0].n = 0;
}

/* 'src' as combine() reads it: its counts, its used layers and stacks.
** A whole struct mat_eval is 2.8 kB, nearly all of it unused layers. */
static void copy_used(struct mat_eval *dst, const struct mat_eval *src)
{
    dst->n_layers = src->n_layers;
    dst->n_stacks = src->n_stacks;
    memcpy(dst->layers, src->layers,
           (size_t)src->n_layers * sizeof src->layers[0]);
    memcpy(dst->stacks, src->stacks,
           (size_t)src->n_stacks * sizeof src->stacks[0]);
}

/* Keeps the MAT_MAX_STACKS heaviest of 'n' candidate stacks. */
struct cand {
    double w;
    const struct mat_eval *a, *b;
    int ia, ib;
};

static void combine(const struct mat_eval *const *alts, const double *w,
                    int n_alts, const struct mat_eval *rest,
                    struct mat_eval *out)
{
    struct cand c[MAT_MAX_STACKS * MAT_MAX_STACKS * 2];
    int nc = 0;
    for (int a = 0; a < n_alts; a++)
        for (int i = 0; i < alts[a]->n_stacks; i++)
            for (int j = 0; j < rest->n_stacks; j++) {
                if (nc >= (int)(sizeof c / sizeof c[0]))
                    break;
                c[nc].w = w[a] * alts[a]->stacks[i].weight *
                          rest->stacks[j].weight;
                c[nc].a = alts[a];
                c[nc].ia = i;
                c[nc].b = rest;
                c[nc].ib = j;
                nc++;
            }
    /* selection of the heaviest (nc is small) */
    for (int i = 0; i < nc; i++)
        for (int j = i + 1; j < nc; j++)
            if (c[j].w > c[i].w) {
                struct cand t = c[i];
                c[i] = c[j];
                c[j] = t;
            }
    if (nc > MAT_MAX_STACKS)
        nc = MAT_MAX_STACKS;
    double total = 0;
    for (int i = 0; i < nc; i++)
        total += c[i].w;
    out->n_layers = 0;
    out->n_stacks = 0;
    for (int i = 0; i < nc; i++) {
        struct mat_stack *s = &out->stacks[out->n_stacks++];
        s->weight = total > 0 ? c[i].w / total : 1.0 / nc;
        s->first = out->n_layers;
        s->n = 0;
        const struct mat_stack *sa = &c[i].a->stacks[c[i].ia];
        const struct mat_stack *sb = &c[i].b->stacks[c[i].ib];
        for (int k = 0; k < sa->n && out->n_layers < MAT_MAX_LAYERS; k++) {
            out->layers[out->n_layers++] = c[i].a->layers[sa->first + k];
            s->n++;
        }
        for (int k = 0; k < sb->n && out->n_layers < MAT_MAX_LAYERS; k++) {
            out->layers[out->n_layers++] = c[i].b->layers[sb->first + k];
            s->n++;
        }
    }
    if (out->n_stacks == 0)
        set_empty(out);
}

static void eval_list(const struct mat_ctx *ctx, const iris_texture *tex,
                      const struct mat_point *pt, struct mat_eval *out,
                      int depth, vec3 *pn);

/* One map entry, 'tex', taken whole (weight 1) over the layers 'rest':
** combine() of it alone. Where 'rest' is empty (the map is the bottom
** layer, as usual) and the entry gives one stack of weight 1 from its
** first layer, combine() would give that stack as it is (its weight
** 1 x 1 x 1, divided by itself: 1), so the entry is evaluated straight
** into 'out' without the copies (the whole of combine() was a third of
** a material_map scene's texture work). */
static void eval_entry_whole(const struct mat_ctx *ctx,
                             const iris_texture *tex,
                             const struct mat_point *pt,
                             const struct mat_eval *rest,
                             struct mat_eval *out, int depth, vec3 *pn)
{
    struct mat_eval alt;
    const struct mat_eval *alts[1] = { &alt };
    double w[1] = { 1.0 };
    if (rest->n_layers == 0 && rest->n_stacks == 1 &&
        rest->stacks[0].weight == 1.0) {
        eval_list(ctx, tex, pt, out, depth + 1, pn);
        if (out->n_stacks == 1 && out->stacks[0].weight == 1.0 &&
            out->stacks[0].first == 0)
            return;
        copy_used(&alt, out);
    } else {
        eval_list(ctx, tex, pt, &alt, depth + 1, pn);
    }
    combine(alts, w, 1, rest, out);
}

/* The most entries of an 'average' texture_map that are shaded. */
#define MAX_AVERAGE 16

/* An 'average' texture_map: every entry shaded and the colours mixed by
** the entries' weights (an entry written without one weighs 1), as
** POV-Ray's average texture does. */
static void eval_average(const struct mat_ctx *ctx, const iris_texture *t,
                         const struct mat_point *pt,
                         const struct mat_eval *rest, struct mat_eval *out,
                         int depth, vec3 *pn)
{
    int n = t->n_entries < MAX_AVERAGE ? t->n_entries : MAX_AVERAGE;
    /* A mesh face's three vertex textures (face_blend) on the stack, as
    ** eval_map()'s entries; longer averages, rarer, on the heap */
    struct mat_eval local[3];
    struct mat_eval *alt = n <= 3 ? local : iris_malloc((size_t)n * sizeof *alt);
    if (!alt) {
        *out = *rest;
        return;
    }
    const struct mat_eval *alts[MAX_AVERAGE];
    double w[MAX_AVERAGE], total = 0.0;
    for (int i = 0; i < n; i++) {
        double wi = t->entries[i].value;
        w[i] = wi != 0.0 && isfinite(wi) ? fabs(wi) : 1.0;
        total += w[i];
    }
    /* a mesh face's three textures: weights varying across the face */
    if (t->map_pattern.kind == IRIS_PAT_FACE_BLEND && n == 3)
        total = mat_face_weights(ctx, &t->map_pattern, pt->p, w);
    struct mat_point wpt = *pt;
    wpt.p = pat_warp_world(ctx, &t->map_pattern, pt->p);
    for (int i = 0; i < n; i++) {
        eval_list(ctx, t->entries[i].texture, &wpt, &alt[i], depth + 1, pn);
        alts[i] = &alt[i];
        w[i] /= total;
    }
    combine(alts, w, n, rest, out);
    if (alt != local)
        iris_free(alt);
}

/* A material_map layer (an image_map pattern over textures): the one
** texture numbered by the texel's palette index or red byte, no blending.
** POV-Ray 3.7.0's material_map takes the number modulo the texture count
** only when it is greater than the count, and a number equal to the
** count walks off the list's end onto its last texture (with 2 textures:
** 2 -> 1, 3 -> 1, 4 -> 0); 3.7.1 made it a plain modulo. iris follows
** 3.7.0, the reference it is compared with. */
static void eval_material_map(const struct mat_ctx *ctx,
                              const iris_texture *t,
                              const struct mat_point *pt,
                              const struct mat_eval *rest,
                              struct mat_eval *out, int depth, vec3 *pn)
{
    const iris_pattern *pat = &t->map_pattern;
    int k = 0;
    if (pat->image)
        k = mat_image_index(ctx, pat->image,
                            pat_space(ctx, pat, pat_input(pat, pt->p, pt)));
    int n = t->n_entries;
    if (k > n)
        k %= n;
    if (k > n - 1)
        k = n - 1;
    struct mat_point wpt = *pt;
    wpt.p = pat_warp_world(ctx, pat, pt->p);
    eval_entry_whole(ctx, t->entries[k].texture, &wpt, rest, out, depth, pn);
}

/* A texture_map layer: the two neighbouring entries and their weights. */
static void eval_map(const struct mat_ctx *ctx, const iris_texture *t,
                     const struct mat_point *pt, const struct mat_eval *rest,
                     struct mat_eval *out, int depth, vec3 *pn)
{
    if (t->map_pattern.kind == IRIS_PAT_AVERAGE ||
        t->map_pattern.kind == IRIS_PAT_FACE_BLEND) {
        eval_average(ctx, t, pt, rest, out, depth, pn);
        return;
    }
    if (t->map_pattern.kind == IRIS_PAT_IMAGE_MAP) {
        eval_material_map(ctx, t, pt, rest, out, depth, pn);
        return;
    }
    const iris_map_entry *e = t->entries;
    int n = t->n_entries, p = 0, c = 0;
    struct mat_point ppt = *pt;
    ppt.n = *pn;
    double v = pat_value(ctx, &t->map_pattern, pt->p, &ppt);
    if (v >= e[n - 1].value) {
        p = c = n - 1;
    } else {
        while (v > e[c].value) {
            p = c;
            c++;
        }
        if (v == e[c].value)
            p = c;
    }
    /* On the stack, not the heap: a malloc and free of these per hit were
    ** 5 % of a texture_map scene's eye pass (18_texture_map, callgrind).
    ** eval_list() nests at most 9 deep (depth > 8 stops it), each level
    ** with its 'rest', these two and eval_average()'s three: under 25 kB
    ** a level, 220 kB in all, far below a thread's stack (8 MB). */
    struct mat_eval alt[2];
    const struct mat_eval *alts[2];
    double w[2];
    int n_alts = 0;
    double frac = p == c ? 1.0 : (v - e[p].value) / (e[c].value - e[p].value);
    /* the entries see the map pattern's warps (pat_warp_world) */
    struct mat_point wpt = *pt;
    wpt.p = pat_warp_world(ctx, &t->map_pattern, pt->p);
    pt = &wpt;
    if (p == c) {              /* one entry, weight 1 */
        eval_entry_whole(ctx, e[c].texture, pt, rest, out, depth, pn);
        return;
    }
    eval_list(ctx, e[c].texture, pt, &alt[0], depth + 1, pn);
    alts[n_alts] = &alt[0];
    w[n_alts++] = frac;
    eval_list(ctx, e[p].texture, pt, &alt[1], depth + 1, pn);
    alts[n_alts] = &alt[1];
    w[n_alts++] = 1.0 - frac;
    combine(alts, w, n_alts, rest, out);
}

static void eval_list(const struct mat_ctx *ctx, const iris_texture *tex,
                      const struct mat_point *pt, struct mat_eval *out,
                      int depth, vec3 *pn)
{
    set_empty(out);
    if (!tex || depth > 8)
        return;
    /* The common case, a list of plain layers (of the first
    ** MAT_MAX_LAYERS, the most kept): one stack, top first. */
    bool plain = true;
    int n = 0;
    for (const iris_texture *t = tex; t && n < MAT_MAX_LAYERS && plain;
         t = t->next, n++)
        plain = !(t->map_pattern.kind != IRIS_PAT_NONE && t->n_entries > 0);
    if (plain) {
        /* Top down, stopping below an opaque layer (a colour with no
        ** filter or transmit): no shading looks through it (POV-Ray's
        ** layer loops end once the filter colour is black), so the
        ** patterns and normals of the layers below would be evaluated
        ** for nothing. eval_layer()'s work, with the point copied once
        ** (its normal follows *pn) and no array of the list. */
        struct mat_point ppt = *pt;
        ppt.n = *pn;
        int used = 0;
        for (const iris_texture *t = tex; t && used < MAT_MAX_LAYERS;
             t = t->next) {
            struct mat_layer *l = &out->layers[used++];
            layer_at(ctx, t, &ppt, pt->n, l);
            if (t->normal && !pt->skip_normals)
                ppt.n = *pn = l->n;
            if (l->valid && l->pigment.f == 0.0 && l->pigment.t == 0.0)
                break;
        }
        out->n_layers = used;
        out->stacks[0].n = used;
        return;
    }
    /* Collect the list so it can be walked bottom-up. */
    const iris_texture *list[MAT_MAX_LAYERS];
    n = 0;
    for (const iris_texture *t = tex; t && n < MAT_MAX_LAYERS; t = t->next)
        list[n++] = t;
    for (int i = n - 1; i >= 0; i--) {
        const iris_texture *t = list[i];
        if (t->map_pattern.kind != IRIS_PAT_NONE && t->n_entries > 0) {
            /* the layers below, which eval_map() puts under its
            ** entries: only their used part is copied */
            struct mat_eval rest;
            copy_used(&rest, out);
            eval_map(ctx, t, pt, &rest, out, depth, pn);
            continue;
        }
        /* A plain layer goes on top of every stack: the stacks are
        ** rebuilt from a copy of the layers only. */
        struct mat_layer l;
        eval_layer(ctx, t, pt, &l, pn);
        struct mat_layer prev[MAT_MAX_LAYERS];
        struct mat_stack pstack[MAT_MAX_STACKS];
        int n_prev = out->n_layers;
        memcpy(prev, out->layers, (size_t)n_prev * sizeof *prev);
        memcpy(pstack, out->stacks, (size_t)out->n_stacks * sizeof *pstack);
        out->n_layers = 0;
        for (int s = 0; s < out->n_stacks; s++) {
            struct mat_stack *ps = &pstack[s], *os = &out->stacks[s];
            os->weight = ps->weight;
            os->first = out->n_layers;
            os->n = 0;
            if (out->n_layers < MAT_MAX_LAYERS) {
                out->layers[out->n_layers++] = l;
                os->n++;
            }
            for (int k = 0; k < ps->n && out->n_layers < MAT_MAX_LAYERS; k++) {
                out->layers[out->n_layers++] = prev[ps->first + k];
                os->n++;
            }
        }
    }
}

/* One texture's layers (mat_eval_texture, in multitex.c, also blends the
** textures of objects that carry several). */
void mat_eval_layers(const struct mat_ctx *ctx, const iris_texture *tex,
                     const struct mat_point *pt, struct mat_eval *out)
{
    /* One plain layer, the usual texture, as eval_list() would do it
    ** without its list walks and point copy (the patterns see the raw
    ** normal, pt->n, no layer having perturbed it yet): 2 % of a simple
    ** scene's eye pass */
    if (tex && !tex->next &&
        !(tex->map_pattern.kind != IRIS_PAT_NONE && tex->n_entries > 0)) {
        set_empty(out);
        layer_at(ctx, tex, pt, pt->n, &out->layers[0]);
        out->n_layers = 1;
        out->stacks[0].n = 1;
        return;
    }
    vec3 pn = pt->n;
    eval_list(ctx, tex, pt, out, 0, &pn);
}

/* ------------------------------------------------------------------ */
/* Optical helpers                                                      */
/* ------------------------------------------------------------------ */

/* mat_rgb_transm(), mat_opacity() and mat_greyscale() are inline in
** material.h. */

double mat_fresnel(double cos_i, double n)
{
    double c = fabs(cos_i);
    double sqx = n * n + c * c - 1.0;
    if (!(sqx > 0.0))
        return 1.0;
    double g = sqrt(sqx);
    double a = (g - c) / (g + c);
    double num = c * (g + c) - 1.0, den = c * (g - c) + 1.0;
    double f = 0.5 * a * a * (1.0 + (num * num) / (den * den));
    if (!isfinite(f))
        return 1.0;
    return mat_fmin(1.0, mat_fmax(0.0, f));
}

/* POV-Ray's metallic factor F(x) of the angle x = acos(c)/(pi/2). */
static double metallic_f(double cos_angle)
{
    double x = fabs(acos(mat_fmin(mat_fmax(cos_angle, -1.0), 1.0))) / M_PI_2;
    double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    return mat_fmin(1.0, mat_fmax(0.0, f));
}

void mat_metallic_tint(double metallic, double cos_angle,
                       const iris_colour *pigment, double out[3])
{
    double f = metallic_f(cos_angle);
    out[0] = 1.0 + metallic * (1.0 - f) * (pigment->r - 1.0);
    out[1] = 1.0 + metallic * (1.0 - f) * (pigment->g - 1.0);
    out[2] = 1.0 + metallic * (1.0 - f) * (pigment->b - 1.0);
}

bool mat_layer_reflectivity(const struct mat_layer *layer, double cos_i,
                            double n, double refl[3], double *weight)
{
    const iris_finish *f = layer->finish;
    const double mx[3] = { f->reflection_max.r, f->reflection_max.g,
                           f->reflection_max.b };
    const double mn[3] = { f->reflection_min.r, f->reflection_min.g,
                           f->reflection_min.b };
    /* Most finishes do not reflect: every branch below then gives 0 (the
    ** tracer asks for the layers whose finish has a reflection) */
    if (mx[0] == 0 && mx[1] == 0 && mx[2] == 0 && mn[0] == 0 && mn[1] == 0 &&
        mn[2] == 0) {
        refl[0] = refl[1] = refl[2] = 0.0;
        *weight = 0.0;
        return false;
    }
    if (f->reflection_fresnel) {
        double fr = mat_fresnel(cos_i, n);
        double sqx = n * n + cos_i * cos_i - 1.0;
        for (int k = 0; k < 3; k++)
            refl[k] = sqx > 0.0 ? fr * mx[k] + (1.0 - fr) * mn[k] : mx[k];
        *weight = mat_fmax(refl[0], mat_fmax(refl[1], refl[2]));
    } else {
        *weight = mat_fmax(mat_fmax(mx[0], mat_fmax(mx[1], mx[2])),
                           mat_fmax(mn[0], mat_fmax(mn[1], mn[2])));
        double falloff = f->reflection_falloff != 0 ? f->reflection_falloff
                                                    : 1.0;
        double frac = fabs(falloff - 1.0) > 1e-10 ? pow(1.0 - cos_i, falloff)
                                                  : 1.0 - cos_i;
        for (int k = 0; k < 3; k++) {
            if (fabs(frac) < 1e-10)
                refl[k] = mn[k];
            else if (fabs(frac - 1.0) < 1e-10)
                refl[k] = mx[k];
            else
                refl[k] = frac * mx[k] + (1.0 - frac) * mn[k];
        }
    }
    if (f->reflection_metallic != 0.0) {
        double tint[3];
        mat_metallic_tint(f->reflection_metallic, cos_i, &layer->pigment,
                          tint);
        for (int k = 0; k < 3; k++)
            refl[k] *= tint[k];
    }
    for (int k = 0; k < 3; k++)
        if (!isfinite(refl[k]))
            refl[k] = 0.0;
    return refl[0] != 0.0 || refl[1] != 0.0 || refl[2] != 0.0;
}
