/* SPDX-License-Identifier: MIT */
/*
** blob.c: POV-Ray blobs with sphere and cylinder components.
**
** Each component adds strength·(1 - r²/R²)² where r < R; r is the distance
** to the centre (sphere) or to the axis segment (cylinder, whose ends are
** hemispheres, as in POV-Ray). Along a ray r² is quadratic in t, so every
** component contributes a quartic on the interval where the ray is within
** its radius (for cylinders: three intervals, the two end hemispheres and
** the side). Between consecutive interval ends the field is one quartic,
** and its crossings of the threshold are solved exactly with roots.c,
** as POV-Ray does.
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/roots.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "math/transform.h"
#include "util/mem.h"

/* A quartic piece of the field, valid for ta < t < tb. */
struct piece {
    double ta, tb;
    double c[5];
};

/* Pieces a ray keeps without allocating (the list and the sweep's
** arrays in geom_blob_hits_in_box) */
#define INLINE_PIECES 32

struct piece_list {
    struct piece *v;
    int n, cap;
    struct piece inline_buf[INLINE_PIECES];
};

static void add_piece(struct piece_list *l, double ta, double tb,
                      const double c[5])
{
    if (!(ta < tb))
        return;
    if (l->n == l->cap) {
        int cap = l->cap * 2;
        struct piece *nv = iris_malloc((size_t)cap * sizeof *nv);
        if (!nv)
            return;
        memcpy(nv, l->v, (size_t)l->n * sizeof *nv);
        if (l->v != l->inline_buf)
            iris_free(l->v);
        l->v = nv;
        l->cap = cap;
    }
    struct piece *p = &l->v[l->n++];
    p->ta = ta;
    p->tb = tb;
    memcpy(p->c, c, sizeof p->c);
}

/*
** Adds s·(1 - q(t)/R²)² for q(t) = qa·t² + qb·t + qc where q < R² and
** lo < t < hi.
*/
static void add_quartic(struct piece_list *l, double qa, double qb, double qc,
                        double R, double s, double lo, double hi)
{
    double R2 = R * R;
    /* Where q(t) < R²: between the roots of qa t² + qb t + (qc - R²) */
    double A = qa, B = qb, C = qc - R2;
    double ta, tb;
    if (A > 0) {
        double disc = B * B - 4 * A * C;
        if (disc <= 0)
            return;
        double q = -0.5 * (B + copysign(sqrt(disc), B));
        double r0 = q / A, r1 = q != 0 ? C / q : r0;
        ta = fmin(r0, r1);
        tb = fmax(r0, r1);
    } else {
        /* Ray parallel to a cylinder's axis: q is constant */
        if (C >= 0)
            return;
        ta = -INFINITY;
        tb = INFINITY;
    }
    ta = fmax(ta, lo);
    tb = fmin(tb, hi);
    if (!(ta < tb))
        return;
    /* w = 1 - q/R² = w2 t² + w1 t + w0; field = s·w² */
    double w2 = -qa / R2, w1 = -qb / R2, w0 = 1 - qc / R2;
    double c[5] = { s * w0 * w0, s * 2 * w0 * w1, s * (w1 * w1 + 2 * w0 * w2),
                    s * 2 * w1 * w2, s * w2 * w2 };
    add_piece(l, ta, tb, c);
}

/* Component-space ray of component 'bc'. */
static void comp_ray(const iris_blob_component *bc, vec3 ro, vec3 rd,
                     vec3 *o, vec3 *d)
{
    if (bc->has_transform) {
        *o = xf_inv_point(&bc->transform, ro);
        *d = xf_inv_dir(&bc->transform, rd);
    } else {
        *o = ro;
        *d = rd;
    }
}

/* Adds the pieces of one component for the ray o + t·d. */
static void component_pieces(const iris_blob_component *bc, vec3 o, vec3 d,
                             double lo, double hi, struct piece_list *l)
{
    double R = bc->radius, s = bc->strength;
    if (!(R > 0) || s == 0)
        return;
    if (bc->kind == 0) {
        vec3 oc = v3_sub(o, bc->a);
        add_quartic(l, v3_len2(d), 2 * v3_dot(oc, d), v3_len2(oc), R, s, lo,
                    hi);
        return;
    }
    vec3 ax = v3_sub(bc->b, bc->a);
    double len = v3_len(ax);
    if (!(len > 0)) {
        vec3 oc = v3_sub(o, bc->a);
        add_quartic(l, v3_len2(d), 2 * v3_dot(oc, d), v3_len2(oc), R, s, lo,
                    hi);
        return;
    }
    vec3 w = v3_scale(ax, 1.0 / len);
    /* h(t) = (o - a)·w + t·d·w: the axial coordinate */
    vec3 oa = v3_sub(o, bc->a);
    double h0 = v3_dot(oa, w), h1 = v3_dot(d, w);
    double ta, tb; /* where 0 <= h <= len */
    if (h1 != 0) {
        double x = -h0 / h1, y = (len - h0) / h1;
        ta = fmin(x, y);
        tb = fmax(x, y);
    } else if (h0 >= 0 && h0 <= len) {
        ta = -INFINITY;
        tb = INFINITY;
    } else {
        ta = tb = h0 < 0 ? INFINITY : -INFINITY;
    }
    /* Side: r² = |oa + t d|² - h(t)² */
    double qa = v3_len2(d) - h1 * h1, qb = 2 * (v3_dot(oa, d) - h0 * h1);
    double qc = v3_len2(oa) - h0 * h0;
    if (ta < tb)
        add_quartic(l, qa, qb, qc, R, s, fmax(lo, ta), fmin(hi, tb));
    /* End hemispheres: the base one where h < 0, the cap one where h > len */
    vec3 ob = v3_sub(o, bc->b);
    double base_lo = lo, base_hi = hi, cap_lo = lo, cap_hi = hi;
    if (h1 > 0) {
        base_hi = fmin(hi, ta);
        cap_lo = fmax(lo, tb);
    } else if (h1 < 0) {
        base_lo = fmax(lo, tb);
        cap_hi = fmin(hi, ta);
    } else {
        if (h0 >= 0)
            base_hi = -INFINITY;
        if (h0 <= len)
            cap_hi = -INFINITY;
    }
    add_quartic(l, v3_len2(d), 2 * v3_dot(oa, d), v3_len2(oa), R, s, base_lo,
                base_hi);
    add_quartic(l, v3_len2(d), 2 * v3_dot(ob, d), v3_len2(ob), R, s, cap_lo,
                cap_hi);
}

/* Field of one component at component-space point 'p', and its gradient. */
static double comp_field(const iris_blob_component *bc, vec3 p, vec3 *g)
{
    double R = bc->radius;
    vec3 c = bc->a;
    if (bc->kind == 1) {
        vec3 ax = v3_sub(bc->b, bc->a);
        double l2 = v3_len2(ax);
        double h = l2 > 0 ? v3_dot(v3_sub(p, bc->a), ax) / l2 : 0;
        h = fmax(0, fmin(1, h));
        c = v3_madd(bc->a, ax, h);
    }
    vec3 dp = v3_sub(p, c);
    double r2 = v3_len2(dp);
    *g = v3(0, 0, 0);
    if (!(R > 0) || r2 >= R * R)
        return 0;
    double w = 1 - r2 / (R * R);
    /* d/dp s·w² = s·2w·(-2/R²)·dp */
    *g = v3_scale(dp, -4 * bc->strength * w / (R * R));
    return bc->strength * w * w;
}

/*
** Density and its gradient in blob space; '*part' (when not NULL) gets
** the component whose field is largest there (its texture is the one a
** hit shows: POV-Ray blends the component textures by field, which a
** single texture per hit can only approximate by the dominant one).
*/
static double density_grad(const iris_object *o, vec3 p, vec3 *grad,
                           int *part)
{
    double f = 0, best = 0;
    vec3 g = v3(0, 0, 0);
    if (part)
        *part = -1;
    for (int i = 0; i < o->u.blob.n_components; i++) {
        const iris_blob_component *bc = &o->u.blob.components[i];
        vec3 q = bc->has_transform ? xf_inv_point(&bc->transform, p) : p;
        vec3 gi;
        double fi = comp_field(bc, q, &gi);
        f += fi;
        if (part && fi > best) {
            best = fi;
            *part = i;
        }
        if (bc->has_transform)
            gi = xf_normal(&bc->transform, gi);
        g = v3_add(g, gi);
    }
    *grad = g;
    return f;
}

double geom_blob_density(const iris_object *o, vec3 p)
{
    vec3 g;
    return density_grad(o, p, &g, NULL);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

static int cmp_piece(const void *a, const void *b)
{
    return cmp_double(&((const struct piece *)a)->ta,
                      &((const struct piece *)b)->ta);
}

/*
** Stable insertion sorts for the few pieces of a ray (three at most per
** component): qsort's comparison calls and merge passes were 8 % of a
** blob scene (185). glibc 2.36's qsort is a merge sort, stable too, so
** pieces with equal starts keep their order and the sums below stay the
** same to the bit; longer lists (from SMALL_SORT) still go to qsort.
*/
#define SMALL_SORT 64

static void sort_doubles(double *v, int n)
{
    if (n > SMALL_SORT) {
        qsort(v, (size_t)n, sizeof *v, cmp_double);
        return;
    }
    for (int i = 1; i < n; i++) {
        double x = v[i];
        int j = i;
        for (; j > 0 && v[j - 1] > x; j--)
            v[j] = v[j - 1];
        v[j] = x;
    }
}

static void sort_pieces(struct piece *v, int n)
{
    if (n > SMALL_SORT) {
        qsort(v, (size_t)n, sizeof *v, cmp_piece);
        return;
    }
    for (int i = 1; i < n; i++) {
        if (!(v[i - 1].ta > v[i].ta))
            continue;
        struct piece x = v[i];
        int j = i;
        for (; j > 0 && v[j - 1].ta > x.ta; j--)
            v[j] = v[j - 1];
        v[j] = x;
    }
}

void geom_blob_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out)
{
    vec3 blo, bhi;
    if (geom_blob_bounds(o, &blo, &bhi))
        geom_blob_hits_in_box(o, blo, bhi, ro, rd, t0, t1, out);
}

void geom_blob_hits_in_box(const iris_object *o, vec3 blo, vec3 bhi,
                           vec3 ro, vec3 rd, double t0, double t1,
                           struct isect_list *out)
{
    double a = t0, b = t1;
    if (!geom_clip_box(blo, bhi, ro, rd, &a, &b))
        return;
    /* Measure t from the box entry so the quartics stay well scaled */
    double ts = isfinite(a) ? a : 0;
    vec3 o2 = v3_madd(ro, rd, ts);

    struct piece_list l = { .n = 0, .cap = INLINE_PIECES };
    l.v = l.inline_buf;
    for (int i = 0; i < o->u.blob.n_components; i++) {
        const iris_blob_component *bc = &o->u.blob.components[i];
        vec3 co, cd;
        comp_ray(bc, o2, rd, &co, &cd);
        component_pieces(bc, co, cd, a - ts, b - ts, &l);
    }

    /* Breakpoints: every piece end. The intervals between them are swept
    ** in order with the pieces sorted by start, keeping the list of those
    ** that cover the interval ('act'): each interval sums only its own
    ** pieces (afresh, so no rounding accumulates), and a ray through
    ** thousands of components costs O(k log k), not O(k^2) (issue 7). */
    int nb = 0;
    /* On the stack while the pieces fit the inline list (a malloc and
    ** free per ray were 4 % of 185) */
    double bp_buf[2 * INLINE_PIECES + 2];
    int act_buf[INLINE_PIECES + 1];
    bool heap = l.n > INLINE_PIECES;
    double *bp = heap ? iris_malloc((size_t)(2 * l.n + 2) * sizeof *bp)
                      : bp_buf;
    int *act = heap ? iris_malloc((size_t)(l.n + 1) * sizeof *act) : act_buf;
    if (bp && act) {
        for (int i = 0; i < l.n; i++) {
            bp[nb++] = l.v[i].ta;
            bp[nb++] = l.v[i].tb;
        }
        sort_doubles(bp, nb);
        sort_pieces(l.v, l.n);
        int n_act = 0, next = 0;
        for (int k = 0; k + 1 < nb; k++) {
            double lo = bp[k], hi = bp[k + 1];
            if (!(lo < hi))
                continue;
            double mid = 0.5 * (lo + hi), c[5] = { -o->u.blob.threshold, 0, 0,
                                                    0, 0 };
            while (next < l.n && l.v[next].ta <= mid)
                act[n_act++] = next++;
            int keep = 0;
            for (int i = 0; i < n_act; i++)
                if (mid < l.v[act[i]].tb)
                    act[keep++] = act[i];
            n_act = keep;
            for (int i = 0; i < n_act; i++)
                for (int e = 0; e < 5; e++)
                    c[e] += l.v[act[i]].c[e];
            if (!n_act)
                continue;
            double r[4];
            int n = roots_in_interval(c, 4, lo, hi, r);
            for (int i = 0; i < n; i++) {
                double t = ts + r[i];
                if (!(t > t0 && t < t1))
                    continue;
                vec3 g;
                int part;
                density_grad(o, v3_madd(ro, rd, t), &g, &part);
                int at = out->n;
                isect_push(out, t, v3_neg(g), 0, 0);
                if (out->n > at)
                    out->v[at].part = part;
            }
        }
    }
    if (heap) {
        iris_free(bp);
        iris_free(act);
    }
    if (l.v != l.inline_buf)
        iris_free(l.v);
}

bool geom_blob_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    bool any = false;
    for (int i = 0; i < o->u.blob.n_components; i++) {
        const iris_blob_component *bc = &o->u.blob.components[i];
        double R = bc->radius;
        /* Negative components only remove density: they add no volume */
        if (!(R > 0) || bc->strength <= 0)
            continue;
        vec3 a = v3_sub(v3_min(bc->a, bc->kind ? bc->b : bc->a), v3(R, R, R));
        vec3 b = v3_add(v3_max(bc->a, bc->kind ? bc->b : bc->a), v3(R, R, R));
        for (int c = 0; c < 8; c++) {
            vec3 p = v3(c & 1 ? b.x : a.x, c & 2 ? b.y : a.y,
                        c & 4 ? b.z : a.z);
            if (bc->has_transform)
                p = xf_point(&bc->transform, p);
            *lo = any ? v3_min(*lo, p) : p;
            *hi = any ? v3_max(*hi, p) : p;
            any = true;
        }
    }
    return any;
}
