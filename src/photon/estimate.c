/* SPDX-License-Identifier: MIT */
/*
** estimate.c: the photon radiance estimate at a surface point, the
** automatic gather radius, and POV-Ray's shadow rule for targets.
**
** Estimate (DESIGN.md, semantics §2.7). The k = gather-max photons nearest
** to the point within the search radius R (expanded once to 3R, POV-Ray's
** adaptive rule, when fewer than gather-min are found) are weighted by the
** seed paper's cone filter w = 1 - d/(kc·r), where r is the distance of
** the farthest photon found (R when fewer than k were found) and kc the
** cone constant (1 here: the weight falls to 0 at r; this kc is not the
** photon count k). Over a disc of uniform density the mean weight is
** 1 - 2/(3·kc), so the sum is divided by that and by the disc area pi·r^2.
** Each photon is shaded as POV-Ray shades it, like a light of colour
** Phi·a in its direction omega with a = 1/clamp(N_raw·omega, 0.1, 1):
** diffuse·|N_layer·omega|^brilliance·opacity — but the pigment enters as
** the reflectance rho(lambda_j) at the photon's own wavelength, and the
** photon becomes linear sRGB through spec_lambda_rgb_weight(lambda_j). A
** white photon (trace.c, pstore.h) stands for every wavelength and adds
** white·pigment, the mean over the spectrum (pmap_white_matrix()).
** POV-Ray also adds phong/specular highlights from photons; iris does not
** (yet).
**
** Progressive passes (progressive.c) scale the estimate radius: r_e = s·r
** with s = estimate_scale <= 1 from the pass schedule, and only photons
** closer than r_e count (the cone weight is 0 beyond it). Why the scaled
** k-nearest radius of the pass's own map is the per-point radius: it adapts
** to the density (a focused caustic is 1e3 times denser than its
** surroundings, where any one global radius fails), and for s < 1 the
** estimate stays unbiased over a uniform density although the radius comes
** from the same photons: given r, the other k-1 photons are uniform in the
** disc of radius r, (k-1)·s^2 of them fall inside r_e on average, and
** E[(k-1)/(pi·r^2)] = rho exactly (pi·r^2·rho is Gamma(k, 1) distributed).
** All passes shoot the same number of photons, so r is distributed alike in
** every pass: the pass's own k-nearest radius stands for the pilot radius
** r_1(x) of Knaus and Zwicker's schedule without storing a radius per point.
*/
#include "config.h"

#include "photon/pmap.h"

#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "spectrum/spectrum.h"
#include "util/mem.h"
#include "util/rng.h"
#include "util/thread.h"

#define STACK_K 512

/* The k nearest within radius 'rad'; *r gets the estimate radius. */
static int gather(const struct photon_map *m, vec3 p, double rad,
                  struct pstore_found *buf, double *r)
{
    double r2;
    int n = pstore_knn(&m->store, p, m->gather_max, rad * rad, buf, &r2);
    *r = n >= m->gather_max ? sqrt(r2) : rad;
    return n;
}

/* The estimate of one map (caustic or global) at 'in'. */
static void shade_map(const struct photon_map *m,
                      const struct photon_shade_input *in, double rgb_out[3])
{
    rgb_out[0] = rgb_out[1] = rgb_out[2] = 0.0;
    if (!m || m->store.n == 0)
        return;
    const iris_finish *fin = in->finish;
    if (!(fin->diffuse > 0.0) && !(fin->diffuse_back > 0.0))
        return;
    struct pstore_found stack_buf[STACK_K];
    struct pstore_found *buf = stack_buf;
    if (m->gather_max > STACK_K) {
        buf = iris_malloc((size_t)m->gather_max * sizeof *buf);
        if (!buf)
            return;
    }
    double r;
    int n = gather(m, in->p, m->radius, buf, &r);
    if (n < m->gather_min) {
        /* POV-Ray's adaptive expansion: accept the 3R search if the
        ** density did not jump, or if it found only a few photons */
        double r_old = r;
        int n_old = n;
        n = gather(m, in->p, 3.0 * m->radius, buf, &r);
        double rho_old = n_old / (r_old * r_old), rho_new = n / (r * r);
        bool accept = (n_old > 0 && (rho_new - rho_old) / rho_old <
                                        m->expand_tol) ||
                      (n > 0 && n < m->expand_min) || n_old == 0;
        if (!accept)
            n = gather(m, in->p, m->radius, buf, &r);
    }
    if (m->estimate_scale > 0.0 && m->estimate_scale < 1.0)
        r *= m->estimate_scale;
    double sum[3] = { 0, 0, 0 };
    double kc = m->cone_k;
    double white_rgb[3]; /* a white photon's rgb on this pigment */
    for (int k = 0; k < 3; k++)
        white_rgb[k] = m->white[k][0] * in->pigment_rgb[0] +
                       m->white[k][1] * in->pigment_rgb[1] +
                       m->white[k][2] * in->pigment_rgb[2];
    double r2 = r * r;
    for (int i = 0; i < n && r > 0.0; i++) {
        /* outside the (progressive) estimate radius first: no decoding */
        if (buf[i].d2 > r2)
            continue;
        double d = sqrt(buf[i].d2);
        double w = 1.0 - d / (kc * r);
        if (w <= 0.0)
            continue;
        size_t j = buf[i].index;
        vec3 om = pstore_direction(&m->store, j);
        double cos_l = v3_dot(in->n_layer, om);
        double diffuse = fin->diffuse;
        if (cos_l <= 1e-10) {
            if (!(fin->diffuse_back > 0.0))
                continue;
            diffuse = fin->diffuse_back;
            cos_l = -cos_l;
        }
        double cos_raw = v3_dot(in->n_raw, om);
        double a = 1.0 / (cos_raw < 0.1 ? 0.1 : cos_raw > 1.0 ? 1.0 : cos_raw);
        double br = fin->brilliance == 1.0 ? cos_l
                                           : pow(cos_l, fin->brilliance);
        double c = w * m->store.ph[j].power * diffuse * br * a;
        if (m->store.ph[j].lambda_q == PSTORE_WHITE) {
            for (int k = 0; k < 3; k++)
                sum[k] += c * white_rgb[k];
            continue;
        }
        double lambda = pstore_lambda(&m->store, j);
        double rho = spec_reflectance(in->pigment_rgb, lambda);
        double wt[3];
        spec_lambda_rgb_weight(lambda, wt);
        for (int k = 0; k < 3; k++)
            sum[k] += c * rho * wt[k];
    }
    if (buf != stack_buf)
        iris_free(buf);
    if (!(r > 0.0))
        return;
    double norm = in->opacity / ((1.0 - 2.0 / (3.0 * kc)) * M_PI * r * r);
    for (int k = 0; k < 3; k++)
        rgb_out[k] = sum[k] * norm;
}

/* The caustic map's light plus the global map's (global.c): the two hold
** disjoint paths, so they add. */
void photon_map_shade(const struct photon_map *m,
                      const struct photon_shade_input *in, double rgb_out[3])
{
    rgb_out[0] = rgb_out[1] = rgb_out[2] = 0.0;
    if (!m || !in->finish || (in->obj && !in->obj->photon_collect))
        return;
    shade_map(m, in, rgb_out);
    if (m->global) {
        double g[3];
        pmap_global_shade(m->global, in, g);
        for (int k = 0; k < 3; k++)
            rgb_out[k] += g[k];
    }
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/*
** POV-Ray's automatic radius (semantics §2.6) estimates a typical density
** rho over sampled photons at gather-max neighbours and gives
** r0 = sqrt(max/(pi·rho)), enlarged where many samples see much lower
** density (sparse regions). Samples are photons at evenly spaced indices,
** so the radius is deterministic.
**
** Why the MEDIAN of the samples' k-nearest radii and not POV-Ray's mean
** density: the mean of n/(pi·r^2) is ruled by its largest term, and a
** caustic focus where k photons nearly coincide (r ~ 1e-8) makes one
** sample 1e14 times denser than the rest, so r0 became ~1e-15 and the
** caustic vanished. Stray photons on a huge far object pull the other way
** (they raised r0 from 0.35 to 1.37 in thin.pov with a 1e6 sky sphere).
** The median moves with neither unless they are half the samples: it is
** the radius that gathers k photons at a typical stored photon. The
** enlargement for sparse regions is measured against the median density.
** Should half the samples still coincide (a map of one point), r0 is
** floored at 1e-6 of the photons' extent (the quantisation box, pstore.c),
** far below any gather radius a scene needs, yet not a degenerate 0.
*/
/* The sampled photons' k-nearest searches, in parallel (one buffer a
** thread): pass 1 records r^2 scaled to k photons (-1: unusable), pass 2
** the density within r0 (rho_out). */
struct radius_job {
    const struct pstore *s;
    int k;
    size_t m;
    struct pstore_found *bufs;   /* 'stride' a thread, k used */
    size_t stride;
    double *r2s;
    double r0;                   /* pass 2 */
    double *rho_out;
};

static void radius_sample(void *ctx, int64_t i, int thread)
{
    struct radius_job *j = ctx;
    const struct pstore *s = j->s;
    struct pstore_found *buf = j->bufs + (size_t)thread * j->stride;
    size_t idx = (size_t)i * s->n / j->m;
    double r2;
    if (!j->rho_out) {
        int n = pstore_knn(s, pstore_position(s, idx), j->k, INFINITY, buf,
                           &r2);
        /* fewer than k photons in the whole map: scale r^2 to k */
        j->r2s[i] = n > 1 && isfinite(r2) ? r2 * j->k / n : -1.0;
        return;
    }
    int n = pstore_knn(s, pstore_position(s, idx), j->k, j->r0 * j->r0, buf,
                       &r2);
    double rr = n >= j->k ? r2 : j->r0 * j->r0;
    j->rho_out[i] = n / (M_PI * rr);
}

double pmap_auto_radius(const struct pstore *s, int gather_max)
{
    return pmap_auto_radius_mt(s, gather_max, 1);
}

double pmap_auto_radius_mt(const struct pstore *s, int gather_max,
                           int threads)
{
    if (s->n == 0 || gather_max <= 0)
        return 0.0;
    if (threads < 1)
        threads = 1;
    size_t m = s->n / 20;
    m = m < 100 ? 100 : m > 1000 ? 1000 : m;
    if (m > s->n)
        m = s->n;
    struct radius_job j = { s, gather_max, m, NULL, 0, NULL, 0.0, NULL };
    /* at least a cache line between two threads' buffers: the k-nearest
    ** heap is written at every photon it keeps, the root at the buffer's
    ** start and the last entries at its end, and a line shared by two
    ** threads' heaps would move between the cores at such writes */
    j.stride = (size_t)gather_max + (64 + sizeof *j.bufs - 1) / sizeof *j.bufs;
    j.bufs = iris_malloc((size_t)threads * j.stride * sizeof *j.bufs);
    j.r2s = iris_malloc(m * sizeof *j.r2s);
    double *rho = iris_malloc(m * sizeof *rho);
    if (!j.bufs || !j.r2s || !rho) {
        iris_free(j.bufs);
        iris_free(j.r2s);
        iris_free(rho);
        return 0.0;
    }
    par_for(threads, (int64_t)m, radius_sample, &j);
    size_t used = 0;
    for (size_t i = 0; i < m; i++)
        if (j.r2s[i] >= 0.0)
            j.r2s[used++] = j.r2s[i];
    double r0 = 0.0;
    if (used > 0) {
        qsort(j.r2s, used, sizeof *j.r2s, cmp_double);
        double med = used % 2 ? j.r2s[used / 2]
                              : 0.5 * (j.r2s[used / 2 - 1] + j.r2s[used / 2]);
        double ext = 0.0; /* the extent of the quantisation box */
        for (int a = 0; a < 3; a++)
            ext = fmax(ext, s->step[a] * 1048575.0);
        double floor_r = 1e-6 * ext;
        r0 = sqrt(med);
        if (!(r0 > floor_r))
            r0 = floor_r;
        double rho_med = gather_max / (M_PI * r0 * r0);
        j.r0 = r0;
        j.rho_out = rho;
        par_for(threads, (int64_t)m, radius_sample, &j);
        size_t less = 0;
        for (size_t i = 0; i < m; i++)
            if (rho[i] > 0.05 * rho_med && rho[i] < 0.7 * rho_med)
                less++;
        r0 *= 1.0 + 20.0 * (double)less / (double)m;
    }
    iris_free(rho);
    iris_free(j.r2s);
    iris_free(j.bufs);
    return r0;
}

bool photon_blocks_shadow(const struct photon_map *m,
                          const iris_object *blocker, const iris_light *light,
                          const iris_object *lit)
{
    if (!m || m->store.n == 0 || !blocker || !light)
        return false;
    if (lit && !lit->photon_collect)
        return false;
    return blocker->photon_target &&
           blocker->photon_refraction != IRIS_OFF &&
           light->photon_refraction != IRIS_OFF &&
           (blocker->photon_refraction == IRIS_ON ||
            light->photon_refraction == IRIS_ON);
}

/* The matrix, computed once: 12000 spectral evaluations, which every
** progressive pass's map build repeated on one thread (1.5 M
** instructions a pass, callgrind) while the other threads waited. */
static double white_matrix[3][3];
static pthread_once_t white_once = PTHREAD_ONCE_INIT;

static void white_matrix_init(void)
{
    enum { STEPS = 4000 };
    double (*out)[3] = white_matrix;
    for (int i = 0; i < STEPS; i++) {
        double lambda = SPEC_LAMBDA_MIN + SPEC_LAMBDA_RANGE * (i + 0.5) / STEPS;
        double wt[3];
        spec_lambda_rgb_weight(lambda, wt);
        for (int c = 0; c < 3; c++) {
            double e[3] = { c == 0, c == 1, c == 2 };
            double rho = spec_reflectance(e, lambda);
            for (int k = 0; k < 3; k++)
                out[k][c] += rho * wt[k] / STEPS;
        }
    }
}

void pmap_white_matrix(double out[3][3])
{
    pthread_once(&white_once, white_matrix_init);
    memcpy(out, white_matrix, sizeof white_matrix);
}

void photon_map_destroy(struct photon_map *m)
{
    if (!m)
        return;
    photon_map_destroy(m->global);
    pmedia_map_destroy(m->media);
    iris_free(m->irr);
    pstore_fini(&m->store);
    iris_free(m);
}
