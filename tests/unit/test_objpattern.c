/* SPDX-License-Identifier: MIT */
/*
** test_objpattern.c: the inside test of the object pattern
** (src/material/objpattern.c) against analytic answers: a difference of
** spheres (a shell) at radii inside, within and outside the shell; a moved
** sphere; inverse; clipped_by; a plane and its inverse (POV-Ray counts
** the plane itself inside both); a closed tetrahedron mesh2 with and
** without an inside_vector; a prism whose outline must be prepared; and a
** random cross-check of a nested CSG tree against the accel's own inside
** test (src/accel/node.c, an independent walk of the same rules).
** Points are kept at least 1e-3 from every boundary, so no tolerance is
** involved: each answer is exact.
*/
#include "config.h"

#include "testutil.h"

#include "material/objpattern.h"
#include "util/rng.h"

#include "scene_builder.h"

static iris_object *csg(iris_scene *sc, enum iris_object_kind k, int n,
                        iris_object **kids)
{
    iris_object *o = obj(sc, k);
    o->texture = NULL;
    o->u.csg.n_children = n;
    o->u.csg.children = arena_array(sc->arena, (size_t)n, sizeof *kids);
    for (int i = 0; i < n; i++)
        o->u.csg.children[i] = kids[i];
    return o;
}

static bool in(const iris_object *o, double x, double y, double z)
{
    return objpat_inside(NULL, o, v3(x, y, z));
}

/* A shell: sphere 1 minus sphere 0.5, both about the origin. */
static void test_difference_shell(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *k[2] = { sphere(sc, v3(0, 0, 0), 1),
                          sphere(sc, v3(0, 0, 0), 0.5) };
    iris_object *d = csg(sc, IRIS_OBJ_DIFFERENCE, 2, k);
    assert_false(in(d, 0.25, 0, 0));       /* in the hole */
    assert_true(in(d, 0, 0.75, 0));        /* in the shell */
    assert_true(in(d, 0, 0, -0.9));
    assert_false(in(d, 1.2, 0, 0));        /* outside */
    d->inverse = true;                     /* everything but the shell */
    assert_true(in(d, 0.25, 0, 0));
    assert_false(in(d, 0, 0.75, 0));
    assert_true(in(d, 1.2, 0, 0));
    arena_destroy(sc->arena);
}

/* The object's own transform: a unit sphere moved to x = 3. */
static void test_transform(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *s = sphere(sc, v3(0, 0, 0), 1);
    xform t;
    xf_identity(&t);
    xf_translate(&t, v3(3, 0, 0));
    apply(s, &t);
    assert_true(in(s, 3.9, 0, 0));
    assert_false(in(s, 0, 0, 0));
    arena_destroy(sc->arena);
}

/* clipped_by: a box cut by a sphere keeps only points in both. */
static void test_clipped_by(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *b = obj(sc, IRIS_OBJ_BOX);
    b->u.box.lo = v3(-1, -1, -1);
    b->u.box.hi = v3(1, 1, 1);
    b->n_clipped_by = 1;
    b->clipped_by = arena_array(sc->arena, 1, sizeof *b->clipped_by);
    b->clipped_by[0] = sphere(sc, v3(1, 0, 0), 1);
    assert_true(in(b, 0.5, 0, 0));
    assert_false(in(b, -0.5, 0, 0));       /* in the box, not the sphere */
    assert_false(in(b, 1.5, 0, 0));        /* in the sphere, not the box */
    arena_destroy(sc->arena);
}

/* plane { y, 1 }: inside below y = 1; the plane itself is inside the
** plane and its inverse alike (POV-Ray's EPSILON). */
static void test_plane(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *p = obj(sc, IRIS_OBJ_PLANE);
    p->u.plane.normal = v3(0, 2, 0);       /* not unit: normalised */
    p->u.plane.distance = 1;
    assert_true(in(p, 5, 0.5, -3));
    assert_false(in(p, 5, 1.5, -3));
    assert_true(in(p, 0, 1, 0));
    p->inverse = true;
    assert_false(in(p, 5, 0.5, -3));
    assert_true(in(p, 5, 1.5, -3));
    assert_true(in(p, 0, 1, 0));
    arena_destroy(sc->arena);
}

/* A closed tetrahedron: inside by the parity of crossings along the
** inside_vector; without one, never inside (POV-Ray's Mesh::Inside). */
static void test_mesh(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *m = obj(sc, IRIS_OBJ_MESH);
    static iris_vec3 v[4] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 2, 0 },
                              { 0, 0, 2 } };
    static int32_t f[12] = { 0, 1, 2, 0, 1, 3, 1, 2, 3, 0, 2, 3 };
    m->u.mesh.n_vertices = 4;
    m->u.mesh.vertices = v;
    m->u.mesh.n_triangles = 4;
    m->u.mesh.tri_vertices = f;
    assert_false(in(m, 0.3, 0.3, 0.3));    /* no inside_vector */
    m->u.mesh.inside_vector = (iris_vec3){ 0.3, 0.2, 1 };
    assert_true(in(m, 0.3, 0.3, 0.3));     /* x + y + z < 2, all > 0 */
    assert_true(in(m, 0.1, 1.2, 0.4));
    assert_false(in(m, 0.8, 0.8, 0.8));    /* x + y + z > 2 */
    assert_false(in(m, -0.2, 0.3, 0.3));
    assert_false(in(m, 0.3, 0.3, -0.5));   /* below: crosses twice */
    arena_destroy(sc->arena);
}

/* A prism needs its outline: prepared by objpat_add, absent without. */
static void test_prism_profile(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *p = obj(sc, IRIS_OBJ_PRISM);
    static iris_vec2 pts[5] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 },
                                { 0, 0 } };
    p->u.prism.spline = IRIS_SPLINE_LINEAR;
    p->u.prism.height1 = 0;
    p->u.prism.height2 = 1;
    p->u.prism.n_points = 5;
    p->u.prism.points = pts;
    struct objpat_set s = { 0 };
    assert_int_equal(objpat_add(&s, sc, p, NULL), IRIS_OK);
    objpat_seal(&s);
    assert_true(objpat_inside(&s, p, v3(0.5, 0.5, 0.5)));
    assert_false(objpat_inside(&s, p, v3(1.5, 0.5, 0.5)));
    assert_false(objpat_inside(&s, p, v3(0.5, 1.5, 0.5)));
    assert_false(objpat_inside(&s, p, v3(0.5, 0.5, -0.5)));
    /* adding it again changes nothing */
    assert_int_equal(objpat_add(&s, sc, p, NULL), IRIS_OK);
    assert_int_equal(s.n, 1);
    objpat_fini(&s);
    arena_destroy(sc->arena);
}

/* A nested tree, answered by objpat_inside and by the accel: union of
** (intersection of two spheres) and (merge of a box with an inverse
** sphere, clipped by a sphere), all under a rotation. */
static void test_against_accel(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *lens[2] = { sphere(sc, v3(-0.5, 0, 0), 1),
                             sphere(sc, v3(0.5, 0, 0), 1) };
    iris_object *a = csg(sc, IRIS_OBJ_INTERSECTION, 2, lens);
    iris_object *b = obj(sc, IRIS_OBJ_BOX);
    b->u.box.lo = v3(1, -1, -1);
    b->u.box.hi = v3(2, 1, 1);
    iris_object *inv = sphere(sc, v3(0, 2, 0), 0.7);
    inv->inverse = true;
    iris_object *mk[2] = { b, inv };
    iris_object *m = csg(sc, IRIS_OBJ_MERGE, 2, mk);
    m->n_clipped_by = 1;
    m->clipped_by = arena_array(sc->arena, 1, sizeof *m->clipped_by);
    m->clipped_by[0] = sphere(sc, v3(1, 0.5, 0), 1.6);
    iris_object *uk[2] = { a, m };
    iris_object *u = add(sc, csg(sc, IRIS_OBJ_UNION, 2, uk));
    xform r;
    xf_identity(&r);
    xf_rotate(&r, v3(20, 35, -10));
    /* the parser folds a CSG's transform into every part */
    apply(u, &r);
    apply(a, &r);
    apply(lens[0], &r);
    apply(lens[1], &r);
    apply(m, &r);
    apply(b, &r);
    apply(inv, &r);
    apply(m->clipped_by[0], &r);
    struct accel *acc = build(sc);
    struct objpat_set s = { 0 };
    assert_int_equal(objpat_add(&s, sc, u, NULL), IRIS_OK);
    objpat_seal(&s);
    rng r64;
    rng_seed(&r64, 12345, 0, 0);
    int n_in = 0;
    for (int i = 0; i < 20000; i++) {
        vec3 p = v3(6 * rng_uniform(&r64) - 3, 6 * rng_uniform(&r64) - 3,
                    6 * rng_uniform(&r64) - 3);
        bool want = accel_inside(acc, u, p);
        assert_int_equal(objpat_inside(&s, u, p), want);
        n_in += want;
    }
    /* both answers occur often: the comparison means something */
    assert_true(n_in > 1000 && n_in < 19000);
    objpat_fini(&s);
    accel_destroy(acc);
    arena_destroy(sc->arena);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_difference_shell),
        cmocka_unit_test(test_transform),
        cmocka_unit_test(test_clipped_by),
        cmocka_unit_test(test_plane),
        cmocka_unit_test(test_mesh),
        cmocka_unit_test(test_prism_profile),
        cmocka_unit_test(test_against_accel),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
