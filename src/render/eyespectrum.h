/* SPDX-License-Identifier: MIT */
/*
** eyespectrum.h: the wavelengths of a camera ray that splits at a
** dispersive interface, and the colour they add up to.
**
** A camera sample that meets a dispersive interior traces n wavelengths
** (n >= the interior's dispersion_samples) and gets back, for each, a
** scalar r_i: what the eye sees at lambda_i relative to white D65. The
** colour is the CIE integral of r(lambda) under D65. Two choices make a
** handful of wavelengths usable:
**
**   - Wavelengths are stratified in the cumulative distribution of
**     p(lambda) ~ (xbar + ybar + zbar)(lambda) · D65(lambda), so samples
**     go where the eye is sensitive (none are wasted at 380 or 780 nm).
**   - Each of X, Y, Z is a SELF-NORMALISED estimate:
**         X = X_white · sum_i r_i·a_i / sum_i a_i,  a_i = xbar·D65/p at lambda_i
**     (likewise Y, Z), then XYZ -> linear sRGB. When r is the same at every
**     wavelength (clear glass, no net dispersion, a grey or white surface)
**     this gives exactly r·(1,1,1) whatever the wavelengths drawn: a white
**     path is white with 2 samples as with 200. A plain 1/p average does
**     not: 7 stratified wavelengths integrate the colour-matching curves to
**     within ~10% only, so white glass came out tinted per pixel. The
**     estimate is consistent (both sums converge to their integrals); its
**     bias for a varying r is O(1/n), and X, Y, Z each stay a convex mix
**     of the r_i, so no estimate exceeds what its brightest wavelength saw.
**
** A spectral colour can lie outside the sRGB gamut (negative channels).
** The eye pass keeps samples unclipped, averages them into the pixel and
** only then maps the pixel into the gamut with eye_gamut_map(), which
** keeps its luminance: clipping negative channels to 0 would add light
** (the mean of a 2-wavelength render came out ~5% too bright).
**
** Depends on: spectrum. Used by: trace.c (the split), eyepass.c (output).
*/
#ifndef IRIS_RENDER_EYESPECTRUM_H
#define IRIS_RENDER_EYESPECTRUM_H

/* The running sums of one split. */
struct eye_spectrum {
    double num[3];             /* sum r_i · a_i, per X, Y, Z */
    double den[3];             /* sum a_i */
    double rsum;               /* sum r_i, for a sum a_i of 0 */
    int n;
};

/* Wavelength i of n (stratum i of the CDF, position u in [0,1) inside
** it); a[3] receives cmf(lambda)·D65(lambda)/p(lambda). */
double eye_lambda_sample(int i, int n, double u, double a[3]);

void eye_spectrum_init(struct eye_spectrum *s);

/* Adds the value 'r' seen at a wavelength whose weights are 'a'. */
void eye_spectrum_add(struct eye_spectrum *s, const double a[3], double r);

/* The linear sRGB of the sums; may have negative channels. */
void eye_spectrum_rgb(const struct eye_spectrum *s, double rgb[3]);

/* Moves 'rgb' into [0, inf)^3 towards the grey of the same luminance Y
** (the sRGB Y row), as little as needed; a colour with Y <= 0 becomes
** black. Colours without negative channels are left as they are. */
void eye_gamut_map(double rgb[3]);

#endif
