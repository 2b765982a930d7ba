/* SPDX-License-Identifier: MIT */
/*
** scene_builder.h: scenes built by hand in an arena, as the parser would
** build them, for the tests of the ray queries (src/accel). Every object
** gets the one texture sb_texture, so a test can check that a hit names
** it; scene_new() has room for 64 top-level objects.
**
** Include after testutil.h (cmocka's asserts) in one test program.
*/
#ifndef IRIS_TESTS_SCENE_BUILDER_H
#define IRIS_TESTS_SCENE_BUILDER_H

#include "accel/accel.h"
#include "math/transform.h"
#include "util/arena.h"

static iris_texture sb_texture;

static inline iris_scene *scene_new(void)
{
    iris_arena *ar = arena_create(0);
    iris_scene *sc = arena_alloc(ar, sizeof *sc);
    sc->arena = ar;
    sc->objects = arena_array(ar, 64, sizeof *sc->objects);
    return sc;
}

static inline iris_object *obj(iris_scene *sc, enum iris_object_kind k)
{
    iris_object *o = arena_alloc(sc->arena, sizeof *o);
    o->kind = k;
    o->texture = &sb_texture;
    iris_transform_identity(&o->transform);
    return o;
}

/* Makes 'o' a top-level object of the scene. */
static inline iris_object *add(iris_scene *sc, iris_object *o)
{
    sc->objects[sc->n_objects++] = o;
    return o;
}

static inline iris_object *sphere(iris_scene *sc, vec3 c, double r)
{
    iris_object *o = obj(sc, IRIS_OBJ_SPHERE);
    o->u.sphere.centre = c;
    o->u.sphere.radius = r;
    return o;
}

static inline iris_object *box_object(iris_scene *sc, vec3 lo, vec3 hi)
{
    iris_object *o = obj(sc, IRIS_OBJ_BOX);
    o->u.box.lo = lo;
    o->u.box.hi = hi;
    return o;
}

/* A CSG object of kind 'k' (union, intersection, ...) of 'a' and 'b'. */
static inline iris_object *csg_pair(iris_scene *sc, enum iris_object_kind k,
                                    iris_object *a, iris_object *b)
{
    iris_object *o = obj(sc, k);
    o->texture = NULL;
    o->u.csg.n_children = 2;
    o->u.csg.children = arena_array(sc->arena, 2, sizeof(iris_object *));
    o->u.csg.children[0] = a;
    o->u.csg.children[1] = b;
    return o;
}

/* Appends transform 'x' after the object's own (POV-Ray order). */
static inline void apply(iris_object *o, const xform *x)
{
    xf_compose(&o->transform, &o->transform, x);
    o->has_transform = true;
}

/* Builds the ray-query structure; any failure fails the test. */
static inline struct accel *build(const iris_scene *sc)
{
    struct accel *a = NULL;
    char err[256];
    assert_int_equal(accel_build(sc, &a, NULL, err, sizeof err), IRIS_OK);
    assert_non_null(a);
    return a;
}

#endif
