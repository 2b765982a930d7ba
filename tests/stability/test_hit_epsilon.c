/* SPDX-License-Identifier: MIT */
/*
** test_hit_epsilon.c: the per-hit ray offset of src/accel (hit.eps).
**
** accel_epsilon() is 1e-9 of the whole scene, so one sphere of radius 1e6
** around a scene makes it 1e-3 and a secondary ray started that far from
** a 1e-7 glass shell jumps over the shell's other wall. hit.eps is 1e-9 of
** the object hit and of |p|: these tests check that it finds such walls,
** that it is still large enough that no secondary ray meets its own
** surface again, at scales 1e-6, 1 and 1e6, and that it scales with the
** scene. Scenes are built by hand, as the parser would build them.
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <stdio.h>

#include "accel/accel.h"
#include "iris/fn.h"
#include "math/transform.h"
#include "util/arena.h"
#include "util/rng.h"

#include "scene_builder.h"

/* difference { sphere { 0, 1 } sphere { 0, 1 - 1e-7 } } inside a sphere of
** radius 1e6: the ray through the centre meets the outer wall at t = 4
** and, started hit.eps beyond it, the inner wall 1e-7 further. */
static void test_thin_shell_in_huge_scene(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *d = add(sc, obj(sc, IRIS_OBJ_DIFFERENCE));
    d->texture = NULL;
    d->u.csg.n_children = 2;
    d->u.csg.children = arena_array(sc->arena, 2, sizeof(iris_object *));
    d->u.csg.children[0] = sphere(sc, v3(0, 0, 0), 1);
    d->u.csg.children[1] = sphere(sc, v3(0, 0, 0), 1 - 1e-7);
    add(sc, sphere(sc, v3(0, 0, 0), 1e6));
    struct accel *a = build(sc);

    struct hit h, h2;
    ray r = { v3(0, 0, -5), v3(0, 0, 1) };
    assert_true(accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h));
    assert_near(h.t, 4, 1e-12);
    /* 1e-9 of the shell's diameter 2 and of |p| = 1 */
    assert_near(h.eps, 2e-9, 1e-15);
    assert_true(accel_epsilon(a) >= 1e-3);

    ray r2 = { h.p, r.d };
    assert_true(accel_intersect(a, &r2, h.eps, INFINITY, 0, &h2));
    /* The inner wall, 1e-7 on: 1e-13 is a thousand ulps of p */
    assert_near(h2.t, 1e-7, 1e-13);
    assert_true(h2.obj == d->u.csg.children[1]);
    accel_destroy(a);
    arena_destroy(sc->arena);
}

/* A plane has no size: its hits keep the scene's offset. */
static void test_unbounded_keeps_global(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *p = add(sc, obj(sc, IRIS_OBJ_PLANE));
    p->u.plane.normal = v3(0, 1, 0);
    p->u.plane.distance = 0;
    add(sc, sphere(sc, v3(0, 5, 0), 1e3));
    struct accel *a = build(sc);
    struct hit h;
    ray r = { v3(0, 1, 0), v3(0, -1, 0) };
    assert_true(accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h));
    assert_true(h.obj == p);
    assert_true(h.eps == accel_epsilon(a));
    accel_destroy(a);
    arena_destroy(sc->arena);
}

/* The SDL function x*x + y*y + z*z - c, compiled by hand. */
static iris_fn *sphere_fn(iris_scene *sc, double c)
{
    static const enum iris_fn_op ops[13] = {
        IRIS_FN_PARAM, IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_PARAM,
        IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_ADD, IRIS_FN_PARAM,
        IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_ADD, IRIS_FN_CONST, IRIS_FN_SUB
    };
    static const int args[13] = { 0, 0, 0, 1, 1, 0, 0, 2, 2, 0, 0, 0, 0 };
    iris_fn *f = arena_alloc(sc->arena, sizeof *f);
    f->n_params = 3;
    f->n_code = 13;
    f->code = arena_array(sc->arena, 13, sizeof *f->code);
    for (int i = 0; i < 13; i++) {
        f->code[i].op = ops[i];
        f->code[i].arg = args[i];
    }
    f->code[11].value = c;
    f->max_stack = 4;
    f->n_results = 1;
    return f;
}

/* Shapes of every solver (quadric, box, torus quartic, blob, superellipsoid
** bisection, isosurface sampling, triangle) scaled by 'scale', and a
** sphere 1e6 times larger around them. */
static iris_scene *shapes_scene(double scale)
{
    iris_scene *sc = scene_new();
    add(sc, sphere(sc, v3(-3, 0, 0), 1));
    iris_object *b = add(sc, obj(sc, IRIS_OBJ_BOX));
    b->u.box.lo = v3(-1, -1, -1);
    b->u.box.hi = v3(1, 0.5, 1);
    xform x;
    xf_rotate(&x, v3(20, 30, 0));
    apply(b, &x);
    iris_object *t = add(sc, obj(sc, IRIS_OBJ_TORUS));
    t->u.torus.major = 1;
    t->u.torus.minor = 0.3;
    xf_translate(&x, v3(3, 0, 0));
    apply(t, &x);
    iris_object *bl = add(sc, obj(sc, IRIS_OBJ_BLOB));
    iris_blob_component *bc = arena_array(sc->arena, 1, sizeof *bc);
    bc[0].a = v3(-3, 3, 0);
    bc[0].radius = 1.5;
    bc[0].strength = 1;
    bl->u.blob.threshold = 0.2;
    bl->u.blob.n_components = 1;
    bl->u.blob.components = bc;
    iris_object *se = add(sc, obj(sc, IRIS_OBJ_SUPERELLIPSOID));
    se->u.superellipsoid.e = 0.3;
    se->u.superellipsoid.n = 2.5;
    xf_translate(&x, v3(0, 3, 0));
    apply(se, &x);
    iris_object *iso = add(sc, obj(sc, IRIS_OBJ_ISOSURFACE));
    iso->u.isosurface.fn = sphere_fn(sc, 0.8);
    iso->u.isosurface.lo = v3(-1, -1, -1);
    iso->u.isosurface.hi = v3(1, 1, 1);
    iso->u.isosurface.max_gradient = 4;
    /* POV-Ray's accuracy is a distance along the ray, not in the shape's
    ** units: a scene scaled by 'scale' scales it too (isosurface.c) */
    iso->u.isosurface.accuracy = 1e-3 * scale;
    iso->u.isosurface.max_trace = 1;
    xf_translate(&x, v3(0, -2, 0));
    apply(iso, &x);
    iris_object *tr = add(sc, obj(sc, IRIS_OBJ_TRIANGLE));
    tr->u.triangle.p[0] = v3(2, 2, 0);
    tr->u.triangle.p[1] = v3(4, 2, 0.5);
    tr->u.triangle.p[2] = v3(3, 4, -0.5);
    xf_scale(&x, v3(scale, scale, scale));
    for (int i = 0; i < sc->n_objects; i++)
        apply(sc->objects[i], &x);
    add(sc, sphere(sc, v3(0, 0, 0), 1e6 * scale));
    return sc;
}

/* Random rays at the shapes (about 1 in 5 meets one); from each hit a secondary ray in a random
** direction (not within 1e-3 of the tangent plane) started hit.eps away.
** None may meet its own surface again within 1e-5 of the scene's size:
** every shape here is thicker than that, so such a hit is a self-hit. */
static void self_hits_at(double scale, double *eps_sum)
{
    iris_scene *sc = shapes_scene(scale);
    struct accel *a = build(sc);
    rng g;
    rng_seed(&g, 5, 0, 0);
    int n = 0, bad = 0;
    *eps_sum = 0;
    for (int i = 0; i < 20000; i++) {
        ray r = { v3_scale(v3(10 * rng_uniform(&g) - 5,
                              8 * rng_uniform(&g) - 3, -9), scale),
                  v3_norm(v3(0.2 * rng_uniform(&g) - 0.1,
                             0.2 * rng_uniform(&g) - 0.1, 1)) };
        struct hit h, h2;
        if (!accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h) ||
            h.t > 100 * scale)
            continue;
        assert_true(h.eps > 0 && h.eps <= accel_epsilon(a));
        *eps_sum += h.eps / scale;
        vec3 d = v3_norm(v3(rng_uniform(&g) - 0.5, rng_uniform(&g) - 0.5,
                            rng_uniform(&g) - 0.5));
        if (fabs(v3_dot(d, h.n)) < 1e-3)
            continue;
        ray r2 = { h.p, d };
        n++;
        if (accel_intersect(a, &r2, h.eps, INFINITY, 0, &h2) &&
            h2.obj == h.obj && h2.t < 1e-5 * scale)
            bad++;
    }
    assert_true(n > 2000);
    if (bad > 0)
        fail_msg("scale %g: %d of %d secondary rays met their own surface "
                 "again", scale, bad, n);
    accel_destroy(a);
    arena_destroy(sc->arena);
}

/* No self-hits at any scale, and the offsets scale with the scene: the
** same rays give the same eps/scale, to float-noise (1e-6 relative). */
static void test_no_self_hits_at_any_scale(void **state)
{
    (void)state;
    double e1, es, el;
    self_hits_at(1, &e1);
    self_hits_at(1e-6, &es);
    self_hits_at(1e6, &el);
    assert_rel(es, e1, 1e-6);
    assert_rel(el, e1, 1e-6);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_thin_shell_in_huge_scene),
        cmocka_unit_test(test_unbounded_keeps_global),
        cmocka_unit_test(test_no_self_hits_at_any_scale),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
