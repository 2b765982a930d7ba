/* SPDX-License-Identifier: MIT */
/*
** global.c: the global photon map, iris's answer to `radiosity {}`
** (diffuse interreflection, the seed paper's Cornell box).
**
** DESIGN. Every light that illuminates (not shadowless) emits
** PMAP_GLOBAL_PHOTONS / n_lights photons per pass over all the directions
** it lights: the whole sphere for point lights, the falloff cone for
** spots, the disc of the finite objects' bounding sphere (cylinder
** lights: the beam's disc) for parallel ones. Directions are stratified:
** cos(theta) in N equal strata of the cap, phi and lambda on a rank-1
** (R2) lattice over the photon index with random offsets per pass, each
** photon uniform inside its stratum, so every pass is an independent
** unbiased sample (progressive.c averages passes). Area lights: the origin is uniform on the light's rectangle.
**
** Power (the normalisation). A photon carries the emission (relative to
** D65, spec_emitter_eval) x spot attenuation x its solid angle
** omega = 2·pi·(1 - cos theta_max)/N (parallel lights: its area), and,
** where it first lands on a diffuse surface after a path of length D,
** x D^2 x the light's fade (trace.c). That is POV-Ray's own photon
** normalisation (shoot.c: flux per area = light colour) and also what the
** light loop computes for direct light, which does not fall off with
** distance: a surface facing a light of colour C gets irradiance C. So the
** global map holds the light that the direct term puts on surfaces,
** re-emitted with albedo diffuse x pigment(lambda) x opacity and carried
** physically from there (Lambertian bounces by Russian roulette, glass
** and mirrors with exact Fresnel, whatever the photon flags say: those
** choose caustic targets, not physics).
**
** What is stored: a photon at a diffuse surface after at least one
** diffuse bounce and at most recursion_limit - 1 (POV-Ray's radiosity
** stops there; with every bounce 81_radiosity_room was 33 dB from
** POV-Ray's image, with POV-Ray's count 47 dB). Direct light (no bounce) is the light loop's and
** light -> specular+ -> diffuse is the caustic map's (shoot.c), so the
** global estimate adds only what neither has: no double counting.
**
** The estimate is read from irradiance precomputed at a quarter of the
** photons (PMAP_GLOBAL_GATHER neighbours each; see precompute_irradiance
** below) at the hits of the final gather's rays (src/render/gather.c):
** eye hits gather instead of reading it, because read directly the map's
** low-frequency noise shows as colour blotches, while the mean over
** 'count' gather rays averages it out.
*/
#include "config.h"

#include "photon/pmap.h"

#include <math.h>
#include <stdatomic.h>
#include <string.h>

#include "photon/trace.h"
#include "spectrum/spectrum.h"
#include "util/mem.h"
#include "util/thread.h"

#define GLOBAL_BATCH 4096

/* Keys the global photons' random streams apart from the caustic ones. */
#define GLOBAL_STREAM 0x676c6f62616cULL

/* Roberts' R2 steps for (phi, lambda) over the photon index. They must be
** rationally independent: with one step for both (the golden ratio, tried
** first) lambda - phi is constant, every azimuth gets one wavelength, and
** a red wall on one side and a green one on the other tint each pass's
** whole image. */
#define STEP_PHI 0.7548776662466927
#define STEP_LAMBDA 0.5698402909980532

struct gsource {
    struct ptrace_combo tc;
    struct spec_emitter em;
    vec3 axis, a, b;           /* emission axis and a basis about it */
    vec3 ctr;                  /* parallel lights: disc centre */
    double cos_max;            /* point and spot: cap of directions */
    double rad;                /* parallel lights: disc radius */
    double omega;              /* solid angle (area) per photon */
    int64_t first, count;
};

struct gshoot {
    const struct pmap_world *w;
    const struct photon_options *opts;
    struct gsource *src;
    int n_src;
    int64_t n_photons;
    double u0, u1;             /* per-pass offsets: wavelength, phi */
    struct ptrace_out *outs;
    _Atomic int64_t tex_cached; /* photon_stats.tex_cached */
};

bool pmap_wants_global(const iris_scene *scene)
{
    if (!scene->settings.radiosity)
        return false;
    /* recursion_limit 1: one bounce, all of it the final gather's
    ** (render/gather.c), which then reads no global map; 0 = not set */
    int rl = scene->settings.rad.recursion_limit;
    if (rl == 1)
        return false;
    for (int i = 0; i < scene->n_lights; i++)
        if (!scene->lights[i]->shadowless)
            return true;
    return false;
}

/* The bounding sphere of the finite objects (parallel lights aim there). */
static bool finite_bounds(const iris_scene *sc, const struct pmap_world *w,
                          vec3 *ctr, double *rad)
{
    vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3_neg(lo);
    bool any = false;
    for (int i = 0; i < sc->n_objects; i++) {
        vec3 a, b;
        if (!w->object_bounds(w->ctx, sc->objects[i], &a, &b))
            continue;
        lo = v3(fmin(lo.x, a.x), fmin(lo.y, a.y), fmin(lo.z, a.z));
        hi = v3(fmax(hi.x, b.x), fmax(hi.y, b.y), fmax(hi.z, b.z));
        any = true;
    }
    if (!any)
        return false;
    *ctr = v3_scale(v3_add(lo, hi), 0.5);
    *rad = 0.5 * v3_len(v3_sub(hi, lo));
    return *rad > 0.0 && isfinite(*rad);
}

static enum iris_status find_sources(struct gshoot *g,
                                     const iris_scene *sc, int64_t total)
{
    g->src = iris_calloc((size_t)(sc->n_lights > 0 ? sc->n_lights : 1),
                         sizeof *g->src);
    if (!g->src)
        return IRIS_ENOMEM;
    int n_lit = 0;
    for (int i = 0; i < sc->n_lights; i++)
        n_lit += !sc->lights[i]->shadowless;
    if (n_lit == 0)
        return IRIS_OK;
    int64_t per = total / n_lit > 1 ? total / n_lit : 1;
    vec3 fctr = v3(0, 0, 0);
    double frad = 0.0;
    bool have_bounds = finite_bounds(sc, g->w, &fctr, &frad);
    for (int i = 0; i < sc->n_lights; i++) {
        const iris_light *l = sc->lights[i];
        if (l->shadowless)
            continue;
        struct gsource *s = &g->src[g->n_src];
        memset(s, 0, sizeof *s);
        s->tc.light = l;
        s->tc.global = true;
        /* POV-Ray's radiosity sees recursion_limit L bounces at an eye
        ** hit: the gather's, whose rays' hits read this map, and L - 1
        ** more, so a photon is stored after 1 .. L - 1 diffuse bounces
        ** only (0 = not set: every bounce, as the unit tests' furnace) */
        int rl = sc->settings.rad.recursion_limit;
        s->tc.max_diffuse = rl >= 2 ? rl - 1 : 0;
        s->tc.parallel = l->parallel || l->kind == IRIS_LIGHT_CYLINDER;
        s->tc.fade_distance = l->fade_distance;
        s->tc.fade_power = l->fade_power;
        s->tc.mat = g->opts->mat;
        spec_emitter_init(&s->em, l);
        double e0 = spec_emitter_eval(&s->em, SPEC_LAMBDA_MIN);
        for (int k = 1; k <= 80 && !s->tc.chromatic; k++)
            if (fabs(spec_emitter_eval(&s->em, SPEC_LAMBDA_MIN + 5.0 * k) -
                     e0) > 1e-12 * fabs(e0))
                s->tc.chromatic = true;
        vec3 to = v3_sub(l->point_at, l->location);
        s->axis = v3_len(to) > 0.0 ? v3_norm(to) : v3(0, 0, 1);
        if (s->tc.parallel) {
            if (l->kind == IRIS_LIGHT_CYLINDER && l->falloff > 0.0) {
                s->ctr = l->location;
                s->rad = l->falloff;
            } else if (have_bounds) {
                /* centre the disc on the bounding sphere's projection */
                vec3 rel = v3_sub(fctr, l->location);
                s->ctr = v3_madd(fctr, s->axis, -v3_dot(rel, s->axis));
                s->rad = frad;
            } else {
                continue; /* nothing finite to light */
            }
            s->omega = M_PI * s->rad * s->rad / (double)per;
        } else {
            s->axis = l->kind == IRIS_LIGHT_SPOT ? s->axis : v3(0, 0, 1);
            s->cos_max = l->kind == IRIS_LIGHT_SPOT && l->falloff < 180.0
                             ? cos(l->falloff * M_PI / 180.0) : -1.0;
            s->omega = 2.0 * M_PI * (1.0 - s->cos_max) / (double)per;
        }
        v3_basis(s->axis, &s->a, &s->b);
        /* Interiors that contain the light */
        if (g->w->inside && !s->tc.parallel)
            for (int k = 0; k < sc->n_objects; k++) {
                const iris_object *o = sc->objects[k];
                if (o->interior && s->tc.n_stack < PTRACE_MAX_STACK &&
                    g->w->inside(g->w->ctx, o, l->location))
                    s->tc.stack[s->tc.n_stack++] = o;
            }
        s->first = g->n_photons;
        s->count = per;
        g->n_photons += per;
        g->n_src++;
    }
    return IRIS_OK;
}

static void shoot_global(const struct gshoot *g, int64_t j,
                         struct ptrace_out *out)
{
    int si = 0;
    while (si + 1 < g->n_src && g->src[si + 1].first <= j)
        si++;
    const struct gsource *s = &g->src[si];
    int64_t k = j - s->first;
    rng r;
    rng_seed(&r, g->opts->seed ^ GLOBAL_STREAM, (uint64_t)g->opts->pass,
             (uint64_t)j);
    /* stratum k of the cap (disc) measure, phi on the golden lattice */
    double u = ((double)k + rng_uniform(&r)) / (double)s->count;
    double v = g->u1 + STEP_PHI * (double)k;
    double ph = 2.0 * M_PI * (v - floor(v));
    vec3 radial = v3_add(v3_scale(s->a, cos(ph)), v3_scale(s->b, sin(ph)));
    vec3 o, d;
    const iris_light *l = s->tc.light;
    if (s->tc.parallel) {
        d = s->axis;
        o = v3_madd(s->ctr, radial, s->rad * sqrt(u));
    } else {
        double z = 1.0 - u * (1.0 - s->cos_max);
        double sz = sqrt(fmax(0.0, 1.0 - z * z));
        d = v3_norm(v3_add(v3_scale(s->axis, z), v3_scale(radial, sz)));
        o = l->location;
    }
    if (l->area && l->size1 > 1 && l->size2 > 1) {
        o = v3_madd(o, l->axis1, rng_uniform(&r) - 0.5);
        o = v3_madd(o, l->axis2, rng_uniform(&r) - 0.5);
    }
    double a = pmap_light_atten(l, s->axis, o, d);
    if (a < 1e-5)
        return;
    double w = g->u0 + STEP_LAMBDA * (double)j;
    double lambda = spec_sample_uniform(w - floor(w));
    double power = s->omega * a * spec_emitter_eval(&s->em, lambda);
    if (!(power > 0.0))
        return;
    ptrace_photon(g->w, &s->tc, o, d, lambda, power, &r, out);
}

static void global_batch(void *ctx, int64_t item, int thread)
{
    (void)thread;
    struct gshoot *g = ctx;
    int64_t lo = item * GLOBAL_BATCH;
    int64_t hi = lo + GLOBAL_BATCH < g->n_photons ? lo + GLOBAL_BATCH
                                                  : g->n_photons;
    /* SIGINT/SIGTERM: the rest of the batch and the batches not yet
    ** started are skipped, and the build returns IRIS_EINTR. Checked per
    ** photon (one load): with recursion_limit 20 bounces on a slow
    ** isosurface one batch took over 20 s */
    volatile int *stop = g->opts->interrupt;
    if (stop && *stop)
        return;
    /* textures of one colour everywhere, evaluated once a batch */
    struct ptrace_tex_cache tex;
    memset(&tex, 0, sizeof tex);
    /* the batch's output record on this stack while written: neighbouring
    ** batches' records share cache lines (false sharing, as shoot.c) */
    struct ptrace_out out = g->outs[item];
    out.tex = g->opts->no_tex_cache ? NULL : &tex;
    for (int64_t j = lo; j < hi && !out.failed && !(stop && *stop); j++)
        shoot_global(g, j, &out);
    out.tex = NULL;
    g->outs[item] = out;
    atomic_fetch_add(&g->tex_cached, tex.hits);
}

/*
** Precomputed irradiance (Christensen's method). Reading the map directly
** costs a 200-nearest search per eye hit, 75% of the Cornell box's render
** time. Instead every IRR_STRIDE-th photon becomes an irradiance point:
** its estimate is computed once, from the photons lit on the same surface
** (normals within IRR_COS), as a 3x3 matrix M with
**   M[k][c] = sum_j w_j·Phi_j·rho_{e_c}(lambda_j)·wt_k(lambda_j) / area
** (white photons: Phi_j·white[k][c]), so that a surface of pigment p
** gets M·p (Burns' reflectance is linear in rgb, spectrum.h). An eye hit
** then blends the IRR_NEAR nearest points on its surface. The normal test
** keeps walls from leaking light through each other at corners and thin
** walls.
*/
#define IRR_STRIDE 16
#define IRR_NEAR 8
#define IRR_FAR 48
#define IRR_COS 0.7

struct irr_job {
    const struct photon_map *ph;  /* the photons */
    struct pstore pts;            /* the points (tree order) */
    float (*irr)[9];
    float (*nrm)[3];              /* each photon's surface normal */
    float (*spec)[9];             /* per lambda_q: rho(e_c)·wt_k, or NULL */
    double radius, scale;
    int k;
    bool failed;
};

static void irr_point(void *ctx, int64_t i, int thread)
{
    (void)thread;
    struct irr_job *j = ctx;
    struct pstore_found buf[PMAP_GLOBAL_GATHER];
    vec3 p = pstore_position(&j->pts, (size_t)i);
    vec3 n = pstore_direction(&j->pts, (size_t)i);
    double r2;
    const struct pstore *s = &j->ph->store;
    int cnt = pstore_knn(s, p, j->k, j->radius * j->radius, buf, &r2);
    double r = cnt >= j->k ? sqrt(r2) : j->radius;
    r *= j->scale;
    double m[9] = { 0 };
    for (int q = 0; q < cnt && r > 0.0; q++) {
        size_t idx = buf[q].index;
        const float *pn = j->nrm[idx];
        if (pn[0] * n.x + pn[1] * n.y + pn[2] * n.z < IRR_COS)
            continue;
        double d = sqrt(buf[q].d2);
        double w = 1.0 - d / r;
        if (w <= 0.0)
            continue;
        double c = w * s->ph[idx].power;
        unsigned lq = s->ph[idx].lambda_q;
        if (lq == PSTORE_WHITE) {
            for (int k = 0; k < 3; k++)
                for (int e = 0; e < 3; e++)
                    m[3 * k + e] += c * j->ph->white[k][e];
            continue;
        }
        const float *sp = j->spec[lq];
        for (int q9 = 0; q9 < 9; q9++)
            m[q9] += c * sp[q9];
    }
    double norm = r > 0.0 ? 1.0 / ((1.0 - 2.0 / 3.0) * M_PI * r * r) : 0.0;
    for (int q = 0; q < 9; q++)
        j->irr[i][q] = (float)(m[q] * norm);
}

/*
** What irr_point reads of every neighbour, decoded once per photon rather
** than once per visit (each photon is a neighbour of ~k/IRR_STRIDE points;
** decoding its normal and evaluating three reflectance curves there were
** a quarter of the precompute's time): the normal as floats, and per
** wavelength present the 3x3 rho_{e_c}(lambda)·wt_k(lambda).
*/
static bool irr_tables(struct irr_job *j)
{
    const struct pstore *s = &j->ph->store;
    j->nrm = iris_malloc((s->n > 0 ? s->n : 1) * sizeof *j->nrm);
    j->spec = iris_malloc(PSTORE_WHITE * sizeof *j->spec);
    bool *seen = iris_calloc(PSTORE_WHITE, sizeof *seen);
    if (!j->nrm || !j->spec || !seen) {
        iris_free(seen);
        return false;
    }
    for (size_t i = 0; i < s->n; i++) {
        vec3 n = pstore_direction(s, i);
        j->nrm[i][0] = (float)n.x;
        j->nrm[i][1] = (float)n.y;
        j->nrm[i][2] = (float)n.z;
        unsigned lq = s->ph[i].lambda_q;
        if (lq == PSTORE_WHITE || seen[lq])
            continue;
        seen[lq] = true;
        double lambda = pstore_lambda(s, i), wt[3];
        spec_lambda_rgb_weight(lambda, wt);
        for (int e = 0; e < 3; e++) {
            double unit[3] = { e == 0, e == 1, e == 2 };
            double rho = spec_reflectance(unit, lambda);
            for (int k = 0; k < 3; k++)
                j->spec[lq][3 * k + e] = (float)(rho * wt[k]);
        }
    }
    iris_free(seen);
    return true;
}

/* Replaces the photons of 'm' by its irradiance points. */
static enum iris_status precompute_irradiance(struct photon_map *m,
                                              const struct photon_options *o)
{
    size_t n_pts = (m->store.n + IRR_STRIDE - 1) / IRR_STRIDE;
    if (n_pts == 0)
        return IRIS_OK;
    struct pstore_raw *raw = iris_malloc(n_pts * sizeof *raw);
    if (!raw)
        return IRIS_ENOMEM;
    for (size_t i = 0; i < n_pts; i++) {
        size_t src = i * IRR_STRIDE;
        vec3 p = pstore_position(&m->store, src);
        vec3 n = pstore_direction(&m->store, src);
        raw[i] = (struct pstore_raw){ { (float)p.x, (float)p.y, (float)p.z },
                                      0.0f, -1.0f,
                                      { (float)n.x, (float)n.y, (float)n.z } };
    }
    struct irr_job j;
    memset(&j, 0, sizeof j);
    j.ph = m;
    enum iris_status rc = pstore_build_mt(&j.pts, raw, n_pts,
                                          o->threads);
    iris_free(raw);
    if (rc != IRIS_OK)
        return rc;
    j.irr = iris_calloc(j.pts.n > 0 ? j.pts.n : 1, sizeof *j.irr);
    if (!j.irr || !irr_tables(&j)) {
        iris_free(j.irr);
        iris_free(j.nrm);
        iris_free(j.spec);
        pstore_fini(&j.pts);
        return IRIS_ENOMEM;
    }
    j.radius = m->radius;
    j.scale = m->estimate_scale;
    j.k = m->gather_max;
    par_for(o->threads, (int64_t)j.pts.n, irr_point, &j);
    iris_free(j.nrm);
    iris_free(j.spec);
    pstore_fini(&m->store);
    m->store = j.pts;
    m->irr = j.irr;
    /* the points are IRR_STRIDE times sparser than the photons: their
    ** IRR_NEAR nearest lie within about sqrt(IRR_NEAR·IRR_STRIDE/k) of
    ** the photon radius; twice that reaches past thin gaps */
    m->irr_radius = 2.0 * m->radius *
                    sqrt((double)IRR_NEAR * IRR_STRIDE / m->gather_max);
    return IRIS_OK;
}

void pmap_global_shade(const struct photon_map *g,
                       const struct photon_shade_input *in, double rgb[3])
{
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    if (!g || !g->irr || g->store.n == 0 || !in->finish ||
        !(in->finish->diffuse > 0.0))
        return;
    struct pstore_found buf[IRR_FAR];
    double m[9] = { 0 }, wsum = 0.0;
    /* the nearest points; at edges and corners, where they may all lie
    ** on the other surface (an eye hit with none would be black), more
    ** of them farther out */
    for (int tries = 0; tries < 2 && !(wsum > 0.0); tries++) {
        int want = tries ? IRR_FAR : IRR_NEAR;
        double rad = g->irr_radius * (tries ? 2.0 : 1.0), r2;
        int cnt = pstore_knn(&g->store, in->p, want, rad * rad, buf, &r2);
        double rmax = sqrt(r2) * 1.01 + 1e-12;
        for (int q = 0; q < cnt; q++) {
            size_t idx = buf[q].index;
            if (v3_dot(pstore_direction(&g->store, idx), in->n_raw) < IRR_COS)
                continue;
            /* a tent over the neighbourhood: no seams between points */
            double w = 1.0 - sqrt(buf[q].d2) / rmax;
            for (int k = 0; k < 9; k++)
                m[k] += w * g->irr[idx][k];
            wsum += w;
        }
    }
    if (!(wsum > 0.0))
        return;
    double f = in->finish->diffuse * in->opacity / wsum;
    for (int k = 0; k < 3; k++)
        rgb[k] = f * (m[3 * k] * in->pigment_rgb[0] +
                      m[3 * k + 1] * in->pigment_rgb[1] +
                      m[3 * k + 2] * in->pigment_rgb[2]);
}

enum iris_status pmap_build_global(const iris_scene *scene,
                                   const struct pmap_world *w,
                                   const struct photon_options *opts,
                                   struct photon_map **out,
                                   struct photon_stats *stats)
{
    *out = NULL;
    if (!pmap_wants_global(scene))
        return IRIS_OK;
    double t0 = par_now();
    struct gshoot g;
    memset(&g, 0, sizeof g);
    atomic_init(&g.tex_cached, 0);
    g.w = w;
    g.opts = opts;
    rng r0;
    rng_seed(&r0, opts->seed ^ GLOBAL_STREAM, (uint64_t)opts->pass,
             UINT64_MAX);
    g.u0 = rng_uniform(&r0);
    g.u1 = rng_uniform(&r0);
    int64_t total = opts->global_photons > 0 ? opts->global_photons
                                             : PMAP_GLOBAL_PHOTONS;
    if (opts->max_photons > 0 && total > opts->max_photons)
        total = opts->max_photons;
    enum iris_status rc = find_sources(&g, scene, total);
    int64_t n_batches = (g.n_photons + GLOBAL_BATCH - 1) / GLOBAL_BATCH;
    if (rc == IRIS_OK && n_batches > 0) {
        g.outs = iris_calloc((size_t)n_batches, sizeof *g.outs);
        if (!g.outs)
            rc = IRIS_ENOMEM;
    }
    if (rc == IRIS_OK && n_batches > 0)
        par_for(opts->threads, n_batches, global_batch, &g);
    if (rc == IRIS_OK && opts->interrupt && *opts->interrupt)
        rc = IRIS_EINTR; /* batches were skipped: no map */
    struct pstore_raw *all = NULL;
    size_t n_all = 0;
    if (rc == IRIS_OK)
        rc = pmap_concat(g.outs, n_batches, &all, &n_all);
    else if (g.outs) /* pmap_concat frees the batches' records; here we do */
        for (int64_t b = 0; b < n_batches; b++)
            if (!g.outs[b].borrowed)
                iris_free(g.outs[b].ph);
    iris_free(g.outs);
    iris_free(g.src);
    double t1 = par_now();
    struct photon_map *m = NULL;
    if (rc == IRIS_OK)
        rc = pmap_from_raw(scene, all, n_all, opts->threads, &m);
    else
        iris_free(all);
    if (rc != IRIS_OK)
        return rc;
    m->gather_max = PMAP_GLOBAL_GATHER;
    m->gather_min = 0; /* no 3R expansion: the global map is smooth */
    m->cone_k = 1.0;
    pmap_white_matrix(m->white);
    m->radius = pmap_auto_radius_mt(&m->store, m->gather_max,
                                    opts->threads);
    m->estimate_scale = opts->radius_scale > 0.0 ? opts->radius_scale : 1.0;
    size_t n_stored = m->store.n;
    rc = precompute_irradiance(m, opts);
    if (rc != IRIS_OK) {
        photon_map_destroy(m);
        return rc;
    }
    if (stats) {
        stats->shot_global = g.n_photons;
        stats->tex_cached += atomic_load(&g.tex_cached);
        stats->stored_global = (int64_t)n_stored;
        stats->bytes += (int64_t)(m->store.n * (sizeof(struct pstore_photon) +
                                                sizeof *m->irr));
        stats->seconds_shoot += t1 - t0;
        stats->seconds_build += par_now() - t1;
    }
    *out = m;
    return IRIS_OK;
}
