/* SPDX-License-Identifier: MIT */
/*
** ior.h: the index of refraction of an interior as a function of the
** wavelength (DESIGN.md, "Index of refraction as a function of
** wavelength").
**
** Models: POV-Ray's own law n·D^((555 - lambda)/350) from 'ior' and
** 'dispersion' (povray-3.7-semantics.md §1.3), Sellmeier (given, or from
** the built-in catalogue by glass name), Cauchy, Abbe (a Cauchy curve
** through n_d with Abbe number V_d) and the seed paper's exponential decay.
**
** Numerical safety: every result is finite and lies in [IOR_MIN, IOR_MAX].
** Inputs that would give no real index (Sellmeier with n^2 <= 0 near a
** resonance, NaN parameters) are clamped into that range; ior_check()
** reports them as warnings, and unknown glass names as errors, so the
** build step can print them with the scene location.
*/
#ifndef IRIS_SPECTRUM_IOR_H
#define IRIS_SPECTRUM_IOR_H

#include <stdbool.h>
#include <stddef.h>

#include "iris/scene.h"

/* The range every index is clamped into. */
#define IOR_MIN 1e-3
#define IOR_MAX 1e3

/* Wavelengths (nm) of the Fraunhofer F, helium d and C lines. */
#define IOR_LAMBDA_F 486.1327
#define IOR_LAMBDA_D 587.5618
#define IOR_LAMBDA_C 656.2725

/* The absolute index of 'in' at 'lambda_nm'; 1 for NULL or an unset ior.
** An unknown glass name falls back to the POV-Ray law. */
double ior_eval(const iris_interior *in, double lambda_nm);

/* Whether the index of 'in' varies with the wavelength. */
bool ior_is_dispersive(const iris_interior *in);

/* The catalogue glass called 'name' (case-insensitive), or NULL. */
const struct spec_glass *ior_glass_find(const char *name);

/* The Sellmeier index n(lambda) of coefficients b, c (lambda in um,
** c in um^2), clamped as above. */
double ior_sellmeier(const double b[4], const double c[4], double lambda_um);

/* Result of ior_check(). */
enum ior_verdict { IOR_FINE = 0, IOR_WARNING = 1, IOR_ERROR = 2 };

/*
** Checks the spectral index of 'in' for what the build step must report:
** an unknown glass name (error), or parameters that clamp somewhere in the
** domain (warning). Writes a one-line message into 'msg' unless the
** verdict is IOR_FINE; the location is in->spectral_ior->loc.
*/
enum ior_verdict ior_check(const iris_interior *in, char *msg, size_t len);

#endif
