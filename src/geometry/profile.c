/* SPDX-License-Identifier: MIT */
/*
** profile.c: 2-D outlines for lathe, sor, prism and text.
**
** Spline profiles are flattened to straight segments (SEG_STEPS per spline
** segment) with POV-Ray's segment polynomials, keeping the spline's own
** tangent at each end so that normals stay smooth. Which side of each
** segment is outside is decided once here with the even-odd rule, probing
** a point just beside the segment's midpoint. Lathe and sor pieces also
** keep the exact curve they stand for (struct geom_curve): sweep.c
** intersects and inside-tests those curves exactly, as POV-Ray does, and
** uses the pieces only for bounds and to orient normals; so do prisms
** with a linear sweep. Text outlines (and conic prisms) are the pieces
** themselves.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>
#include <string.h>

#include "util/mem.h"

/* Straight pieces per spline segment: the chord of a segment of a smooth
** spline deviates from the curve by about (1/SEG_STEPS)² / 8 of its size,
** 5e-4 for 16 steps (the prism's error; lathe and sor bounds are padded
** by it). */
#define SEG_STEPS 16

/* Segments per run (geom.h): a glyph contour of 100-300 pieces becomes
** 13-38 boxes, of which a ray meets a few. */
#define PROFILE_RUN 8

struct geom_profile *geom_profile_new(int cap)
{
    struct geom_profile *p = iris_calloc(1, sizeof *p);
    if (!p)
        return NULL;
    if (cap < 4)
        cap = 4;
    p->a = iris_calloc((size_t)cap, sizeof *p->a);
    p->b = iris_calloc((size_t)cap, sizeof *p->b);
    p->ta = iris_calloc((size_t)cap, sizeof *p->ta);
    p->tb = iris_calloc((size_t)cap, sizeof *p->tb);
    p->side = iris_calloc((size_t)cap, 1);
    p->curve = iris_calloc((size_t)cap, sizeof *p->curve);
    p->cs0 = iris_calloc((size_t)cap, sizeof *p->cs0);
    p->cs1 = iris_calloc((size_t)cap, sizeof *p->cs1);
    p->cap = cap;
    if (!p->a || !p->b || !p->ta || !p->tb || !p->side || !p->curve ||
        !p->cs0 || !p->cs1) {
        geom_profile_free(p);
        return NULL;
    }
    return p;
}

void geom_profile_free(struct geom_profile *p)
{
    if (!p)
        return;
    iris_free(p->a);
    iris_free(p->b);
    iris_free(p->ta);
    iris_free(p->tb);
    iris_free(p->side);
    iris_free(p->curve);
    iris_free(p->cs0);
    iris_free(p->cs1);
    iris_free(p->curves);
    iris_free(p->group_first);
    iris_free(p->group_count);
    iris_free(p->group_lo);
    iris_free(p->group_hi);
    iris_free(p->run_first);
    iris_free(p->group_run);
    iris_free(p->run_lo);
    iris_free(p->run_hi);
    iris_free(p->group_closed);
    for (int k = 0; k < 3; k++) {
        iris_free(p->par_lo[k]);
        iris_free(p->par_hi[k]);
    }
    iris_free(p);
}

static bool grow(void **ptr, size_t n, size_t size)
{
    void *q = iris_realloc(*ptr, n * size);
    if (!q)
        return false;
    *ptr = q;
    return true;
}

bool geom_profile_add_curved(struct geom_profile *p, iris_vec2 a, iris_vec2 b,
                             iris_vec2 ta, iris_vec2 tb)
{
    if (!isfinite(a.u) || !isfinite(a.v) || !isfinite(b.u) || !isfinite(b.v))
        return true;
    if (a.u == b.u && a.v == b.v)
        return true; /* a zero-length segment bounds nothing */
    if (p->n_seg == p->cap) {
        size_t cap = (size_t)p->cap * 2;
        if (!grow((void **)&p->a, cap, sizeof *p->a) ||
            !grow((void **)&p->b, cap, sizeof *p->b) ||
            !grow((void **)&p->ta, cap, sizeof *p->ta) ||
            !grow((void **)&p->tb, cap, sizeof *p->tb) ||
            !grow((void **)&p->side, cap, 1) ||
            !grow((void **)&p->curve, cap, sizeof *p->curve) ||
            !grow((void **)&p->cs0, cap, sizeof *p->cs0) ||
            !grow((void **)&p->cs1, cap, sizeof *p->cs1))
            return false;
        p->cap = (int)cap;
    }
    p->a[p->n_seg] = a;
    p->b[p->n_seg] = b;
    p->ta[p->n_seg] = ta;
    p->tb[p->n_seg] = tb;
    p->curve[p->n_seg] = -1;
    p->cs0[p->n_seg] = p->cs1[p->n_seg] = 0;
    p->n_seg++;
    return true;
}

/* Adds curve 'c' to 'p'; returns its index, or -1 out of memory. */
static int add_curve(struct geom_profile *p, const struct geom_curve *c)
{
    if (p->n_curves == p->cap_curves) {
        size_t cap = p->cap_curves ? (size_t)p->cap_curves * 2 : 8;
        if (!grow((void **)&p->curves, cap, sizeof *p->curves))
            return -1;
        p->cap_curves = (int)cap;
    }
    p->curves[p->n_curves] = *c;
    return p->n_curves++;
}

/* Adds the straight piece a..b standing in for curve 'ci' over its
** parameters s0..s1. */
static bool add_piece(struct geom_profile *p, iris_vec2 a, iris_vec2 b,
                      iris_vec2 ta, iris_vec2 tb, int ci, double s0,
                      double s1)
{
    int had = p->n_seg;
    if (!geom_profile_add_curved(p, a, b, ta, tb))
        return false;
    if (p->n_seg > had) {
        p->curve[had] = ci;
        p->cs0[had] = s0;
        p->cs1[had] = s1;
    }
    return true;
}

bool geom_profile_add(struct geom_profile *p, iris_vec2 a, iris_vec2 b)
{
    iris_vec2 t = { b.u - a.u, b.v - a.v };
    return geom_profile_add_curved(p, a, b, t, t);
}

bool geom_profile_close_group(struct geom_profile *p)
{
    int first = 0;
    if (p->n_groups > 0)
        first = p->group_first[p->n_groups - 1] +
                p->group_count[p->n_groups - 1];
    if (first == p->n_seg)
        return true;
    size_t n = (size_t)p->n_groups + 1;
    if (!grow((void **)&p->group_first, n, sizeof(int)) ||
        !grow((void **)&p->group_count, n, sizeof(int)) ||
        !grow((void **)&p->group_lo, n, sizeof(iris_vec2)) ||
        !grow((void **)&p->group_hi, n, sizeof(iris_vec2)))
        return false;
    p->group_first[p->n_groups] = first;
    p->group_count[p->n_groups] = p->n_seg - first;
    p->n_groups++;
    return true;
}

/* Parity of the crossings of the +u ray from (u, v) with segments
** i .. end-1. */
static int run_parity(const struct geom_profile *p, int i, int end,
                      double u, double v)
{
    int parity = 0;
    for (; i < end; i++) {
        iris_vec2 a = p->a[i], b = p->b[i];
        if ((a.v > v) == (b.v > v))
            continue;
        double x = a.u + (v - a.v) * (b.u - a.u) / (b.v - a.v);
        parity ^= x > u;
    }
    return parity;
}

bool geom_profile_inside2d(const struct geom_profile *p, double u, double v)
{
    int parity = 0;
    for (int g = 0; g < p->n_groups; g++) {
        /* The +u ray from (u, v) meets no segment of a group it misses */
        if (v < p->group_lo[g].v || v > p->group_hi[g].v ||
            u > p->group_hi[g].u)
            continue;
        if (!p->n_runs) {
            parity ^= run_parity(p, p->group_first[g],
                                 p->group_first[g] + p->group_count[g], u, v);
            continue;
        }
        /* A closed chain wholly right of u (by more than run_pad, so
        ** that every crossing computes right of u): the +u ray enters
        ** and leaves it, an even count, whatever v. Its ends' "above
        ** v" tests change an even number of times around the chain, and
        ** run_parity counts exactly those changes. */
        if (p->group_closed[g] && u < p->group_lo[g].u - p->run_pad)
            continue;
        /* nor any segment of a run it misses: below or above the run a
        ** segment's ends are both above or both below v (skipped by
        ** the test in run_parity exactly); right of it (widened by
        ** run_pad) every crossing lies left of u */
        for (int k = p->group_run[g]; k < p->group_run[g + 1]; k++)
            if (!(v < p->run_lo[k].v || v > p->run_hi[k].v ||
                  u > p->run_hi[k].u + p->run_pad))
                parity ^= run_parity(p, p->run_first[k],
                                     p->run_first[k + 1], u, v);
    }
    return parity;
}

/* The box of segments f..e-1 (both ends of each): a run's or a group's. */
static void segments_box(const struct geom_profile *p, int f, int e,
                         iris_vec2 *lo_out, iris_vec2 *hi_out)
{
    iris_vec2 lo = p->a[f], hi = p->a[f];
    for (int i = f; i < e; i++) {
        lo.u = fmin(lo.u, fmin(p->a[i].u, p->b[i].u));
        lo.v = fmin(lo.v, fmin(p->a[i].v, p->b[i].v));
        hi.u = fmax(hi.u, fmax(p->a[i].u, p->b[i].u));
        hi.v = fmax(hi.v, fmax(p->a[i].v, p->b[i].v));
    }
    *lo_out = lo;
    *hi_out = hi;
}

/* Drops the runs (the segments are then visited one by one). */
static void free_runs(struct geom_profile *p)
{
    iris_free(p->run_first);
    iris_free(p->group_run);
    iris_free(p->run_lo);
    iris_free(p->run_hi);
    iris_free(p->group_closed);
    p->run_first = p->group_run = NULL;
    p->run_lo = p->run_hi = NULL;
    p->group_closed = NULL;
    p->n_runs = 0;
}

/* The runs of geom.h over the finished groups; none when out of memory
** (the tests then visit every segment, as before). */
static void build_runs(struct geom_profile *p)
{
    free_runs(p);
    int n = 0;
    for (int g = 0; g < p->n_groups; g++)
        n += (p->group_count[g] + PROFILE_RUN - 1) / PROFILE_RUN;
    if (n == 0)
        return;
    p->run_first = iris_malloc(((size_t)n + 1) * sizeof *p->run_first);
    p->group_run = iris_malloc(((size_t)p->n_groups + 1) *
                               sizeof *p->group_run);
    p->run_lo = iris_malloc((size_t)n * sizeof *p->run_lo);
    p->run_hi = iris_malloc((size_t)n * sizeof *p->run_hi);
    p->group_closed = iris_malloc((size_t)p->n_groups);
    if (!p->run_first || !p->group_run || !p->run_lo || !p->run_hi ||
        !p->group_closed) {
        free_runs(p);
        return;
    }
    int k = 0;
    for (int g = 0; g < p->n_groups; g++) {
        p->group_run[g] = k;
        int end = p->group_first[g] + p->group_count[g];
        bool closed = p->b[end - 1].u == p->a[p->group_first[g]].u &&
                      p->b[end - 1].v == p->a[p->group_first[g]].v;
        for (int i = p->group_first[g]; i + 1 < end && closed; i++)
            closed = p->b[i].u == p->a[i + 1].u && p->b[i].v == p->a[i + 1].v;
        p->group_closed[g] = closed;
        for (int f = p->group_first[g]; f < end; f += PROFILE_RUN, k++) {
            int e = f + PROFILE_RUN < end ? f + PROFILE_RUN : end;
            iris_vec2 lo, hi;
            segments_box(p, f, e, &lo, &hi);
            p->run_first[k] = f;
            p->run_lo[k] = lo;
            p->run_hi[k] = hi;
        }
    }
    p->group_run[p->n_groups] = k;
    p->run_first[k] = p->n_seg;
    p->run_pad = 1e-9 * (p->hi.u - p->lo.u + p->hi.v - p->lo.v);
    p->n_runs = k;
}

void geom_profile_finish(struct geom_profile *p)
{
    geom_profile_close_group(p);
    bool have = false;
    for (int g = 0; g < p->n_groups; g++) {
        int f = p->group_first[g], end = f + p->group_count[g];
        iris_vec2 lo, hi;
        segments_box(p, f, end, &lo, &hi);
        p->group_lo[g] = lo;
        p->group_hi[g] = hi;
        geom_box2_add(&p->lo, &p->hi, &have, lo, hi);
    }
    build_runs(p);
    /* Each curve's pieces and their extent, for the ray's quick tests */
    for (int i = 0; i < p->n_seg; i++) {
        if (p->curve[i] < 0)
            continue;
        struct geom_curve *c = &p->curves[p->curve[i]];
        double vlo = fmin(p->a[i].v, p->b[i].v);
        double vhi = fmax(p->a[i].v, p->b[i].v);
        double um = fmax(fabs(p->a[i].u), fabs(p->b[i].u));
        if (c->n == 0) {
            c->first = i;
            c->vlo = vlo;
            c->vhi = vhi;
            c->umax = um;
        }
        c->n = i + 1 - c->first;
        c->vlo = fmin(c->vlo, vlo);
        c->vhi = fmax(c->vhi, vhi);
        c->umax = fmax(c->umax, um);
    }
    /* Outward side: probe beside each midpoint, 1e-7 of the segment length
    ** away (far below any feature, far above rounding) */
    for (int i = 0; i < p->n_seg; i++) {
        iris_vec2 a = p->a[i], b = p->b[i];
        double du = b.u - a.u, dv = b.v - a.v;
        double mu = 0.5 * (a.u + b.u), mv = 0.5 * (a.v + b.v);
        /* Right of a->b is (dv, -du) */
        bool right_in = geom_profile_inside2d(p, mu + 1e-7 * dv,
                                              mv - 1e-7 * du);
        p->side[i] = right_in ? -1 : 1;
    }
}

/* Point s in [0,1] of POV-Ray's segment polynomial A s³ + B s² + C s + D,
** and its derivative. */
static void seg_eval(const iris_vec2 c[4], double s, iris_vec2 *pt,
                     iris_vec2 *tan)
{
    pt->u = ((c[0].u * s + c[1].u) * s + c[2].u) * s + c[3].u;
    pt->v = ((c[0].v * s + c[1].v) * s + c[2].v) * s + c[3].v;
    tan->u = (3 * c[0].u * s + 2 * c[1].u) * s + c[2].u;
    tan->v = (3 * c[0].v * s + 2 * c[1].v) * s + c[2].v;
}

/* Coefficients of spline segment 'i' of 'pts' (POV-Ray's lathe.cpp). */
static void seg_coeffs(enum iris_spline sp, const iris_vec2 *P, int i,
                       iris_vec2 c[4])
{
#define LIN(k, w0, w1, w2, w3)                                              \
    c[k].u = (w0) * P[i].u + (w1) * P[i + 1].u + (w2) * P[i + 2].u +         \
             (w3) * P[i + 3].u;                                             \
    c[k].v = (w0) * P[i].v + (w1) * P[i + 1].v + (w2) * P[i + 2].v +         \
             (w3) * P[i + 3].v
    switch (sp) {
    case IRIS_SPLINE_QUADRATIC:
        c[0].u = c[0].v = 0;
        c[1].u = 0.5 * P[i].u - P[i + 1].u + 0.5 * P[i + 2].u;
        c[1].v = 0.5 * P[i].v - P[i + 1].v + 0.5 * P[i + 2].v;
        c[2].u = -0.5 * P[i].u + 0.5 * P[i + 2].u;
        c[2].v = -0.5 * P[i].v + 0.5 * P[i + 2].v;
        c[3] = P[i + 1];
        break;
    case IRIS_SPLINE_CUBIC:
        LIN(0, -0.5, 1.5, -1.5, 0.5);
        LIN(1, 1.0, -2.5, 2.0, -0.5);
        LIN(2, -0.5, 0, 0.5, 0);
        c[3] = P[i + 1];
        break;
    case IRIS_SPLINE_BEZIER:
        LIN(0, -1, 3, -3, 1);
        LIN(1, 3, -6, 3, 0);
        LIN(2, -3, 3, 0, 0);
        c[3] = P[i];
        break;
    default:
        c[0].u = c[0].v = c[1].u = c[1].v = 0;
        c[2].u = P[i + 1].u - P[i].u;
        c[2].v = P[i + 1].v - P[i].v;
        c[3] = P[i];
        break;
    }
#undef LIN
}

/* Number of segments and the index step of spline 'sp' over 'n' points. */
static int seg_count(enum iris_spline sp, int n, int *step)
{
    *step = 1;
    switch (sp) {
    case IRIS_SPLINE_QUADRATIC: return n - 2;
    case IRIS_SPLINE_CUBIC: return n - 3;
    case IRIS_SPLINE_BEZIER: *step = 4; return n / 4;
    default: return n - 1;
    }
}

/* The Bezier control points of the cubic c[0] s³ + c[1] s² + c[2] s +
** c[3] of 'cv' (equal powers of s in both forms) and their extent. */
static void bezier_points(struct geom_curve *cv)
{
    const iris_vec2 *c = cv->c;
    iris_vec2 *b = cv->bz;
    b[0] = c[3];
    b[1].u = c[3].u + c[2].u / 3;
    b[1].v = c[3].v + c[2].v / 3;
    b[2].u = c[3].u + 2 * c[2].u / 3 + c[1].u / 3;
    b[2].v = c[3].v + 2 * c[2].v / 3 + c[1].v / 3;
    b[3].u = c[0].u + c[1].u + c[2].u + c[3].u;
    b[3].v = c[0].v + c[1].v + c[2].v + c[3].v;
    cv->ext = 0;
    for (int k = 0; k < 4; k++)
        cv->ext = fmax(cv->ext, fmax(fabs(b[k].u), fabs(b[k].v)));
}

/* Adds spline segment 'i' of 'P': its exact curve (not for linear
** splines) and the chords that bound it. */
static bool add_segment(struct geom_profile *p, enum iris_spline sp,
                        const iris_vec2 *P, int i)
{
    iris_vec2 c[4], a, ta;
    seg_coeffs(sp, P, i, c);
    int steps = sp == IRIS_SPLINE_LINEAR ? 1 : SEG_STEPS;
    int ci = -1;
    if (sp != IRIS_SPLINE_LINEAR) {
        struct geom_curve cv = { .kind = GEOM_CURVE_POLY };
        memcpy(cv.c, c, sizeof cv.c);
        bezier_points(&cv);
        if ((ci = add_curve(p, &cv)) < 0)
            return false;
    }
    seg_eval(c, 0, &a, &ta);
    for (int j = 1; j <= steps; j++) {
        iris_vec2 b, tb;
        seg_eval(c, (double)j / steps, &b, &tb);
        if (!add_piece(p, a, b, ta, tb, ci, (double)(j - 1) / steps,
                       (double)j / steps))
            return false;
        a = b;
        ta = tb;
    }
    return true;
}

/* Adds the spline through 'pts' to 'p', segment by segment. */
static bool add_spline(struct geom_profile *p, enum iris_spline sp,
                       const iris_vec2 *pts, int n)
{
    int step, ns = seg_count(sp, n, &step);
    for (int k = 0; k < ns; k++)
        if (!add_segment(p, sp, pts, k * step))
            return false;
    return true;
}

/*
** sor: r² is a cubic in y on each segment between points i+1 and i+2,
** matching r² and its slope (from the neighbours) at both ends; the first
** and last points only steer the slopes (POV-Ray's sor.cpp). Flattened
** like the splines, and closed with caps unless 'open'.
*/
static bool add_sor(struct geom_profile *p, const iris_object *o)
{
    const iris_vec2 *P = o->u.lathe.points;
    int n = o->u.lathe.n_points;
    for (int i = 0; i + 3 < n; i++) {
        double y1 = P[i + 1].v, y2 = P[i + 2].v;
        if (!(y2 > y1) || !(P[i + 2].v > P[i].v) ||
            !(P[i + 3].v > P[i + 1].v))
            return false;
        double k0 = P[i + 1].u * P[i + 1].u, k1 = P[i + 2].u * P[i + 2].u;
        double s0 = 2 * P[i + 1].u * (P[i + 2].u - P[i].u) /
                    (P[i + 2].v - P[i].v);
        double s1 = 2 * P[i + 2].u * (P[i + 3].u - P[i + 1].u) /
                    (P[i + 3].v - P[i + 1].v);
        /* Hermite cubic in h = (y - y1)/(y2 - y1) */
        double dy = y2 - y1;
        /* The same cubic by powers of h, for the exact crossing */
        struct geom_curve cv = { .kind = GEOM_CURVE_SOR, .y0 = y1, .dy = dy };
        cv.c[0].u = 2 * k0 + dy * s0 - 2 * k1 + dy * s1;
        cv.c[1].u = -3 * k0 - 2 * dy * s0 + 3 * k1 - dy * s1;
        cv.c[2].u = dy * s0;
        cv.c[3].u = k0;
        int ci = add_curve(p, &cv);
        if (ci < 0)
            return false;
        iris_vec2 prev = { 0, 0 }, prev_t = { 0, 0 };
        for (int j = 0; j <= SEG_STEPS; j++) {
            double h = (double)j / SEG_STEPS;
            double h2 = h * h, h3 = h2 * h;
            double f = (2 * h3 - 3 * h2 + 1) * k0 + (h3 - 2 * h2 + h) * dy * s0 +
                       (-2 * h3 + 3 * h2) * k1 + (h3 - h2) * dy * s1;
            double df = ((6 * h2 - 6 * h) * k0 + (3 * h2 - 4 * h + 1) * dy * s0 +
                         (-6 * h2 + 6 * h) * k1 + (3 * h2 - 2 * h) * dy * s1) /
                        dy;
            double r = sqrt(fmax(0, f));
            iris_vec2 pt = { r, y1 + h * dy };
            /* d r / d y = f' / (2 r); tangent (dr/dy, 1) */
            iris_vec2 tn = { r > 0 ? df / (2 * r) : 0, 1 };
            if (j > 0 && !add_piece(p, prev, pt, prev_t, tn, ci,
                                    (double)(j - 1) / SEG_STEPS, h))
                return false;
            prev = pt;
            prev_t = tn;
        }
    }
    if (!o->open && n >= 4) {
        iris_vec2 b0 = { 0, P[1].v }, b1 = { P[1].u, P[1].v };
        iris_vec2 c0 = { P[n - 2].u, P[n - 2].v }, c1 = { 0, P[n - 2].v };
        if (!geom_profile_add(p, b0, b1) || !geom_profile_add(p, c0, c1))
            return false;
    }
    return true;
}

/* Whether two profile points coincide (POV-Ray's EPSILON, 1e-10). */
static bool same_point(iris_vec2 a, iris_vec2 b)
{
    return fabs(a.u - b.u) < 1e-10 && fabs(a.v - b.v) < 1e-10;
}


/*
** prism: POV-Ray's walk over the points (prism.cpp Compute_Prism). A
** sub-polygon ends when a segment reaches its first point (P[0] of the
** linear spline, the first non-control point P[1] of the quadratic and
** cubic ones); the points that follow start the next one, after skipping
** the closing control points. Bezier segments take four points each.
*/
static bool add_prism(struct geom_profile *p, const iris_object *o)
{
    const iris_vec2 *P = o->u.prism.points;
    int n = o->u.prism.n_points;
    enum iris_spline sp = o->u.prism.spline;
    /* Points a segment needs beyond its first index */
    int need = sp == IRIS_SPLINE_LINEAR ? 1 : sp == IRIS_SPLINE_QUADRATIC ? 2
                                                                          : 3;
    iris_vec2 first = sp == IRIS_SPLINE_LINEAR || sp == IRIS_SPLINE_BEZIER
                          ? P[0] : P[1];
    bool closed = false;
    for (int i = 0; i < n - 1 && i + need < n; i++) {
        if (!add_segment(p, sp, P, i))
            return false;
        closed = false;
        switch (sp) {
        case IRIS_SPLINE_LINEAR:
            if (same_point(P[i + 1], first)) {
                i++;
                if (i + 1 < n)
                    first = P[i + 1];
                closed = true;
            }
            break;
        case IRIS_SPLINE_QUADRATIC:
        case IRIS_SPLINE_CUBIC:
            if (same_point(P[i + 2], first)) {
                i += sp == IRIS_SPLINE_QUADRATIC ? 2 : 3;
                if (i + 2 < n)
                    first = P[i + 2];
                closed = true;
            }
            break;
        case IRIS_SPLINE_BEZIER:
            i += 3;
            closed = true;
            break;
        }
        if (closed && sp != IRIS_SPLINE_BEZIER &&
            !geom_profile_close_group(p))
            return false;
    }
    /* POV-Ray closes an open linear prism with a last segment */
    if (!closed && sp == IRIS_SPLINE_LINEAR) {
        int g_first = 0;
        if (p->n_groups > 0)
            g_first = p->group_first[p->n_groups - 1] +
                      p->group_count[p->n_groups - 1];
        if (g_first < p->n_seg &&
            !geom_profile_add(p, p->b[p->n_seg - 1], p->a[g_first]))
            return false;
    }
    return geom_profile_close_group(p);
}

/* The outline of a prism, lathe, sor or text object (geom_prepare()
** without the bound); NULL for other kinds, and on failure with '*why'. */
static struct geom_profile *prepare_outline(const iris_object *o,
                                            const char **why)
{
    *why = NULL;
    struct geom_profile *p = NULL;
    bool ok = true;
    switch (o->kind) {
    case IRIS_OBJ_LATHE:
        if (o->u.lathe.n_points < 2 || !o->u.lathe.points) {
            *why = "lathe has fewer than 2 points";
            return NULL;
        }
        p = geom_profile_new(o->u.lathe.n_points * SEG_STEPS);
        ok = p && add_spline(p, o->u.lathe.spline, o->u.lathe.points,
                             o->u.lathe.n_points);
        break;
    case IRIS_OBJ_SOR:
        if (o->u.lathe.n_points < 4 || !o->u.lathe.points) {
            *why = "sor has fewer than 4 points";
            return NULL;
        }
        p = geom_profile_new(o->u.lathe.n_points * SEG_STEPS);
        if (p && !add_sor(p, o)) {
            geom_profile_free(p);
            *why = "sor heights must increase";
            return NULL;
        }
        break;
    case IRIS_OBJ_PRISM:
        if (o->u.prism.n_points < 3 || !o->u.prism.points) {
            *why = "prism has fewer than 3 points";
            return NULL;
        }
        p = geom_profile_new(o->u.prism.n_points * SEG_STEPS);
        ok = p && add_prism(p, o);
        if (p) {
            p->h1 = fmin(o->u.prism.height1, o->u.prism.height2);
            p->h2 = fmax(o->u.prism.height1, o->u.prism.height2);
            p->conic = o->u.prism.sweep == 1;
            p->open = o->open;
        }
        break;
    case IRIS_OBJ_TEXT:
        return geom_text_profile(o, why);
    case IRIS_OBJ_PARAMETRIC:
        /* no outline: the bounds of its 'precompute' */
        if (o->u.parametric.precompute_depth <= 0 ||
            !o->u.parametric.precompute_axes)
            return NULL;
        if ((*why = geom_parametric_check(o)) != NULL)
            return NULL;
        p = iris_calloc(1, sizeof *p);
        if (!p || !geom_parametric_precompute(o, p)) {
            geom_profile_free(p);
            *why = "out of memory";
            return NULL;
        }
        return p;
    default:
        return NULL;
    }
    if (!p || !ok) {
        geom_profile_free(p);
        *why = "out of memory";
        return NULL;
    }
    geom_profile_finish(p);
    if (p->n_seg == 0) {
        geom_profile_free(p);
        *why = "the outline is empty";
        return NULL;
    }
    return p;
}

struct geom_profile *geom_prepare(const iris_object *o, const char **why)
{
    struct geom_profile *p = prepare_outline(o, why);
    if (*why || !o->bounded_by || !geom_is_analytic(o->kind))
        return p;
    if (!p) {
        /* A shape without an outline gets an empty profile for the
        ** bound; checked first, as callers check a shape without one */
        if ((*why = geom_validate(o)) != NULL)
            return NULL;
        p = iris_calloc(1, sizeof *p);
        if (!p) {
            *why = "out of memory";
            return NULL;
        }
    }
    geom_bound_prepare(o, p);
    return p;
}
