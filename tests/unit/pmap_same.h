/* SPDX-License-Identifier: MIT */
/*
** pmap_same.h: asserts that two photon maps built two ways (fast path or
** accel, texture cache or none) hold the same records to the bit, for
** test_pfast.c and test_ptexcache.c. Include after testutil.h.
*/
#ifndef IRIS_TESTS_PMAP_SAME_H
#define IRIS_TESTS_PMAP_SAME_H

#include "photon/pmap.h"

/* The caustic map of 'a' and 'b', or, when they have one, their global
** maps with their irradiance points: the same count (over 1000, else the
** comparison says little), records, irradiances and gather radius. */
static inline void assert_same_photon_maps(const struct photon_map *a,
                                           const struct photon_map *b)
{
    if (a->global) {
        assert_non_null(b->global);
        a = a->global;
        b = b->global;
        assert_int_equal(a->store.n, b->store.n);
        assert_memory_equal(a->irr, b->irr, a->store.n * sizeof *a->irr);
    }
    assert_true(a->store.n > 1000);
    assert_int_equal(a->store.n, b->store.n);
    assert_memory_equal(a->store.ph, b->store.ph,
                        a->store.n * sizeof *a->store.ph);
    assert_true(a->radius == b->radius);
}

#endif
