/* SPDX-License-Identifier: MIT */
/*
** roots.h: real roots of polynomials, for ray/surface intersection.
**
** Roots are isolated in brackets with one sign change each, and a
** safeguarded Newton/bisection refines each bracket to full precision.
** Up to degree 6 (torus and blob quartics, the cubics of prism and sor
** curves, the lathe's sextic) the roots of p lie between consecutive
** roots of p', so the roots of the derivative isolate them (found
** recursively; a cubic's in closed form). From degree 7 (sphere_sweep's
** degree-10 envelopes, poly of high order) the Bernstein form on the
** interval is split until each part shows at most one sign change
** (Descartes' rule), cheaper than refining every derivative's roots;
** clustered roots fall back to the derivatives.
** Neither loses a simple root the way closed-form quartic formulas can
** when coefficients cancel, which matters for thin tori seen edge-on.
** POV-Ray's 'sturm' keyword asks for exactly this robustness, so it needs
** no separate path: every object gets it.
** Cubics whose roots are well separated (roots_cubic) are solved in
** closed form as POV-Ray solves them, then polished by Newton's method:
** the sor's and prism's curves, and a quartic's critical points; where
** two roots nearly meet, the closed form is not accurate and the
** bracketing solver above takes over.
*/
#ifndef IRIS_GEOMETRY_ROOTS_H
#define IRIS_GEOMETRY_ROOTS_H

#include <stdbool.h>

#define ROOTS_MAX_DEGREE 35

/*
** Stores in 'out' (ascending) the real roots in the open interval (lo, hi)
** of c[0] + c[1]·t + ... + c[deg]·t^deg, and returns their count (at most
** 'deg'). Infinite 'lo'/'hi' are replaced by Cauchy's root bound. Roots of
** even multiplicity (the polynomial touches zero without changing sign)
** are not reported: for a ray they are grazing contacts.
*/
int roots_in_interval(const double *c, int deg, double lo, double hi,
                      double *out);

/*
** The first min(cap, their count) of the roots roots_in_interval() stores,
** the same values to the bit, without refining the others: for a caller
** that keeps only the nearest crossing (accel/node.c, the torus).
*/
int roots_first_in_interval(const double *c, int deg, double lo, double hi,
                            double *out, int cap);

/*
** roots_in_interval(c, 3, lo, hi, out) for a cubic, the same contract,
** in closed form where that is accurate (POV-Ray's solve_cubic: the
** trigonometric form for three real roots, Cardano's for one), each root
** then polished by Newton's method on c; cubics with nearly coincident
** roots, or whose normalised coefficients overflow, are left to
** roots_in_interval(). For the exact curves of sor and prism.
*/
int roots_cubic(const double *c, double lo, double hi, double *out);

/*
** Whether every value roots_eval(c, deg, t) can take for t in [lo, hi]
** (finite) surely exceeds v, by a margin beyond rounding (roots.c, a
** Bernstein bound). False means "not proved", not "no".
*/
bool roots_surely_above(const double *c, int deg, double lo, double hi,
                        double v);

/* Horner evaluation of the polynomial above. */
double roots_eval(const double *c, int deg, double t);

#endif
