/* SPDX-License-Identifier: MIT */
/*
** subsurface.c: POV-Ray 3.7's subsurface light transport (subsurface.h
** says what it computes). Distances are scene units on rays and mm in the
** diffusion terms (global_settings mm_per_unit).
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "render/light.h"
#include "render/media.h"
#include "render/subsurface.h"
#include "util/rng.h"

#define SSS_EPSILON 1e-10      /* POV-Ray's EPSILON in these tests */

/* ------------------------------------------------------------------ */
/* Diffusion terms                                                      */
/* ------------------------------------------------------------------ */

double sss_fresnel_diffuse(double eta)
{
    if (eta < 1.0)
        return eta * eta - pow(eta, 2.25);
    double k = 1.0 - 1.0 / eta;
    return (k + 3.0 * pow(k, 4.5)) / 4.0;
}

double sss_fresnel_transmit(double cos_i, double eta)
{
    double g2 = eta * eta + cos_i * cos_i - 1.0;
    /* past the critical angle g is imaginary: POV-Ray's sqrt gives NaN
    ** there, which its clip to 0..1 turns into F = 0 (full transmission);
    ** the same holds where both sides of a quotient are 0 */
    if (!(g2 >= 0.0))
        return 1.0;
    double g = sqrt(g2);
    double a = g + cos_i, b = cos_i * (g - cos_i) + 1.0;
    if (a == 0.0 || b == 0.0)
        return 1.0;
    double f = 0.5 * (g - cos_i) * (g - cos_i) / (a * a);
    double e = cos_i * a - 1.0;
    f *= 1.0 + e * e / (b * b);
    if (!(f > 0.0))
        f = 0.0;
    return 1.0 - fmin(1.0, f);
}

double sss_total_reflectance(double A, double alpha)
{
    double root = sqrt(3.0 * (1.0 - alpha));
    return 0.5 * alpha * (1.0 + exp(-(4.0 / 3.0) * A * root)) * exp(-root);
}

double sss_dipole_profile(double r_mm, double sigma_s, double sigma_a,
                          double A)
{
    double sigma_t = sigma_s + sigma_a;
    double alpha = sigma_s / sigma_t;
    double sigma_tr = sqrt(3.0 * sigma_a * sigma_t);
    double r2 = r_mm * r_mm;
    /* the real source one mean free path deep, its mirror image above the
    ** extrapolated boundary 2AD higher (D = 1/(3 s'_t)) */
    double z_r = 1.0 / sigma_t;
    double z_v = z_r * (1.0 + A * 4.0 / 3.0);
    double d2_r = z_r * z_r + r2, d_r = sqrt(d2_r);
    double d2_v = z_v * z_v + r2, d_v = sqrt(d2_v);
    double real = z_r * (sigma_tr + 1.0 / d_r) * exp(-sigma_tr * d_r) / d2_r;
    double virt = z_v * (sigma_tr + 1.0 / d_v) * exp(-sigma_tr * d_v) / d2_v;
    return alpha / (4.0 * M_PI) * (real + virt);
}

void sss_albedo_table_init(struct sss_albedo_table *tab, double ior)
{
    double fdr = sss_fresnel_diffuse(ior);
    double A = (1.0 + fdr) / (1.0 - fdr);
    tab->ior = ior;
    tab->alpha[0] = 0.0f;
    tab->alpha[SSS_ALBEDO_STEPS] = 1.0f;
    /* R_d rises monotonically with a' from 0 (a' = 0) to 1 (a' = 1):
    ** bisection finds each node to far below float precision */
    for (int i = 1; i < SSS_ALBEDO_STEPS; i++) {
        double want = (double)i / SSS_ALBEDO_STEPS;
        double lo = 0.0, hi = 1.0;
        for (int it = 0; it < 60; it++) {
            double mid = 0.5 * (lo + hi);
            if (sss_total_reflectance(A, mid) < want)
                lo = mid;
            else
                hi = mid;
        }
        tab->alpha[i] = (float)(0.5 * (lo + hi));
    }
}

double sss_reduced_albedo(const struct sss_albedo_table *tab, double rd)
{
    /* POV-Ray indexes its table with the unclipped value (reading past
    ** it for pigment x diffuse > 1); here it is clipped */
    double x = fmin(fmax(rd, 0.0), 1.0) * SSS_ALBEDO_STEPS;
    int i0 = (int)floor(x), i1 = (int)ceil(x);
    double p = x - i0;
    return (1.0 - p) * tab->alpha[i0] + p * tab->alpha[i1];
}

/* ------------------------------------------------------------------ */
/* Shading                                                              */
/* ------------------------------------------------------------------ */

/* Per thread: the depth of nested subsurface shading (POV-Ray's
** subsurfaceRecursionDepth: full samples at the eye's hit, one each
** below, none past two), and the albedo tables of the last interiors
** (one per index of refraction; a table costs 6000 exp()). */
static _Thread_local int sss_depth;
#define SSS_TABLES 4
static _Thread_local struct sss_albedo_table sss_tables[SSS_TABLES];
static _Thread_local int sss_n_tables, sss_next_table;

static const struct sss_albedo_table *albedo_table(double ior)
{
    for (int i = 0; i < sss_n_tables; i++)
        if (sss_tables[i].ior == ior)
            return &sss_tables[i];
    int i = sss_next_table;
    sss_next_table = (sss_next_table + 1) % SSS_TABLES;
    if (sss_n_tables < SSS_TABLES)
        sss_n_tables++;
    sss_albedo_table_init(&sss_tables[i], ior);
    return &sss_tables[i];
}

/* What one shading point's samples share. */
struct sss_point {
    struct trace_ctx *c;
    const struct tray *eye;
    const struct hit *h;
    vec3 n_out;                /* surface normal facing the eye */
    vec3 v_out;                /* towards the eye */
    double eta, A, mm;
    double sigma_s[3], sigma_a[3], sigma_t[3];
    bool live[3];              /* channels with a finite medium */
};

/* POV-Ray's IsSameSSLTObject: the same interior (here: the same object
** where neither has an interior{}, as trace.c keys interiors). */
static bool same_medium(const struct hit *a, const struct hit *b)
{
    if (a->interior || b->interior)
        return a->interior == b->interior;
    const void *ka = a->top ? (const void *)a->top : (const void *)a->obj;
    const void *kb = b->top ? (const void *)b->top : (const void *)b->obj;
    return ka == kb;
}

/* The tmin of a ray leaving a surface hit (trace.c's leave_eps). */
static double leave_eps(const struct tracer *t, double eps)
{
    return eps > 0.0 && eps < t->q.eps ? eps : t->q.eps;
}

/* The nearest surface along 'o' + s 'd' for s in (tmin, tmax). */
static bool find_hit(const struct tracer *t, vec3 o, vec3 d, double tmin,
                     double tmax, struct hit *h)
{
    ray r = { o, d };
    return t->q.intersect(t->q.impl, &r, tmin, tmax, ACCEL_SKIP_NONE, h) &&
           h->t > 0.0 && isfinite(h->t);
}

/* A surface point's normal for the BSSRDF: the unperturbed one. */
static vec3 sss_normal(const struct hit *h)
{
    return h->shading_n;
}

/* The Fresnel transmittance at 'cos_i', clipped to -1..1 as POV-Ray
** clips it before its acos. */
static double ft_angle(double cos_i, double eta)
{
    return sss_fresnel_transmit(fmin(fmax(cos_i, -1.0), 1.0), eta);
}

/* The lights that shade 'h' (trace.c's diffuse_light): the scene's unless
** the object is in a light_group without global_lights, then its group's. */
static void light_range(const struct tracer *t, const struct hit *h,
                        int *j0, int *j1)
{
    const iris_object *ob = h->obj;
    *j0 = ob && ob->no_global_lights ? t->n_lights : 0;
    *j1 = t->n_lights + (ob ? ob->light_group_count : 0);
}

static int light_index(const struct tracer *t, const struct hit *h, int j)
{
    return j < t->n_lights ? j : j + h->obj->light_group_first;
}

/* Halton's radical inverse of 'i' in base 'b'. */
static double radical_inverse(unsigned i, unsigned b)
{
    double inv = 1.0 / b, f = inv, r = 0.0;
    while (i > 0) {
        r += f * (i % b);
        i /= b;
        f *= inv;
    }
    return r;
}

/* POV-Ray's ComputeDiffuseSampleBase: a mean free path 'free' below the
** surface, or half way to the far side where the object is thinner. */
static vec3 sample_base(const struct sss_point *s, double free)
{
    const struct tracer *t = s->c->t;
    vec3 n_in = v3_neg(s->n_out);
    struct hit b;
    s->c->rays++;
    if (find_hit(t, s->h->p, n_in, leave_eps(t, s->h->eps), 2.0 * free, &b)) {
        if (same_medium(s->h, &b))
            return v3_madd(s->h->p, n_in, b.t / 2.0);
        return v3_madd(s->h->p, n_in, fmin(free, b.t - SSS_EPSILON));
    }
    return v3_madd(s->h->p, n_in, free);
}

/* One light's light at surface point 'in' through the dipole
** (POV-Ray's ComputeDiffuseContribution1), times 'weight', into 'sum'. */
static void diffuse_one_light(const struct sss_point *s, int i,
                              const struct hit *in, vec3 n_in,
                              double weight, double sum[3])
{
    struct trace_ctx *c = s->c;
    vec3 L;
    double lc[3];
    if (!trace_media_light(c, &s->eye->st, i, in->p, &L, lc))
        return;
    double cos_in = v3_dot(n_in, L);
    /* lit from inside the object: the normal is taken as wrong */
    if (cos_in < 0.0) {
        n_in = v3_neg(n_in);
        cos_in = -cos_in;
    }
    if (cos_in < SSS_EPSILON)
        return;
    double F = ft_angle(cos_in, s->eta) *
               ft_angle(v3_dot(s->v_out, s->n_out), s->eta);
    double r = v3_len(v3_sub(in->p, s->h->p)) * s->mm;
    for (int k = 0; k < 3; k++)
        if (s->live[k])
            sum[k] += lc[k] * cos_in * weight * F *
                      sss_dipole_profile(r, s->sigma_s[k], s->sigma_a[k],
                                         s->A);
}

/* Multiple scattering (the dipole) over 'n' surface samples. */
static void diffuse_part(const struct sss_point *s, int n, double out[3])
{
    struct trace_ctx *c = s->c;
    const struct tracer *t = c->t;
    double sa = mat_greyscale(s->sigma_a), ss = mat_greyscale(s->sigma_s);
    if (!(sa + ss > 0.0) || !isfinite(sa + ss))
        return;
    vec3 base = sample_base(s, 1.0 / ((sa + ss) * s->mm));
    rng *rg = rng_lazy_get(&c->rng);
    /* Halton points (bases 2, 3) turned by a random offset per shading
    ** point: POV-Ray draws its directions from one Halton sequence per
    ** thread, which this stratifies alike without depending on the
    ** order pixels are rendered in */
    double du = rng_uniform(rg), dv = rng_uniform(rg);
    int j0, j1;
    light_range(t, s->h, &j0, &j1);
    double sum[3] = { 0, 0, 0 };
    int found = 0;
    for (int i = 0; i < n; i++) {
        double u = radical_inverse((unsigned)i + 1, 2) + du;
        double v = radical_inverse((unsigned)i + 1, 3) + dv;
        u -= floor(u);
        v -= floor(v);
        double z = 1.0 - 2.0 * u, rxy = sqrt(fmax(0.0, 1.0 - z * z));
        double phi = 2.0 * M_PI * v;
        vec3 d = v3(rxy * cos(phi), rxy * sin(phi), z);
        struct hit in;
        c->rays++;
        if (!find_hit(t, base, d, accel_origin_epsilon(base, t->q.eps),
                      t->max_distance, &in))
            continue;
        vec3 delta = v3_sub(in.p, base);
        double dist = v3_len(delta);
        if (!(dist > 0.0))
            continue;
        vec3 n_in = sss_normal(&in);
        double cos_phi = fabs(v3_dot(v3_scale(delta, 1.0 / dist), n_in));
        if (cos_phi < 0.01)    /* POV-Ray's limit on a grazing sample */
            cos_phi = 0.01;
        double area = 4.0 * M_PI * (dist * s->mm) * (dist * s->mm) / cos_phi;
        found++;
        if (!same_medium(&in, s->h))
            continue;
        for (int j = j0; j < j1; j++)
            diffuse_one_light(s, light_index(t, s->h, j), &in, n_in, area,
                              sum);
    }
    if (found > 0)
        for (int k = 0; k < 3; k++)
            out[k] += sum[k] / found;
}

/* One light's single scattering at 'bend', 's_out' mm along the refracted
** eye ray, channel 'k' (POV-Ray's ComputeOneSingleScatteringContribution). */
static double single_one_light(const struct sss_point *s, int i, int k,
                               vec3 bend, double s_out, double cos_out,
                               double cos_out_t)
{
    struct trace_ctx *c = s->c;
    const struct tracer *t = c->t;
    vec3 L;
    double depth;
    light_ray(&t->lights[i], bend, v3(0, 0, 0), &L, &depth);
    /* where a ray to the light leaves the object (refraction ignored) */
    struct hit xi;
    c->rays++;
    if (!find_hit(t, bend, L, accel_origin_epsilon(bend, t->q.eps),
                  t->max_distance, &xi) || !same_medium(&xi, s->h))
        return 0.0;
    double lc[3];
    if (!trace_media_light(c, &s->eye->st, i, xi.p, &L, lc))
        return 0.0;
    double cos_in = fabs(v3_dot(sss_normal(&xi), L));
    if (cos_in < SSS_EPSILON)
        return 0.0;
    double sin2_t = (1.0 - cos_in * cos_in) / (s->eta * s->eta);
    if (sin2_t > 1.0)
        return 0.0;
    double cos_in_t = sqrt(1.0 - sin2_t);
    if (cos_in_t <= SSS_EPSILON)
        return 0.0;
    double si = v3_len(v3_sub(bend, xi.p)) * s->mm;
    double s_in = si * cos_in / cos_in_t;
    double F = ft_angle(cos_in, s->eta) * ft_angle(cos_out, s->eta);
    double sigma_t = s->sigma_t[k];
    double G = fabs(cos_out_t / cos_in_t);
    double sigma_tc = sigma_t + G * sigma_t;
    /* isotropic phase 1/(4 pi) without its 1/pi (POV-Ray's lights) */
    double f = s->sigma_s[k] * F * 0.25 / sigma_tc *
               exp(-s_in * sigma_t) * exp(-s_out * sigma_t);
    if (!(f < 1e300))
        f = 1e300;
    return lc[k] * cos_in * f;
}

/* Single scattering along 'refr' (unit, into the object) over 'n' depths
** per channel; 'dist' mm to the far side. */
static void single_part(const struct sss_point *s, int n, vec3 refr,
                        double dist, double out[3])
{
    if (n <= 0)
        return;
    struct trace_ctx *c = s->c;
    const struct tracer *t = c->t;
    double cos_out = v3_dot(s->v_out, s->n_out);
    double e2 = (1.0 - cos_out * cos_out) / (s->eta * s->eta);
    double cos_out_t = sqrt(fmax(0.0, 1.0 - e2));
    int j0, j1;
    light_range(t, s->h, &j0, &j1);
    rng *rg = rng_lazy_get(&c->rng);
    for (int k = 0; k < 3; k++) {
        if (!s->live[k])
            continue;
        double sum = 0.0;
        for (int i = 0; i < n; i++) {
            /* depths distributed as exp(-s_t s): stratified uniform
            ** numbers where POV-Ray draws plain random ones */
            double e = (i + rng_uniform(rg)) / n;
            if (!(e > 0.0))
                continue;
            double s_out = fabs(log(e)) / s->sigma_t[k];
            if (s_out >= dist)
                continue;      /* past the far side: the unscattered part */
            vec3 bend = v3_madd(s->h->p, refr, s_out / s->mm);
            for (int j = j0; j < j1; j++)
                sum += single_one_light(s, light_index(t, s->h, j), k, bend,
                                        s_out, cos_out, cos_out_t);
        }
        out[k] += sum / n;
    }
}

/* The refracted eye ray leaving the far side, traced on (attenuated by
** exp(-s'_t d), no Fresnel at either interface, as POV-Ray 3.7). */
static void unscattered_part(const struct sss_point *s, vec3 refr,
                             const struct hit *far, double dist,
                             double out[3])
{
    struct trace_ctx *c = s->c;
    const struct tracer *t = c->t;
    double att[3];
    double w = 0.0;
    for (int k = 0; k < 3; k++) {
        att[k] = s->live[k] ? exp(-s->sigma_t[k] * dist) : 0.0;
        w = fmax(w, att[k]);
    }
    if (!(w > t->adc) || !same_medium(far, s->h))
        return;
    vec3 n2 = sss_normal(far);
    if (v3_dot(refr, n2) > 0.0)
        n2 = v3_neg(n2);
    vec3 d2;
    if (!trace_refract_dir(refr, n2, s->eta, &d2))
        return;
    struct tray r;
    tray_copy(&r, s->eye);
    r.r.o = far->p;
    r.r.d = v3_norm(d2);
    r.tmin = far->eps;
    double col[3];
    trace_ray(c, &r, w, false, col);
    for (int k = 0; k < 3; k++)
        out[k] += col[k] * att[k];
}

const struct mat_layer *subsurface_shade(struct trace_ctx *c,
                                         const struct tray *eye,
                                         const struct hit *h,
                                         const struct mat_layer *l, vec3 raw,
                                         double eta, bool lit,
                                         struct subsurface_layer *keep,
                                         double out[3])
{
    const struct tracer *t = c->t;
    const iris_global_settings *g = &t->scene->settings;
    keep->finish = *l->finish;
    keep->finish.diffuse = keep->finish.diffuse_back = 0.0;
    keep->layer = *l;
    keep->layer.finish = &keep->finish;
    if (sss_depth >= 2 || !(eta > 0.0) || !isfinite(eta))
        return &keep->layer;
    int n_diffuse = sss_depth == 1 ? 1 : g->sss_samples_diffuse;
    int n_single = sss_depth == 1 ? 1 : g->sss_samples_single;

    struct sss_point s;
    s.c = c;
    s.eye = eye;
    s.h = h;
    s.n_out = raw;
    s.v_out = v3_neg(eye->r.d);
    s.eta = eta;
    s.mm = g->mm_per_unit;
    double fdr = sss_fresnel_diffuse(eta);
    s.A = (1.0 + fdr) / (1.0 - fdr);
    double ior = h->interior && h->interior->ior > 0 ? h->interior->ior : 1.0;
    const struct sss_albedo_table *tab = albedo_table(ior);
    const double pig[3] = { l->pigment.r, l->pigment.g, l->pigment.b };
    const double tl[3] = { l->finish->translucency.r,
                           l->finish->translucency.g,
                           l->finish->translucency.b };
    bool any = false;
    for (int k = 0; k < 3; k++) {
        double alpha = sss_reduced_albedo(
            tab, pig[k] * iris_finish_raw_diffuse(l->finish));
        /* a channel with no mean free path or no albedo has no transport
        ** (POV-Ray divides by 0 there) */
        s.live[k] = tl[k] > 0.0 && alpha > 0.0 && isfinite(tl[k]);
        s.sigma_s[k] = s.live[k] ? 1.0 / tl[k] : 0.0;
        s.sigma_t[k] = s.live[k] ? s.sigma_s[k] / alpha : 0.0;
        s.sigma_a[k] = s.sigma_t[k] - s.sigma_s[k];
        any = any || s.live[k];
    }
    if (!any || !(s.mm > 0.0) || !isfinite(s.mm))
        return &keep->layer;

    sss_depth++;
    double sum[3] = { 0, 0, 0 };
    if (lit)
        diffuse_part(&s, n_diffuse, sum);
    vec3 refr;
    if (trace_refract_dir(eye->r.d, raw, 1.0 / eta, &refr)) {
        refr = v3_norm(refr);
        struct hit far;
        c->rays++;
        bool found = find_hit(t, h->p, refr, leave_eps(t, h->eps),
                              t->max_distance, &far);
        double dist = found ? v3_len(v3_sub(h->p, far.p)) * s.mm : HUGE_VAL;
        if (lit)
            single_part(&s, n_single, refr, dist, sum);
        if (found)
            unscattered_part(&s, refr, &far, dist, sum);
    }
    sss_depth--;
    for (int k = 0; k < 3; k++)
        if (isfinite(sum[k]))
            out[k] += sum[k];
    return &keep->layer;
}
