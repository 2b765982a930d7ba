/* SPDX-License-Identifier: MIT */
/*
** pmedia.c: photons in participating media (pmedia.h; docs/media.md,
** "Media photons"): the extinction of a photon segment, the media photons
** it deposits, their map and its estimate.
**
** What POV-Ray 3.7 computes (photons.cpp DepositMediaPhotons and
** addMediaPhoton, media.cpp ComputeMediaPhotons), and where iris differs:
**
**  - Steps. Each of the 'intervals' sampling intervals of a segment (of
**    length ds) gets n = ds/(spread·D·factor) media photons (parallel
**    lights: ds/(spread·factor)), D the path length from the light to the
**    segment's start, at most MAX_STEPS; at stratified positions
**    jittered by the photons' 'jitter'. POV-Ray deposits none when n
**    truncates to 0 (short segments go dark); iris deposits at least one,
**    so the deposited energy per unit length never depends on the step.
**  - Power. Each media photon carries the photon's flux times the length
**    of its step, Phi·ds/n, with Phi = P·D(s)^2·fade(D(s)) as a surface
**    photon's (POV-Ray's power normalisation, shoot.c): over a beam of
**    irradiance E the media photons hold E per unit volume, which the
**    estimate turns into sigma_s·E, the units of a light's direct
**    in-scattering (media.c). POV-Ray uses factor·spread·(D+s) for the
**    step, which exceeds ds/n by (D+s)/D and drops the int truncation;
**    iris uses the step actually taken.
**  - Extinction. POV-Ray deposits with the power at the segment's start
**    and dims the photon by the whole segment after; iris dims each
**    deposit by the transmittance up to its own position, at the photon's
**    wavelength (Beer-Lambert; the coefficient sigma_t upsampled from rgb
**    by Burns' curves, linear in rgb). Constant media (no density) are
**    integrated exactly; with densities sigma_t is taken constant over
**    each step around its sample (a Riemann sum, as POV-Ray's method 2).
**  - Spectrum. The photon's sibling wavelengths (trace.h) are each dimmed
**    at their own; a media photon has one wavelength, the siblings taking
**    the steps of a chromatic path in turn (pmedia_segment), or is white
**    when nothing on its path depended on it (trace.c); the estimate applies the
**    scattering coefficient at that wavelength, never as an rgb product.
**  - Estimate: as POV-Ray's, the k = gather-max nearest media photons in
**    a sphere, expanded once to 3R when fewer than gather-min are found,
**    uniform weights over the sphere 4/3·pi·r^3 (no cone filter), the
**    phase function of each photon's direction. The automatic radius is
**    the median k-nearest radius at sampled media photons (estimate.c's
**    reason: a mean density is ruled by its densest sample), enlarged
**    for sparse regions and doubled as POV-Ray does for media.
*/
#include "config.h"

#include "photon/pmedia.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "material/material.h"
#include "photon/pmap.h"
#include "photon/trace.h"
#include "spectrum/spectrum.h"
#include "util/mem.h"

#define PMEDIA_MAX 32          /* media on one segment, as media.h */
#define PMEDIA_STACK_K 512
#define PMEDIA_MAX_SAMPLES 256 /* extinction samples of a density medium */
#define PMEDIA_MAX_STEPS 10000  /* media MAX_STEPS is capped (as media's
                                   intervals and samples, docs/media.md) */

/* ------------------------------------------------------------------ */
/* The scene                                                            */
/* ------------------------------------------------------------------ */

static bool medium_scatters(const iris_media *m)
{
    return m->scattering.r != 0.0 || m->scattering.g != 0.0 ||
           m->scattering.b != 0.0;
}

/* 1: some interior has media; 2: some interior medium scatters. */
static int walk_media(const iris_object *o, int depth)
{
    if (!o || depth > 64)
        return 0;
    int best = 0;
    if (o->interior)
        for (int i = 0; i < o->interior->n_media; i++)
            best = medium_scatters(o->interior->media[i]) ? 2
                                                         : (best ? best : 1);
    if (best == 2)
        return 2;
    if (o->kind >= IRIS_OBJ_UNION && o->kind <= IRIS_OBJ_LIGHT_GROUP)
        for (int i = 0; i < o->u.csg.n_children; i++) {
            int b = walk_media(o->u.csg.children[i], depth + 1);
            if (b > best)
                best = b;
            if (best == 2)
                break;
        }
    return best;
}

static int scene_media(const iris_scene *scene)
{
    int best = 0;
    for (int i = 0; i < scene->n_objects && best < 2; i++) {
        int b = walk_media(scene->objects[i], 0);
        if (b > best)
            best = b;
    }
    return best;
}

bool pmedia_scene_has_media(const iris_scene *scene)
{
    return scene && (scene->n_media > 0 || scene_media(scene) > 0);
}

bool pmedia_scene_wants_photons(const iris_scene *scene)
{
    if (!scene)
        return false;
    const iris_photon_settings *ps = &scene->settings.photons;
    return ps->enabled && ps->media_max_steps > 0 && scene_media(scene) == 2;
}

void pmedia_setup(struct pmedia_path *mp, const iris_scene *scene,
                  double dtheta)
{
    memset(mp, 0, sizeof *mp);
    if (!pmedia_scene_has_media(scene))
        return;
    mp->scene = scene;
    mp->spread = dtheta;
    if (pmedia_scene_wants_photons(scene)) {
        const iris_photon_settings *ps = &scene->settings.photons;
        mp->max_steps = ps->media_max_steps > PMEDIA_MAX_STEPS
                            ? PMEDIA_MAX_STEPS : ps->media_max_steps;
        mp->factor = ps->media_factor > 0.0 ? ps->media_factor : 1.0;
    }
}

/* ------------------------------------------------------------------ */
/* Transport                                                            */
/* ------------------------------------------------------------------ */

double pmedia_phase(const iris_media *m, double alpha)
{
    switch (m->scattering_type) {
    case IRIS_SCATTER_RAYLEIGH:
        return 0.799372013 * (1.0 + alpha * alpha);
    case IRIS_SCATTER_MIE_HAZY:
        return 0.576655375 * (1.0 + 9.0 * pow(0.5 * (1.0 + alpha), 8.0));
    case IRIS_SCATTER_MIE_MURKY:
        return 0.495714547 * (1.0 + 50.0 * pow(0.5 * (1.0 + alpha), 32.0));
    case IRIS_SCATTER_HENYEY_GREENSTEIN: {
        double g = m->eccentricity;
        return (1.0 - g * g) / pow(1.0 + g * g - 2.0 * g * alpha, 1.5);
    }
    default:
        return 1.0;
    }
}

/* True when the phase of 'm' is 1 in every direction (isotropic, and
** Henyey-Greenstein with g = 0): the photons' directions are not needed. */
static bool phase_is_one(const iris_media *m)
{
    switch (m->scattering_type) {
    case IRIS_SCATTER_RAYLEIGH:
    case IRIS_SCATTER_MIE_HAZY:
    case IRIS_SCATTER_MIE_MURKY:
        return false;
    case IRIS_SCATTER_HENYEY_GREENSTEIN:
        return m->eccentricity == 0.0;
    default:
        return true;
    }
}

/* The product of the densities' colours at 'p' (media.c's density_at);
** without a material context (unit tests) the pigments' solid colours. */
static void density_at(const struct mat_ctx *mat, const iris_media *m,
                       vec3 p, vec3 d, double out[3])
{
    out[0] = out[1] = out[2] = 1.0;
    for (int i = 0; i < m->n_densities; i++) {
        iris_colour col = m->densities[i]->colour;
        if (mat) {
            struct mat_point pt = { p, v3(0, 0, 0), d, { 0, 0 }, NULL, true };
            if (!mat_eval_pigment(mat, m->densities[i], &pt, &col))
                col.r = col.g = col.b = 0.0;
        }
        out[0] *= col.r;
        out[1] *= col.g;
        out[2] *= col.b;
    }
}

/* The rgb extinction and scattering of media 'm' at 'p'. */
static void coefficients(const struct mat_ctx *mat,
                         const iris_media *const *m, int n, vec3 p, vec3 d,
                         double ext[3], double sca[3])
{
    ext[0] = ext[1] = ext[2] = 0.0;
    sca[0] = sca[1] = sca[2] = 0.0;
    for (int i = 0; i < n; i++) {
        double dn[3];
        density_at(mat, m[i], p, d, dn);
        const double a[3] = { m[i]->absorption.r, m[i]->absorption.g,
                              m[i]->absorption.b };
        const double s[3] = { m[i]->scattering.r, m[i]->scattering.g,
                              m[i]->scattering.b };
        for (int k = 0; k < 3; k++) {
            ext[k] += dn[k] * (a[k] + m[i]->sc_ext * s[k]);
            sca[k] += dn[k] * s[k];
        }
    }
}

static bool grey3(const double c[3])
{
    return c[0] == c[1] && c[1] == c[2];
}

/* rgb coefficient -> its value at lambda (Burns' curves, linear in rgb;
** grey is flat). */
static double at_lambda(const double c[3], double lambda)
{
    return grey3(c) ? c[0] : spec_reflectance(c, lambda);
}

/* Appends a tagged media photon to 'out'. */
static void append(struct ptrace_out *out, vec3 p, double power,
                   double lambda, vec3 from)
{
    ptrace_out_push(out, p, power,
                    PMEDIA_TAG + (float)(lambda < 0.0 ? -1.0 : lambda), from);
}

/* POV-Ray's landing factor of a photon 'depth' along its path (trace.c):
** D^2 (not for parallel lights) and the light's fade. */
static double landing(const struct ptrace_combo *c, double depth)
{
    double f = c->parallel ? 1.0 : depth * depth;
    if (c->fade_power > 0.0 && fabs(c->fade_distance) > 1e-10)
        f *= 2.0 / (1.0 + pow(depth / c->fade_distance, c->fade_power));
    return f;
}

/* Each sibling's power (an 'equal' set keeps the common one in
** power[0] only: trace.h). */
static double sib_power(const struct ptrace_sibs *s, int j)
{
    return s->equal ? s->power[0] : s->power[j];
}

/* Multiplies each sibling's power by exp(-od[j]); an 'equal' set stays
** equal when every od[j] is the same (a grey medium). */
static void sib_extinguish(struct ptrace_sibs *s, const double od[],
                           bool same)
{
    if (s->equal && !same) {
        for (int j = 1; j < s->n; j++)
            s->power[j] = s->power[0];
        s->equal = false;
    }
    int n = s->equal ? 1 : s->n;
    for (int j = 0; j < n; j++) {
        double t = s->power[j] * exp(-od[j]);
        s->power[j] = isfinite(t) ? t : 0.0; /* negative absorption */
    }
}

void pmedia_segment(const struct ptrace_combo *c,
                    const iris_object *const *stack, int n_stack, vec3 o,
                    vec3 d, double len, double depth0, int level,
                    struct ptrace_sibs *sb, bool *chroma, rng *r,
                    struct ptrace_out *out)
{
    const struct pmedia_path *mp = &c->media;
    if (!mp->scene || !(len > 0.0) || !isfinite(len))
        return;
    /* POV-Ray's IsHollowRay: media only outside non-hollow objects */
    const iris_media *m[PMEDIA_MAX];
    int n = 0, n_interior;
    for (int i = 0; i < n_stack; i++) {
        if (!stack[i]->hollow)
            return;
        const iris_interior *in = stack[i]->interior;
        for (int j = 0; in && j < in->n_media && n < PMEDIA_MAX; j++)
            m[n++] = in->media[j];
    }
    n_interior = n;
    const iris_scene *sc = mp->scene;
    for (int j = 0; j < sc->n_media && n < PMEDIA_MAX; j++)
        m[n++] = sc->media[j];
    if (n == 0)
        return;
    /* Siblings (trace.h): each its own optical depth at its own
    ** wavelength (Beer-Lambert per sibling, as the coloured fade); the
    ** media photons of a chromatic path one sibling a step, in turn
    ** (below). */
    const int ns = sb->n;

    /* 'im': the interior medium with the most intervals (POV-Ray's
    ** IMedia), which sets the sampling */
    bool constant = true, scatters = false, collects = false;
    const iris_media *im = m[0];
    for (int i = 0; i < n; i++) {
        constant = constant && m[i]->n_densities == 0;
        if (i < n_interior) {
            scatters = scatters || medium_scatters(m[i]);
            collects = collects || !m[i]->ignore_photons;
            if (m[i]->intervals > im->intervals)
                im = m[i];
        }
    }
    /* POV-Ray: not into media that all have 'collect off' */
    bool deposit = level > 1 && mp->max_steps > 0 && scatters && collects;
    double ext[3], sca[3];
    double od[PTRACE_SIBS];
    if (!deposit && constant) {
        /* Beer-Lambert in closed form */
        coefficients(c->mat, m, n, o, d, ext, sca);
        bool grey = grey3(ext);
        for (int j = 0; j < ns; j++)
            od[j] = at_lambda(ext, sb->lambda[j]) * len;
        if (!grey && od[0] != 0.0)
            *chroma = true;
        sib_extinguish(sb, od, grey);
        return;
    }

    /* Steps: the deposits' (POV-Ray's count per interval), or stratified
    ** samples of the densities for the extinction alone */
    int intervals = deposit && im->intervals > 1 ? im->intervals : 1;
    double ds = len / intervals;
    double jitter = sc->settings.photons.jitter >= 0.0
                        ? sc->settings.photons.jitter : 0.4;
    for (int j = 0; j < ns; j++)
        od[j] = 0.0;
    bool chromatic_od = false;
    /* the sibling of the segment's first deposit (the rest follow in
    ** turn): uniform, so that each sibling's expected deposit at every
    ** step is its own (one draw a segment, none for one wavelength) */
    int turn = deposit && ns > 1 ? (int)(rng_uniform(r) * ns) : 0;
    if (turn >= ns)
        turn = ns - 1;
    for (int iv = 0; iv < intervals; iv++) {
        int steps;
        if (deposit) {
            double spacing = c->parallel ? mp->spread
                                         : tan(mp->spread) * depth0;
            double want = ds / (spacing * mp->factor);
            steps = want >= mp->max_steps || !isfinite(want)
                        ? mp->max_steps : (int)want;
            if (steps < 1)
                steps = 1;
        } else {
            steps = im->intervals * im->min_samples;
            steps = steps < 1 ? 1 : steps > PMEDIA_MAX_SAMPLES
                                        ? PMEDIA_MAX_SAMPLES : steps;
            jitter = 1.0;
        }
        double step = ds / steps;
        for (int k = 0; k < steps; k++) {
            double u = rng_uniform(r);
            double f = k + 0.5 + jitter * (u - 0.5);
            double s_in = f * step;        /* from the interval's start */
            double s = iv * ds + s_in;
            vec3 p = v3_madd(o, d, s);
            coefficients(c->mat, m, n, p, d, ext, sca);
            bool grey = grey3(ext);
            double sig[PTRACE_SIBS];
            for (int j = 0; j < ns; j++)
                sig[j] = at_lambda(ext, sb->lambda[j]);
            if (sig[0] != 0.0 && !grey)
                chromatic_od = true;
            if (deposit) {
                if (chromatic_od)
                    *chroma = true;
                /* A chromatic path stores one record a step: the
                ** siblings in turn, each with ns times its power
                ** (unbiased: with the uniform first turn, sibling j
                ** deposits at each step with probability 1/ns). Not one
                ** record per sibling at the same point: the media map
                ** would triple, and the k nearest records would be k/3
                ** distinct points, a lattice-like kNN estimate biased low
                ** by ~4% (test_sibling_media: as one wavelength with k/3).
                ** In turn, a gather meets three wavelengths along each
                ** path it crosses. A white path: one white record of the
                ** siblings' summed power. */
                double land = landing(c, depth0 + s);
                double here = s_in - k * step, sum;
                int mult = ns; /* equal siblings: one of them times ns */
                if (*chroma) {
                    sum = sib_power(sb, turn) * exp(-(od[turn] +
                                                      sig[turn] * here));
                } else if (sb->equal) {
                    sum = sb->power[0] * exp(-(od[0] + sig[0] * here));
                } else {
                    sum = 0.0;
                    mult = 1;
                    for (int j = 0; j < ns; j++)
                        sum += sb->power[j] * exp(-(od[j] + sig[j] * here));
                }
                /* one wavelength: power·exp·landing·step, as before */
                double phi = sum * land * step * mult;
                if (phi > 0.0 && isfinite(phi))
                    append(out, p, phi, *chroma ? sb->lambda[turn] : -1.0,
                           v3_neg(d));
                if (*chroma && ++turn == ns)
                    turn = 0;
                if (out->failed) {
                    for (int j = 0; j < ns; j++)
                        sb->power[j] = 0.0;
                    return;
                }
            }
            for (int j = 0; j < ns; j++)
                od[j] += sig[j] * step;
        }
    }
    if (chromatic_od)
        *chroma = true;
    /* 'same': every sibling has the same optical depth (grey media) */
    bool same = true;
    for (int j = 1; j < ns; j++)
        same = same && od[j] == od[0];
    sib_extinguish(sb, od, same);
}

/* ------------------------------------------------------------------ */
/* The map                                                              */
/* ------------------------------------------------------------------ */

const struct pmedia_map *pmedia_of(const struct photon_map *m)
{
    return m ? m->media : NULL;
}

void pmedia_map_destroy(struct pmedia_map *m)
{
    if (!m)
        return;
    pstore_fini(&m->store);
    iris_free(m);
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/*
** The automatic search radius (see the header comment): the median over
** sampled media photons of the radius holding k of them, r0 =
** (3k/(4·pi·rho))^(1/3) at the median density rho, times 1 + 20·(the
** fraction of samples with 0.05 rho < rho_i < 0.7 rho within r0), times
** 2 (POV-Ray's media doubling).
*/
static double auto_radius(const struct pstore *s, int k)
{
    if (s->n == 0 || k <= 0)
        return 0.0;
    size_t m = s->n / 20;
    m = m < 100 ? 100 : m > 1000 ? 1000 : m;
    if (m > s->n)
        m = s->n;
    struct pstore_found *buf = iris_malloc((size_t)k * sizeof *buf);
    double *r2s = iris_malloc(m * sizeof *r2s);
    if (!buf || !r2s) {
        iris_free(buf);
        iris_free(r2s);
        return 0.0;
    }
    size_t used = 0;
    for (size_t i = 0; i < m; i++) {
        double r2;
        size_t idx = i * s->n / m;
        int got = pstore_knn(s, pstore_position(s, idx), k, INFINITY, buf,
                             &r2);
        /* fewer than k photons in all: scale the volume to k */
        if (got > 1 && r2 > 0.0 && isfinite(r2))
            r2s[used++] = r2 * pow((double)k / got, 2.0 / 3.0);
    }
    double r0 = 0.0;
    if (used > 0) {
        qsort(r2s, used, sizeof *r2s, cmp_double);
        r0 = sqrt(r2s[used / 2]);
        double rho = 3.0 * k / (4.0 * M_PI * r0 * r0 * r0);
        size_t less = 0;
        for (size_t i = 0; i < m; i++) {
            double r2;
            size_t idx = i * s->n / m;
            int got = pstore_knn(s, pstore_position(s, idx), k, r0 * r0,
                                 buf, &r2);
            double rr = got >= k ? sqrt(r2) : r0;
            double rh = got / (4.0 / 3.0 * M_PI * rr * rr * rr);
            if (rh > 0.05 * rho && rh < 0.7 * rho)
                less++;
        }
        r0 *= 1.0 + 20.0 * (double)less / (double)m;
    }
    iris_free(buf);
    iris_free(r2s);
    return 2.0 * r0;
}

enum iris_status pmedia_take(const iris_scene *scene, struct pstore_raw *all,
                             size_t *n, int threads, struct pmedia_map **out)
{
    *out = NULL;
    if (!all || *n == 0 || !pmedia_scene_wants_photons(scene))
        return IRIS_OK;
    size_t count = 0;
    for (size_t i = 0; i < *n; i++)
        count += all[i].lambda >= PMEDIA_TAG - 2.0f;
    if (count == 0)
        return IRIS_OK;
    struct pmedia_map *pm = iris_calloc(1, sizeof *pm);
    struct pstore_raw *mr = iris_malloc(count * sizeof *mr);
    if (!pm || !mr) {
        iris_free(pm);
        iris_free(mr);
        return IRIS_ENOMEM;
    }
    /* a stable split: both kinds keep their order (the maps do not
    ** depend on the thread count) */
    size_t w = 0, k = 0;
    for (size_t i = 0; i < *n; i++) {
        if (all[i].lambda >= PMEDIA_TAG - 2.0f) {
            mr[k] = all[i];
            mr[k].lambda -= PMEDIA_TAG;
            if (mr[k].lambda < 0.0f)
                mr[k].lambda = -1.0f;
            k++;
        } else {
            all[w++] = all[i];
        }
    }
    *n = w;
    enum iris_status rc = pstore_build_in_place(&pm->store, mr, count,
                                                threads);
    if (rc != IRIS_OK) {
        iris_free(pm);
        return rc;
    }
    const iris_photon_settings *ps = &scene->settings.photons;
    pm->gather_min = ps->gather_min > 0 ? ps->gather_min : 0;
    pm->gather_max = ps->gather_max > PSTORE_MAX_K ? PSTORE_MAX_K
                                                   : ps->gather_max;
    pm->expand_tol = ps->expand_tol;
    pm->expand_min = ps->expand_min;
    pmap_white_matrix(pm->white);
    pm->radius = auto_radius(&pm->store, pm->gather_max);
    *out = pm;
    return IRIS_OK;
}

/* ------------------------------------------------------------------ */
/* The estimate                                                         */
/* ------------------------------------------------------------------ */

static int gather(const struct pmedia_map *pm, vec3 p, double rad,
                  struct pstore_found *buf, double *r)
{
    double r2;
    int n = pstore_knn(&pm->store, p, pm->gather_max, rad * rad, buf, &r2);
    *r = n >= pm->gather_max ? sqrt(r2) : rad;
    return n;
}

void pmedia_gather(const struct pmedia_map *pm, const iris_media *const *m,
                   int n, vec3 p, vec3 dir, const double sca[3],
                   double emi[3])
{
    if (!pm || pm->store.n == 0 || n <= 0 || !(pm->radius > 0.0) ||
        (sca[0] == 0.0 && sca[1] == 0.0 && sca[2] == 0.0))
        return;
    struct pstore_found stack_buf[PMEDIA_STACK_K], *buf = stack_buf;
    if (pm->gather_max > PMEDIA_STACK_K) {
        buf = iris_malloc((size_t)pm->gather_max * sizeof *buf);
        if (!buf)
            return;
    }
    double r;
    int got = gather(pm, p, pm->radius, buf, &r);
    if (got < pm->gather_min) {
        /* POV-Ray's gatherPhotonsAdaptive: one expansion to 3R, kept when
        ** the density (n/r^2, as POV-Ray's) did not jump or when few
        ** photons were found */
        double r_old = r;
        int n_old = got;
        got = gather(pm, p, 3.0 * pm->radius, buf, &r);
        double rho_old = n_old / (r_old * r_old), rho_new = got / (r * r);
        bool accept = (n_old > 0 && (rho_new - rho_old) / rho_old <
                                        pm->expand_tol) ||
                      (got > 0 && got < pm->expand_min) || n_old == 0;
        if (!accept)
            got = gather(pm, p, pm->radius, buf, &r);
    }
    bool isotropic = true;
    for (int i = 0; i < n; i++)
        isotropic = isotropic && phase_is_one(m[i]);
    double white_rgb[3];
    for (int k = 0; k < 3; k++)
        white_rgb[k] = pm->white[k][0] * sca[0] + pm->white[k][1] * sca[1] +
                       pm->white[k][2] * sca[2];
    double sum[3] = { 0, 0, 0 };
    for (int i = 0; i < got; i++) {
        size_t j = buf[i].index;
        double k = 1.0;
        if (!isotropic) {
            double alpha = v3_dot(pstore_direction(&pm->store, j), dir);
            k = 0.0;
            for (int q = 0; q < n; q++)
                k += pmedia_phase(m[q], alpha);
            k /= n;
        }
        double c = k * pm->store.ph[j].power;
        if (pm->store.ph[j].lambda_q == PSTORE_WHITE) {
            for (int q = 0; q < 3; q++)
                sum[q] += c * white_rgb[q];
            continue;
        }
        double lambda = pstore_lambda(&pm->store, j);
        double s = spec_reflectance(sca, lambda), wt[3];
        spec_lambda_rgb_weight(lambda, wt);
        for (int q = 0; q < 3; q++)
            sum[q] += c * s * wt[q];
    }
    if (buf != stack_buf)
        iris_free(buf);
    if (got <= 0 || !(r > 0.0))
        return;
    double norm = 3.0 / (4.0 * M_PI * r * r * r);
    for (int q = 0; q < 3; q++)
        if (isfinite(sum[q] * norm))
            emi[q] += sum[q] * norm;
}
