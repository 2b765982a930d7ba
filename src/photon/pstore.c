/* SPDX-License-Identifier: MIT */
/*
** pstore.c: packing photons, building the implicit kd-tree, k-NN search
** (pstore.h).
*/
#include "config.h"

#include "photon/pstore.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "spectrum/spectrum.h"
#include "util/mem.h"
#include "util/thread.h"

#define QBITS 20
#define QMAX ((1u << QBITS) - 1u)
#define AXIS_SHIFT 60
#define MIN_TRIM 8

/* ---- direction: octahedral map, 8 bits per coordinate ---- */

static double sign_nz(double v)
{
    return v < 0.0 ? -1.0 : 1.0;
}

uint16_t pstore_encode_dir(vec3 d)
{
    double s = fabs(d.x) + fabs(d.y) + fabs(d.z);
    if (!(s > 0.0))
        return 0;
    double u = d.x / s, v = d.y / s;
    if (d.z < 0.0) {
        double u2 = (1.0 - fabs(v)) * sign_nz(u);
        v = (1.0 - fabs(u)) * sign_nz(v);
        u = u2;
    }
    int qu = (int)lrint((u * 0.5 + 0.5) * 255.0);
    int qv = (int)lrint((v * 0.5 + 0.5) * 255.0);
    return (uint16_t)((qu & 255) | ((qv & 255) << 8));
}

vec3 pstore_decode_dir(uint16_t q)
{
    double u = (q & 255) / 255.0 * 2.0 - 1.0;
    double v = ((q >> 8) & 255) / 255.0 * 2.0 - 1.0;
    vec3 d = v3(u, v, 1.0 - fabs(u) - fabs(v));
    if (d.z < 0.0) {
        double x = (1.0 - fabs(d.y)) * sign_nz(d.x);
        d.y = (1.0 - fabs(d.x)) * sign_nz(d.y);
        d.x = x;
    }
    return v3_norm(d);
}

/* ---- tree build ---- */

static inline void swap_raw(struct pstore_raw *a, size_t i, size_t j)
{
    struct pstore_raw t = a[i];
    a[i] = a[j];
    a[j] = t;
}

/*
** Quickselect: puts the element of rank 'k' of a[lo..hi) at k along
** 'axis', smaller or equal ones before, larger or equal ones after.
** Hoare's partition with a median-of-three pivot that also serves as the
** two scans' sentinels: it swaps only the pairs on the wrong sides, about
** a third of what a three-way partition swaps, and the 32-byte swaps
** were most of the kd-tree build (perf). Elements equal to the pivot stop
** both scans, so runs of equal coordinates split evenly. With distinct
** coordinates the sets on either side of every median, and so the tree,
** do not depend on the selection algorithm. No NaN reaches here
** (pstore_build drops photons outside the box).
*/
static void select_kth(struct pstore_raw *a, size_t lo, size_t hi, size_t k,
                       int axis)
{
    if (hi - lo < 2)
        return;
    size_t l = lo, ir = hi - 1;
    for (;;) {
        if (ir <= l + 1) {
            if (ir == l + 1 && a[ir].p[axis] < a[l].p[axis])
                swap_raw(a, l, ir);
            return;
        }
        size_t mid = l + (ir - l) / 2;
        swap_raw(a, mid, l + 1);
        if (a[l].p[axis] > a[ir].p[axis])
            swap_raw(a, l, ir);
        if (a[l + 1].p[axis] > a[ir].p[axis])
            swap_raw(a, l + 1, ir);
        if (a[l].p[axis] > a[l + 1].p[axis])
            swap_raw(a, l, l + 1);
        /* a[l] <= pivot = a[l + 1] <= a[ir]: the scans' sentinels */
        size_t i = l + 1, j = ir;
        struct pstore_raw pv = a[l + 1];
        float pivot = pv.p[axis];
        for (;;) {
            do
                i++;
            while (a[i].p[axis] < pivot);
            do
                j--;
            while (a[j].p[axis] > pivot);
            if (j < i)
                break;
            swap_raw(a, i, j);
        }
        a[l + 1] = a[j];
        a[j] = pv;
        if (j >= k)
            ir = j - 1;
        if (j <= k)
            l = i;
    }
}

/* Recursively arranges raw[lo..hi) into tree order, recording each
** median's axis in 'axes'. The segment's cell [mn, mx] is its parent's
** cut at the parent's median: splitting along the cell's longest side
** needs no pass over the photons (a tight box per node made the build
** O(n log n) in box scans, a third of a progressive pass). */
static void build_rec(struct pstore_raw *raw, uint8_t *axes, size_t lo,
                      size_t hi, const double cell_mn[3],
                      const double cell_mx[3])
{
    double mn[3] = { cell_mn[0], cell_mn[1], cell_mn[2] };
    double mx[3] = { cell_mx[0], cell_mx[1], cell_mx[2] };
    while (hi - lo > 1) {
        int axis = 0;
        for (int a = 1; a < 3; a++)
            if (mx[a] - mn[a] > mx[axis] - mn[axis])
                axis = a;
        size_t mid = lo + (hi - lo) / 2;
        select_kth(raw, lo, hi, mid, axis);
        axes[mid] = (uint8_t)axis;
        double cut = raw[mid].p[axis], keep = mx[axis];
        mx[axis] = cut;
        build_rec(raw, axes, lo, mid, mn, mx);
        mx[axis] = keep;
        mn[axis] = cut;
        lo = mid + 1; /* tail call on the right half */
    }
}

/*
** The same tree built by several threads. A serial build is the progressive
** pass's largest serial part (a quarter of a pass of bench/caustic_ball.pov
** on 1 thread), which capped 2 threads at 1.7x. The top levels are split
** level by level, the segments of one level in parallel (each median
** selection is build_rec's own step), until there are PAR_SEGMENTS per
** thread; then the segments' subtrees are built in parallel. Every step is
** the serial build's, so the tree does not depend on the thread count.
*/
#define PAR_MIN_PHOTONS 16384
#define PAR_SEGMENTS 8

struct seg {
    size_t lo, hi;
    double mn[3], mx[3];
};

struct par_build {
    struct pstore_raw *raw;
    uint8_t *axes;
    struct seg *cur, *next;       /* a level's segments, the next's */
};

/* Splits segment 'item' of the level at its median (build_rec's step). */
static void split_seg(void *ctx, int64_t item, int thread)
{
    (void)thread;
    struct par_build *b = ctx;
    struct seg sg = b->cur[item];
    struct seg *l = &b->next[2 * item], *r = &b->next[2 * item + 1];
    if (sg.hi - sg.lo <= 1) {
        *l = sg;
        *r = sg;
        r->lo = r->hi = sg.hi; /* empty */
        return;
    }
    int axis = 0;
    for (int a = 1; a < 3; a++)
        if (sg.mx[a] - sg.mn[a] > sg.mx[axis] - sg.mn[axis])
            axis = a;
    size_t mid = sg.lo + (sg.hi - sg.lo) / 2;
    select_kth(b->raw, sg.lo, sg.hi, mid, axis);
    b->axes[mid] = (uint8_t)axis;
    double cut = b->raw[mid].p[axis];
    *l = sg;
    l->hi = mid;
    l->mx[axis] = cut;
    *r = sg;
    r->lo = mid + 1;
    r->mn[axis] = cut;
}

static void finish_seg(void *ctx, int64_t item, int thread)
{
    (void)thread;
    struct par_build *b = ctx;
    const struct seg *sg = &b->cur[item];
    build_rec(b->raw, b->axes, sg->lo, sg->hi, sg->mn, sg->mx);
}

static bool build_par(struct pstore_raw *raw, uint8_t *axes, size_t n,
                      const double mn[3], const double mx[3], int threads)
{
    size_t target = (size_t)threads * PAR_SEGMENTS, cap = 4 * target + 4;
    struct par_build b = { raw, axes, iris_malloc(cap * sizeof(struct seg)),
                           iris_malloc(cap * sizeof(struct seg)) };
    if (!b.cur || !b.next) {
        iris_free(b.cur);
        iris_free(b.next);
        return false;
    }
    b.cur[0].lo = 0;
    b.cur[0].hi = n;
    memcpy(b.cur[0].mn, mn, sizeof b.cur[0].mn);
    memcpy(b.cur[0].mx, mx, sizeof b.cur[0].mx);
    size_t n_seg = 1;
    while (n_seg < target) {
        par_for(threads, (int64_t)n_seg, split_seg, &b);
        size_t k = 0;
        for (size_t i = 0; i < 2 * n_seg; i++)
            if (b.next[i].hi - b.next[i].lo > 1)
                b.cur[k++] = b.next[i]; /* 0 or 1 photon: done */
        n_seg = k;
        if (n_seg == 0)
            break;
    }
    par_for(threads, (int64_t)n_seg, finish_seg, &b);
    iris_free(b.cur);
    iris_free(b.next);
    return true;
}

static uint64_t quantise(double x, double lo, double step)
{
    double q = step > 0.0 ? (x - lo) / step : 0.0;
    if (!(q > 0.0))
        return 0;
    if (q > QMAX)
        return QMAX;
    return (uint64_t)llrint(q);
}

/* The unsigned key of float 'f' whose order is the floats' order (-0
** just below +0): the sign bit set for positives, every bit flipped for
** negatives. */
static uint32_t float_key(float f)
{
    uint32_t u;
    memcpy(&u, &f, sizeof u);
    return u & 0x80000000u ? ~u : u | 0x80000000u;
}

static float key_float(uint32_t k)
{
    uint32_t u = k & 0x80000000u ? k & 0x7fffffffu : ~k;
    float f;
    memcpy(&f, &u, sizeof f);
    return f;
}

/*
** Sorts v[0..m) ascending (m <= ROBUST_SAMPLES): a least-significant-
** digit radix sort, four passes of 8 bits over the float_key()s: 1.0 M
** instructions for the three axes against qsort()'s 3.7 M with its
** comparison callback, on one thread while the others wait, at every
** progressive pass (bench/caustic_ball.pov, callgrind). The same order
** as qsort's, -0 and +0 aside (the box below cannot tell them apart),
** and NaNs at the ends instead of anywhere.
*/
#define ROBUST_SAMPLES 4096
static void sort_floats(float *v, size_t m, uint32_t *tmp_a, uint32_t *tmp_b)
{
    for (size_t i = 0; i < m; i++)
        tmp_a[i] = float_key(v[i]);
    uint32_t *from = tmp_a, *to = tmp_b;
    for (int shift = 0; shift < 32; shift += 8) {
        size_t count[257] = { 0 };
        for (size_t i = 0; i < m; i++)
            count[((from[i] >> shift) & 255u) + 1]++;
        for (int d = 0; d < 256; d++)
            count[d + 1] += count[d];
        for (size_t i = 0; i < m; i++)
            to[count[(from[i] >> shift) & 255u]++] = from[i];
        uint32_t *t = from;
        from = to;
        to = t;
    }
    /* four passes: the keys are back in tmp_a */
    for (size_t i = 0; i < m; i++)
        v[i] = key_float(from[i]);
}

/*
** A level's box (pstore.h). 20 bits over the box of ALL photons fail when
** a few photons fly far: a photon reflected almost horizontally onto an
** infinite floor lands kilometres away, and the box of a 2-unit caustic
** then has centimetre steps, wider than the photons' spacing. The box is
** therefore the core of the photons - the quantiles (below) of each axis
** over up to 4096 evenly spaced photons - widened on every side by the
** core's largest extent E; the photons outside it make the next level.
** Which quantiles. The strays of a hidden object can be many: a 1e6
** sphere around a caustic scene (thin.pov with SKY=1 in tests/stability)
** catches 1.1-4% of the stored photons. A sparse part (a floor lit by 15%
** of the photons over 1000 times the focus's size) is as well served by a
** level of its own. So the smallest trim among 0.1%, 0.5%, 2%, 5%, 10%
** and 25% whose box is at most SPREAD_MAX times as wide as the middle
** half's is taken: a level's root steps are then at most ~3·SPREAD_MAX /
** 2^20 of its middle half's extent. A small map trims at least MIN_TRIM
** samples on each side (5% of them below 160).
*/
#define SPREAD_MAX 64.0

static void robust_box(const struct pstore_raw *raw, size_t n, double lo[3],
                       double hi[3], bool whole)
{
    enum { SAMPLES = ROBUST_SAMPLES };
    /* trims tried, smallest first, and how far beyond the 25%-75% box the
    ** trimmed box may reach */
    static const double trims[] = { 0.001, 0.005, 0.02, 0.05, 0.10, 0.25 };
    enum { N_TRIMS = sizeof trims / sizeof trims[0] };
    const double spread_max = SPREAD_MAX;
    size_t m = n < SAMPLES ? n : SAMPLES;
    static _Thread_local float buf[3][SAMPLES];
    static _Thread_local uint32_t keys[2][SAMPLES];
    size_t cut[N_TRIMS];
    double ext[N_TRIMS];
    for (int t = 0; t < N_TRIMS; t++) {
        cut[t] = (size_t)(trims[t] * (double)(m - 1));
        if (cut[t] < MIN_TRIM)
            cut[t] = m >= 20 * MIN_TRIM ? MIN_TRIM : m / 20;
        ext[t] = 0.0;
    }
    for (int a = 0; a < 3; a++) {
        lo[a] = INFINITY;
        hi[a] = -INFINITY;
    }
    /* one pass over the photons for the three axes */
    for (size_t i = 0; i < n; i++)
        for (int a = 0; a < 3; a++) {
            /* comparisons, not fmin/fmax (library calls; the same
            ** answer, a NaN ignored too) */
            double v = raw[i].p[a];
            if (v < lo[a])
                lo[a] = v;
            if (v > hi[a])
                hi[a] = v;
        }
    if (whole) /* the last level: the box of all */
        return;
    for (int a = 0; a < 3; a++) {
        for (size_t i = 0; i < m; i++)
            buf[a][i] = raw[i * n / m].p[a];
        sort_floats(buf[a], m, keys[0], keys[1]);
        for (int t = 0; t < N_TRIMS; t++)
            ext[t] = fmax(ext[t], (double)buf[a][m - 1 - cut[t]] -
                                      (double)buf[a][cut[t]]);
    }
    int pick = 2; /* 2%: when the middle half is one point */
    if (ext[N_TRIMS - 1] > 0.0)
        for (pick = 0; pick < N_TRIMS - 1; pick++)
            if (ext[pick] <= spread_max * ext[N_TRIMS - 1])
                break;
    double e = ext[pick] > 0.0 ? ext[pick] : 1.0;
    for (int a = 0; a < 3; a++) {
        lo[a] = fmax(lo[a], (double)buf[a][cut[pick]] - e);
        hi[a] = fmin(hi[a], (double)buf[a][m - 1 - cut[pick]] + e);
    }
}

enum iris_status pstore_build(struct pstore *s, struct pstore_raw *raw,
                              size_t n)
{
    return pstore_build_mt(s, raw, n, 1);
}

/* ---- levels and cells (pstore.h) ---- */

/* Cells of at least this many photons; at most this deep (511 cells,
** 24 kB a level: by 8 levels the kd cuts have bounded every side of the
** cells where photons crowd, so deeper cells would add little). */
#define CELL_MIN 1024
#define CELL_DEPTH_MAX 8

static int cell_depth(size_t n)
{
    int d = 0;
    while (d < CELL_DEPTH_MAX && (n >> (d + 1)) >= CELL_MIN)
        d++;
    return d;
}

/* The level of record 'i'. */
static inline const struct pstore_level *level_of(const struct pstore *s,
                                                  size_t i)
{
    int l = 0;
    while (l + 1 < s->n_levels && i >= s->level[l + 1].begin)
        l++;
    return &s->level[l];
}

/* The heap number of the cell record 'i' (counted from the level's first)
** is quantised over: its own node if it is a median of the top
** lv->depth levels, else its depth-'depth' ancestor. */
static size_t cell_of(const struct pstore_level *lv, size_t i)
{
    size_t node = 1, lo = 0, hi = lv->n;
    for (int d = 0; d < lv->depth; d++) {
        size_t mid = lo + (hi - lo) / 2;
        if (i == mid)
            return node;
        if (i < mid) {
            hi = mid;
            node = 2 * node;
        } else {
            lo = mid + 1;
            node = 2 * node + 1;
        }
    }
    return node;
}

/*
** Fills the cells of node 'node' (depth d, the level's records [lo, hi))
** and below, from the cell [mn, mx]. The median's quantised coordinate
** comes from 'raw' while building (the records are packed after) or from
** the records 'ph' of a loaded map: the same number either way, so a
** loaded map's cells are the built map's. raw, axes and ph start at the
** level's first record.
*/
static void fill_cells(struct pstore_level *lv, const struct pstore_raw *raw,
                       const uint8_t *axes, const struct pstore_photon *ph,
                       size_t node, int d, size_t lo, size_t hi,
                       const double mn[3], const double mx[3])
{
    struct pstore_cell *c = &lv->cells[node];
    for (int a = 0; a < 3; a++) {
        c->lo[a] = mn[a];
        c->step[a] = (mx[a] - mn[a]) / QMAX;
    }
    if (d == lv->depth)
        return;
    double lmx[3] = { mx[0], mx[1], mx[2] };
    double rmn[3] = { mn[0], mn[1], mn[2] };
    size_t mid = lo + (hi - lo) / 2;
    if (hi > lo) {
        unsigned axis = raw ? axes[mid]
                            : (unsigned)((ph[mid].pos >> AXIS_SHIFT) & 3);
        uint64_t q = raw ? quantise(raw[mid].p[axis], c->lo[axis],
                                    c->step[axis])
                         : (ph[mid].pos >> (axis * QBITS)) & QMAX;
        double cut = c->lo[axis] + (double)q * c->step[axis];
        /* one step of slack: the stored cut is the true one rounded */
        lmx[axis] = fmin(mx[axis], cut + c->step[axis]);
        rmn[axis] = fmax(mn[axis], cut - c->step[axis]);
    } else {
        mid = lo; /* empty: both children empty */
    }
    fill_cells(lv, raw, axes, ph, 2 * node, d + 1, lo, mid, mn, lmx);
    fill_cells(lv, raw, axes, ph, 2 * node + 1, d + 1,
               hi > lo ? mid + 1 : lo, hi, rmn, mx);
}

/* Sets lv->depth and lv->cells (lv->begin, n, lo and step set). */
static enum iris_status make_cells(struct pstore_level *lv,
                                   const struct pstore_raw *raw,
                                   const uint8_t *axes,
                                   const struct pstore_photon *ph)
{
    iris_free(lv->cells);
    lv->depth = cell_depth(lv->n);
    lv->cells = iris_malloc(((size_t)2 << lv->depth) * sizeof *lv->cells);
    if (!lv->cells)
        return IRIS_ENOMEM;
    double mn[3], mx[3];
    for (int a = 0; a < 3; a++) {
        mn[a] = lv->lo[a];
        mx[a] = lv->lo[a] + lv->step[a] * QMAX;
    }
    memset(&lv->cells[0], 0, sizeof lv->cells[0]);
    fill_cells(lv, raw, axes, ph, 1, 0, 0, lv->n, mn, mx);
    return IRIS_OK;
}

enum iris_status pstore_index_cells(struct pstore *s)
{
    for (int l = 0; l < s->n_levels; l++) {
        struct pstore_level *lv = &s->level[l];
        if (make_cells(lv, NULL, NULL, s->ph + lv->begin) != IRIS_OK)
            return IRIS_ENOMEM;
    }
    return IRIS_OK;
}

size_t pstore_bytes(const struct pstore *s)
{
    size_t b = s->n * sizeof *s->ph;
    for (int l = 0; l < s->n_levels; l++)
        if (s->level[l].cells)
            b += ((size_t)2 << s->level[l].depth) * sizeof(struct pstore_cell);
    return b;
}

/* The packed record of raw photon 'r' whose kd split axis is 'axis',
** quantised over cell 'c'. */
static struct pstore_photon pack(const struct pstore_cell *c,
                                 const struct pstore_raw *r, unsigned axis)
{
    struct pstore_photon ph;
    ph.pos = quantise(r->p[0], c->lo[0], c->step[0]) |
             quantise(r->p[1], c->lo[1], c->step[1]) << QBITS |
             quantise(r->p[2], c->lo[2], c->step[2]) << (2 * QBITS) |
             (uint64_t)axis << AXIS_SHIFT;
    /* 65535 is reserved for white photons (raw lambda < 0) */
    double lq = (r->lambda - SPEC_LAMBDA_MIN) / SPEC_LAMBDA_RANGE * 65534.0;
    lq = lq < 0.0 ? 0.0 : lq > 65534.0 ? 65534.0 : lq;
    if (r->lambda < 0.0f)
        lq = PSTORE_WHITE;
    ph.power = r->power;
    ph.lambda_q = (uint16_t)lrint(lq);
    ph.dir_q = pstore_encode_dir(v3(r->dir[0], r->dir[1], r->dir[2]));
    return ph;
}

/*
** Packing in parallel. In place, record i (16 bytes at 16i) lands on raw
** record i/2, so the records are packed in waves: [0, PACK_CHUNK) in
** order on one thread, then [L, 2L) for L = PACK_CHUNK, 2·PACK_CHUNK,
** 4·PACK_CHUNK, ..., each wave in chunks on all threads. A wave reads raw
** records [L, 2L) and writes over [L/2, L), which earlier waves have
** read: nothing a thread reads is written during its wave. The packing
** is 5.3 M instructions a pass of bench/caustic_ball.pov (40 000
** photons; callgrind), all of it on one thread before: 1.2% of a pass's
** time on 2 threads.
*/
#define PACK_CHUNK 4096
_Static_assert(sizeof(struct pstore_raw) == 2 * sizeof(struct pstore_photon),
               "in place, record i lands on raw record i/2");

struct pack_job {
    const struct pstore *s;
    struct pstore_raw *raw;
    struct pstore_photon *ph;
    const uint8_t *axes;
    size_t lo, hi;             /* this wave */
};

static void pack_range(const struct pack_job *j, size_t lo, size_t hi)
{
    for (size_t i = lo; i < hi; i++) {
        struct pstore_raw r;
        memcpy(&r, &j->raw[i], sizeof r); /* before ph[i] may cover it */
        const struct pstore_level *lv = level_of(j->s, i);
        j->ph[i] = pack(&lv->cells[cell_of(lv, i - lv->begin)], &r,
                        j->axes[i]);
    }
}

static void pack_chunk(void *ctx, int64_t item, int thread)
{
    (void)thread;
    const struct pack_job *j = ctx;
    size_t lo = j->lo + (size_t)item * PACK_CHUNK;
    pack_range(j, lo, lo + PACK_CHUNK < j->hi ? lo + PACK_CHUNK : j->hi);
}

static void pack_all(const struct pstore *s, struct pstore_raw *raw,
                     struct pstore_photon *ph, const uint8_t *axes,
                     size_t n, int threads)
{
    struct pack_job j = { s, raw, ph, axes, 0, n };
    if (threads <= 1 || n <= 2 * PACK_CHUNK) {
        pack_range(&j, 0, n);
        return;
    }
    pack_range(&j, 0, PACK_CHUNK);
    for (size_t lo = PACK_CHUNK; lo < n; lo = j.hi) {
        j.lo = lo;
        j.hi = 2 * lo < n ? 2 * lo : n;
        par_for(threads, (int64_t)((j.hi - lo + PACK_CHUNK - 1) / PACK_CHUNK),
                pack_chunk, &j);
    }
}

/*
** The build of pstore_build_mt() and pstore_build_in_place(). In place,
** the packed records are written over the raw array itself and the array
** shrunk to them: record i (16 bytes at 16i) only overwrites raw records
** at or below i/2, already packed, and each raw record is copied out
** before its packed one is stored. The peak is then the raw array and
** the axis bytes (33 bytes a photon) instead of both arrays (49).
*/
static enum iris_status build(struct pstore *s, struct pstore_raw *raw,
                              size_t n, int threads, bool in_place)
{
    memset(s, 0, sizeof *s);
    if (n == 0) {
        if (in_place)
            iris_free(raw);
        return IRIS_OK;
    }
    uint8_t *axes = iris_calloc(n, 1);
    struct pstore_photon *ph =
        in_place ? (struct pstore_photon *)(void *)raw
                 : iris_malloc(n * sizeof *ph); /* all written below */
    if (!axes || !ph) {
        iris_free(axes);
        iris_free(in_place ? (void *)raw : (void *)ph);
        return IRIS_ENOMEM;
    }
    /* non-finite positions cannot be placed: left out */
    size_t kept = 0;
    for (size_t i = 0; i < n; i++)
        if (isfinite(raw[i].p[0]) && isfinite(raw[i].p[1]) &&
            isfinite(raw[i].p[2]))
            raw[kept++] = raw[i];
    s->n_dropped = n - kept;
    n = kept;
    s->n = n;
    /* the levels: each the photons inside the box of the bulk of those
    ** left, the last all that remain */
    for (size_t begin = 0; begin < n; s->n_levels++) {
        struct pstore_raw *r = raw + begin;
        size_t m = n - begin, k = 0;
        double mn[3], mx[3];
        robust_box(r, m, mn, mx, s->n_levels == PSTORE_LEVELS - 1);
        /* those inside first (a deterministic partition) */
        for (size_t i = 0, j = m; i < j;) {
            bool in = true;
            for (int a = 0; a < 3; a++)
                in = in && r[i].p[a] >= mn[a] && r[i].p[a] <= mx[a];
            if (in)
                i++, k++;
            else
                swap_raw(r, i, --j);
        }
        if (k == 0) { /* cannot happen (the box holds its quantiles) */
            robust_box(r, m, mn, mx, true);
            k = m;
        }
        struct pstore_level *lv = &s->level[s->n_levels];
        lv->begin = begin;
        lv->n = k;
        for (int a = 0; a < 3; a++) {
            lv->lo[a] = mn[a];
            lv->step[a] = (mx[a] - mn[a]) / QMAX;
        }
        if (threads <= 1 || k < PAR_MIN_PHOTONS ||
            !build_par(r, axes + begin, k, mn, mx, threads))
            build_rec(r, axes + begin, 0, k, mn, mx);
        if (make_cells(lv, r, axes + begin, NULL) != IRIS_OK) {
            iris_free(axes);
            iris_free(in_place ? (void *)raw : (void *)ph);
            pstore_fini(s);
            return IRIS_ENOMEM;
        }
        begin += k;
    }
    if (s->n_levels > 0) {
        memcpy(s->lo, s->level[0].lo, sizeof s->lo);
        memcpy(s->step, s->level[0].step, sizeof s->step);
    }
    pack_all(s, raw, ph, axes, n, threads);
    iris_free(axes);
    if (in_place && n > 0) {
        /* shrinking: glibc returns a large block's tail without copying */
        struct pstore_photon *small = iris_realloc(ph, n * sizeof *ph);
        if (small)
            ph = small; /* else the larger block still holds them */
    } else if (in_place) {
        iris_free(ph);
        ph = NULL;
    }
    s->ph = ph;
    s->n = n;
    return IRIS_OK;
}

enum iris_status pstore_build_mt(struct pstore *s, struct pstore_raw *raw,
                                 size_t n, int threads)
{
    return build(s, raw, n, threads, false);
}

enum iris_status pstore_build_in_place(struct pstore *s,
                                       struct pstore_raw *raw, size_t n,
                                       int threads)
{
    return build(s, raw, n, threads, true);
}

void pstore_fini(struct pstore *s)
{
    iris_free(s->ph);
    for (int l = 0; l < PSTORE_LEVELS; l++)
        iris_free(s->level[l].cells);
    memset(s, 0, sizeof *s);
}

static inline double coord(const struct pstore_cell *c, uint64_t pos, int a)
{
    return c->lo[a] + (double)((pos >> (a * QBITS)) & QMAX) * c->step[a];
}

vec3 pstore_position(const struct pstore *s, size_t i)
{
    uint64_t p = s->ph[i].pos;
    const struct pstore_level *lv = level_of(s, i);
    const struct pstore_cell *c = &lv->cells[cell_of(lv, i - lv->begin)];
    return v3(coord(c, p, 0), coord(c, p, 1), coord(c, p, 2));
}

double pstore_lambda(const struct pstore *s, size_t i)
{
    /* a white photon reports the domain's middle */
    if (s->ph[i].lambda_q == PSTORE_WHITE)
        return SPEC_LAMBDA_MIN + 0.5 * SPEC_LAMBDA_RANGE;
    return SPEC_LAMBDA_MIN + SPEC_LAMBDA_RANGE * s->ph[i].lambda_q / 65534.0;
}

vec3 pstore_direction(const struct pstore *s, size_t i)
{
    return pstore_decode_dir(s->ph[i].dir_q);
}

/* ---- k-nearest search with a bounded max-heap ---- */

/*
** The search is the recursive one (near side first, the far side only
** when its plane is nearer than the k-th photon found so far), written as
** a loop over an explicit stack with the query, the steps and the heap in
** locals: the estimate is most of the eye pass of a caustic scene, and
** the recursion reloaded them through pointers at every node. The far
** side is pushed with its plane's squared distance and tested when
** popped, which is when the recursion tested it, so the nodes are visited
** and the photons pushed in the same order: the same heap, bit for bit.
*/

/* Adds photon 'idx' at squared distance 'd2' (< the current bound) to
** the max-heap h of *n entries (at most k); returns the new bound. */
static inline double heap_add(struct pstore_found *h, int *n, int k,
                              double bound, uint32_t idx, double d2)
{
    if (*n < k) {
        int i = (*n)++;
        while (i > 0 && h[(i - 1) / 2].d2 < d2) {
            h[i] = h[(i - 1) / 2];
            i = (i - 1) / 2;
        }
        h[i].index = idx;
        h[i].d2 = (float)d2;
        return *n == k ? h[0].d2 : bound;
    }
    /* replace the root (the farthest) and sift down */
    int i = 0, m = *n;
    for (;;) {
        int c = 2 * i + 1;
        if (c >= m)
            break;
        c += c + 1 < m && h[c + 1].d2 > h[c].d2;
        if (h[c].d2 <= d2)
            break;
        h[i] = h[c];
        i = c;
    }
    h[i].index = idx;
    h[i].d2 = (float)d2;
    return h[0].d2;
}

/* Squared distance from the query 'q' (relative to the box corner, so a
** coordinate costs one multiply) to the photon packed in 'pos'; d[] gets
** the per-axis differences. */
static inline double pos_d2(uint64_t pos, const double q[3],
                            const double step[3], double d[3])
{
    d[0] = q[0] - (double)(pos & QMAX) * step[0];
    d[1] = q[1] - (double)((pos >> QBITS) & QMAX) * step[1];
    d[2] = q[2] - (double)((pos >> (2 * QBITS)) & QMAX) * step[2];
    return 0.0 + d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

/* Segments this small are scanned whole: cheaper than descending them. */
#define KNN_LEAF 12
/* Deeper than any tree of 2^32 photons. */
#define KNN_STACK 64

#if defined(__GNUC__)
#define KNN_PREFETCH(p) __builtin_prefetch(p)
#else
#define KNN_PREFETCH(p) ((void)(p))
#endif

/* The search (see above); returns the number found in 'h'. The query
** is taken relative to the corner of the cell of the node being visited
** (pstore.h): the cell changes only in the top s->depth levels. */
static double knn_search(const struct pstore *s,
                         const struct pstore_level *lv, const double q[3],
                         int k, double max_d2, struct pstore_found *h,
                         int *n_io)
{
    /* the level's records, indices reported from the store's first */
    const struct pstore_photon *ph = s->ph + lv->begin;
    const uint32_t base = (uint32_t)lv->begin;
    const struct pstore_cell *cells = lv->cells;
    /* nodes below this heap number have children with cells */
    const size_t inner = (size_t)1 << lv->depth;
    struct {
        size_t lo, hi, node, cell;
        double plane_d2;
    } stack[KNN_STACK];
    int sp = 0, n = *n_io;
    stack[sp].lo = 0;
    stack[sp].hi = lv->n;
    stack[sp].node = 1;
    stack[sp].cell = 1;
    stack[sp++].plane_d2 = 0.0;
    while (sp > 0) {
        sp--;
        size_t lo = stack[sp].lo, hi = stack[sp].hi;
        size_t node = stack[sp].node, cell = stack[sp].cell;
        if (!(stack[sp].plane_d2 < max_d2))
            continue;
        const struct pstore_cell *c = &cells[cell];
        double qq[3] = { q[0] - c->lo[0], q[1] - c->lo[1], q[2] - c->lo[2] };
        double step[3] = { c->step[0], c->step[1], c->step[2] };
        while (lo < hi) {
            double d[3];
            if (hi - lo <= KNN_LEAF) {
                /* no cell boundary in here: cells hold >= CELL_MIN */
                for (size_t i = lo; i < hi; i++) {
                    double d2 = pos_d2(ph[i].pos, qq, step, d);
                    if (d2 < max_d2)
                        max_d2 = heap_add(h, &n, k, max_d2,
                                          base + (uint32_t)i, d2);
                }
                break;
            }
            size_t mid = lo + (hi - lo) / 2;
            uint64_t pos = ph[mid].pos;
            double d2 = pos_d2(pos, qq, step, d);
            if (d2 < max_d2)
                max_d2 = heap_add(h, &n, k, max_d2, base + (uint32_t)mid,
                                  d2);
            double da = d[(pos >> AXIS_SHIFT) & 3];
            /* the children's heap numbers while they have cells, else 0 */
            size_t nl = node && node < inner ? 2 * node : 0;
            size_t nr = nl ? nl + 1 : 0;
            size_t near_node = da < 0.0 ? nl : nr;
            size_t far_node = da < 0.0 ? nr : nl;
            /* near side now, the far side later (if sp allows: a
            ** deeper tree than KNN_STACK cannot be built). The far
            ** side's median is fetched into the cache meanwhile: it is
            ** far away in the array, and read first if the side is
            ** searched (+4% to +10% queries a second, measured) */
            if (sp < KNN_STACK) {
                size_t flo = da < 0.0 ? mid + 1 : lo;
                size_t fhi = da < 0.0 ? hi : mid;
                KNN_PREFETCH(&ph[flo + (fhi - flo) / 2]);
                stack[sp].plane_d2 = da * da;
                stack[sp].lo = flo;
                stack[sp].hi = fhi;
                stack[sp].node = far_node;
                stack[sp++].cell = far_node ? far_node : cell;
            }
            if (da < 0.0)
                hi = mid;
            else
                lo = mid + 1;
            node = near_node;
            if (node) {
                /* a child with its own cell: the query relative to it */
                cell = node;
                c = &cells[cell];
                for (int a = 0; a < 3; a++) {
                    qq[a] = q[a] - c->lo[a];
                    step[a] = c->step[a];
                }
            }
        }
    }
    *n_io = n;
    return max_d2;
}

int pstore_knn(const struct pstore *s, vec3 q, int k, double max_d2,
               struct pstore_found *out, double *r2)
{
    *r2 = 0.0;
    if (k <= 0 || s->n == 0)
        return 0;
    if (k > PSTORE_MAX_K)
        k = PSTORE_MAX_K;
    const double qa[3] = { q.x, q.y, q.z };
    int n = 0;
    /* one heap over the levels: each later level's search is bounded by
    ** the k-th distance found so far */
    for (int l = 0; l < s->n_levels; l++)
        max_d2 = knn_search(s, &s->level[l], qa, k, max_d2, out, &n);
    /* the heap's root is its farthest photon */
    *r2 = n > 0 ? out[0].d2 : 0.0;
    return n;
}
