/* SPDX-License-Identifier: MIT */
/*
** fastpath.h: the photon tracer's ray query for scenes of a few spheres
** and planes (fastpath.c), without the general accel.
*/
#ifndef IRIS_PHOTON_FASTPATH_H
#define IRIS_PHOTON_FASTPATH_H

#include <stdbool.h>
#include <stdio.h> /* accel.h uses FILE */

#include "accel/accel.h"

struct pfast;

/* At most this many primitives take the fast path (a linear scan). */
#define PFAST_MAX_PRIMS 8

/*
** The fast query of 'scene' as built in 'a', or NULL when the scene is not
** made only of top-level spheres and planes without clipped_by (then the
** caller uses accel_intersect), or on out of memory. Both are borrowed.
*/
struct pfast *pfast_build(const iris_scene *scene, const struct accel *a);

void pfast_destroy(struct pfast *f);

/*
** Whether 'f' answers with its plain scan: no primitive transformed and
** no sphere whose texture may read uv, so the query calls no function.
** Either scan gives the same hits (tests/unit/test_pfast.c runs both).
*/
bool pfast_plain(const struct pfast *f);

/* The accel 'f' was built from. */
const struct accel *pfast_accel(const struct pfast *f);

/*
** accel_intersect() of the scene 'f' was built from, for photons: the
** same nearest hit, t, p, normals, eps, texture and interior to the bit,
** but uv is left 0 (no material code reads a hit's uv: uv_mapping is
** ignored, docs/parity.md; a sphere's uv was two inverse trigonometric
** calls per photon hit). 'f' is a struct pfast.
*/
bool pfast_intersect(const void *f, const ray *r, double tmin, double tmax,
                     unsigned skip, struct hit *h);

#endif
