/* SPDX-License-Identifier: MIT */
/*
** scene_world.h: a parsed scene with what photon shooting needs beside it
** (its Embree accel and material context), for the photon tracer's unit
** tests (test_pwave.c, test_wflanes.c). Fails the test if any part cannot
** be built.
*/
#ifndef IRIS_TESTS_SCENE_WORLD_H
#define IRIS_TESTS_SCENE_WORLD_H

#include "parse_util.h"

#include "accel/accel.h"
#include "material/material.h"

struct world {
    iris_scene *sc;
    struct accel *a;
    struct mat_ctx *mc;
};

/* Parses 'sdl' and builds its accel and material context into 'w'. */
static inline void world_open(struct world *w, const char *sdl)
{
    w->sc = pt_scene_with(sdl, NULL);
    w->a = NULL;
    char err[256];
    assert_int_equal(accel_build(w->sc, &w->a, stderr, err, sizeof err),
                     IRIS_OK);
    w->mc = NULL;
    assert_int_equal(mat_ctx_create(w->sc, stderr, &w->mc), IRIS_OK);
}

static inline void world_close(struct world *w)
{
    mat_ctx_destroy(w->mc);
    accel_destroy(w->a);
    iris_scene_destroy(w->sc);
}

#endif
