/* SPDX-License-Identifier: MIT */
/*
** targets.h: the objects photons are shot at, found as POV-Ray 3.7 finds
** them (targets.c), and the test that a photon's first hit is on its
** target.
*/
#ifndef IRIS_PHOTON_TARGETS_H
#define IRIS_PHOTON_TARGETS_H

#include <stdbool.h>

#include "iris/common.h"
#include "iris/scene.h"

/* A list of objects. */
struct ptargets {
    const iris_object **o;
    bool *top;                 /* ptargets_find(): o[i] is one of the
                                  scene's top-level objects; else NULL */
    int n, cap;
};

/*
** The photon targets of 'sc' in the order POV-Ray 3.7 shoots them
** (targets.c): into *out (its arrays o and top iris_free()d by the
** caller, also on failure). Returns IRIS_OK or IRIS_ENOMEM.
*/
IRIS_NODISCARD enum iris_status ptargets_find(const iris_scene *sc,
                                              struct ptargets *out);

/*
** The leaves (objects that are not CSG) of target 't', sorted by address
** for ptargets_has(); empty (n 0) when 't' is itself a leaf. Returns
** IRIS_OK or IRIS_ENOMEM.
*/
IRIS_NODISCARD enum iris_status ptargets_leaves(const iris_object *t,
                                                struct ptargets *out);

/* Whether leaf 'o' is in 'sorted' (ptargets_leaves). */
bool ptargets_has(const iris_object *const *sorted, int n,
                  const iris_object *o);

#endif
