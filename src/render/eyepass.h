/* SPDX-License-Identifier: MIT */
/*
** eyepass.h: tracing the image: tiles handed to threads, one camera ray
** per pixel or POV-Ray's antialiasing (+AM1, +AM2) or stratified
** supersampling, into linear RGBA with alpha 1.
**
** Depends on: util (threads), render (trace, camera). Used by: render.c
** and the unit tests (with a scene double behind the tracer).
*/
#ifndef IRIS_RENDER_EYEPASS_H
#define IRIS_RENDER_EYEPASS_H

#include "iris/render.h"
#include "render/trace.h"

/*
** Renders the window of 'opts' into 'out' with 'threads' threads. NaN and
** Inf samples become 0 and are counted in stats->nan_pixels; negative
** values are clamped to 0. Returns IRIS_OK, IRIS_ENOMEM, IRIS_EINVAL (an
** empty window) or IRIS_EINTR when *opts->interrupt was set.
*/
enum iris_status eyepass_run(const struct tracer *tr,
                             const iris_render_options *opts, int threads,
                             iris_image *out, iris_render_stats *stats);

/*
** The pixel window of 'opts' (POV-Ray's +SC/+EC/+SR/+ER, 1-based, 0 =
** the image edge) as 0-based inclusive bounds clamped to the image.
** Returns false when it is empty.
*/
bool eye_window(const iris_render_options *opts, int *x0, int *x1, int *y0,
                int *y1);

/*
** The colour POV-Ray's AA threshold compares: each channel, clipped at 0,
** to the power e = 1/aa_gamma (§4.1). eye_aa_gamma_apply() writes it to
** 'g' and returns a bound on sum |g - pow(c, e)|: 0 where it used pow()
** (or e is 1), else at most g * rel per channel from a float powf(), or
** g * lut_rel from the interpolated table (0 < e < 1, the usual
** aa_gamma 2.5 among them).
** The eye pass uses the bound to redo the rare comparisons it could flip.
*/
/* The table of the fast path for 0 < e < 1: v^e at 128 points per octave
** over [2^EYE_AA_LUT_LO, 2^EYE_AA_LUT_HI), linearly interpolated. */
#define EYE_AA_LUT_LO (-19)
#define EYE_AA_LUT_HI 4
#define EYE_AA_LUT_N ((EYE_AA_LUT_HI - EYE_AA_LUT_LO) * 128)
struct eye_aa_gamma {
    double e;                  /* 1 / aa_gamma */
    float ef;                  /* e rounded to float */
    double rel;                /* relative error bound of the fast path */
    bool fast;                 /* e allows the float path */
    bool lut;                  /* 0 < e < 1: the table instead of powf */
    double lut_rel;            /* relative error bound of the table */
    double tab[EYE_AA_LUT_N + 1];
};
void eye_aa_gamma_init(struct eye_aa_gamma *a, double aa_gamma);
double eye_aa_gamma_apply(const struct eye_aa_gamma *a, const double c[3],
                          double g[3]);

/*
** The pixel of a legacy scene without assumed_gamma (§3.9):
** (float)iris_srgb_decode(v), the same float, in about a fifth of its
** cost (pow() per channel was 5-7 % of such a scene's eye pass). Over
** (0.04045, 1) a cubic per 1/EYE_SRGB_N of v gives the value within
** EYE_SRGB_REL of it (eyepass.c proves the bound); where that interval
** holds a float rounding boundary, iris_srgb_decode() decides.
*/
#define EYE_SRGB_N 1024
#define EYE_SRGB_REL 1e-9
struct eye_srgb {
    float at_one;              /* (float)iris_srgb_decode(1.0) */
    double coef[EYE_SRGB_N][4]; /* Taylor coefficients at i / EYE_SRGB_N */
};
void eye_srgb_init(struct eye_srgb *s);
float eye_srgb_decode(const struct eye_srgb *s, double v);
/* The cubic alone (no rounding check), for the test of the bound;
** v in (0.04045, 1). */
double eye_srgb_cubic(const struct eye_srgb *s, double v);

#endif
