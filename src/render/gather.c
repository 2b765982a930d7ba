/* SPDX-License-Identifier: MIT */
/*
** gather.c: the final gather of radiosity{} and its irradiance cache
** (see gather.h), after what POV-Ray 3.7's radiosity computes
** (source/core/lighting/radiosity.cpp; semantics §3 step 4).
**
** WHY a final gather: reading the global photon map directly at eye hits
** shows its low-frequency noise as colour blotches, and a photon map
** cannot carry light that does not start at a light source (the sky seen
** by an outdoor scene, objects glowing by ambient or emission), which
** POV-Ray's radiosity gathers. Here the eye hit gathers; the hits of the
** gather rays read the global map (one bounce later, where its noise
** averages out over 'count' rays) and see sky, emission and ambient as
** POV-Ray's sample rays see them.
**
** What a sample is (POV-Ray's GatherLight): 'count' rays from the hit in
** fixed cosine-distributed directions about the normal (a golden-angle
** spiral over the projected disc: stratified, and the same set at every
** sample, so neighbouring samples err alike and the image shows no
** blotches, as with POV-Ray's fixed direction pool); each is traced as an
** ordinary ray (gi_depth 1: no highlights; the global map when
** recursion_limit >= 2, or another gather there when the scene has no
** global map, see Recursion below). The sample is the mean of what
** they return (no cosine factor: the directions carry it; the rays and
** what they spawn pass no_radiosity objects, trace.c), its validity
** radius the harmonic mean of their hit distances clamped to
** [minimum_reuse, maximum_reuse] x the distance to the camera. With
** 'normal on' the hemisphere is about the layer's perturbed normal, cut
** off at the surface, and the cache is searched and filled under that
** normal (POV-Ray's effectiveNormal; dir_next() below).
**
** Recursion: with recursion_limit >= 2 the hits of gather rays gather
** again, as POV-Ray's do, down to recursion_limit levels: everything in
** a scene with no light that casts shadows (no global map), and beside a
** global map, which holds only the light sources' bounces, the rest
** (rays that see no light source: sky, emission, ambient), each with
** POV-Ray's settings for its depth d (RadiosityRecursionSettings):
** max(5, count / 2^d) rays, error bound and reuse radii x 2^d, reuse
** count nearest_count, 2, then 1. Records keep their depth and serve only
** lookups of the same depth.
**
** Reuse (POV-Ray's AverageNearBlock): a record at distance d with radius
** r (shrunk towards its nearest hit in that direction) and normal n' has
** error d/r + 2 sqrt(1 - n·n'); it is used when that is below
** error_bound (plus 0.25 - weight for faint rays), and when it does not
** lie in front of the point; weight 1 - e/eb in the pretrace and
** POV-Ray's smooth "pseudo-sigmoid" of e/eb in the final pass.
**
** Determinism (images must not depend on the thread count): the cache is
** filled by a pretrace over the image at pixel steps pretrace_start x
** size, halving down to pretrace_end (at least to 4 pixels). During one
** step the shared cache is read-only; the 32x32 tiles fall into 2^step
** groups (tile serial mod 2^step, POV-Ray's +HR nominal threads), each
** traced in tile order by one thread into its own list (a tile reuses
** the deeper records of its group's earlier tiles, but only its own eye-
** hit records), and after the step the groups' lists are appended in
** group order and the grid is rebuilt. The eye pass reads the shared cache and, like
** POV-Ray's tiles under +HR, stores what it must add in a list local to
** the tile (gather_tile_begin() clears it). So every record depends only
** on the image position, never on which thread traced what first.
**
** The shared cache is a multi-level hash grid: a record of influence
** radius R sits at the level whose cells are >= 2R wide, in the (at most
** 8) cells its sphere touches, so a lookup visits one cell per level;
** the tiles' own lists have the same kind of grid. As in POV-Ray's
** octree, a record is found only inside its node's cube (pov_node).
*/
#include "config.h"

#include "render/gather.h"
#include "render/eyepass.h"
#include "render/gather_sources.h"

#include <math.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "photon/pmap.h"
#include "render/camera.h"
#include "util/mem.h"
#include "util/thread.h"

#define TILE 32
#define IN_FRONT_LIMIT (-0.05)   /* POV-Ray's: points just in front stay */
#define NEAR_EPS 1e-6            /* POV-Ray's AVG_NEAR_EPSILON */
#define MAX_LEVELS 128          /* rec_level() spans -40..60 */
#define LOCAL_MAX 8192           /* records one tile keeps (then: no more) */
#define FILL_STEP 4               /* pixels: the pretrace's finest step */
#define GI_CAUSTIC_K 20          /* caustic photons a gather hit reads */
#define GOLDEN_ANGLE 2.399963229728653 /* pi (3 - sqrt 5) */
#define MAX_DEPTH 8              /* recursion levels gathered (POV-Ray: 20) */

struct grec {
    vec3 p, n;                 /* point, unit normal facing the eye */
    vec3 to_near;              /* unit direction of the nearest hit */
    double ri;                 /* harmonic mean distance, clamped */
    double near;               /* distance of the nearest hit */
    float e[3];                /* mean radiance (before brightness) */
    int depth;                 /* the bounce it serves: 0 = eye hits */
    vec3 nc;                   /* centre and half-size of the cube where */
    double ns;                 /* POV-Ray's octree finds it (pov_node) */
};

struct grec_list {
    struct grec *r;
    size_t n, cap;
};

/* A tile's own records, with a hash grid of the same levels and cells
** as the shared one (grid_build), so that a lookup does not scan the
** list: with recursion the deeper levels add thousands of records per
** tile, and the scan was 90% of the render time. */
struct lslot {
    int32_t lvl;
    int64_t ix, iy, iz;
    uint32_t head;             /* first node; UINT32_MAX = empty slot */
};

struct lnode {
    uint32_t rec, next;
};

struct gather_local {
    struct grec_list l;
    struct lslot *slots;
    size_t mask;               /* slots - 1 (a power of two), or 0 */
    size_t *used;              /* the slots taken, to clear them */
    size_t n_used;
    struct lnode *nodes;
    size_t n_nodes, cap_nodes;
    int n_levels;
    int levels[MAX_LEVELS * MAX_DEPTH]; /* lvl_key()s present */
    size_t cap;                /* records it keeps (then: no more):
                                  LOCAL_MAX per tile it spans */
    size_t own_from;           /* eye-hit (depth 0) records before this
                                  index are earlier tiles': not reused */
};

struct gcell {
    int32_t lvl;
    int64_t ix, iy, iz;
    uint32_t first, count;     /* in gather.idx; count 0 = empty slot */
};

struct gather {
    const iris_scene *scene;
    iris_radiosity_settings rs;
    vec3 eye;                  /* camera location: reuse radii scale */
    int depths;                /* levels that gather: 1, or
                                  recursion_limit when gathering recursively */
    bool importance;           /* some radiosity importance is below 1 */
    bool split;                /* recursing beside a global map: deeper
                                  levels gather only the sky's light */
    int count[MAX_DEPTH];      /* rays per sample at each level */
    vec3 *dirs[MAX_DEPTH];     /* their directions, z = the normal */
    int *rank[MAX_DEPTH];      /* with importance: each direction's place
                                  in the order rays are ranked in */
    bool pretrace;             /* the pretrace is running */
    bool strict;               /* its POV-Ray steps (pretrace_start to
                                  pretrace_end): reuse needs nearest_count */
    double eb;                 /* the error bound of this phase */
    struct grec_list all;      /* the shared cache */
    int n_levels;
    int levels[MAX_LEVELS * MAX_DEPTH]; /* lvl_key()s present */
    struct gcell *cells;
    size_t cells_mask;
    uint32_t *idx;
    struct photon_map view;    /* t->photon_map without its global map */
    struct photon_map view_gi; /* what gather rays' hits read */
};

bool gather_at_depth(const struct gather *g, int gi_depth)
{
    return g && gi_depth < g->depths;
}

bool gather_lit(const struct gather *g, int gi_depth)
{
    if (!g)
        return true;
    if (gi_depth == 0)
        return !g->pretrace;
    return !(g->split && gi_depth >= 2);
}

bool gather_wanted(const struct tracer *t)
{
    return t->scene->settings.radiosity && (t->quality & TQ_ADVANCED) &&
           !(t->quality & TQ_FULL_AMBIENT);
}

/* ------------------------------------------------------------------ */
/* Record lists and the grid                                            */
/* ------------------------------------------------------------------ */

static bool list_push(struct grec_list *l, const struct grec *r)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 64;
        struct grec *nr = iris_realloc(l->r, cap * sizeof *nr);
        if (!nr)
            return false;
        l->r = nr;
        l->cap = cap;
    }
    l->r[l->n++] = *r;
    return true;
}

/* The largest error bound a lookup at 'depth' uses: eb + 0.25 for the
** faintest rays (gather_irradiance), doubled per level (POV-Ray's
** errorBoundFactor). */
static double max_bound(const struct gather *g, int depth)
{
    return ldexp(g->rs.error_bound + 0.25, depth);
}

/*
** Where POV-Ray's octree can find record 'r' (octree.cpp ot_index_sphere,
** ot_point_in_node): the smallest power-of-two node whose cube, widened
** by half its size on every side, holds the box of half-size
** ri x error_bound x 2^depth / overfill about the point, with overfill 1
** for eye hits and 8 deeper. A lookup outside that cube misses the record
** even where its error would allow it: at depth >= 1 this makes reuse
** about four times more local than the error bound says, which is
** POV-Ray's choice (fewer records per lookup) and decides how many
** deeper samples it takes.
*/
#define OT_BIAS 1e7              /* POV-Ray's octree origin offset */
static void pov_node(const struct gather *g, struct grec *r)
{
    double rad = r->ri * ldexp(g->rs.error_bound, r->depth) /
                 (r->depth ? 8.0 : 1.0);
    int e;
    (void)frexp(2.0 * rad, &e);
    double s = 2.0 * rad > 0.0 && isfinite(rad) ? ldexp(1.0, e - 1) : 1.0;
    const double p[3] = { r->p.x, r->p.y, r->p.z };
    double id[3];
    for (int k = 0; k < 3; k++)
        id[k] = floor((p[k] + OT_BIAS) / s);
    for (int it = 0; it < 256; it++) {
        bool in = true;
        for (int k = 0; k < 3 && in; k++) {
            double c = (id[k] + 0.5) * s - OT_BIAS;
            in = fabs(p[k] - rad - c) < s && fabs(p[k] + rad - c) < s;
        }
        if (in)
            break;
        for (int k = 0; k < 3; k++)
            id[k] = floor(id[k] / 2.0);
        s *= 2.0;
    }
    r->nc = v3((id[0] + 0.5) * s - OT_BIAS, (id[1] + 0.5) * s - OT_BIAS,
               (id[2] + 0.5) * s - OT_BIAS);
    r->ns = s;
}

/* The box a lookup can reuse 'r' in: its sphere of influence for the
** largest error bound, cut by its octree cube. */
static void rec_box(const struct gather *g, const struct grec *r,
                    double lo[3], double hi[3])
{
    double R = r->ri * max_bound(g, r->depth);
    const double p[3] = { r->p.x, r->p.y, r->p.z };
    const double c[3] = { r->nc.x, r->nc.y, r->nc.z };
    for (int k = 0; k < 3; k++) {
        lo[k] = fmax(p[k] - R, c[k] - r->ns);
        hi[k] = fmin(p[k] + R, c[k] + r->ns);
        if (hi[k] < lo[k])
            hi[k] = lo[k];
    }
}

static int64_t cell_of(double v, double s)
{
    double q = floor(v / s);
    return (int64_t)fmax(-4.0e18, fmin(4.0e18, q));
}

static uint64_t cell_hash(int32_t lvl, int64_t ix, int64_t iy, int64_t iz)
{
    uint64_t h = rng_mix64((uint64_t)(uint32_t)lvl * 0x9e3779b97f4a7c15ULL ^
                           (uint64_t)ix);
    h = rng_mix64(h ^ (uint64_t)iy * 0xbf58476d1ce4e5b9ULL);
    return rng_mix64(h ^ (uint64_t)iz * 0x94d049bb133111ebULL);
}

static int rec_level(double rinf)
{
    int l = (int)ceil(log2(fmax(2.0 * rinf, 1e-12)));
    return l < -40 ? -40 : l > 60 ? 60 : l;
}

/* Cells are keyed by level and recursion depth together, so that a
** lookup walks only the records of its own depth. */
static int lvl_key(int l, int depth)
{
    return l + MAX_LEVELS * depth;
}

static int key_depth(int key)
{
    return (key + MAX_LEVELS / 2) / MAX_LEVELS;
}

struct cpair {
    int32_t lvl;
    int64_t ix, iy, iz;
    uint32_t rec;
};

static int cpair_cmp(const void *a, const void *b)
{
    const struct cpair *x = a, *y = b;
    if (x->lvl != y->lvl) return x->lvl < y->lvl ? -1 : 1;
    if (x->ix != y->ix) return x->ix < y->ix ? -1 : 1;
    if (x->iy != y->iy) return x->iy < y->iy ? -1 : 1;
    if (x->iz != y->iz) return x->iz < y->iz ? -1 : 1;
    return (x->rec > y->rec) - (x->rec < y->rec);
}

static void grid_free(struct gather *g)
{
    iris_free(g->cells);
    iris_free(g->idx);
    g->cells = NULL;
    g->idx = NULL;
    g->cells_mask = 0;
    g->n_levels = 0;
}

/* Rebuilds the grid over g->all. */
static enum iris_status grid_build(struct gather *g)
{
    grid_free(g);
    size_t n = g->all.n;
    if (n == 0)
        return IRIS_OK;
    struct cpair *pairs = iris_malloc(8 * n * sizeof *pairs);
    if (!pairs)
        return IRIS_ENOMEM;
    size_t np = 0;
    bool seen[MAX_DEPTH][MAX_LEVELS] = { { false } };
    for (size_t i = 0; i < n; i++) {
        const struct grec *r = &g->all.r[i];
        double bl[3], bh[3];
        rec_box(g, r, bl, bh);
        double R = 0.5 * fmax(bh[0] - bl[0], fmax(bh[1] - bl[1], bh[2] - bl[2]));
        int l = rec_level(R);
        double s = ldexp(1.0, l);
        seen[r->depth][l + 40] = true;
        int64_t lo[3] = { cell_of(bl[0], s), cell_of(bl[1], s),
                          cell_of(bl[2], s) };
        int64_t hi[3] = { cell_of(bh[0], s), cell_of(bh[1], s),
                          cell_of(bh[2], s) };
        for (int64_t x = lo[0]; x <= hi[0] && x <= lo[0] + 1; x++)
            for (int64_t y = lo[1]; y <= hi[1] && y <= lo[1] + 1; y++)
                for (int64_t z = lo[2]; z <= hi[2] && z <= lo[2] + 1; z++)
                    pairs[np++] = (struct cpair){ lvl_key(l, r->depth),
                                                  x, y, z, (uint32_t)i };
    }
    for (int d = 0; d < MAX_DEPTH; d++)
        for (int l = 0; l < MAX_LEVELS; l++)
            if (seen[d][l])
                g->levels[g->n_levels++] = lvl_key(l - 40, d);
    qsort(pairs, np, sizeof *pairs, cpair_cmp);
    size_t n_cells = 0;
    for (size_t i = 0; i < np; i++)
        n_cells += i == 0 || pairs[i].lvl != pairs[i - 1].lvl ||
                   pairs[i].ix != pairs[i - 1].ix ||
                   pairs[i].iy != pairs[i - 1].iy ||
                   pairs[i].iz != pairs[i - 1].iz;
    size_t cap = 16;
    while (cap < 2 * n_cells)
        cap *= 2;
    g->cells = iris_calloc(cap, sizeof *g->cells);
    g->idx = iris_malloc(np * sizeof *g->idx);
    if (!g->cells || !g->idx) {
        iris_free(pairs);
        grid_free(g);
        return IRIS_ENOMEM;
    }
    g->cells_mask = cap - 1;
    for (size_t i = 0; i < np;) {
        size_t k = i;
        while (k < np && pairs[k].lvl == pairs[i].lvl &&
               pairs[k].ix == pairs[i].ix && pairs[k].iy == pairs[i].iy &&
               pairs[k].iz == pairs[i].iz) {
            g->idx[k] = pairs[k].rec;
            k++;
        }
        size_t slot = cell_hash(pairs[i].lvl, pairs[i].ix, pairs[i].iy,
                                pairs[i].iz) & g->cells_mask;
        while (g->cells[slot].count != 0)
            slot = (slot + 1) & g->cells_mask;
        g->cells[slot] = (struct gcell){ pairs[i].lvl, pairs[i].ix,
                                         pairs[i].iy, pairs[i].iz,
                                         (uint32_t)i, (uint32_t)(k - i) };
        i = k;
    }
    iris_free(pairs);
    return IRIS_OK;
}

/* ------------------------------------------------------------------ */
/* Reuse                                                                */
/* ------------------------------------------------------------------ */

struct lookup {
    vec3 p, n;
    double eb;
    bool smooth;               /* the final pass's weights */
    int depth;                 /* records of this level only */
    double w, sum[3];
};

/* POV-Ray's AverageNearBlock for one record. Inline in both lookups:
** a radiosity scene's lookups call it 20 million times at 320 x 240
** (81, 82), most of them for a record whose octree cube holds not the
** point; those fail the first test, so the call cost as much as the
** test. The three axes are tested without branching between them
** (the same answer: nothing here has a side effect). */
static inline void consider(struct lookup *q, const struct grec *r)
{
    if (r->depth != q->depth ||
        ((fabs(q->p.x - r->nc.x) >= r->ns) |
         (fabs(q->p.y - r->nc.y) >= r->ns) |
         (fabs(q->p.z - r->nc.z) >= r->ns)))
        return;
    vec3 delta = v3_sub(q->p, r->p);
    double d2 = v3_len2(delta);
    double quick = r->ri * q->eb;
    if (!(d2 < quick * quick))
        return;
    double dist = sqrt(d2), ri = r->ri;
    vec3 du = v3(0, 0, 0);
    if (dist > NEAR_EPS) {
        du = v3_scale(delta, 1.0 / dist);
        /* the radius shrinks towards the nearest surface the sample saw:
        ** light changes fastest there */
        double cn = v3_dot(r->to_near, du);
        if (cn > 0.0)
            ri = cn * r->near + (1.0 - cn) * ri;
    }
    if (!(dist < ri * q->eb))
        return;
    double err = dist / ri + 2.0 * sqrt(fabs(1.0 - v3_dot(q->n, r->n)));
    if (!(err < q->eb))
        return;
    if (dist > NEAR_EPS) {
        /* a record in front of the point may see what shadows it */
        vec3 half = v3_add(q->n, r->n);
        double hl = v3_len(half);
        if (hl > 0.0 && v3_dot(du, half) / hl <= IN_FRONT_LIMIT)
            return;
    }
    double t = err / q->eb, w;
    if (!q->smooth)
        w = 1.0 - t;
    else
        w = t < 0.5 ? 1.0 - 2.0 * t * t : 2.0 * (1.0 - t) * (1.0 - t);
    if (!(w > 0.0))
        return;
    q->w += w;
    for (int k = 0; k < 3; k++)
        q->sum[k] += w * r->e[k];
}

static void lookup_shared(const struct gather *g, struct lookup *q)
{
    if (!g->cells)
        return;
    for (int i = 0; i < g->n_levels; i++) {
        int key = g->levels[i];
        if (key_depth(key) != q->depth)
            continue;
        double s = ldexp(1.0, key - MAX_LEVELS * q->depth);
        int64_t ix = cell_of(q->p.x, s), iy = cell_of(q->p.y, s),
                iz = cell_of(q->p.z, s);
        size_t slot = cell_hash(key, ix, iy, iz) & g->cells_mask;
        for (;;) {
            const struct gcell *c = &g->cells[slot];
            if (c->count == 0)
                break;
            if (c->lvl == key && c->ix == ix && c->iy == iy && c->iz == iz) {
                for (uint32_t k = 0; k < c->count; k++)
                    consider(q, &g->all.r[g->idx[c->first + k]]);
                break;
            }
            slot = (slot + 1) & g->cells_mask;
        }
    }
}

static struct lslot *local_slot(struct gather_local *gl, int32_t lvl,
                                 int64_t ix, int64_t iy, int64_t iz)
{
    size_t slot = cell_hash(lvl, ix, iy, iz) & gl->mask;
    for (;;) {
        struct lslot *c = &gl->slots[slot];
        if (c->head == UINT32_MAX ||
            (c->lvl == lvl && c->ix == ix && c->iy == iy && c->iz == iz))
            return c;
        slot = (slot + 1) & gl->mask;
    }
}

static void local_clear(struct gather_local *gl)
{
    for (size_t i = 0; i < gl->n_used; i++)
        gl->slots[gl->used[i]].head = UINT32_MAX;
    gl->n_used = 0;
    gl->n_nodes = 0;
    gl->n_levels = 0;
    gl->l.n = 0;
    gl->own_from = 0;
}

/* Files record 'i' of gl->l in the cells its sphere of influence
** touches. Returns false when out of memory. */
static bool local_index(const struct gather *g, struct gather_local *gl,
                        uint32_t i);

/* Rebuilds the local grid, twice as large, over gl->l. */
static bool local_grow(const struct gather *g, struct gather_local *gl)
{
    size_t cap = gl->mask ? 2 * (gl->mask + 1) : 1024;
    struct lslot *ns = iris_malloc(cap * sizeof *ns);
    size_t *nu = iris_malloc(cap * sizeof *nu);
    if (!ns || !nu) {
        iris_free(ns);
        iris_free(nu);
        return false;
    }
    for (size_t k = 0; k < cap; k++)
        ns[k].head = UINT32_MAX;
    iris_free(gl->slots);
    iris_free(gl->used);
    gl->slots = ns;
    gl->used = nu;
    gl->mask = cap - 1;
    gl->n_used = 0;
    gl->n_nodes = 0;
    gl->n_levels = 0;
    for (size_t k = 0; k < gl->l.n; k++)
        if (!local_index(g, gl, (uint32_t)k))
            return false;
    return true;
}

static bool local_index(const struct gather *g, struct gather_local *gl,
                        uint32_t i)
{
    const struct grec *r = &gl->l.r[i];
    double bl[3], bh[3];
    rec_box(g, r, bl, bh);
    double R = 0.5 * fmax(bh[0] - bl[0], fmax(bh[1] - bl[1], bh[2] - bl[2]));
    int lv = rec_level(R), l = lvl_key(lv, r->depth);
    double s = ldexp(1.0, lv);
    int64_t lo[3] = { cell_of(bl[0], s), cell_of(bl[1], s),
                      cell_of(bl[2], s) };
    int64_t hi[3] = { cell_of(bh[0], s), cell_of(bh[1], s),
                      cell_of(bh[2], s) };
    /* at most 8 new cells: keep the table at most half full */
    if (!gl->mask || 2 * (gl->n_used + 8) > gl->mask + 1)
        return local_grow(g, gl);
    if (gl->n_nodes + 8 > gl->cap_nodes) {
        size_t cap = gl->cap_nodes ? 2 * gl->cap_nodes : 1024;
        struct lnode *nn = iris_realloc(gl->nodes, cap * sizeof *nn);
        if (!nn)
            return false;
        gl->nodes = nn;
        gl->cap_nodes = cap;
    }
    bool known = false;
    for (int k = 0; k < gl->n_levels && !known; k++)
        known = gl->levels[k] == l;
    if (!known)
        gl->levels[gl->n_levels++] = l;
    for (int64_t x = lo[0]; x <= hi[0] && x <= lo[0] + 1; x++)
        for (int64_t y = lo[1]; y <= hi[1] && y <= lo[1] + 1; y++)
            for (int64_t z = lo[2]; z <= hi[2] && z <= lo[2] + 1; z++) {
                struct lslot *c = local_slot(gl, l, x, y, z);
                if (c->head == UINT32_MAX) {
                    *c = (struct lslot){ l, x, y, z, UINT32_MAX };
                    gl->used[gl->n_used++] = (size_t)(c - gl->slots);
                }
                gl->nodes[gl->n_nodes] = (struct lnode){ i, c->head };
                c->head = (uint32_t)gl->n_nodes++;
            }
    return true;
}

/* The records of gl->l that may be reused at q (each once). */
static void lookup_local(struct gather_local *gl, struct lookup *q)
{
    if (!gl->mask)
        return;
    for (int i = 0; i < gl->n_levels; i++) {
        int l = gl->levels[i];
        if (key_depth(l) != q->depth)
            continue;
        double s = ldexp(1.0, l - MAX_LEVELS * q->depth);
        struct lslot *c = local_slot(gl, l, cell_of(q->p.x, s),
                                     cell_of(q->p.y, s), cell_of(q->p.z, s));
        for (uint32_t k = c->head; k != UINT32_MAX; k = gl->nodes[k].next)
            if (q->depth > 0 || gl->nodes[k].rec >= gl->own_from)
                consider(q, &gl->l.r[gl->nodes[k].rec]);
    }
}

/* ------------------------------------------------------------------ */
/* One sample                                                           */
/* ------------------------------------------------------------------ */

/* The directions of one sample about 'n': the level's set, and with
** 'normal on' (n perturbed away from the raw normal) only those in front
** of the surface, as POV-Ray's GatherLight draws from its pool until
** 'count' of them are (SampleDirectionGenerator: at most 5 x count
** tries, then the raw normal). WHY turned copies of the set: it has
** 'count' directions; the next copies of the golden-angle spiral (each
** turned by a further golden angle) stand for the pool's next entries,
** so a tilted normal still gets 'count' rays, cosine distributed about n
** and cut off at the raw tangent plane. */
struct dir_seq {
    const vec3 *set;
    int count, turns, turn, i, got;
    vec3 a, b, n, raw;
    double cs, sn;             /* this turn's rotation of the set */
};

static void dir_seq_init(struct dir_seq *q, const struct gather *g,
                         int depth, vec3 n, vec3 raw, bool perturbed)
{
    q->set = g->dirs[depth];
    q->count = g->count[depth];
    q->turns = perturbed ? 5 : 1;
    q->turn = q->i = q->got = 0;
    q->n = n;
    q->raw = raw;
    q->cs = 1.0;
    q->sn = 0.0;
    v3_basis(n, &q->a, &q->b);
}

/* The next direction, or false when 'count' were given or the tries ran
** out. Unperturbed, the set as it is (cos 0 and sin 0 leave it exact). */
static bool dir_next(struct dir_seq *q, vec3 *d)
{
    while (q->got < q->count && q->turn < q->turns) {
        if (q->i == q->count) {
            q->i = 0;
            q->turn++;
            q->cs = cos(GOLDEN_ANGLE * q->turn);
            q->sn = sin(GOLDEN_ANGLE * q->turn);
            continue;
        }
        vec3 l = q->set[q->i++];
        double x = l.x * q->cs - l.y * q->sn, y = l.x * q->sn + l.y * q->cs;
        *d = v3_norm(v3_add(v3_add(v3_scale(q->a, x), v3_scale(q->b, y)),
                            v3_scale(q->n, l.z)));
        if (q->turns > 1 && !(v3_dot(*d, q->raw) > 0.0))
            continue;
        q->got++;
        return true;
    }
    return false;
}

/* POV-Ray's GatherLight: the mean radiance over the hemisphere about 'n'
** at 'h' ('raw' is the unperturbed normal, the same as n unless the
** scene says 'normal on'). Returns whether the sample may be cached
** (*rec filled). */
static bool gather_sample(struct trace_ctx *c, const struct gather *g,
                          const struct tray *eye, const struct hit *h,
                          vec3 n, vec3 raw, double e[3], struct grec *rec)
{
    const struct tracer *t = c->t;
    /* what a gather ray changes in the context, restored below */
    int level = c->level, depth = c->gi_depth;
    /* POV-Ray's settings per level: reuse radii doubled, rays halved
    ** (at least 5), the rays' weight (brightness / 2)^(depth + 1) */
    double to_eye = v3_len(v3_sub(g->eye, h->p));
    double min_d = ldexp(to_eye * g->rs.minimum_reuse, depth);
    double max_d = ldexp(to_eye * g->rs.maximum_reuse, depth);
    /* POV-Ray's similar(): an unperturbed normal takes the plain set */
    bool perturbed = fabs(n.x - raw.x) >= 1e-4 || fabs(n.y - raw.y) >= 1e-4 ||
                     fabs(n.z - raw.z) >= 1e-4;
    struct dir_seq seq;
    dir_seq_init(&seq, g, depth, n, raw, perturbed);
    double transm = c->transm;
    bool spectral = c->spectral;
    c->gi_depth = depth + 1;
    double wt = fmax(t->adc + 1e-6, pow(0.5 * g->rs.brightness, depth + 1));
    double sum[3] = { 0, 0, 0 }, inv = 0.0, nearest = HUGE_VAL;
    vec3 near_dir = n;
    struct tray gr;
    tray_copy(&gr, eye);
    gr.reflected = true;
    gr.r.o = h->p;
    gr.tmin = h->eps;
    /* importance (POV-Ray's): ray of rank k of n (rank_init) asks for
    ** k / (n - 1); a hit on an object of importance I below that gives
    ** only its distance, the others count n / (floor(I (n - 1)) + 1)
    ** times, so each object is shaded by about I x n rays and still
    ** weighs what it covers (the mean divides by their sum). The
    ** found importance is restored around this sample: the hits' own
    ** gathers overwrite it */
    float imp_saved = c->imp_found;
    int n_rank = g->count[depth];
    double qsum = 0.0;
    int count = 0;
    for (;;) {
        if (!dir_next(&seq, &gr.r.d)) {
            if (count > 0 || seq.turns == 1)
                break;
            /* none in front: POV-Ray falls back to the raw normal */
            dir_seq_init(&seq, g, depth, n = raw, raw, false);
            continue;
        }
        count++;
        double col[3];
        c->level = 0; /* a new ray from scratch, as POV-Ray starts it */
        /* the rank of the set's direction this one is (turned or not) */
        float rank = g->importance && n_rank > 1
                         ? (float)g->rank[depth][seq.i - 1] /
                               (float)(n_rank - 1)
                         : 0.0f;
        if (g->importance) {
            c->imp_check = true;
            c->imp_query = rank;
        }
        double d = trace_ray(c, &gr, wt, false, col);
        c->imp_check = false;
        double quality = 1.0;
        if (g->importance) {
            float found = c->imp_found;
            if (found < rank)
                col[0] = col[1] = col[2] = quality = 0.0;
            else if (found < 1.0f)
                quality = (double)n_rank /
                          (floor(found * (float)(n_rank - 1)) + 1.0);
        }
        if (g->rs.max_sample > 0.0) {
            double m = fmax(col[0], fmax(col[1], col[2]));
            if (m > g->rs.max_sample)
                for (int k = 0; k < 3; k++)
                    col[k] *= g->rs.max_sample / m;
        }
        qsum += quality;
        for (int k = 0; k < 3; k++)
            if (isfinite(col[k]))
                sum[k] += g->importance ? col[k] * quality : col[k];
        if (d < nearest) {
            nearest = d;
            near_dir = gr.r.d;
        }
        if (d > 0.0 && isfinite(d))
            inv += 1.0 / d;
    }
    c->level = level;
    c->gi_depth = depth;
    c->transm = transm;
    c->spectral = spectral;
    c->imp_found = imp_saved;
    for (int k = 0; k < 3; k++)
        e[k] = g->importance ? (qsum > 0.0 ? sum[k] / qsum : sum[k])
                             : sum[k] / count;
    /* almost touching another surface: rays may have slipped through it
    ** (POV-Ray's rule) */
    if (!(nearest > max_d * 1e-4))
        return false;
    double mean = inv > 0.0 ? count / inv : HUGE_VAL;
    mean = fmin(fmax(mean, min_d), max_d);
    if (!(mean > 0.0) || !isfinite(mean))
        return false;
    *rec = (struct grec){ h->p, n, near_dir, mean, fmin(nearest, mean),
                          { (float)e[0], (float)e[1], (float)e[2] }, depth,
                          v3(0, 0, 0), 0.0 };
    pov_node(g, rec);
    return true;
}

void gather_irradiance(struct trace_ctx *c, const struct tray *eye,
                       const struct hit *h, vec3 raw, vec3 layer_n,
                       double weight, double out[3])
{
    const struct gather *g = c->t->gather;
    /* POV-Ray's effectiveNormal: the cache is searched and filled under
    ** the layer's perturbed normal with 'normal on' */
    vec3 n = g && g->rs.normal ? layer_n : raw;
    out[0] = out[1] = out[2] = 0.0;
    if (!g)
        return;
    if (!c->gl) {
        c->gl = iris_calloc(1, sizeof *c->gl);
        if (!c->gl)
            return;
    }
    int depth = c->gi_depth;
    if (depth >= g->depths)
        return;
    /* the final pass's smooth weights only for eye hits (POV-Ray's) */
    struct lookup q = { h->p, n, g->eb, !g->pretrace && depth == 0, depth,
                        0.0, { 0, 0, 0 } };
    /* faint rays may reuse from farther (POV-Ray's weight offset) */
    if (weight < 0.25)
        q.eb += 0.25 - weight;
    q.eb = ldexp(q.eb, depth);
    lookup_shared(g, &q);
    lookup_local(c->gl, &q);
    double e[3];
    /* POV-Ray's reuse count: nearest_count, then 2, then 1 */
    int need = depth == 0 ? g->rs.nearest_count
               : depth == 1 ? (g->rs.nearest_count < 2 ? g->rs.nearest_count : 2)
                            : 1;
    bool enough = g->strict ? 4.0 * q.w >= need
                            : q.w > 0.0 && !g->rs.always_sample;
    if (enough) {
        for (int k = 0; k < 3; k++)
            e[k] = q.sum[k] / q.w;
    } else {
        struct grec rec;
        double en[3];
        if (gather_sample(c, g, eye, h, n, raw, en, &rec) &&
            c->gl->l.n < (c->gl->cap ? c->gl->cap : LOCAL_MAX) &&
            list_push(&c->gl->l, &rec) &&
            !local_index(g, c->gl, (uint32_t)(c->gl->l.n - 1)))
            c->gl->l.n--; /* out of memory: not kept */
        /* blended with what could be reused, as POV-Ray does */
        for (int k = 0; k < 3; k++)
            e[k] = (q.sum[k] + en[k]) / (q.w + 1.0);
    }
    double gt = g->rs.gray_threshold;
    double grey = mat_greyscale(e);
    for (int k = 0; k < 3; k++)
        out[k] = g->rs.brightness * (e[k] * (1.0 - gt) + gt * grey);
}

void gather_tile_begin(struct trace_ctx *c)
{
    if (c->gl)
        local_clear(c->gl);
}

void gather_ctx_fini(struct trace_ctx *c)
{
    if (c->gl) {
        iris_free(c->gl->l.r);
        iris_free(c->gl->slots);
        iris_free(c->gl->used);
        iris_free(c->gl->nodes);
        iris_free(c->gl);
        c->gl = NULL;
    }
}

/* ------------------------------------------------------------------ */
/* Pretrace                                                             */
/* ------------------------------------------------------------------ */

struct pre_job {
    struct gather *g;
    const struct tracer *t;
    const iris_render_options *opts;
    const struct interior_stack *cam;
    struct trace_ctx *ctx;     /* one per thread */
    struct grec_list *out;     /* one per tile */
    int x0, y0, x1, y1, tiles_x;
    int64_t n_tiles;           /* in the window */
    int64_t groups;            /* tile groups of this step (pre_group) */
    int step, round;
    atomic_int failed;
};

/* The pretrace samples of tile 'item' of the current step, traced in
** raster order into the context's local list. */
static void pre_tile(struct pre_job *j, struct trace_ctx *c, int64_t item)
{
    const iris_scene *sc = j->t->scene;
    int tx = (int)(item % j->tiles_x), ty = (int)(item / j->tiles_x);
    int tx0 = j->x0 + tx * TILE, ty0 = j->y0 + ty * TILE;
    int tx1 = tx0 + TILE - 1 < j->x1 ? tx0 + TILE - 1 : j->x1;
    int ty1 = ty0 + TILE - 1 < j->y1 ? ty0 + TILE - 1 : j->y1;
    int s = j->step, half = s / 2;
    bool ortho = sc->camera.kind == IRIS_CAM_ORTHOGRAPHIC ||
                 sc->camera.kind == IRIS_CAM_MESH;
    /* the samples lie on one grid over the window, whatever the tiles */
    for (int y = j->y0 + half; y <= ty1; y += s) {
        if (y < ty0)
            continue;
        for (int x = j->x0 + half; x <= tx1; x += s) {
            if (x < tx0)
                continue;
            struct tray r;
            vec3 raw;
            r.reflected = false;
            r.lambda = 0.0;
            r.tmin = 0.0;
            if (!camera_ray_raw(&sc->camera, j->opts->width,
                                j->opts->height, x, y, &r.r, &raw))
                continue;
            if (ortho) {
                trace_containing(j->t, r.r.o, &r.st);
            } else {
                r.st.n = j->cam->n;
                for (int i = 0; i < r.st.n; i++)
                    r.st.e[i] = j->cam->e[i];
            }
            rng_lazy_seed(&c->rng, j->opts->seed,
                          0x67617468ULL + (uint64_t)j->round,
                          ((uint64_t)(uint32_t)y << 32) | (uint32_t)x);
            c->level = 0;
            c->spectral = false;
            double rgb[3];
            trace_ray(c, &r, 1.0, false, rgb);
        }
    }
}

/*
** One group of tiles of a pretrace step: tiles item, item + groups, ...
** in that order, sharing one local list for the deeper levels, as
** POV-Ray's +HR pretrace shares records between the tiles of one nominal
** thread (tile id = serial % nominalThreads, nominalThreads 1 in the
** first step and doubled at each). WHY: with a list per 32x32 tile, the
** first, coarse step (a few eye samples per tile, whose gather rays hit
** the whole scene) took its deeper samples again in every tile:
** 82_radiosity_emissive_room at 160x120 took 527 depth-1 samples in it
** where POV-Ray takes 78. Eye-hit (depth 0) records stay tile-local
** (own_from), as before: sharing them too, as POV-Ray does, took fewer
** eye samples (188 where POV-Ray takes 169 on 135_no_radiosity, 196
** before) but lowered 135's PSNR against POV-Ray by 0.9 dB over 5 seeds.
*/
static void pre_group(void *vctx, int64_t item, int thread)
{
    struct pre_job *j = vctx;
    struct trace_ctx *c = &j->ctx[thread];
    gather_tile_begin(c);
    for (int64_t t = item; t < j->n_tiles; t += j->groups) {
        if (atomic_load(&j->failed) ||
            (j->opts->interrupt && *j->opts->interrupt))
            break;
        if (c->gl) {
            c->gl->cap = (size_t)LOCAL_MAX * (size_t)((t - item) / j->groups + 1);
            c->gl->own_from = c->gl->l.n;
        }
        pre_tile(j, c, t);
    }
    /* hand the group's records over (the list moves, nothing is copied) */
    if (c->gl) {
        struct grec_list l = c->gl->l;
        local_clear(c->gl);
        c->gl->cap = 0;
        j->out[item] = l;
        memset(&c->gl->l, 0, sizeof c->gl->l);
    }
}

static enum iris_status pretrace(struct gather *g, const struct tracer *t,
                                 const iris_render_options *opts, int threads,
                                 const struct interior_stack *cam)
{
    struct pre_job j;
    memset(&j, 0, sizeof j);
    j.g = g;
    j.t = t;
    j.opts = opts;
    j.cam = cam;
    if (!eye_window(opts, &j.x0, &j.x1, &j.y0, &j.y1))
        return IRIS_OK;
    j.tiles_x = (j.x1 - j.x0) / TILE + 1;
    int64_t n_tiles = (int64_t)j.tiles_x * ((j.y1 - j.y0) / TILE + 1);
    j.n_tiles = n_tiles;
    int size = opts->width > opts->height ? opts->width : opts->height;
    int first = (int)lround(g->rs.pretrace_start * size);
    int end = (int)lround(g->rs.pretrace_end * size);
    if (end < 1) end = 1;
    if (first < end) first = end;
    if (first > 256) first = 256;
    /* POV-Ray's steps down to pretrace_end, then, with the eye pass's
    ** rule (a sample wherever nothing can be reused), steps down to 4
    ** pixels: what POV-Ray's final pass adds lands here in the shared
    ** cache rather than in tile-local lists */
    int last = end < FILL_STEP ? end : FILL_STEP;
    j.ctx = iris_calloc((size_t)threads, sizeof *j.ctx);
    j.out = iris_calloc((size_t)n_tiles, sizeof *j.out);
    enum iris_status st = j.ctx && j.out ? IRIS_OK : IRIS_ENOMEM;
    int n_ctx = 0;
    for (; st == IRIS_OK && n_ctx < threads; n_ctx++)
        if (!trace_ctx_init(&j.ctx[n_ctx], t)) {
            trace_ctx_fini(&j.ctx[n_ctx]);
            st = IRIS_ENOMEM;
        }
    g->pretrace = true;
    for (int s = first; st == IRIS_OK; s = s / 2 > last ? s / 2 : last) {
        j.step = s;
        g->strict = s >= end;
        g->eb = g->rs.error_bound * (g->strict ? g->rs.low_error_factor : 1);
        atomic_init(&j.failed, 0);
        /* POV-Ray's nominal threads: 1, then doubled at each step */
        j.groups = j.round < 62 ? (int64_t)1 << j.round : n_tiles;
        if (j.groups > n_tiles)
            j.groups = n_tiles;
        par_for(threads, j.groups, pre_group, &j);
        for (int64_t i = 0; i < n_tiles; i++) {
            for (size_t k = 0; k < j.out[i].n && st == IRIS_OK; k++)
                if (!list_push(&g->all, &j.out[i].r[k]))
                    st = IRIS_ENOMEM;
            iris_free(j.out[i].r);
            memset(&j.out[i], 0, sizeof j.out[i]);
        }
        if (st == IRIS_OK)
            st = grid_build(g);
        if (opts->interrupt && *opts->interrupt)
            st = IRIS_EINTR;
        j.round++;
        if (s == last)
            break;
    }
    for (int i = 0; i < n_ctx; i++)
        trace_ctx_fini(&j.ctx[i]);
    iris_free(j.ctx);
    iris_free(j.out);
    g->pretrace = g->strict = false;
    g->eb = g->rs.error_bound;
    return st;
}

/* ------------------------------------------------------------------ */
/* Set-up                                                               */
/* ------------------------------------------------------------------ */

/* The direction sets and ranks of levels 0 .. g->depths - 1, and g. */
static void gather_free(struct gather *g)
{
    for (int d = 0; d < g->depths; d++) {
        iris_free(g->dirs[d]);
        iris_free(g->rank[d]);
    }
    iris_free(g);
}

#define RANK_STEP 1.4142135623730951 /* sqrt 2 */

static int rank_cmp(const void *a, const void *b)
{
    int i = *(const int *)a, j = *(const int *)b;
    double ki = fmod(i * RANK_STEP, 1.0), kj = fmod(j * RANK_STEP, 1.0);
    return ki < kj ? -1 : ki > kj ? 1 : (i > j) - (i < j);
}

/*
** The ranks of level d's directions for importance: a ray of rank k is
** shaded on objects of importance >= k / (count - 1), so the first ranks
** must spread over the hemisphere. WHY not the set's order: the spiral
** goes outwards from the normal, and an object seen only at grazing
** angles would never be shaded. Ordered by frac(i sqrt 2), any first
** ranks take every ~1/I-th direction of the spiral, spread in both
** angles, as POV-Ray's random pool's first entries are. (Not by the
** golden ratio: the spiral's azimuth is frac(i x golden ratio), so the
** first half were the directions of one half-plane: a scene with the
** #default importance 0.5 was 27.7 dB from its image without importance,
** with sqrt 2 39.2 dB, its noise.)
*/
static bool rank_init(struct gather *g, int d)
{
    int n = g->count[d];
    int *order = iris_calloc((size_t)n, sizeof *order);
    g->rank[d] = iris_calloc((size_t)n, sizeof *g->rank[d]);
    if (!order || !g->rank[d]) {
        iris_free(order);
        return false;
    }
    for (int i = 0; i < n; i++)
        order[i] = i;
    qsort(order, (size_t)n, sizeof *order, rank_cmp);
    for (int k = 0; k < n; k++)
        g->rank[d][order[k]] = k;
    iris_free(order);
    return true;
}

enum iris_status gather_begin(struct tracer *t,
                              const iris_render_options *opts, int threads,
                              const struct interior_stack *cam)
{
    t->gather = NULL;
    t->photon_map_local = t->photon_map_gather = t->photon_map;
    if (!gather_wanted(t))
        return IRIS_OK;
    struct gather *g = iris_calloc(1, sizeof *g);
    if (!g)
        return IRIS_ENOMEM;
    g->scene = t->scene;
    g->rs = t->scene->settings.rad;
    if (g->rs.count < 1)
        g->rs.count = 35;
    if (!(g->rs.error_bound > 0.0))
        g->rs.error_bound = 1.8;
    if (!(g->rs.low_error_factor > 0.0))
        g->rs.low_error_factor = 1.0;
    if (!(g->rs.maximum_reuse > 0.0))
        g->rs.maximum_reuse = 0.2;
    if (g->rs.minimum_reuse > g->rs.maximum_reuse)
        g->rs.minimum_reuse = g->rs.maximum_reuse;
    g->eye = t->scene->camera.location;
    g->eb = g->rs.error_bound;
    g->importance = t->scene->settings.rad_importance_used;
    /* Later bounces: from the global photon map when the scene's lights
    ** fill one; with none (light only from emission, ambient or the sky)
    ** the map would be empty, so the gather rays' hits gather again, as
    ** POV-Ray's do, down to recursion_limit levels. */
    int rl = g->rs.recursion_limit;
    /* With a global map, the map carries the light sources' further
    ** bounces but not those of the sky, emission or (#version < 3.7)
    ** ambient: the gather rays' hits then gather too, and their rays see
    ** no light source (no direct light, no photons), only that light and
    ** their own deeper gathers, so nothing is counted twice. (In a scene
    ** with none of it those deeper gathers return exactly 0, so they are
    ** not traced when a walk over the scene proves there is none:
    ** radiosity/cornell at 160x120 took 9.3 s of CPU with them, 3.8 s
    ** without, the same image.) */
    const iris_scene *sc = t->scene;
    bool global = pmap_wants_global(sc);
    const struct photon_map *pm = t->photon_map;
    g->split = rl >= 2 && global && pm && pm->global &&
               gather_scene_has_unlit_light(sc, t->legacy, g->rs.media);
    g->depths = rl >= 2 && (!global || g->split)
                    ? (rl < MAX_DEPTH ? rl : MAX_DEPTH) : 1;
    /* Malley's method over a golden-angle spiral: points spread evenly
    ** over the unit disc, lifted to the hemisphere, are cosine
    ** distributed. The spiral turns by an angle keyed by the seed, so
    ** that progressive passes (each with its own seed) average different
    ** direction sets; cos^2 theta stays on the midpoints of its strata.
    ** Level d has POV-Ray's max(5, count / 2^d) rays, its own set. */
    double turn = 2.0 * M_PI * (double)(rng_mix64(opts->seed ^ 0x676174686572ULL)
                                        >> 11) * 0x1p-53;
    for (int d = 0; d < g->depths; d++) {
        int cnt = (int)ldexp(g->rs.count, -d);
        g->count[d] = cnt > 5 ? cnt : 5;
        g->dirs[d] = iris_calloc((size_t)g->count[d], sizeof *g->dirs[d]);
        if (!g->dirs[d]) {
            g->depths = d;
            gather_free(g);
            return IRIS_ENOMEM;
        }
        for (int i = 0; i < g->count[d]; i++) {
            double u = (i + 0.5) / g->count[d], r = sqrt(u);
            double ph = GOLDEN_ANGLE * i + turn;
            g->dirs[d][i] = v3(r * cos(ph), r * sin(ph),
                               sqrt(fmax(0.0, 1.0 - u)));
        }
        if (g->importance && !rank_init(g, d)) {
            g->depths = d + 1;
            gather_free(g);
            return IRIS_ENOMEM;
        }
    }
    t->photon_map_gather = t->photon_map;
    if (t->photon_map) {
        /* eye hits that gather must not add the global map themselves */
        const struct photon_map *m = t->photon_map;
        g->view = *m;
        g->view.global = NULL;
        t->photon_map_local = &g->view;
        /* The gather rays' hits: the global map only if recursion_limit
        ** allows one more bounce, and the caustic estimate from at most
        ** GI_CAUSTIC_K photons. Why: that k-nearest search at every
        ** gather hit was 2/3 of the gather's time; 'count' rays average
        ** the noisier estimates, and a smaller k only lowers their bias. */
        g->view_gi = *m;
        if (g->rs.recursion_limit < 2)
            g->view_gi.global = NULL;
        if (g->view_gi.gather_max > GI_CAUSTIC_K)
            g->view_gi.gather_max = GI_CAUSTIC_K;
        if (g->view_gi.gather_min > g->view_gi.gather_max / 4)
            g->view_gi.gather_min = g->view_gi.gather_max / 4;
        t->photon_map_gather = &g->view_gi;
    }
    t->gather = g;
    enum iris_status st = pretrace(g, t, opts, threads, cam);
    if (st != IRIS_OK)
        gather_end(t);
    return st;
}

void gather_end(struct tracer *t)
{
    struct gather *g = t->gather;
    t->gather = NULL;
    t->photon_map_local = t->photon_map_gather = t->photon_map;
    if (!g)
        return;
    grid_free(g);
    iris_free(g->all.r);
    gather_free(g);
}
