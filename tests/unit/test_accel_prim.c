/* SPDX-License-Identifier: MIT */
/*
** test_accel_prim.c: accel_prim_hit(), the one-primitive test behind the
** shadow cache (trace.c point_shadow). The cache declares a shadow ray
** blocked when the primitive that last blocked its light has a crossing
** in the ray's range; that is only right if then accel_intersect() over
** the same range hits something too, at or before that crossing. This
** checks that rule, and that a hit's own primitive gives the hit's t to
** the bit, on random rays through a scene of spheres, boxes, CSG, a
** clipped object and a plane, once searched linearly and once through
** Embree (more than accel.c's LINEAR_MAX primitives).
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "util/arena.h"
#include "util/rng.h"

#include "scene_builder.h"

/* 'n_spheres' spheres on a grid, a box with a sphere cut out, an
** intersection, a sphere clipped by a box, a no_shadow sphere and a
** floor plane, in the box -4..4. */
static iris_scene *make_scene(int n_spheres, iris_object **noshadow)
{
    iris_scene *sc = scene_new();
    for (int i = 0; i < n_spheres; i++)
        add(sc, sphere(sc, v3(-3 + 2 * (i % 4), 0.5 * (i / 4), 2 - (i % 3)),
                       0.45));
    add(sc, csg_pair(sc, IRIS_OBJ_DIFFERENCE, box_object(sc, v3(-1, 0, -1), v3(1, 2, 1)),
                sphere(sc, v3(0, 2, 0), 1.2)));
    add(sc, csg_pair(sc, IRIS_OBJ_INTERSECTION, sphere(sc, v3(2, 1, -2), 1),
                sphere(sc, v3(2.8, 1, -2), 1)));
    iris_object *cl = add(sc, sphere(sc, v3(-2, 1, -2), 1));
    cl->n_clipped_by = 1;
    cl->clipped_by = arena_array(sc->arena, 1, sizeof(iris_object *));
    cl->clipped_by[0] = box_object(sc, v3(-3, 0, -3), v3(-2, 3, -1));
    *noshadow = add(sc, sphere(sc, v3(0, 3, -3), 0.7));
    (*noshadow)->no_shadow = true;
    iris_object *pl = add(sc, obj(sc, IRIS_OBJ_PLANE));
    pl->u.plane.normal = v3(0, 1, 0);
    pl->u.plane.distance = -0.5;
    return sc;
}

/* A random point in -5..5 on each axis. */
static vec3 rand_point(rng *r)
{
    return v3(10 * rng_uniform(r) - 5, 10 * rng_uniform(r) - 5,
              10 * rng_uniform(r) - 5);
}

static void check_scene(int n_spheres, bool want_embree)
{
    iris_object *noshadow;
    iris_scene *sc = make_scene(n_spheres, &noshadow);
    struct accel *a = build(sc);
    assert_true(accel_prim_cache_pays(a) == want_embree);
    double eps = accel_epsilon(a);
    const void *seen[64];
    int n_seen = 0;
    rng r;
    rng_seed(&r, 12345, (uint64_t)n_spheres, 0);
    int hits = 0, cache_yes = 0, noshadow_hits = 0;
    for (int i = 0; i < 20000; i++) {
        vec3 o = rand_point(&r);
        vec3 d = v3_sub(rand_point(&r), o);
        if (!(v3_len(d) > 1e-3))
            continue;
        ray ry = { o, v3_norm(d) };
        /* half the rays end at a point, as shadow rays do */
        double tmax = (i & 1) ? INFINITY : 12 * rng_uniform(&r);
        unsigned skip = (i & 2) ? ACCEL_SKIP_NO_SHADOW : 0;
        struct hit h;
        bool any = accel_intersect_prim(a, &ry, eps, tmax, skip, &h);
        /* the same hit as the query without the prim */
        struct hit h0;
        assert_true(accel_intersect(a, &ry, eps, tmax, skip, &h0) == any);
        if (any)
            assert_true(h0.t == h.t && h0.obj == h.obj);
        if (any) {
            hits++;
            /* the hit's own primitive: the same crossing, to the bit */
            assert_non_null(h.prim);
            double t = -1;
            assert_true(accel_prim_hit(a, h.prim, &ry, eps, tmax, skip, &t));
            assert_true(t == h.t);
            /* and nothing in (eps, h.t]: the open range ends before it */
            double t2;
            if (accel_prim_hit(a, h.prim, &ry, eps, h.t, skip, &t2))
                fail_msg("prim_hit found t=%g before the nearest %g", t2,
                         h.t);
            if (h.obj == noshadow)
                noshadow_hits++;
            int k = 0;
            while (k < n_seen && seen[k] != h.prim)
                k++;
            if (k == n_seen && n_seen < 64)
                seen[n_seen++] = h.prim;
        }
        /* the cache's rule: any primitive's crossing in the range means
        ** the query hits, at or before it */
        for (int k = 0; k < n_seen; k++) {
            double t;
            if (!accel_prim_hit(a, seen[k], &ry, eps, tmax, skip, &t))
                continue;
            cache_yes++;
            assert_true(any);
            assert_true(h.t <= t);
            assert_true(t > eps && t < tmax);
        }
    }
    /* the rays met the scene, the no_shadow sphere only when not
    ** skipped, and most primitives were tested by the cache rule */
    assert_true(hits > 2000);
    assert_true(noshadow_hits > 0);
    assert_true(cache_yes > hits);
    assert_true(n_seen >= n_spheres);
    /* the no_shadow sphere is passed through by a shadow query */
    ray down = { v3(0, 5, -3), v3(0, -1, 0) };
    struct hit h;
    assert_true(accel_intersect_prim(a, &down, eps, INFINITY, 0, &h));
    assert_true(h.obj == noshadow);
    double t;
    assert_true(accel_prim_hit(a, h.prim, &down, eps, INFINITY, 0, &t));
    assert_false(accel_prim_hit(a, h.prim, &down, eps, INFINITY,
                                ACCEL_SKIP_NO_SHADOW, &t));
    /* a non-finite ray or an empty range is no hit, as for the query */
    ray bad = { v3(NAN, 0, 0), v3(0, -1, 0) };
    assert_false(accel_prim_hit(a, h.prim, &bad, eps, INFINITY, 0, &t));
    assert_false(accel_prim_hit(a, h.prim, &down, 3, 3, 0, &t));
    accel_destroy(a);
    arena_destroy(sc->arena);
}

/* Four primitives (the CSG, the clipped and the no_shadow sphere): the
** linear search. */
static void test_linear(void **state)
{
    (void)state;
    check_scene(0, false);
}

/* Many: Embree, where the shadow cache is used (render.c). */
static void test_embree(void **state)
{
    (void)state;
    check_scene(16, true);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_linear),
        cmocka_unit_test(test_embree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
