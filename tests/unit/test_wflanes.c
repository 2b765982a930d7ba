/* SPDX-License-Identifier: MIT */
/*
** The wavefront tracer's lanes kept between photon passes (shoot.c,
** wf_lanes_take/wf_lanes_give; issue 8): a progressive render shoots a
** map every pass, and fresh lanes (~1 MB a thread) each time cost every
** thread ~300 page faults a pass. Checked here:
**  - a map shot with lanes another scene left dirty (a dispersive glass
**    with more bounces and other lane counts, at 3 threads) is the map
**    shot with fresh lanes, record for record: nothing in the lanes may
**    survive from one run to the next (an exact comparison: the same
**    float operations on the same inputs; any stale lane read shows);
**  - the lanes are in fact reused: the repeat shoot allocates no block
**    of a lane's size (counted through iris_replace_allocator), where
**    the first allocated two per thread. Without the second check the
**    first could pass with lanes never kept.
** This is its own program: the first shoot of the process is the only
** one sure to get fresh lanes.
*/
#include "config.h"

#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "material/material.h"
#include "parse_util.h"
#include "scene_world.h"
#include "photon/pmap.h"

/* bench/caustic_ball.pov, as in test_pwave.c */
#define BALL_HEAD                                                          \
    "global_settings { assumed_gamma 1 max_trace_level 6\n"                \
    "  photons { count 100000 autostop 0 jitter 0.4 } }\n"                 \
    "light_source { <0, 20, 0> color rgb 1 cylinder point_at <0, 0, 0>\n"  \
    "  radius 1 falloff 1 tightness 0\n"                                   \
    "  photons { refraction on reflection on } }\n"                        \
    "plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"

static const char *const BALL =
    BALL_HEAD
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* another pair for the lanes: dispersion (chromatic lanes, three a
** photon), a mirror finish, a deeper trace */
static const char *const OTHER =
    "global_settings { assumed_gamma 1 max_trace_level 10\n"
    "  photons { count 60000 autostop 0 jitter 0.4 } }\n"
    "light_source { <1, 20, -2> color rgb <1, 0.5, 0.15>\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"
    "sphere { <0.3, 2, 0>, 1.2 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 reflection 0.3 }\n"
    "  interior { ior 1.7 dispersion 1.1 dispersion_samples 7 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* Counting allocator: blocks at least LANE_MIN bytes. A lane block is
** 0.4-0.7 MB (wavefront.c's struct wf_state, wavefront.h's struct
** wf_run); the photon batches of this scene are under 100 kB, and the
** concatenated store, the kd-tree and the scene's tables are counted
** alike in both shoots (the same scene, the same thread count), so the
** difference of the counts is the lanes. */
#define LANE_MIN (256u * 1024u)
static int n_big;

static void *count_malloc(size_t n)
{
    if (n >= LANE_MIN)
        __atomic_add_fetch(&n_big, 1, __ATOMIC_RELAXED);
    return malloc(n);
}

static void *count_realloc(void *p, size_t n)
{
    if (n >= LANE_MIN)
        __atomic_add_fetch(&n_big, 1, __ATOMIC_RELAXED);
    return realloc(p, n);
}

static struct photon_map *shoot(const struct world *w, int threads,
                                int pass, int *big)
{
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = threads;
    o.seed = 5;
    o.pass = pass;
    o.mat = w->mc;
    struct photon_stats st;
    struct photon_map *m = NULL;
    int before = __atomic_load_n(&n_big, __ATOMIC_RELAXED);
    assert_int_equal(photon_map_build(w->sc, w->a, &o, &m, &st), IRIS_OK);
    *big = __atomic_load_n(&n_big, __ATOMIC_RELAXED) - before;
    assert_non_null(m);
    /* the wavefront tracer took every photon: the lanes were used */
    assert_true(st.shot > 1000);
    assert_int_equal(st.wavefront, st.shot);
    return m;
}

static void test_kept_lanes(void **state)
{
    (void)state;
    struct world ball, other;
    world_open(&ball, BALL);
    world_open(&other, OTHER);
    int big_fresh, big_other, big_kept;
    struct photon_map *fresh = shoot(&ball, 2, 3, &big_fresh);
    /* 3 threads: both kept pairs dirtied, a third made */
    struct photon_map *dirty = shoot(&other, 3, 1, &big_other);
    struct photon_map *kept = shoot(&ball, 2, 3, &big_kept);
    assert_true(fresh->store.n > 1000);
    assert_int_equal(fresh->store.n, kept->store.n);
    assert_memory_equal(fresh->store.ph, kept->store.ph,
                        fresh->store.n * sizeof *fresh->store.ph);
    /* two lane blocks (state, run) a thread made the first time, none
    ** the third: exact, as the rest of the two shoots is the same */
    assert_int_equal(big_fresh - big_kept, 2 * 2);
    photon_map_destroy(fresh);
    photon_map_destroy(dirty);
    photon_map_destroy(kept);
    world_close(&other);
    world_close(&ball);
}

int main(void)
{
    /* before anything is allocated (mem.c: hooks set once) */
    iris_replace_allocator(count_malloc, count_realloc, free);
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kept_lanes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
