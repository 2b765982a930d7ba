/* SPDX-License-Identifier: MIT */
/*
** normal.c: normal{} perturbation as POV-Ray 3.7's Perturb_Normal does it.
**
** The normal is taken into pattern space (the transpose of the pattern's
** local-to-world matrix), normalised, displaced there, and taken back with
** the inverse transpose, so bumps keep their look under any scale (not
** so with no_bump_scale, which leaves out the normalising). The
** dedicated normal patterns (bumps, dents, wrinkles, ripples, waves,
** quilted) add their own displacement vectors; every other pattern is
** differentiated numerically on POV-Ray's tetrahedron of four sample
** points at distance 'accuracy', scaled by -5 * amount * 0.02 / accuracy,
** through the slope_map when one is given.
*/
#include "config.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "material/mat_internal.h"
#include "material/noise.h"
#include "math/transform.h"

/* POV-Ray's Pyramid_Vect: four unit vectors of a regular tetrahedron. */
static const vec3 pyramid[4] = {
    { 0.942809041, -0.333333333, 0.0 },
    { -0.471404521, -0.333333333, 0.816496581 },
    { -0.471404521, -0.333333333, -0.816496581 },
    { 0.0, 1.0, 0.0 },
};

/* World normal to pattern space: the transpose of the local-to-world 3x3
** (the inverse transpose of world-to-pattern). */
static vec3 normal_to_pattern(const iris_transform *t, vec3 n)
{
    return v3(t->m[0][0] * n.x + t->m[1][0] * n.y + t->m[2][0] * n.z,
              t->m[0][1] * n.x + t->m[1][1] * n.y + t->m[2][1] * n.z,
              t->m[0][2] * n.x + t->m[1][2] * n.y + t->m[2][2] * n.z);
}

/* Pattern normal back to world: the transpose of the world-to-pattern 3x3. */
static vec3 normal_to_world(const iris_transform *t, vec3 n)
{
    return v3(t->inv[0][0] * n.x + t->inv[1][0] * n.y + t->inv[2][0] * n.z,
              t->inv[0][1] * n.x + t->inv[1][1] * n.y + t->inv[2][1] * n.z,
              t->inv[0][2] * n.x + t->inv[1][2] * n.y + t->inv[2][2] * n.z);
}

/* Warp_Normal: the normal through every transform on the way to pattern
** space, in the order pat_space() applies them. Normalised before and
** after unless 'no_bump_scale' (keep): then a pattern scaled by s sees
** a normal of length ~s and the same displacement, so its bumps grow
** 1/s times stronger, as in POV-Ray. */
static vec3 warp_normal(const iris_pattern *pat, vec3 n, bool keep)
{
    if (!keep)
        n = v3_norm(n);
    if (pat->has_transform)
        n = normal_to_pattern(&pat->transform, n);
    for (int i = pat->n_warps - 1; i >= 0; i--)
        if (pat->warps[i].kind == IRIS_WARP_TRANSFORM)
            n = normal_to_pattern(&pat->warps[i].transform, n);
    return keep ? n : v3_norm(n);
}

/* UnWarp_Normal: back to world space, in the reverse order. */
static vec3 unwarp_normal(const iris_pattern *pat, vec3 n, bool keep)
{
    if (!keep)
        n = v3_norm(n);
    for (int i = 0; i < pat->n_warps; i++)
        if (pat->warps[i].kind == IRIS_WARP_TRANSFORM)
            n = normal_to_world(&pat->warps[i].transform, n);
    if (pat->has_transform)
        n = normal_to_world(&pat->transform, n);
    return keep ? n : v3_norm(n);
}

static vec3 waves_normal(const struct mat_ctx *ctx, const iris_normal *nrm,
                         vec3 q, vec3 n, bool ripples)
{
    int count = ctx && ctx->n_waves > 0 ? ctx->n_waves : 10;
    double freq = nrm->pattern.frequency != 0 ? nrm->pattern.frequency : 1;
    for (int i = 0; i < count; i++) {
        vec3 src;
        double f;
        noise_wave_source(i, &src, &f);
        vec3 d = v3_sub(q, src);
        double len = v3_len(d);
        if (len == 0.0)
            len = 1.0;
        double s;
        if (ripples)
            s = noise_cycloidal(len * freq + nrm->pattern.phase) * nrm->amount;
        else
            s = noise_cycloidal(len * freq * f + nrm->pattern.phase) *
                nrm->amount / f;
        n = v3_madd(n, d, s / (len * count));
    }
    return n;
}

static vec3 wrinkles_normal(const iris_normal *nrm, vec3 q, vec3 n)
{
    vec3 r = v3(0, 0, 0);
    double scale = 1.0;
    for (int i = 0; i < 10; i++, scale *= 2.0) {
        vec3 v = noise_vector(v3_scale(q, scale));
        r = v3_add(r, v3(fabs(v.x / scale), fabs(v.y / scale),
                         fabs(v.z / scale)));
    }
    return v3_madd(n, r, nrm->amount);
}

/* Hermite interpolation of a slope_map between two <height, slope>. */
/*
** facets [size S] [coords C] [metric M] (a normal-only pattern, POV-Ray
** 3.7's facets in normal.cpp): one random point per unit cube (the same
** points as crackle's); the normal, scaled by 1/S (coords 0) or the
** point itself (coords C != 0), is moved to the nearest such point among
** its cube's 80 neighbours within a 3-D knight's move. Without coords the
** point's position becomes the normal, which makes flat facets that
** follow a curved surface; with coords the normal is pushed by C times
** the part of the noise vector at that point across it, the same
** everywhere in one Voronoi cell. Metric 2 is the squared distance,
** metric 1 POV-Ray's signed dx+dy+dz, others the sum of |d|^M.
*/
static vec3 facet_point(int x, int y, int z)
{
    vec3 r = noise_pattern_rand3(
        (unsigned long)noise_hash3d(x & 0xFFF, y & 0xFFF, z & 0xFFF));
    return v3(x + r.x, y + r.y, z + r.z);
}

static double facet_metric(vec3 d, double metric)
{
    if (metric == 2)
        return v3_len2(d);
    if (metric == 1)
        return d.x + d.y + d.z;
    return pow(fabs(d.x), metric) + pow(fabs(d.y), metric) +
           pow(fabs(d.z), metric);
}

static vec3 facets_normal(const iris_pattern *pat, vec3 q, vec3 n)
{
    double size = pat->params[0], coords = pat->params[1];
    double metric = pat->params[3];
    n = v3_norm(n);
    vec3 t = v3_scale(coords != 0 ? q : n, size < 1e-6 ? 1e6 : 1.0 / size);
    /* floor, not a mirror about 0, a hair below the point (POV-Ray's
    ** PickInCube) */
    int bx = (int)floor(t.x - 1e-10), by = (int)floor(t.y - 1e-10),
        bz = (int)floor(t.z - 1e-10);
    vec3 best = v3(0, 0, 0);
    double best_d = INFINITY;
    bool first = true;
    for (int dx = -2; dx <= 2; dx++)
        for (int dy = -2; dy <= 2; dy++)
            for (int dz = -2; dz <= 2; dz++) {
                if ((abs(dx) == 2) + (abs(dy) == 2) + (abs(dz) == 2) > 1)
                    continue;
                vec3 c = facet_point(bx + dx, by + dy, bz + dz);
                double d = facet_metric(v3_sub(c, t), metric);
                if (first || d < best_d) {
                    best_d = d;
                    best = c;
                    first = false;
                }
            }
    if (coords == 0)
        return best;
    vec3 pert = noise_vector(best);
    pert = v3_sub(pert, v3_scale(n, v3_dot(pert, n)));
    return v3_madd(n, pert, coords);
}

static double hermite(double t, double h1, double s1, double h2, double s2)
{
    double tt = t * t, ttt = tt * t;
    return ttt * (s1 + s2 + 2.0 * (h1 - h2)) -
           tt * (2.0 * s1 + s2 + 3.0 * (h1 - h2)) + t * s1 + h1;
}

static double slope_map(const iris_normal *nrm, double v)
{
    if (!nrm->is_slope_map || nrm->n_entries <= 0)
        return v;
    const iris_map_entry *e = nrm->entries;
    int last = nrm->n_entries - 1;
    if (v >= e[last].value)
        return e[last].height;
    int p = 0, c = 0;
    while (v > e[c].value) {
        p = c;
        c++;
    }
    if (v == e[c].value || p == c)
        return e[c].height;
    double t = (v - e[p].value) / (e[c].value - e[p].value);
    return hermite(t, e[p].height, e[p].slope, e[c].height, e[c].slope);
}

/* The pattern normal by finite differences on the tetrahedron. */
static vec3 pattern_normal(const struct mat_ctx *ctx, const iris_normal *nrm,
                           vec3 q, vec3 n, const struct mat_point *pt)
{
    double delta = nrm->accuracy > 0 ? nrm->accuracy : 0.02;
    double amount = nrm->amount * -5.0 * (0.02 / delta);
    for (int i = 0; i < 4; i++) {
        vec3 p1 = v3_madd(q, pyramid[i], delta);
        double v = slope_map(nrm, pat_eval_at(ctx, &nrm->pattern, p1, pt));
        n = v3_madd(n, pyramid[i], v * amount);
    }
    return n;
}

static bool is_normal_map(const iris_normal *nrm)
{
    return nrm->n_entries > 0 && !nrm->is_slope_map;
}

static vec3 perturb(const struct mat_ctx *ctx, const iris_normal *nrm,
                    const struct mat_point *pt, vec3 n, bool keep);

/* Entry 'e' of normal_map 'map' at 'pt' (already through the map's
** warps): with the map's entry_xf (shared entries, scene.h), the point
** moved back by it and the normal taken to its space and back, as the
** entry's own transform would have done had the parser pushed it in. */
static vec3 perturb_entry(const struct mat_ctx *ctx, const iris_normal *map,
                          const iris_normal *e, const struct mat_point *pt,
                          vec3 n, bool keep)
{
    if (!map->entry_xf || !e || e->pattern.kind == IRIS_PAT_NONE)
        return perturb(ctx, e, pt, n, keep);
    struct mat_point ept = *pt;
    ept.p = xf_inv_point(map->entry_xf, pt->p);
    vec3 r = perturb(ctx, e, &ept, normal_to_pattern(map->entry_xf, n), keep);
    r = normal_to_world(map->entry_xf, r);
    return keep ? r : v3_norm(r);
}

/* Perturb_Normal; 'keep' is no_bump_scale, set on the normal or handed
** down from a normal_map holding it (POV-Ray's NormalBlendMap::Post). */
static vec3 perturb(const struct mat_ctx *ctx, const iris_normal *nrm,
                    const struct mat_point *pt, vec3 n, bool keep)
{
    if (!nrm || nrm->pattern.kind == IRIS_PAT_NONE)
        return n;
    const iris_pattern *pat = &nrm->pattern;
    keep = keep || nrm->no_bump_scale;
    if (is_normal_map(nrm) && pat->kind != IRIS_PAT_AVERAGE) {
        /* normal_map: blend the perturbed normals of the two entries */
        double v = pat_value(ctx, pat, pt->p, pt);
        int last = nrm->n_entries - 1, p = 0, c = 0;
        if (v >= nrm->entries[last].value) {
            p = c = last;
        } else {
            while (v > nrm->entries[c].value) {
                p = c;
                c++;
            }
            if (v == nrm->entries[c].value)
                p = c;
        }
        /* the entries see the map pattern's warps (pat_warp_world) */
        struct mat_point wpt = *pt;
        wpt.p = pat_warp_world(ctx, pat, pat_input(pat, pt->p, pt));
        vec3 nc = perturb_entry(ctx, nrm, nrm->entries[c].normal, &wpt, n,
                                keep);
        if (p == c)
            return v3_norm(nc);
        vec3 np = perturb_entry(ctx, nrm, nrm->entries[p].normal, &wpt, n,
                                keep);
        double t = (v - nrm->entries[p].value) /
                   (nrm->entries[c].value - nrm->entries[p].value);
        return v3_norm(v3_add(v3_scale(np, 1 - t), v3_scale(nc, t)));
    }
    if (pat->kind == IRIS_PAT_AVERAGE && nrm->n_entries > 0) {
        vec3 sum = v3(0, 0, 0);
        double total = 0;
        struct mat_point wpt = *pt;
        wpt.p = pat_warp_world(ctx, pat, pat_input(pat, pt->p, pt));
        for (int i = 0; i < nrm->n_entries; i++) {
            double w = nrm->entries[i].value != 0 ? nrm->entries[i].value : 1;
            sum = v3_madd(sum, perturb_entry(ctx, nrm, nrm->entries[i].normal,
                                             &wpt, n, keep), w);
            total += w;
        }
        return total > 0 ? v3_norm(sum) : n;
    }
    vec3 np = warp_normal(pat, n, keep);
    vec3 q = pat_space(ctx, pat, pat_input(pat, pt->p, pt));
    switch (pat->kind) {
    case IRIS_PAT_IMAGE_MAP:
        if (nrm->bump_map) {
            vec3 b;
            if (mat_image_bump(ctx, nrm->bump_map, q, nrm->amount, np, &b))
                np = b;
        }
        break;
    case IRIS_PAT_BUMPS:
        np = v3_madd(np, noise_vector(q), nrm->amount);
        break;
    case IRIS_PAT_DENTS: {
        double v = noise_value(q, pat_noise_generator(ctx, pat));
        np = v3_madd(np, noise_vector(q), v * v * v * nrm->amount);
        break;
    }
    case IRIS_PAT_WRINKLES:
        np = wrinkles_normal(nrm, q, np);
        break;
    case IRIS_PAT_RIPPLES:
        np = waves_normal(ctx, nrm, q, np, true);
        break;
    case IRIS_PAT_WAVES:
        np = waves_normal(ctx, nrm, q, np, false);
        break;
    case IRIS_PAT_FACETS:
        np = facets_normal(pat, q, np);
        break;
    case IRIS_PAT_QUILTED:
        /* a normal-only pattern in POV-Ray: the cell vector, not the
        ** slope of the pattern value */
        np = v3_madd(np, pat_quilt_vector(pat, q), nrm->amount);
        break;
    default:
        np = pattern_normal(ctx, nrm, q, np, pt);
        break;
    }
    vec3 r = unwarp_normal(pat, np, keep);
    if (!(isfinite(r.x) && isfinite(r.y) && isfinite(r.z)) || v3_len2(r) == 0)
        return n;
    return r;
}

vec3 mat_perturb_normal(const struct mat_ctx *ctx, const iris_normal *nrm,
                        const struct mat_point *pt, vec3 n)
{
    vec3 r = perturb(ctx, nrm, pt, n, false);
    /* POV-Ray's Trace normalises a layer's normal after a no_bump_scale
    ** normal; the others come back normalised already */
    return nrm && nrm->no_bump_scale ? v3_norm(r) : r;
}
