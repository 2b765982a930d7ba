/* SPDX-License-Identifier: MIT */
/*
** ior.c: index of refraction models (ior.h) and the glass catalogue
** lookup.
*/
#include "config.h"

#include "spectrum/ior.h"

#include <math.h>
#include <stdio.h>
#include <strings.h>

#include "spectrum/spectrum.h"
#include "spectrum/tables.h"

/*
** Clamps an index into [IOR_MIN, IOR_MAX]; sets *clamped when it had to.
** NaN (from NaN parameters) becomes 1, the index of vacuum.
*/
static double clamp_n(double n, bool *clamped)
{
    if (n != n) {
        *clamped = true;
        return 1.0;
    }
    if (n < IOR_MIN) {
        *clamped = true;
        return IOR_MIN;
    }
    if (n > IOR_MAX) {
        *clamped = true;
        return IOR_MAX;
    }
    return n;
}

static double base_ior(const iris_interior *in)
{
    return in->ior > 0.0 ? in->ior : 1.0;
}

const struct spec_glass *ior_glass_find(const char *name)
{
    if (!name)
        return NULL;
    for (int i = 0; i < spec_tab_n_glass; i++)
        if (strcasecmp(spec_tab_glass[i].name, name) == 0)
            return &spec_tab_glass[i];
    return NULL;
}

/*
** ior_glass_find() remembering the last glass found, per thread: a
** Sellmeier index by glass name is evaluated at every refraction of every
** photon, and the catalogue scan was most of it. The remembered entry is
** checked against the name (one strcasecmp), so a name freed with its
** scene and a new one at the same address cannot return a stale glass.
*/
static const struct spec_glass *glass_find_cached(const char *name)
{
    static _Thread_local const struct spec_glass *last;
    if (name && last && strcasecmp(last->name, name) == 0)
        return last;
    const struct spec_glass *g = ior_glass_find(name);
    if (g)
        last = g;
    return g;
}

/* n^2 - 1 = sum B·l^2/(l^2 - C); n^2 <= 0 (inside an absorption band,
** where the formula has no meaning) clamps to IOR_MIN. */
static double sellmeier_raw(const double b[4], const double c[4],
                            double lambda_um, bool *clamped)
{
    double l2 = lambda_um * lambda_um, n2 = 1.0;
    for (int k = 0; k < 4; k++)
        if (b[k] != 0.0)
            n2 += b[k] * l2 / (l2 - c[k]);
    if (!(n2 > IOR_MIN * IOR_MIN)) {
        *clamped = true;
        return n2 != n2 ? 1.0 : IOR_MIN;
    }
    return clamp_n(sqrt(n2), clamped);
}

double ior_sellmeier(const double b[4], const double c[4], double lambda_um)
{
    bool clamped = false;
    return sellmeier_raw(b, c, lambda_um, &clamped);
}

/*
** Cauchy coefficients (lambda in um) of the Abbe model: n(d) = n_d and
** (n_d - 1)/(n_F - n_C) = V_d. A V_d that is not positive and finite
** means no dispersion (B = 0).
*/
static void abbe_to_cauchy(double nd, double vd, double *a, double *b)
{
    double lf = IOR_LAMBDA_F * 1e-3, lc = IOR_LAMBDA_C * 1e-3;
    double ld = IOR_LAMBDA_D * 1e-3;
    *b = 0.0;
    if (vd > 0.0 && isfinite(vd))
        *b = (nd - 1.0) / (vd * (1.0 / (lf * lf) - 1.0 / (lc * lc)));
    *a = nd - *b / (ld * ld);
}

/* The index before the final clamp is applied; *clamped is set when the
** model itself had to clamp. */
static double eval_model(const iris_interior *in, double lambda,
                         bool *clamped)
{
    const iris_ior_spec *s = in->spectral_ior;
    double lum = lambda * 1e-3;
    if (s) {
        switch (s->model) {
        case IRIS_IOR_SELLMEIER: {
            const struct spec_glass *g = glass_find_cached(s->glass_name);
            if (s->glass_name && !g)
                break; /* unknown: ior_check() reports it */
            return g ? sellmeier_raw(g->b, g->c, lum, clamped)
                     : sellmeier_raw(s->b, s->c, lum, clamped);
        }
        case IRIS_IOR_CAUCHY:
            return s->cauchy_a + s->cauchy_b / (lum * lum);
        case IRIS_IOR_ABBE: {
            double a, b;
            abbe_to_cauchy(s->abbe_nd, s->abbe_vd, &a, &b);
            return a + b / (lum * lum);
        }
        case IRIS_IOR_DECAY: {
            /* Clamping the exponent keeps (n1 - n2)·e finite; spread <= 0
            ** means an instant step from n1 to n2. */
            double spread = s->decay_spread;
            double x = spread > 0.0 ? (lambda - SPEC_LAMBDA_MIN) / spread
                                    : (lambda > SPEC_LAMBDA_MIN ? 700 : 0);
            if (x > 700.0)
                x = 700.0;
            if (x < -700.0)
                x = -700.0;
            double d = s->decay_n1 - s->decay_n2;
            return d == 0.0 ? s->decay_n2 : d * exp(-x) + s->decay_n2;
        }
        case IRIS_IOR_POV:
        default:
            break;
        }
    }
    double n = base_ior(in), disp = in->dispersion;
    if (!(in->ior > 0.0) || !(disp > 0.0) || disp == 1.0)
        return n;
    return n * pow(disp, (555.0 - lambda) / 350.0);
}

double ior_eval(const iris_interior *in, double lambda_nm)
{
    if (!in)
        return 1.0;
    /* The common plain 'ior' without dispersion: eval_model's last case,
    ** without the call (ior_eval runs twice per refraction per photon) */
    if (!in->spectral_ior &&
        (!(in->ior > 0.0) || !(in->dispersion > 0.0) ||
         in->dispersion == 1.0)) {
        double n = base_ior(in);
        if (n >= IOR_MIN && n <= IOR_MAX)
            return n;
    }
    bool clamped = false;
    return clamp_n(eval_model(in, lambda_nm, &clamped), &clamped);
}

bool ior_is_dispersive(const iris_interior *in)
{
    if (!in)
        return false;
    if (!in->spectral_ior || in->spectral_ior->model == IRIS_IOR_POV)
        return in->ior > 0.0 && in->dispersion > 0.0 &&
               fabs(in->dispersion - 1.0) > 1e-10;
    double n0 = ior_eval(in, SPEC_LAMBDA_MIN);
    for (double l = SPEC_LAMBDA_MIN + 50.0; l <= SPEC_LAMBDA_MAX; l += 50.0)
        if (fabs(ior_eval(in, l) - n0) > 1e-12)
            return true;
    return false;
}

enum ior_verdict ior_check(const iris_interior *in, char *msg, size_t len)
{
    if (!in || !in->spectral_ior)
        return IOR_FINE;
    const iris_ior_spec *s = in->spectral_ior;
    if (s->model == IRIS_IOR_SELLMEIER && s->glass_name &&
        !ior_glass_find(s->glass_name)) {
        int w = snprintf(msg, len, "unknown glass \"%s\"; known glasses:",
                         s->glass_name);
        for (int i = 0; i < spec_tab_n_glass && w > 0 && (size_t)w < len;
             i++)
            w += snprintf(msg + w, len - (size_t)w, "%s %s",
                          i ? "," : "", spec_tab_glass[i].name);
        return IOR_ERROR;
    }
    double lo = INFINITY;
    for (double l = SPEC_LAMBDA_MIN; l <= SPEC_LAMBDA_MAX; l += 1.0) {
        bool clamped = false;
        double n = clamp_n(eval_model(in, l, &clamped), &clamped);
        if (clamped) {
            snprintf(msg, len,
                     "index of refraction leaves [%g, %g] or is undefined "
                     "at %g nm; clamped", IOR_MIN, IOR_MAX, l);
            return IOR_WARNING;
        }
        lo = fmin(lo, n);
    }
    if (lo < 1.0) {
        snprintf(msg, len, "index of refraction falls to %.4g (< 1) in "
                 "380-780 nm", lo);
        return IOR_WARNING;
    }
    if (s->model == IRIS_IOR_ABBE && !(s->abbe_vd > 0.0 && isfinite(s->abbe_vd))) {
        snprintf(msg, len, "Abbe number %g is not positive: no dispersion",
                 s->abbe_vd);
        return IOR_WARNING;
    }
    return IOR_FINE;
}
