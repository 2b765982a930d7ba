/* SPDX-License-Identifier: MIT */
/*
** pmap_same.h: asserts that two photon maps built two ways (fast path or
** accel, texture cache or none) hold the same records to the bit, for
** test_pfast.c and test_ptexcache.c. Include after testutil.h.
*/
#ifndef IRIS_TESTS_PMAP_SAME_H
#define IRIS_TESTS_PMAP_SAME_H

#include <string.h>

#include "photon/pmap.h"

/* Builds the photon maps of scene 'sc' twice, on 2 threads with 'seed',
** material context 'mc' (may be NULL) and a tenth of the default global
** photons (a fast test): m[0] with the default options, m[1] after
** 'second' has changed them (the way under comparison turned off). */
static inline void build_photon_map_pair(
    const iris_scene *sc, const struct accel *a, struct mat_ctx *mc,
    uint64_t seed, void (*second)(struct photon_options *),
    struct photon_map *m[2], struct photon_stats st[2])
{
    for (int k = 0; k < 2; k++) {
        struct photon_options o;
        memset(&o, 0, sizeof o);
        o.threads = 2;
        o.seed = seed;
        o.mat = mc;
        o.global_photons = 40000;
        /* both ways are the scalar tracer's, whose maps these compare
        ** record for record (the wavefront tracer's is another sample:
        ** test_pwave.c) */
        o.no_wavefront = true;
        if (k == 1)
            second(&o);
        m[k] = NULL;
        assert_int_equal(photon_map_build(sc, a, &o, &m[k], &st[k]),
                         IRIS_OK);
        assert_non_null(m[k]);
    }
}

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
