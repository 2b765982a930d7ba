/* SPDX-License-Identifier: MIT */
/*
** pigment.c: pigments: solid colours, colour maps, pigment maps, average,
** and image maps, as POV-Ray's Compute_Pigment and image_map compute them.
**
** A colour map is searched as POV-Ray searches it (Search_Blend_Map): the
** first entry whose value is >= v, blended linearly with the one before;
** below the first entry and above the last the end colours hold. A
** pattern given without a map gets POV-Ray's default map for its kind.
*/
#include "config.h"

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>

#include "image/srgb8.h"
#include "iris/image.h"
#include "material/mat_internal.h"
#include "math/transform.h"

static void image_to_working(const struct mat_ctx *ctx,
                             const iris_image_ref *ref, iris_colour *c);
static bool image_texel_colour(const struct mat_ctx *ctx,
                               const iris_image_ref *ref, vec3 q,
                               bool working, iris_colour *out);

/* A colour-map entry of POV-Ray's built-in default maps. */
struct def_entry {
    double v, r, g, b;
};

static const struct def_entry gray_map[] = { { 0, 0, 0, 0 }, { 1, 1, 1, 1 } };
static const struct def_entry bozo_map[] = {
    { 0.4, 1, 1, 1 }, { 0.4, 0, 1, 0 }, { 0.6, 0, 1, 0 },
    { 0.6, 0, 0, 1 }, { 0.8, 0, 0, 1 }, { 0.8, 1, 0, 0 } };
static const struct def_entry wood_map[] = {
    { 0.6, 0.666, 0.312, 0.2 }, { 0.6, 0.4, 0.1333, 0.066 } };
static const struct def_entry agate_map[] = {
    { 0.0, 1, 1, 1 }, { 0.5, 0.95, 0.75, 0.5 }, { 0.5, 0.9, 0.7, 0.5 },
    { 0.6, 0.9, 0.7, 0.4 }, { 0.6, 1.0, 0.7, 0.4 }, { 1.0, 0.6, 0.3, 0.0 } };
static const struct def_entry radial_map[] = {
    { 0.0, 0, 1, 1 }, { 0.333, 1, 1, 0 }, { 0.666, 1, 0, 1 },
    { 1.0, 0, 1, 1 } };
static const struct def_entry marble_map[] = {
    { 0.0, 0.9, 0.8, 0.8 }, { 0.9, 0.9, 0.08, 0.08 }, { 0.9, 0, 0, 0 } };
static const struct def_entry brick_map[] = {
    { 0.0, 0.5, 0.5, 0.5 }, { 1.0, 0.6, 0.15, 0.15 } };
static const struct def_entry hex_map[] = {
    { 0.0, 0, 0, 1 }, { 1.0, 0, 1, 0 }, { 2.0, 1, 0, 0 } };

/* POV-Ray's default map for a pattern given without one. */
static const struct def_entry *default_map(enum iris_pattern_kind k, int *n)
{
#define RET(m) do { *n = (int)(sizeof m / sizeof m[0]); return m; } while (0)
    switch (k) {
    case IRIS_PAT_BOZO: RET(bozo_map);
    case IRIS_PAT_BRICK: RET(brick_map);
    case IRIS_PAT_WOOD: RET(wood_map);
    case IRIS_PAT_RADIAL: RET(radial_map);
    case IRIS_PAT_AGATE: RET(agate_map);
    case IRIS_PAT_MARBLE: RET(marble_map);
    case IRIS_PAT_HEXAGON: RET(hex_map);
    case IRIS_PAT_CHECKER: case IRIS_PAT_OBJECT:
        *n = 2;
        return hex_map; /* POV-Ray: checker uses the first two hex colours */
    default: RET(gray_map);
    }
#undef RET
}

static iris_colour colour_rgb(double r, double g, double b)
{
    iris_colour c = { r, g, b, 0, 0 };
    return c;
}

static iris_colour colour_lerp(iris_colour a, iris_colour b, double t)
{
    iris_colour c = { a.r + t * (b.r - a.r), a.g + t * (b.g - a.g),
                      a.b + t * (b.b - a.b), a.f + t * (b.f - a.f),
                      a.t + t * (b.t - a.t) };
    return c;
}

/*
** Long colour maps (the wood maps of POV-Ray's include files hold 256
** entries, searched ~900 instructions a lookup) are searched by
** bisection when their values ascend (POV-Ray's search is linear, but
** over ascending values the first entry >= v is the same entry). Whether
** a map ascends is remembered per thread, keyed by its address and size
** and by the epoch of mat_texel_memo_forget() (bumped whenever a mat_ctx
** is destroyed), so a map allocated later at the same address is looked
** at afresh. Only with a mat_ctx: the maps then belong to its scene.
*/
#define MAP_LINEAR_MAX 16
#define MAP_ORDER_SLOTS 8
struct map_order {
    const iris_map_entry *e;
    int n;
    unsigned epoch;
    bool ascending;
};
static _Thread_local struct map_order map_order_memo[MAP_ORDER_SLOTS];
/* The epoch of these memos and of the texel memo below: from 1, so the
** empty (zeroed) entries, epoch 0, never match. Wraps after 2^32
** destroyed contexts; an entry would have to survive all of them. */
static atomic_uint ctx_epoch = 1;

static __attribute__((noinline)) bool map_ascends(const iris_map_entry *e,
                                                  int n)
{
    unsigned epoch = atomic_load_explicit(&ctx_epoch, memory_order_acquire);
    struct map_order *m =
        &map_order_memo[((uintptr_t)e / sizeof *e) % MAP_ORDER_SLOTS];
    if (m->e != e || m->n != n || m->epoch != epoch) {
        m->e = e;
        m->n = n;
        m->epoch = epoch;
        m->ascending = true;
        for (int i = 0; i + 1 < n; i++)
            if (!(e[i].value <= e[i + 1].value)) { /* NaN: not ascending */
                m->ascending = false;
                break;
            }
    }
    return m->ascending;
}

/* Search_Blend_Map over the 'n' values of 'e' or else 'd': sets *prev,
** *cur. 'ascending': e's values ascend (bisect). */
static inline void search_map(double v, const iris_map_entry *e,
                              const struct def_entry *d, int n,
                              bool ascending, int *prev, int *cur)
{
#define VAL(i) (e ? e[i].value : d[i].v)
    int last = n - 1;
    if (v >= VAL(last)) {
        *prev = *cur = last;
        return;
    }
    int c = 0;
    if (ascending) {
        /* the first c in [0, last] with !(v > VAL(c)): last qualifies */
        int hi = last;
        while (c < hi) {
            int mid = c + (hi - c) / 2;
            if (v > VAL(mid))
                c = mid + 1;
            else
                hi = mid;
        }
    } else {
        /* (ends at 'last' at the latest: v < VAL(last) here) */
        while (v > VAL(c))
            c++;
    }
    *prev = v == VAL(c) || c == 0 ? c : c - 1;
    *cur = c;
#undef VAL
}

/* search_map() over a pigment's own map entries. */
static inline void search_entries(const struct mat_ctx *ctx, double v,
                                  const iris_map_entry *e, int n, int *prev,
                                  int *cur)
{
    bool bisect = ctx && n > MAP_LINEAR_MAX && map_ascends(e, n);
    search_map(v, e, NULL, n, bisect, prev, cur);
}

static double map_value(const iris_map_entry *e, const struct def_entry *d,
                        int i)
{
    return e ? e[i].value : d[i].v;
}

static bool entry_colour(const struct mat_ctx *ctx, const iris_pigment *pig,
                         const struct def_entry *d, int i,
                         const struct mat_point *pt, iris_colour *out);

/* The average pattern: the weighted mean of the map's pigments. */
static bool average(const struct mat_ctx *ctx, const iris_pigment *pig,
                    const struct mat_point *pt, iris_colour *out)
{
    iris_colour sum = { 0, 0, 0, 0, 0 };
    double total = 0;
    for (int i = 0; i < pig->n_entries; i++) {
        iris_colour c;
        double w = pig->entries[i].value;
        if (w == 0 && pig->n_entries > 0)
            w = 1.0; /* entries written without weights count once */
        if (!entry_colour(ctx, pig, NULL, i, pt, &c))
            memset(&c, 0, sizeof c);
        sum.r += w * c.r; sum.g += w * c.g; sum.b += w * c.b;
        sum.f += w * c.f; sum.t += w * c.t;
        total += w;
    }
    if (total > 0) {
        sum.r /= total; sum.g /= total; sum.b /= total;
        sum.f /= total; sum.t /= total;
    }
    *out = sum;
    return true;
}

static bool entry_colour(const struct mat_ctx *ctx, const iris_pigment *pig,
                         const struct def_entry *d, int i,
                         const struct mat_point *pt, iris_colour *out)
{
    if (d) {
        *out = colour_rgb(d[i].r, d[i].g, d[i].b);
        return true;
    }
    const iris_map_entry *e = &pig->entries[i];
    if (pig->is_pigment_map || e->pigment) {
        if (!e->pigment) {
            memset(out, 0, sizeof *out);
            return true;
        }
        return mat_eval_pigment(ctx, e->pigment, pt, out);
    }
    *out = e->colour;
    return true;
}

static bool eval_pigment(const struct mat_ctx *ctx, const iris_pigment *pig,
                         const struct mat_point *pt, iris_colour *out);

/*
** The commonest pigments, no quick colour in force: a plain colour (in
** mat_eval_pigment() itself, which then needs no stack frame), and a
** pattern with a colour map of plain colours, a list pattern's colours
** included (colour_map_pigment()). These are eval_pigment()'s steps for
** them without the tests that cannot apply; the numbers are
** eval_pigment()'s (the same pat_value(), search and blend). A map whose
** entries turn out to be pigments goes the general way.
*/
static __attribute__((noinline)) bool
colour_map_pigment(const struct mat_ctx *ctx, const iris_pigment *pig,
                   const struct mat_point *pt, iris_colour *out)
{
    const iris_map_entry *e = pig->entries;
    double v = pat_value(ctx, &pig->pattern, pt->p, pt);
    int prev, cur;
    search_entries(ctx, v, e, pig->n_entries, &prev, &cur);
    if (e[cur].pigment || e[prev].pigment)
        return eval_pigment(ctx, pig, pt, out);
    if (prev == cur) {
        *out = e[cur].colour;
        return true;
    }
    double v0 = e[prev].value, v1 = e[cur].value;
    double t = v1 > v0 ? (v - v0) / (v1 - v0) : 1.0;
    *out = colour_lerp(e[prev].colour, e[cur].colour, t);
    return true;
}

bool mat_eval_pigment(const struct mat_ctx *ctx, const iris_pigment *pig,
                      const struct mat_point *pt, iris_colour *out)
{
    if (pig && !(ctx && ctx->quick_colour)) {
        enum iris_pattern_kind k = pig->pattern.kind;
        if (k == IRIS_PAT_NONE) {
            *out = pig->colour;
            return true;
        }
        if (pig->n_entries > 0 && !pig->is_pigment_map &&
            !pig->entries[0].pigment && k != IRIS_PAT_IMAGE_MAP &&
            k != IRIS_PAT_AVERAGE)
            return colour_map_pigment(ctx, pig, pt, out);
    }
    return eval_pigment(ctx, pig, pt, out);
}

/* mat_eval_pigment(), every case. */
static bool eval_pigment(const struct mat_ctx *ctx, const iris_pigment *pig,
                         const struct mat_point *pt, iris_colour *out)
{
    memset(out, 0, sizeof *out);
    if (!pig)
        return true;
    const iris_pattern *pat = &pig->pattern;
    const iris_colour *qc = &pig->quick_colour;
    if (ctx && ctx->quick_colour &&
        (qc->r != 0 || qc->g != 0 || qc->b != 0 || qc->f != 0 || qc->t != 0)) {
        *out = *qc;
        return true;
    }
    if (pat->kind == IRIS_PAT_NONE) {
        *out = pig->colour;
        return true;
    }
    if (pat->kind == IRIS_PAT_IMAGE_MAP) {
        if (!pat->image)
            return true;
        vec3 q = pat_space(ctx, pat, pat_input(pat, pt->p, pt));
        if (!image_texel_colour(ctx, pat->image, q, true, out)) {
            iris_colour clear = { 1, 1, 1, 0, 1 };
            *out = clear;
            return false;
        }
        return true;
    }
    /* Map entries that are pigments see the map pattern's warps. */
    struct mat_point wpt;
    const struct mat_point *ept = pt;
    if (pig->n_entries > 0 && (pig->is_pigment_map ||
                               pig->entries[0].pigment) &&
        pat->n_warps > 0) {
        wpt = *pt;
        wpt.p = pat_warp_world(ctx, pat, pat_input(pat, pt->p, pt));
        ept = &wpt;
    }
    /* ...and the pigment's transforms the shared entries lack */
    if (pig->entry_xf && pig->n_entries > 0) {
        wpt = *ept;
        wpt.p = xf_inv_point(pig->entry_xf, wpt.p);
        ept = &wpt;
    }
    if (pat->kind == IRIS_PAT_AVERAGE)
        return average(ctx, pig, ept, out);

    const iris_map_entry *e = pig->n_entries > 0 ? pig->entries : NULL;
    const struct def_entry *d = NULL;
    int n = pig->n_entries;
    if (!e)
        d = default_map(pat->kind, &n);

    double v = pat_value(ctx, pat, pt->p, pt);
    int prev, cur;
    if (e)
        search_entries(ctx, v, e, n, &prev, &cur);
    else
        search_map(v, NULL, d, n, false, &prev, &cur);
    iris_colour c_cur, c_prev;
    bool found = entry_colour(ctx, pig, d, cur, ept, &c_cur);
    if (prev == cur) {
        *out = c_cur;
        return found;
    }
    found = entry_colour(ctx, pig, d, prev, ept, &c_prev) || found;
    double v0 = map_value(e, d, prev), v1 = map_value(e, d, cur);
    double t = v1 > v0 ? (v - v0) / (v1 - v0) : 1.0;
    *out = colour_lerp(c_prev, c_cur, t);
    return found;
}

/* ------------------------------------------------------------------ */
/* Image maps (POV-Ray's imageutil.cpp)                                 */
/* ------------------------------------------------------------------ */

const iris_image *mat_find_image(const struct mat_ctx *ctx,
                                 const iris_image_ref *ref)
{
    if (!ctx)
        return NULL;
    for (int i = 0; i < ctx->n_images; i++)
        if (ctx->images[i].ref == ref ||
            (ctx->images[i].ref->path && ref->path &&
             strcmp(ctx->images[i].ref->path, ref->path) == 0))
            return ctx->images[i].img.width > 0 ? &ctx->images[i].img : NULL;
    return NULL;
}

/* x mod w in [0, w). */
static double wrap(double x, double w)
{
    /* fmod() is a library call per texel; within one period either side
    ** of [0, w) it returns x itself, exactly, so those need none */
    if (x >= 0 && x < w)
        return x;
    double r = x >= -w && x < 0 ? x : fmod(x, w);
    if (r < 0)
        r += w;
    if (r >= w)
        r = 0;
    return r;
}

/* The angle of (x, z) from +x in [0, 1), as POV-Ray's mappers compute it. */
static double angle_xz(double x, double z, double len)
{
    double theta;
    if (z == 0.0)
        theta = x > 0 ? 0.0 : M_PI;
    else {
        theta = acos(fmin(fmax(x / len, -1.0), 1.0));
        if (z < 0.0)
            theta = 2 * M_PI - theta;
    }
    return theta / (2 * M_PI);
}

/* Image coordinates (pixels, before the y flip) of 'q'; false if the
** point is off a 'once' image. */
static bool map_pos(const iris_image_ref *ref, int w, int h, vec3 q,
                    double *u, double *v)
{
    *u = *v = 0;
    switch (ref->map_type) {
    case 1: { /* spherical */
        double len = v3_len(q);
        if (len == 0.0)
            return false;
        vec3 n = v3_scale(q, 1.0 / len);
        double phi = 0.5 + asin(fmin(fmax(n.y, -1.0), 1.0)) / M_PI;
        double lxz = sqrt(n.x * n.x + n.z * n.z);
        double theta = lxz == 0.0 ? 0.0 : angle_xz(n.x, n.z, lxz);
        *u = theta * w;
        *v = phi * h;
        break;
    }
    case 2: { /* cylindrical */
        if (ref->once && (q.y < 0.0 || q.y > 1.0))
            return false;
        *v = fmod(q.y * h, (double)h);
        double len = v3_len(q);
        if (len == 0.0)
            return false;
        double x = q.x / len, z = q.z / len;
        double lxz = sqrt(x * x + z * z);
        if (lxz == 0.0)
            return false;
        *u = angle_xz(x, z, lxz) * w;
        break;
    }
    case 5: { /* torus of major radius 1 around y (POV-Ray's
               ** torus_image_map): u the angle around y, v the angle
               ** around the tube from its inside */
        double len = sqrt(q.x * q.x + q.z * q.z);
        if (len == 0.0)
            return false;
        double theta = angle_xz(q.x, q.z, len);
        double x = len - 1.0;
        double lxy = sqrt(x * x + q.y * q.y);
        if (lxy == 0.0)
            return false;
        double phi = acos(fmin(fmax(-x / lxy, -1.0), 1.0));
        if (q.y > 0.0)
            phi = 2 * M_PI - phi;
        *u = theta * w; /* POV-Ray negates it twice */
        *v = phi / (2 * M_PI) * h;
        break;
    }
    default: /* planar: x runs along the width, y along the height */
        if (ref->once && (q.x < 0.0 || q.x > 1.0 || q.y < 0.0 || q.y > 1.0))
            return false;
        *u = fmod(q.x * w, (double)w);
        *v = fmod(q.y * h, (double)h);
        break;
    }
    *u += 1e-10;
    *v += 1e-10;
    if (ref->once && (*u >= w || *v >= h || *u < 0.0 || *v < 0.0))
        return false;
    *u = wrap(*u, w);
    *v = wrap(-*v, h); /* image rows run downwards */
    return true;
}

static const struct mat_image *find_entry(const struct mat_ctx *ctx,
                                          const iris_image_ref *ref);

/* POV-Ray's 'filter N, V' / 'transmit N, V': palette entry N's filter or
** transmit replaced, wherever the texel holds index N. */
static void palette_ft(const struct mat_image *mi, const iris_image_ref *ref,
                       int ix, int iy, iris_colour *c)
{
    if (!mi || !mi->index || !mi->index_palette || ix >= mi->index_w ||
        iy >= mi->index_h)
        return;
    int k = mi->index[(size_t)iy * mi->index_w + ix];
    for (int i = 0; i < ref->n_palette_ft; i++)
        if (ref->palette_ft[i].index == k)
            *(ref->palette_ft[i].which ? &c->t : &c->f) =
                ref->palette_ft[i].value;
}

/* The column (or row) of image position x in an image n texels across:
** clamped to the edge for `once`, wrapped otherwise. */
static inline int texel_index(const iris_image_ref *ref, double x, int n)
{
    if (ref->once)
        return x < 0 ? 0 : x >= n ? n - 1 : (int)x;
    return (int)wrap(x, n);
}

/* The texel in column ix, row iy (texel_index()'s), and in 'at' its
** address (the key of the converted-texel memo below). */
static inline void texel_at(const struct mat_image *mi, const iris_image *img,
                            const iris_image_ref *ref, int ix, int iy,
                            const float **at, iris_colour *c)
{
    const float *px = &img->pixels[((size_t)iy * img->width + ix) * 4];
    *at = px;
    c->r = px[0];
    c->g = px[1];
    c->b = px[2];
    c->f = 0;
    c->t = 1.0 - px[3];
    if (ref->n_palette_ft > 0)
        palette_ft(mi, ref, ix, iy, c);
    c->f += ref->filter_all;
    c->t += ref->transmit_all;
}

/*
** The conversions of a texel channel value 'v' that take powers (below:
** to_stored, image_to_working), with parameters 'a' and 'b'.
*/
enum texel_conv {
    CONV_STORED_GAMMA,   /* the stored value, to the power a ('gamma') */
    CONV_WORKING_GAMMA,  /* that, then into working gamma b */
    CONV_WORKING         /* the decoded value into working gamma b */
};

/* iris_srgb_encode(v); by srgb8's table for a texel value (a float). */
static double encode_texel(double v)
{
    return (double)(float)v == v ? srgb8_encode((float)v)
                                 : iris_srgb_encode(v);
}

static double conv_compute(enum texel_conv kind, double a, double b,
                           double v)
{
    switch (kind) {
    case CONV_STORED_GAMMA: {
        double s = encode_texel(v);
        return s > 0 ? pow(s, a) : s;
    }
    case CONV_WORKING_GAMMA: {
        /* 'gamma G' (POV-Ray's gammaOverride): the stored values decoded
        ** as v^G, then put into the working gamma */
        double s = encode_texel(v);
        double lin = s > 0 ? pow(s, a) : s;
        return b > 0 && b != 1.0 && lin > 0 ? pow(lin, 1.0 / b) : lin;
    }
    case CONV_WORKING:
    default:
        return v > 0 ? pow(v, 1.0 / b) : v;
    }
}

/*
** conv_compute() for a texel channel, from a table when the value is one
** decoded from 8-bit data (image/srgb8.h): each entry is filled on first
** use by conv_compute() itself, so it holds the same bits, and a texel
** then costs a lookup instead of one to three pow() calls (a third of a
** bump-mapped scene's time, parity 37). The tables belong to the thread
** (no locks; rendering does not depend on which thread filled what) and
** hold the last CONV_SLOTS conversions used; an entry not yet filled is
** NaN, which no conversion of a finite value >= 0 gives.
*/
#define CONV_SLOTS 4
struct conv_table {
    bool used;
    enum texel_conv kind;
    double a, b;
    double v[SRGB8_N];
};
static _Thread_local struct conv_table conv_tables[CONV_SLOTS];
static _Thread_local int conv_next;

static double conv_texel(enum texel_conv kind, double a, double b, double v)
{
    int k = srgb8_index((float)v);
    if (k < 0 || (double)(float)v != v)
        return conv_compute(kind, a, b, v);
    struct conv_table *t = NULL;
    for (int i = 0; i < CONV_SLOTS; i++) {
        struct conv_table *c = &conv_tables[i];
        if (c->used && c->kind == kind && c->a == a && c->b == b) {
            t = c;
            break;
        }
    }
    if (!t) {
        t = &conv_tables[conv_next];
        conv_next = (conv_next + 1) % CONV_SLOTS;
        t->used = true;
        t->kind = kind;
        t->a = a;
        t->b = b;
        for (int i = 0; i < SRGB8_N; i++)
            t->v[i] = NAN;
    }
    if (isnan(t->v[k]))
        t->v[k] = conv_compute(kind, a, b, srgb8_value(k));
    return t->v[k];
}

/* A texel's colour as the file stores it (iris_image_read decodes 8-bit
** files from sRGB): for the images POV-Ray reads without gamma handling.
** An explicit 'gamma G' decodes the stored values as v^G (POV-Ray's
** gammaOverride; no working-space conversion for these images). */
static void to_stored(const iris_image_ref *ref, iris_colour *c)
{
    double *ch[3] = { &c->r, &c->g, &c->b };
    for (int k = 0; k < 3; k++)
        *ch[k] = ref->gamma > 0
                     ? conv_texel(CONV_STORED_GAMMA, ref->gamma, 0, *ch[k])
                     : encode_texel(*ch[k]);
}

/*
** Converted texels, remembered. image_to_working() and to_stored() give a
** texel's r, g, b from its stored r, g, b and the conversion's parameters
** alone (ref->gamma; the scene's assumed_gamma and version), and a
** magnified image map or bump map converts the same few texels again
** and again: each bilinear sample four, neighbouring samples mostly the
** same four. Each conversion (srgb8_index, the table search of
** conv_texel, three channels) was 25 % of an image-map scene's eye pass
** (43_image_map_gamma, callgrind), srgb8_encode 16 % of a bump map's
** (37). So each thread keeps the last conversions it made in a small
** direct-mapped table keyed by the texel's address and those
** parameters, and a hit returns the very doubles the conversion gave.
** The images belong to a mat_ctx and are immutable while it lives; when
** one is destroyed (mat_ctx_destroy calls mat_texel_memo_forget) the
** epoch changes and no entry made before matches again, so an image
** allocated later at the same address is never answered from an old
** entry. Thread-local: no locks, and nothing allocated.
*/
#define TEXEL_MEMO_BITS 9
struct texel_memo {
    const float *px;       /* the texel's address; NULL: empty */
    unsigned epoch;        /* ctx_epoch when filled */
    unsigned mode;         /* texel_as() */
    double gamma, working_gamma;
    double rgb[3];         /* the converted r, g, b */
};
static _Thread_local struct texel_memo texel_memo[1 << TEXEL_MEMO_BITS];

/* Forgets the texel memo and the map orders (the epoch, ctx_epoch above). */
void mat_texel_memo_forget(void)
{
    atomic_fetch_add_explicit(&ctx_epoch, 1, memory_order_release);
}

/* Texels as stored (POV-Ray's gamma modes before 3.7), as the parser
** found the mode where the image was read, else from the version. */
static bool image_as_stored(const iris_scene *sc, const iris_image_ref *ref)
{
    if (ref->as_stored)
        return ref->as_stored > 0;
    return sc->version > 0 && sc->version < 3.7;
}

/* What texel_as() converts with, the same for every texel of a sample:
** the conversion ('working', as image_to_working, and/or 'stored', as
** to_stored) and the memo's key besides the texel's address. */
struct texel_conv_key {
    const struct mat_ctx *working;
    bool stored;
    bool convert;          /* false: the texel is taken as it is */
    unsigned mode, epoch;
    double working_gamma;
};

static void texel_conv_key_of(const struct mat_ctx *working,
                              const iris_image_ref *ref, bool stored,
                              struct texel_conv_key *k)
{
    k->working = working;
    k->stored = stored;
    /* everything the two conversions read besides the texel */
    const iris_scene *sc = working ? working->scene : NULL;
    k->mode = (working ? 1u : 0u) | (stored ? 2u : 0u) | (sc ? 4u : 0u) |
              (sc && image_as_stored(sc, ref) ? 8u : 0u);
    double wg = sc ? sc->settings.assumed_gamma : 0.0;
    k->working_gamma = wg;
    /* without 'stored', only image_to_working() converts, and it changes
    ** nothing when its three tests fail: an image map in a linear scene
    ** (assumed_gamma 1) needs no memo */
    k->convert = stored || (sc && (ref->gamma > 0 || (k->mode & 8u) ||
                                   (wg > 0 && wg != 1.0)));
    k->epoch = atomic_load_explicit(&ctx_epoch, memory_order_acquire);
}

/* texel_at() (ix, iy), converted as 'k' says, through the memo. */
static inline void texel_as(const struct texel_conv_key *k,
                            const struct mat_image *mi, const iris_image *img,
                            const iris_image_ref *ref, int ix, int iy,
                            iris_colour *c)
{
    const float *px;
    texel_at(mi, img, ref, ix, iy, &px, c);
    if (!k->convert)
        return;
    /* texels are 16 bytes apart; the multiply spreads rows that a
    ** power-of-two width would put in one slot */
    uint64_t h = ((uint64_t)(uintptr_t)px >> 4) * UINT64_C(0x9e3779b97f4a7c15);
    struct texel_memo *m = &texel_memo[h >> (64 - TEXEL_MEMO_BITS)];
    if (m->px == px && m->epoch == k->epoch && m->mode == k->mode &&
        m->gamma == ref->gamma && m->working_gamma == k->working_gamma) {
        c->r = m->rgb[0];
        c->g = m->rgb[1];
        c->b = m->rgb[2];
        return;
    }
    if (k->working)
        image_to_working(k->working, ref, c);
    if (k->stored)
        to_stored(ref, c);
    m->px = px;
    m->epoch = k->epoch;
    m->mode = k->mode;
    m->gamma = ref->gamma;
    m->working_gamma = k->working_gamma;
    m->rgb[0] = c->r;
    m->rgb[1] = c->g;
    m->rgb[2] = c->b;
}

/* The weights of texels (ix, iy), (ix-1, iy), (ix, iy-1), (ix-1, iy-1)
** at fractions (p, q) past texel ix-1, iy-1's centre: bilinear. */
static void bilinear_weights(double p, double q, double *f0, double *f1,
                             double *f2, double *f3)
{
    *f0 = p * q;
    *f1 = (1 - p) * q;
    *f2 = p * (1 - q);
    *f3 = (1 - p) * (1 - q);
}

/* The same for interpolate 4, POV-Ray's norm_dist: each texel weighs
** 1 / its squared distance to the sample, normalised to sum 1. On a
** texel's centre POV-Ray divides by 0 (NaN); that texel alone here. */
static void norm_dist_weights(double p, double q, double *f0, double *f1,
                              double *f2, double *f3)
{
    double d[4] = { (1 - p) * (1 - p) + (1 - q) * (1 - q),
                    p * p + (1 - q) * (1 - q),
                    (1 - p) * (1 - p) + q * q,
                    p * p + q * q };
    double w[4], sum = 0.0;
    for (int k = 0; k < 4; k++) {
        if (!(d[k] > 0.0)) {
            *f0 = k == 0; *f1 = k == 1; *f2 = k == 2; *f3 = k == 3;
            return;
        }
        w[k] = 1.0 / d[k];
        sum += w[k];
    }
    *f0 = w[0] / sum;
    *f1 = w[1] / sum;
    *f2 = w[2] / sum;
    *f3 = w[3] / sum;
}

/* The image's colour at image coordinates (x, y), interpolated as the
** reference asks (POV-Ray's image_colour_at). With 'working' (an
** image_map's colours) each texel is first put into the working gamma
** space, as POV-Ray converts the image as it reads it; with 'stored' it
** is taken as the file stores it (bump maps, image_pattern); both before
** any interpolation. */
static void sample_at_as(const struct mat_ctx *working,
                         const struct mat_image *mi, const iris_image *img,
                         const iris_image_ref *ref, double x, double y,
                         bool stored, iris_colour *out)
{
    struct texel_conv_key k;
    texel_conv_key_of(working, ref, stored, &k);
    int w = img->width, h = img->height;
    if (ref->interpolate != 2 && ref->interpolate != 4) {
        texel_as(&k, mi, img, ref, texel_index(ref, x, w),
                 texel_index(ref, y, h), out);
        return;
    }
    /* The four texels around the sample, weighted bilinearly or by
    ** normalised inverse squared distances (POV-Ray's Interp). */
    x += 0.5;
    y += 0.5;
    int ix = (int)x, iy = (int)y;
    double p = x - ix, qf = y - iy;
    double f0, f1, f2, f3;
    if (ref->interpolate == 4)
        norm_dist_weights(p, qf, &f0, &f1, &f2, &f3);
    else
        bilinear_weights(p, qf, &f0, &f1, &f2, &f3);
    /* the two columns and two rows, each wrapped (or clamped) once */
    int cx0 = texel_index(ref, ix, w), cx1 = texel_index(ref, ix - 1, w);
    int ry0 = texel_index(ref, iy, h), ry1 = texel_index(ref, iy - 1, h);
    iris_colour c0, c1, c2, c3;
    texel_as(&k, mi, img, ref, cx0, ry0, &c0);
    texel_as(&k, mi, img, ref, cx1, ry0, &c1);
    texel_as(&k, mi, img, ref, cx0, ry1, &c2);
    texel_as(&k, mi, img, ref, cx1, ry1, &c3);
    out->r = c0.r * f0 + c1.r * f1 + c2.r * f2 + c3.r * f3;
    out->g = c0.g * f0 + c1.g * f1 + c2.g * f2 + c3.g * f3;
    out->b = c0.b * f0 + c1.b * f1 + c2.b * f2 + c3.b * f3;
    out->f = c0.f * f0 + c1.f * f1 + c2.f * f2 + c3.f * f3;
    out->t = c0.t * f0 + c1.t * f1 + c2.t * f2 + c3.t * f3;
}

/* The colour of image 'ref' at q, black for a missing image (reported
** once); texels converted into the working space when 'working' (an
** image_map pigment), as the file stores them otherwise (image_pattern:
** POV-Ray reads it with no gamma handling). False off a `once` image. */
static bool image_texel_colour(const struct mat_ctx *ctx,
                               const iris_image_ref *ref, vec3 q,
                               bool working, iris_colour *out)
{
    memset(out, 0, sizeof *out);
    const iris_image *img = mat_find_image(ctx, ref);
    if (!img || img->width <= 0 || img->height <= 0)
        return true;
    double x, y;
    if (!map_pos(ref, img->width, img->height, q, &x, &y))
        return false;
    sample_at_as(working ? ctx : NULL, find_entry(ctx, ref), img, ref, x, y,
                 !working, out);
    return true;
}

bool mat_image_lookup(const struct mat_ctx *ctx, const iris_image_ref *ref,
                      vec3 q, iris_colour *out)
{
    return image_texel_colour(ctx, ref, q, false, out);
}

/* The context's entry for the file of 'ref', or NULL. */
static const struct mat_image *find_entry(const struct mat_ctx *ctx,
                                          const iris_image_ref *ref)
{
    for (int i = 0; ctx && ref && i < ctx->n_images; i++)
        if (ctx->images[i].ref == ref ||
            (ctx->images[i].ref->path && ref->path &&
             strcmp(ctx->images[i].ref->path, ref->path) == 0))
            return &ctx->images[i];
    return NULL;
}

double mat_density_file(const struct mat_ctx *ctx, const iris_pattern *pat,
                        vec3 q)
{
    const struct mat_image *mi = find_entry(ctx, pat->image);
    if (!mi)
        return 0.0;
    return iris_df3_density(&mi->df3, pat->image->interpolate, q.x, q.y,
                            q.z);
}

/* The palette index of the texel at image position (x, y) as texel_at()
** picks it, without interpolation (POV-Ray only reads a palette index
** from an uninterpolated lookup): clamped for `once`, else wrapped. */
static int index_at(const struct mat_image *mi, const iris_image_ref *ref,
                    double x, double y)
{
    int w = mi->index_w;
    return mi->index[(size_t)texel_index(ref, y, mi->index_h) * w +
                     texel_index(ref, x, w)];
}

int mat_image_index(const struct mat_ctx *ctx, const iris_image_ref *ref,
                    vec3 q)
{
    const struct mat_image *mi = find_entry(ctx, ref);
    if (!mi || !mi->index || mi->index_w <= 0 || mi->index_h <= 0)
        return 0;
    int w = mi->index_w, h = mi->index_h;
    double x, y;
    if (!map_pos(ref, w, h, q, &x, &y))
        return 0;
    return index_at(mi, ref, x, y);
}

/* Image colours come decoded to linear light (iris_image_read), but the
** shading works in the scene's working gamma space (assumed_gamma,
** semantics §3.9), so POV-Ray 3.7 hands an image_map's colours over in
** that space: v^(1/assumed_gamma); a pre-3.7 scene without assumed_gamma
** (gamma handling off) gets the file's encoded values back, as POV-Ray 3.6
** read them. Without this an assumed_gamma 2.2 scene rendered its image
** maps darker (a test PNG texel of 64 came out as 5). */
static void image_to_working(const struct mat_ctx *ctx,
                             const iris_image_ref *ref, iris_colour *c)
{
    const iris_scene *sc = ctx ? ctx->scene : NULL;
    if (!sc)
        return;
    double g = sc->settings.assumed_gamma;
    bool legacy = image_as_stored(sc, ref);
    double *ch[3] = { &c->r, &c->g, &c->b };
    for (int k = 0; k < 3; k++) {
        double v = *ch[k];
        if (ref->gamma > 0)
            *ch[k] = conv_texel(CONV_WORKING_GAMMA, ref->gamma, g, v);
        else if (legacy)
            *ch[k] = encode_texel(v);
        else if (g > 0 && g != 1.0)
            *ch[k] = conv_texel(CONV_WORKING, 0, g, v);
    }
}

/* The grey level of a bump map sample on the file's stored values:
** POV-Ray 3.7 reads a bump_map's image with no gamma handling
** (Parse_Image's GammaCorrect is off for bump maps, "no gamma adjustment
** performed on input image"), so iris's decoded texels are encoded back.
** Measured: parity scene 117's use_color panel 111.5 dB at 320x240
** against 34.8 dB on decoded values; textures/normals/bumpmap.pov
** (interpolated) 38.0 against 38.6 dB, its error lying elsewhere. */
static double bump_grey(const iris_image *img, const iris_image_ref *ref,
                        double x, double y)
{
    iris_colour c;
    sample_at_as(NULL, NULL, img, ref, x, y, true, &c);
    const double g[3] = { c.r, c.g, c.b };
    return mat_greyscale(g);
}

/* 'v' wrapped into [0, n) by one period, as POV-Ray's bump_map does. */
static double wrap_once(double v, double n)
{
    if (v < 0.0)
        return v + n;
    if (v >= n)
        return v - n;
    return v;
}

/* A bump_map's height at (x, y) with use_index: the texel's palette
** index itself (POV-Ray's bump_map takes Amount * index), when the image
** is a palette image read without interpolation (POV-Ray has an index
** only then); false otherwise, and the grey level is used. */
static bool bump_index(const struct mat_image *mi, const iris_image_ref *ref,
                       double x, double y, double *out)
{
    if (!mi || !mi->index || !mi->index_palette ||
        (ref->interpolate == 2 || ref->interpolate == 4))
        return false;
    *out = index_at(mi, ref, x, y);
    return true;
}

bool mat_image_bump(const struct mat_ctx *ctx, const iris_image_ref *ref,
                    vec3 q, double amount, vec3 n, vec3 *out)
{
    const iris_image *img = mat_find_image(ctx, ref);
    if (!img || img->width <= 0 || img->height <= 0)
        return false;
    double x, y;
    if (!map_pos(ref, img->width, img->height, q, &x, &y))
        return false;
    double w = img->width, h = img->height;
    /* three samples: here, one pixel left and down, one right and down */
    double x2 = wrap_once(x - 1.0, w), y2 = wrap_once(y + 1.0, h);
    double x3 = wrap_once(x2 + 2.0, w);
    double g1, g2, g3;
    const struct mat_image *mi = ref->use_index ? find_entry(ctx, ref) : NULL;
    if (!(mi && bump_index(mi, ref, x, y, &g1) &&
          bump_index(mi, ref, x2, y2, &g2) &&
          bump_index(mi, ref, x3, y2, &g3))) {
        g1 = bump_grey(img, ref, x, y);
        g2 = bump_grey(img, ref, x2, y2);
        g3 = bump_grey(img, ref, x3, y2);
    }
    /* the normal of the triangle through them, in a frame around 'n' */
    vec3 p1 = v3(0, amount * g1, 0), p2 = v3(-1, amount * g2, 1),
         p3 = v3(1, amount * g3, 1);
    vec3 bn = v3_norm(v3_cross(v3_sub(p3, p2), v3_sub(p1, p2)));
    vec3 yp = n, xp = v3_cross(n, v3(0, 1, 0));
    double len = v3_len(xp);
    if (len < 1e-10) {
        yp = fabs(n.y - 1.0) < 1e-10 ? v3(0, 1, 0) : v3(0, -1, 0);
        xp = v3(1, 0, 0);
        len = 1.0;
    }
    xp = v3_scale(xp, 1.0 / len);
    vec3 zp = v3_norm(v3_cross(xp, yp));
    vec3 r = v3_sub(v3_add(v3_scale(xp, bn.x), v3_scale(yp, bn.y)),
                    v3_scale(zp, bn.z));
    if (!(isfinite(r.x) && isfinite(r.y) && isfinite(r.z)))
        return false;
    *out = r;
    return true;
}

/* ------------------------------------------------------------------ */
/* Context-free evaluation for src/fn                                   */
/* ------------------------------------------------------------------ */

double mat_pattern_at(const iris_pattern *pat, double x, double y, double z)
{
    if (!pat)
        return 0.0;
    struct mat_point pt = { v3(x, y, z), v3(0, 1, 0), v3(0, 0, 1), { 0, 0 },
                            NULL, true };
    double v = pat_value(NULL, pat, pt.p, &pt);
    return isfinite(v) ? v : 0.0;
}

void mat_pigment_at(const iris_pigment *pig, double x, double y, double z,
                    double rgbft[5])
{
    iris_colour c = { 0, 0, 0, 0, 0 };
    struct mat_point pt = { v3(x, y, z), v3(0, 1, 0), v3(0, 0, 1), { 0, 0 },
                            NULL, true };
    if (pig)
        (void)mat_eval_pigment(NULL, pig, &pt, &c);
    const double v[5] = { c.r, c.g, c.b, c.f, c.t };
    for (int i = 0; i < 5; i++)
        rgbft[i] = isfinite(v[i]) ? v[i] : 0.0;
}
