/* SPDX-License-Identifier: MIT */
/*
** subsurface.h: POV-Ray 3.7's subsurface light transport ("SSLT"), the
** dipole BSSRDF of Jensen, Marschner, Levoy and Hanrahan, "A Practical
** Model for Subsurface Light Transport" (SIGGRAPH 2001), as POV-Ray 3.7
** computes it for finish { subsurface { translucency C } } when
** global_settings has subsurface { samples A, B } (semantics: POV-Ray's
** Trace::ComputeSubsurfaceScattering and lighting/subsurface.cpp).
**
** Per colour channel: the reduced albedo a' is the one whose total
** diffuse reflectance (Jensen's closed form) is pigment x diffuse; the
** reduced scattering coefficient s'_s = 1/C per mm (mm_per_unit mm to a
** scene unit), s'_t = s'_s/a', s_a = s'_t - s'_s. The colour of a point
** is the sum of
**   - multiple scattering: A points on the object's surface, found by
**     rays in uniform directions from a point one mean free path below
**     the surface, each lit by every light (with shadows) and weighted by
**     the dipole profile R_d(r) and the Fresnel transmittances in and out
**     (area per sample 4 pi dist^2 / cos, averaged over the samples that
**     met a surface, as POV-Ray does);
**   - single scattering: B points along the refracted eye ray at
**     exponentially distributed depths, each lit through the surface
**     point where a ray towards the light leaves the object;
**   - the unscattered light: the refracted eye ray leaving the object on
**     its far side, traced on, attenuated by exp(-s'_t d).
** POV-Ray leaves the finish's diffuse term out of such a layer, from its
** lights and its photons: the BSSRDF stands for it. Its 1/pi factors are
** left out too (POV-Ray's light intensities imply them).
**
** Left out: subsurface { radiosity on } (radiosity's ambient through the
** BSSRDF) and anisotropy, which POV-Ray 3.7 parses and does not use.
**
** Depends on: render/trace.h (trace_ray), media.h (trace_media_light),
** light.h.
** Used by: trace.c (one call in lighted_texture).
*/
#ifndef IRIS_RENDER_SUBSURFACE_H
#define IRIS_RENDER_SUBSURFACE_H

#include <stdbool.h>

#include "render/trace.h"

/* ---- the diffusion terms (pure functions, tested on their own) ---- */

/* POV-Ray 3.7's approximation of the diffuse Fresnel reflectance F_dr(eta)
** (its own fit, not Jensen's polynomial, which it found unstable for
** large eta and eta < 1). A = (1 + F_dr)/(1 - F_dr). */
double sss_fresnel_diffuse(double eta);

/* 1 - F(theta): the unpolarised Fresnel transmittance of a dielectric of
** relative index 'eta' at incidence cos theta = 'cos_i' (Cook-Torrance's
** form), clipped to 0..1. */
double sss_fresnel_transmit(double cos_i, double eta);

/* Jensen's total diffuse reflectance of a semi-infinite medium with
** reduced albedo 'alpha' and boundary term 'A' (eq. 5 integrated over
** the plane): (a'/2)(1 + exp(-4/3 A sqrt(3(1-a')))) exp(-sqrt(3(1-a'))). */
double sss_total_reflectance(double A, double alpha);

/* The dipole's diffuse reflectance profile R_d at distance 'r_mm' (mm)
** from the point of entry, for reduced scattering 'sigma_s' and
** absorption 'sigma_a' (per mm), with boundary term 'A'; per mm^2. */
double sss_dipole_profile(double r_mm, double sigma_s, double sigma_a,
                          double A);

/* The reduced albedo whose total reflectance is 'rd', as POV-Ray takes it
** from a table of 101 values (rd = 0, 0.01 .. 1) for the interior's
** index 'ior', interpolated linearly. 'rd' is clipped to 0..1. */
#define SSS_ALBEDO_STEPS 100
struct sss_albedo_table {
    double ior;
    float alpha[SSS_ALBEDO_STEPS + 1];
};
void sss_albedo_table_init(struct sss_albedo_table *tab, double ior);
double sss_reduced_albedo(const struct sss_albedo_table *tab, double rd);

/* ---- the shading ---- */

/* Whether subsurface light transport runs in 't' at all: a subsurface{}
** block in global_settings and quality 9 (POV-Ray's Q_SUBSURFACE). */
static inline bool subsurface_enabled(const struct tracer *t)
{
    return t->scene->settings.subsurface && (t->quality & TQ_ADVANCED);
}

/* A layer without its diffuse term, for the lights and photons that
** shade what the BSSRDF does not (highlights). */
struct subsurface_layer {
    struct mat_layer layer;
    iris_finish finish;
};

/*
** Adds the BSSRDF's light at hit 'h' of 'eye', layer 'l' (its finish has
** subsurface), to 'out' (rgb, before the layers' filter). 'raw' is the
** surface normal facing the eye, 'eta' POV-Ray's relative index of the
** interface; without 'lit' (a radiosity pretrace's or a deeper gather's
** hit, which sees no light source: trace.c) only the unscattered part is
** traced. Returns 'keep' filled with 'l' without its diffuse term, which
** the caller shades the lights and photons with.
*/
const struct mat_layer *subsurface_shade(struct trace_ctx *c,
                                         const struct tray *eye,
                                         const struct hit *h,
                                         const struct mat_layer *l, vec3 raw,
                                         double eta, bool lit,
                                         struct subsurface_layer *keep,
                                         double out[3]);

#endif
