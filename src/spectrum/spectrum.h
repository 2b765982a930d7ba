/* SPDX-License-Identifier: MIT */
/*
** spectrum.h: colour matching, RGB <-> spectrum, light emission spectra.
**
** The spectral domain is [SPEC_LAMBDA_MIN, SPEC_LAMBDA_MAX] = 380..780 nm.
** Every curve here is a continuous function of the wavelength, the linear
** interpolation of the compiled tables (tables.h), so a renderer samples
** any lambda it likes.
**
** Units. A wavelength drawn uniformly from the domain (pdf 1/400 per nm)
** contributes linear sRGB
**
**     rgb = spectral_value(lambda) * spec_lambda_rgb_weight(lambda),
**
** where spectral_value is 1 for white light (D65) on a white surface. The
** weight includes D65, the CMFs and 1/pdf; its uniform average over the
** domain is exactly (1, 1, 1), channel by channel (see spectrum.c). So a
** photon or a camera sample that carries a wavelength only ever multiplies
** scalars (light relative to D65, reflectance, transmittance) and turns
** them into RGB with one call.
**
** Depends on: iris/scene.h (light kinds). Used by: material, photon,
** render. All functions are thread-safe (the derived constants are set up
** once, under pthread_once).
*/
#ifndef IRIS_SPECTRUM_SPECTRUM_H
#define IRIS_SPECTRUM_SPECTRUM_H

#include "iris/scene.h"

#define SPEC_LAMBDA_MIN 380.0
#define SPEC_LAMBDA_MAX 780.0
#define SPEC_LAMBDA_RANGE (SPEC_LAMBDA_MAX - SPEC_LAMBDA_MIN)

/* CIE 1931 2-degree x, y, z at 'lambda' nm (1 nm table, interpolated;
** zero outside 360..830 nm). */
void spec_cmf(double lambda, double xyz[3]);

/* CIE D65 relative SPD at 'lambda' (S(560) = 100, interpolated). */
double spec_d65(double lambda);

/* XYZ (Y = 1 white) to linear sRGB, and back: the full-precision D65
** matrices of data/srgb.md. */
void spec_xyz_to_rgb(const double xyz[3], double rgb[3]);
void spec_rgb_to_xyz(const double rgb[3], double xyz[3]);

/*
** Burns' linear RGB -> reflectance: r·rhoR(lambda) + g·rhoG + b·rhoB,
** with the three curves of tools/burns.c. For rgb in [0,1]^3 the result is
** in [0,1]; (1,1,1) gives exactly 1, and grey g gives the flat curve g.
** 'lambda' is clamped to the domain. Outside the unit cube the result is
** the same linear combination (it may leave [0,1]).
*/
double spec_reflectance(const double rgb[3], double lambda);

/*
** The linear sRGB of one sample at 'lambda' drawn uniformly from the
** domain under D65 white light: w_c(lambda) = k_c · [M·cmf(lambda)·
** D65(lambda)]_c with per-channel constants k_c chosen so that the mean of
** w_c over the domain is exactly 1 (the integral uses the same linear
** interpolants, integrated exactly). Without the per-channel balance, D65
** would map to (1.00004, 1.00002, 0.99973) instead of white.
*/
void spec_lambda_rgb_weight(double lambda, double w[3]);

/*
** An illuminant's SPD normalised to Y = 1: its integral against ybar over
** the domain is 1 (per nm). 'kelvin' is used only by IRIS_SPEC_BLACKBODY
** (clamped to [100, 1e6] K). F1..F12 are interpolated linearly between
** the 5 nm CIE values, as CIE 015 does.
*/
double spec_illuminant(enum iris_light_spectrum s, double kelvin,
                       double lambda);

/*
** The emission of light 'l' at 'lambda' relative to white D65 of the same
** luminance: (its Y = 1 shape / D65's Y = 1 shape) times the light colour
** upsampled with spec_reflectance (negative channels count as 0). A plain
** white POV-Ray light gives 1 at every wavelength; colour 2 gives 2. Times
** spec_lambda_rgb_weight() this is the light's linear sRGB.
*/
double spec_light(const iris_light *l, double lambda);

/*
** spec_light() of one light, prepared once: the normalisation of a
** blackbody needs an integral, which a photon loop must not repeat.
*/
struct spec_emitter {
    enum iris_light_spectrum shape;
    double kelvin;
    double scale;              /* 1 / Y of the shape, times D65's Y */
    double rgb[3];             /* light colour, negative channels = 0 */
};
void spec_emitter_init(struct spec_emitter *e, const iris_light *l);
double spec_emitter_eval(const struct spec_emitter *e, double lambda);

/*
** The linear sRGB that light 'l' gives a white diffuse surface: its
** colour unchanged for the default D65 shape (POV-Ray's shading), else
** the domain mean of spec_light() x spec_lambda_rgb_weight() (what its
** photons give a white surface). For the lighting that stays RGB.
*/
void spec_light_rgb(const iris_light *l, double rgb[3]);

/* Maps u in [0,1) to a wavelength, uniform over the domain (pdf 1/400). */
static inline double spec_sample_uniform(double u)
{
    return SPEC_LAMBDA_MIN + u * SPEC_LAMBDA_RANGE;
}

#endif
