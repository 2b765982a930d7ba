/* SPDX-License-Identifier: MIT */
/*
** media.c: participating media on a ray segment (see media.h), following
** what POV-Ray 3.7's media.cpp computes: the segment is cut into lit and
** unlit parts by the spot and cylinder light cones (point lights light
** all of it), those into sampling intervals, and each interval sampled
** by method 1 (random positions), 2 (stratified) or 3 (adaptive: the
** ends and the middle of each sub-interval, subdivided where the
** samples differ by more than aa_threshold, up to aa_level; as POV-Ray
** 3.7.0 does it, the version installed for the parity tests). The
** colour 'rgb' coming from the segment's end reaches its start as
** rgb·exp(-τ) + Σ emitted·exp(-τ before it), as ComputeMediaColour
** sums it.
*/
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "photon/pmedia.h"
#include "render/focalblur.h"
#include "render/media.h"
#include "util/mem.h"

#define M_EPSILON 1e-10
#define SMALL_TOLERANCE 0.001    /* POV-Ray's, lit-interval ends */
#define MAX_DISTANCE 1.0e7       /* POV-Ray's open ends of light cones */
#define STACK_INTERVALS 64
#define MAX_INTERVALS (1 << 16)

/* A sampling interval and its sums (POV-Ray's MediaInterval). */
struct interval {
    bool lit;
    double s0, s1, ds;
    double od[3], te[3], te2[3];
    int samples;
};

/* The part of the segment one light lights (LightSourceEntry). */
struct lit_light {
    int idx;
    double s0, s1;
};

/* A lit or unlit stretch of the segment (LitInterval). */
struct lit_span {
    bool lit;
    double s0, s1;
};

/* What one segment's sampling needs. */
struct seg {
    struct trace_ctx *c;
    const iris_media *const *m;
    int n;
    const struct tray *r;
    bool shadow;
    bool scattering;           /* some media scatters */
    const struct lit_light *lights;
    int n_lights;
    const iris_media *im;      /* the media with the most intervals */
    const struct pmedia_map *pm; /* media photons to gather, or NULL */
};

bool media_in_stack(const struct interior_stack *st)
{
    for (int i = 0; i < st->n; i++)
        if (st->e[i].in && st->e[i].in->n_media > 0)
            return true;
    return false;
}

int media_of_stack(const struct interior_stack *st, const iris_media **out,
                   int max)
{
    int n = 0;
    for (int i = 0; i < st->n; i++) {
        const iris_interior *in = st->e[i].in;
        for (int j = 0; in && j < in->n_media && n < max; j++)
            out[n++] = in->media[j];
    }
    return n;
}

static double rnd(struct trace_ctx *c)
{
    return rng_uniform(rng_lazy_get(&c->rng));
}

/* The product of the densities' colours at 'p' (1 without densities). */
static void density_at(const struct tracer *t, const iris_media *m, vec3 p,
                       vec3 d, double out[3])
{
    out[0] = out[1] = out[2] = 1.0;
    for (int i = 0; i < m->n_densities; i++) {
        struct mat_point pt = { p, v3(0, 0, 0), d, { 0, 0 }, NULL, true };
        iris_colour col;
        if (!mat_eval_pigment(t->mat, m->densities[i], &pt, &col))
            col.r = col.g = col.b = 0.0;
        out[0] *= col.r;
        out[1] *= col.g;
        out[2] *= col.b;
    }
}

/* POV-Ray's phase functions (ComputeMediaScatteringAttenuation), not
** normalised: isotropic is 1 (pmedia.c, which the media photons' estimate
** shares). 'alpha' is the cosine between the ray direction and the
** direction towards the light. */
static double phase(const iris_media *m, double alpha)
{
    return pmedia_phase(m, alpha);
}

/*
** POV-Ray's ComputeOneMediaSample at fraction 'f' of interval 'iv': the
** emitted (and in-scattered) light 'col' of the interval and its optical
** depth 'od', both for the interval's whole length. Methods 1 and 2 also
** add to the interval's sums; method 3 leaves that to its caller.
*/
static void sample(const struct seg *s, struct interval *iv, double f,
                   int method, double col[3], double od[3])
{
    const struct tracer *t = s->c->t;
    double d0 = f * iv->ds, dist = iv->s0 + d0;
    vec3 p = v3_madd(s->r->r.o, s->r->r.d, dist);
    double ext[3] = { 0, 0, 0 }, emi[3] = { 0, 0, 0 }, sca[3] = { 0, 0, 0 };
    for (int i = 0; i < s->n; i++) {
        const iris_media *m = s->m[i];
        double dn[3];
        density_at(t, m, p, s->r->r.d, dn);
        const double a[3] = { m->absorption.r, m->absorption.g,
                              m->absorption.b };
        const double e[3] = { m->emission.r, m->emission.g, m->emission.b };
        const double sc[3] = { m->scattering.r, m->scattering.g,
                               m->scattering.b };
        for (int k = 0; k < 3; k++) {
            ext[k] += dn[k] * (a[k] + m->sc_ext * sc[k]);
            if (!s->shadow) {
                emi[k] += dn[k] * e[k];
                sca[k] += dn[k] * sc[k];
            }
        }
    }
    for (int k = 0; k < 3; k++)
        od[k] = ext[k] * iv->ds;
    if (method != 3)
        for (int k = 0; k < 3; k++)
            iv->od[k] += od[k];
    if (!s->shadow && s->scattering && iv->lit &&
        (sca[0] != 0.0 || sca[1] != 0.0 || sca[2] != 0.0)) {
        for (int i = 0; i < s->n_lights; i++) {
            const struct lit_light *ll = &s->lights[i];
            if (!(dist >= ll->s0 && dist <= ll->s1))
                continue;
            vec3 L;
            double lc[3];
            if (!trace_media_light(s->c, &s->r->st, ll->idx, p, &L, lc))
                continue;
            double alpha = v3_dot(L, s->r->r.d), k = 0.0;
            for (int j = 0; j < s->n; j++)
                k += phase(s->m[j], alpha);
            k /= s->n;
            for (int c = 0; c < 3; c++)
                emi[c] += k * sca[c] * lc[c];
        }
    }
    /* media photons, lit interval or not (POV-Ray's ComputeMediaPhotons) */
    if (s->pm && !s->shadow && s->scattering)
        pmedia_gather(s->pm, s->m, s->n, p, s->r->r.d, sca, emi);
    for (int k = 0; k < 3; k++) {
        /* method 3 attenuates in order later; 1 and 2 assume the
        ** extinction constant over the interval */
        col[k] = method == 3 ? emi[k] * iv->ds
                             : emi[k] * iv->ds * exp(-ext[k] * d0);
        if (method != 3) {
            iv->te[k] += col[k];
            iv->te2[k] += col[k] * col[k];
        }
    }
    iv->samples++;
}

static double colour_distance(const double a[3], const double b[3])
{
    return fabs(a[0] - b[0]) + fabs(a[1] - b[1]) + fabs(a[2] - b[2]);
}

/*
** POV-Ray's ComputeOneMediaSampleRecursive: the mean emission 'res' and
** optical depth 'odr' of the sub-interval (f1, f3) whose ends gave
** c1/od1 and c3/od3, from its (jittered) middle, subdivided while the
** colours differ by more than the threshold and 'depth' remains. The
** weights are POV-Ray's (1:1:1 at the last level, 2:1 and 1:2 halves).
*/
static void sample_recursive(const struct seg *s, struct interval *iv,
                             double f1, double f3, const double c1[3],
                             const double c3[3], const double od1[3],
                             const double od3[3], int depth, double thr,
                             double res[3], double odr[3])
{
    double f2 = 0.5 * (f1 + f3);
    double jd = f2;
    if (s->im->jitter != 0.0)
        jd += s->im->jitter * (f3 - f1) * (rnd(s->c) - 0.5);
    double c2[3], od2[3], r2[3], o2[3];
    sample(s, iv, jd, 3, c2, od2);
    if (depth <= 0) {
        for (int k = 0; k < 3; k++) {
            res[k] = (c1[k] + c2[k] + c3[k]) / 3.0;
            odr[k] = (od1[k] + od2[k] + od3[k]) / 3.0;
        }
        return;
    }
    if (colour_distance(c1, c2) > thr) {
        sample_recursive(s, iv, f1, f2, c1, c2, od1, od2, depth - 1, thr,
                         r2, o2);
        for (int k = 0; k < 3; k++) {
            res[k] = r2[k] / 2.0;
            odr[k] = o2[k] / 2.0;
        }
    } else {
        for (int k = 0; k < 3; k++) {
            res[k] = c1[k] / 3.0 + c2[k] / 6.0;
            odr[k] = od1[k] / 3.0 + od2[k] / 6.0;
        }
    }
    if (colour_distance(c2, c3) > thr) {
        sample_recursive(s, iv, f2, f3, c2, c3, od2, od3, depth - 1, thr,
                         r2, o2);
        for (int k = 0; k < 3; k++) {
            res[k] += r2[k] / 2.0;
            odr[k] += o2[k] / 2.0;
        }
    } else {
        for (int k = 0; k < 3; k++) {
            res[k] += c2[k] / 6.0 + c3[k] / 3.0;
            odr[k] += od2[k] / 6.0 + od3[k] / 3.0;
        }
    }
}

/*
** POV-Ray 3.7.0's ComputeMediaAdaptiveSampling (method 3), the version
** the parity tests compare with (3.7.0.10; 3.7.1 changed it): S =
** MIN/2 + 1 (at least 2) samples at 0, 1/(S+1), ..., S/(S+1) of the
** interval, each consecutive pair integrated by sample_recursive; the
** pair's mean emission is attenuated by the mean optical depth of the
** pairs before it, e^(-Σod/S), and the interval's sums are the means of
** the S pairs. (The last 1/(S+1) of the interval is not sampled, and
** no pair is attenuated by its own depth: a left Riemann sum, which
** 3.7.1 made exact for constant media.)
*/
static void adaptive_sampling(const struct seg *s, struct interval *iv,
                              int n_iv, double thr)
{
    const iris_media *im = s->im;
    int count = im->min_samples / 2 + 1;
    if (count < 2)
        count = 2;
    double dd = 1.0 / (count + 1), n = 1.0 / count;
    for (int i = 0; i < n_iv; i++) {
        struct interval *v = &iv[i];
        double c0[3], od0[3], c1[3], od1[3];
        double d0 = 0.0;
        double jj = im->jitter != 0.0 ? dd * im->jitter * (rnd(s->c) - 0.5)
                                      : 0.0;
        sample(s, v, d0 + jj, 3, c0, od0);
        memset(v->te, 0, sizeof v->te);
        memset(v->od, 0, sizeof v->od);
        d0 += dd;
        for (int j = 1; j <= count; j++, d0 += dd) {
            jj = im->jitter != 0.0 ? dd * im->jitter * (rnd(s->c) - 0.5)
                                   : 0.0;
            sample(s, v, d0 + jj, 3, c1, od1);
            double res[3], odr[3];
            sample_recursive(s, v, d0 - dd, d0, c0, c1, od0, od1,
                             im->aa_level - 1, thr, res, odr);
            for (int k = 0; k < 3; k++) {
                v->te[k] += res[k] * exp(-v->od[k] * n);
                v->od[k] += odr[k];
                c0[k] = c1[k];
                od0[k] = od1[k];
            }
        }
        v->samples = count;
    }
}

/* POV-Ray's ComputeMediaRegularSampling (methods 1 and 2, and shadow rays
** through constant media): min_samples per interval, then more while the
** variance of an interval's samples is above the confidence threshold. */
static void regular_sampling(const struct seg *s, struct interval *iv,
                             int n_iv, bool constant_shadow)
{
    const iris_media *im = s->im;
    int mins = im->min_samples;
    double col[3], od[3];
    for (int i = 0; i < n_iv; i++)
        for (int j = 0; j < mins; j++) {
            if (im->method == 2)
                sample(s, &iv[i], (j + 0.5) / mins +
                       rnd(s->c) * im->jitter / mins, 2, col, od);
            else
                sample(s, &iv[i], rnd(s->c), 1, col, od);
            if (constant_shadow)
                break;
        }
    if (s->shadow || im->max_samples <= mins)
        return;
    /* Media::PostProcess's thresholds: variance · chi2inv(i+1, conf) /
    ** chi2inv(max-1, conf) after i+1 samples */
    double t = chi2_upper_inv(im->max_samples - 1, im->confidence);
    t = t > 0.0 ? im->variance / t : im->variance * 1e-10;
    for (int i = 0; i < n_iv; i++) {
        struct interval *v = &iv[i];
        if (v->samples < 1 || v->samples >= im->max_samples)
            continue;
        /* as POV-Ray: sample until the variance of the mean is below the
        ** threshold for this many samples, or past max_samples */
        for (;;) {
            double n = 1.0 / v->samples;
            double thr = t * chi2_upper_inv(v->samples, im->confidence);
            bool small = true;
            for (int k = 0; k < 3; k++) {
                double va = (v->te2[k] * n - (v->te[k] * n) * (v->te[k] * n))
                            * n;
                small = small && va < thr; /* 3.7.0: no fabs */
            }
            if (small)
                break;
            sample(s, v, rnd(s->c), 1, col, od);
            if (v->samples > im->max_samples)
                break;
        }
    }
}

/* The roots t1 <= t2 of a t^2 + 2 b t + c = 0 when its discriminant
** b^2 - a c exceeds M_EPSILON (POV-Ray's test for a spot or cylinder
** light's boundary), and where they lie along the light's axis: l = k2 +
** t k1. */
static bool axis_roots(double a, double b, double c, double k1, double k2,
                       double *t1, double *t2, double *l1, double *l2)
{
    double d = b * b - a * c;
    if (!(d > M_EPSILON))
        return false;
    d = sqrt(d);
    *t1 = (-b + d) / a;
    *t2 = (-b - d) / a;
    if (*t1 > *t2) {
        double tmp = *t1;
        *t1 = *t2;
        *t2 = tmp;
    }
    *l1 = k2 + *t1 * k1;
    *l2 = k2 + *t2 * k1;
    return true;
}

/* POV-Ray's ComputeSpotLightInterval: where the ray is inside the cone
** of spot light 'l' ('cos_falloff' the cone's cosine). */
static bool spot_interval(const ray *r, const struct rlight *l, double *d1,
                          double *d2)
{
    double cf = l->cos_falloff;
    if (!(fabs(cf) > M_EPSILON))
        return false;
    double m = 1.0 / (cf * cf);
    vec3 v1 = v3_sub(r->o, l->centre);
    double k1 = v3_dot(r->d, l->dir), k2 = v3_dot(v1, l->dir);
    double len = v3_len(v1);
    bool in_cone = len > M_EPSILON && k2 / len >= cf;
    if (k1 <= 0.0 && k2 < 0.0)
        return false;
    double k3 = v3_dot(v1, r->d), k4 = v3_len2(v1);
    double a = 1.0 - k1 * k1 * m, b = k3 - k1 * k2 * m, c = k4 - k2 * k2 * m;
    if (a != 0.0) {
        double t1, t2, l1, l2;
        if (axis_roots(a, b, c, k1, k2, &t1, &t2, &l1, &l2)) {
            if (l1 <= 0.0 && l2 <= 0.0)
                return false;
            if (l1 <= 0.0 || l2 <= 0.0) {
                if (l1 <= 0.0) {
                    if (in_cone) {
                        t1 = 0.0;
                        t2 = t2 > 0.0 ? t2 : MAX_DISTANCE;
                    } else {
                        t1 = t2;
                        t2 = MAX_DISTANCE;
                    }
                } else {
                    if (in_cone) {
                        t2 = t1;
                        t1 = 0.0;
                    } else {
                        t2 = MAX_DISTANCE;
                    }
                }
            }
            *d1 = t1;
            *d2 = t2;
            return true;
        }
        if (b * b - a * c > -M_EPSILON) { /* tangent to the cone */
            if (in_cone) {
                *d1 = 0.0;
                *d2 = -b / a;
            } else {
                *d1 = -b / a;
                *d2 = MAX_DISTANCE;
            }
            return true;
        }
    } else if (in_cone) {
        *d1 = 0.0;
        *d2 = -c / b;
        return true;
    }
    return false;
}

/* POV-Ray's ComputeCylinderLightInterval: where the ray is within the
** falloff radius of cylinder light 'l'. */
static bool cylinder_interval(const ray *r, const struct rlight *l,
                              double *d1, double *d2)
{
    vec3 v1 = v3_sub(r->o, l->centre);
    double k1 = v3_dot(r->d, l->dir), k2 = v3_dot(v1, l->dir);
    if (k1 <= 0.0 && k2 < 0.0)
        return false;
    double a = 1.0 - k1 * k1;
    if (a == 0.0)
        return false;
    double k3 = v3_dot(v1, r->d), k4 = v3_len2(v1);
    double b = k3 - k1 * k2;
    double c = k4 - k2 * k2 - l->falloff * l->falloff;
    double t1, t2, l1, l2;
    if (!axis_roots(a, b, c, k1, k2, &t1, &t2, &l1, &l2))
        return false;
    if (l1 <= 0.0 && l2 <= 0.0)
        return false;
    if (l1 <= 0.0 || l2 <= 0.0) {
        if (l1 <= 0.0)
            t1 = 0.0;
        else
            t2 = (MAX_DISTANCE - k2) / k1;
    }
    *d1 = t1;
    *d2 = t2;
    return true;
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* POV-Ray's ComputeMediaLightInterval: the lights that interact with
** media (not shadowless ones) and the lit/unlit spans they make. Returns
** the number of spans written to 'spans' (room for 2·n_lights + 2);
** 's0' and 's1' are scratch for n_lights values each. */
static int light_spans(struct trace_ctx *c, const ray *r, double depth,
                       struct lit_light *ll, int *n_ll,
                       struct lit_span *spans, double *s0, double *s1)
{
    const struct tracer *t = c->t;
    int n = 0;
    for (int i = 0; i < t->n_lights; i++) {
        const struct rlight *l = &t->lights[i];
        if (!l->src->media_interaction || l->fill)
            continue;
        double t1 = 0.0, t2 = 0.0;
        bool insert;
        if (l->cylinder)
            insert = cylinder_interval(r, l, &t1, &t2) && t1 < depth &&
                     t2 > SMALL_TOLERANCE;
        else if (l->spot)
            insert = spot_interval(r, l, &t1, &t2) && t1 < depth &&
                     t2 > SMALL_TOLERANCE;
        else {
            t2 = depth;
            insert = true;
        }
        if (!insert)
            continue;
        ll[n].idx = i;
        ll[n].s0 = fmax(t1, 0.0);
        ll[n].s1 = fmin(t2, depth);
        n++;
    }
    *n_ll = n;
    if (n == 0)
        return 0;
    /* the starts and the ends sorted apart, as POV-Ray merges them */
    for (int i = 0; i < n; i++) {
        s0[i] = ll[i].s0;
        s1[i] = ll[i].s1;
    }
    qsort(s0, (size_t)n, sizeof *s0, cmp_double);
    qsort(s1, (size_t)n, sizeof *s1, cmp_double);
    int ns = 0;
    if (s0[0] > 0.0)
        spans[ns++] = (struct lit_span){ false, 0.0, s0[0] };
    spans[ns++] = (struct lit_span){ true, s0[0], s1[0] };
    for (int i = 1; i < n; i++) {
        if (s0[i] > spans[ns - 1].s1) {
            double e = spans[ns - 1].s1;
            spans[ns++] = (struct lit_span){ false, e, s0[i] };
            spans[ns++] = (struct lit_span){ true, s0[i], s1[i] };
        } else if (s1[i] > spans[ns - 1].s1) {
            spans[ns - 1].s1 = s1[i];
        }
    }
    if (spans[ns - 1].s1 < depth) {
        double e = spans[ns - 1].s1;
        spans[ns++] = (struct lit_span){ false, e, depth };
    }
    return ns;
}

static void set_interval(struct interval *v, bool lit, double s0, double s1)
{
    memset(v, 0, sizeof *v);
    v->lit = lit;
    v->s0 = s0;
    v->s1 = s1;
    v->ds = s1 - s0;
}

/* POV-Ray's ComputeMediaSampleInterval: how many sampling intervals each
** span gets (the lit ones 'ratio' of them), plus an unlit interval before
** the first and after the last where they leave a gap. Returns the count
** ('out' has room for max(intervals, n_spans) + 2). */
static int sample_intervals(const struct lit_span *sp, int n_sp,
                            const iris_media *im, bool constant,
                            double depth, struct interval *out)
{
    int intervals = im->intervals > n_sp ? im->intervals : n_sp;
    int n = 0;
    if (n_sp == 1) {
        if (!sp[0].lit && constant) {
            set_interval(&out[n++], false, sp[0].s0, sp[0].s1);
        } else {
            double delta = (sp[0].s1 - sp[0].s0) / intervals;
            for (int i = 0; i < intervals; i++)
                set_interval(&out[n++], sp[0].lit, sp[0].s0 + delta * i,
                             sp[0].s0 + delta * (i + 1));
        }
    } else {
        double sum = 0.0;
        for (int i = 0; i < n_sp; i++)
            sum += sp[i].lit ? im->ratio : 1.0 - im->ratio;
        int remaining = intervals;
        for (int i = 0; i < n_sp; i++) {
            double w = sp[i].lit ? im->ratio : 1.0 - im->ratio;
            double nf = sum > 0.0 ? w / sum * intervals : 0.0;
            int k = (nf > MAX_INTERVALS ? MAX_INTERVALS : (int)nf) + 1;
            int rem = remaining - n_sp + i + 1;
            if (k > rem)
                k = rem;
            if (k < 1)
                k = 1;
            double delta = (sp[i].s1 - sp[i].s0) / k;
            for (int j = 0; j < k; j++)
                set_interval(&out[n++], sp[i].lit, sp[i].s0 + delta * j,
                             sp[i].s0 + delta * (j + 1));
            remaining -= k;
        }
    }
    /* gaps at the ends (a lit span past the segment) stay unsampled by
    ** the lights but count for the extinction */
    if (n > 0 && out[0].s0 > 0.0) {
        memmove(out + 1, out, (size_t)n * sizeof *out);
        set_interval(&out[0], false, 0.0, out[1].s0);
        n++;
    }
    if (n > 0 && out[n - 1].s1 < depth) {
        double e = out[n - 1].s1;
        set_interval(&out[n++], false, e, depth);
    }
    return n;
}

/* POV-Ray's ComputeMediaColour: the intervals' mean emission attenuated
** by the optical depth before each, and the whole segment's
** transmittance on 'rgb' and 'transm'. */
static void media_colour(const struct interval *iv, int n, double rgb[3],
                         double *transm)
{
    double od[3] = { 0, 0, 0 }, te[3] = { 0, 0, 0 };
    for (int i = 0; i < n; i++) {
        double w = iv[i].samples > 0 ? 1.0 / iv[i].samples : 0.0;
        for (int k = 0; k < 3; k++) {
            te[k] += iv[i].te[k] * w * exp(-od[k]);
            od[k] += iv[i].od[k] * w;
        }
    }
    double tr[3];
    for (int k = 0; k < 3; k++) {
        tr[k] = exp(-od[k]);
        double v = rgb[k] * tr[k] + te[k];
        rgb[k] = isfinite(v) ? v : 0.0;
    }
    if (transm) {
        double g = mat_greyscale(tr);  /* > 1 under negative absorption */
        *transm = isfinite(g) ? *transm * g : 0.0;
    }
}

void media_segment(struct trace_ctx *c, const iris_media *const *m, int n,
                   const struct tray *r, double depth, bool shadow,
                   double rgb[3], double *transm)
{
    if (n <= 0 || !(depth > 0.0) || !isfinite(depth))
        return;
    if (n > MEDIA_MAX_PER_RAY)
        n = MEDIA_MAX_PER_RAY;
    const iris_media *im = m[0];
    double thr = HUGE_VAL;
    bool extinction = false, scattering = false, constant = true;
    for (int i = 0; i < n; i++) {
        const iris_media *x = m[i];
        if (x->intervals > im->intervals)
            im = x;
        if (x->aa_threshold < thr)
            thr = x->aa_threshold;
        bool sc = x->scattering.r != 0 || x->scattering.g != 0 ||
                  x->scattering.b != 0;
        bool ab = x->absorption.r != 0 || x->absorption.g != 0 ||
                  x->absorption.b != 0;
        extinction = extinction || sc || ab;
        scattering = scattering || sc;
        /* POV-Ray's is_constant: no density at all; its fast shadow path
        ** also takes plain-colour densities */
        for (int j = 0; j < x->n_densities; j++)
            constant = constant &&
                       x->densities[j]->pattern.kind == IRIS_PAT_NONE;
    }
    if (shadow && !extinction)
        return;
    bool iv_constant = true;   /* the interval rule uses "no densities" */
    for (int i = 0; i < n; i++)
        iv_constant = iv_constant && m[i]->n_densities == 0;

    struct lit_light ll_buf[16], *ll = ll_buf;
    struct lit_span sp_buf[34], *sp = sp_buf;
    double s0_buf[16], s1_buf[16], *s0 = s0_buf, *s1 = s1_buf;
    const struct tracer *t = c->t;
    int n_ll = 0, n_sp = 0;
    bool heap_ll = false;
    if (!shadow && t->n_lights > 16) {
        ll = iris_malloc((size_t)t->n_lights * sizeof *ll);
        sp = iris_malloc((size_t)(2 * t->n_lights + 2) * sizeof *sp);
        s0 = iris_malloc((size_t)t->n_lights * sizeof *s0);
        s1 = iris_malloc((size_t)t->n_lights * sizeof *s1);
        heap_ll = true;
        if (!ll || !sp || !s0 || !s1)
            goto out;
    }
    if (!shadow)
        n_sp = light_spans(c, &r->r, depth, ll, &n_ll, sp, s0, s1);
    if (n_sp == 0) {
        sp[0] = (struct lit_span){ false, 0.0, depth };
        n_sp = 1;
    }
    {
        int cap = (im->intervals > n_sp ? im->intervals : n_sp) + 2;
        struct interval iv_buf[STACK_INTERVALS], *iv = iv_buf;
        if (cap > STACK_INTERVALS) {
            iv = iris_malloc((size_t)cap * sizeof *iv);
            if (!iv)
                goto out;
        }
        int n_iv = sample_intervals(sp, n_sp, im, iv_constant, depth, iv);
        struct seg s = { c, m, n, r, shadow, scattering, ll, n_ll, im,
                         shadow || !scattering ? NULL
                                               : pmedia_of(t->photon_map) };
        bool constant_shadow = shadow && constant;
        if (im->method == 3 && !constant_shadow)
            adaptive_sampling(&s, iv, n_iv, thr);
        else
            regular_sampling(&s, iv, n_iv, constant_shadow);
        media_colour(iv, n_iv, rgb, transm);
        if (iv != iv_buf)
            iris_free(iv);
    }
out:
    if (heap_ll) {
        iris_free(ll);
        iris_free(sp);
        iris_free(s0);
        iris_free(s1);
    }
}
