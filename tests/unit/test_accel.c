/* SPDX-License-Identifier: MIT */
/*
** test_accel.c: ray queries through the Embree scene: transformed shapes,
** CSG, inside tests, skip flags, meshes, scale invariance and robustness.
** Scenes are built by hand in an arena, as the parser would build them.
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "iris/fn.h"
#include "math/transform.h"
#include "util/arena.h"
#include "util/rng.h"
#include "util/thread.h"

#include "scene_builder.h"

static iris_texture tex_b;
static iris_interior glass;

/* A texture that reads a hit's uv (a uv_mapping pattern): the fast paths
** compute uv only for such textures (accel.c texture_reads_uv). */
static iris_pigment uv_pig = { .pattern = { .kind = IRIS_PAT_CHECKER,
                                            .uv_mapping = true } };
static iris_texture uv_tex = { .pigment = &uv_pig };

static void scene_free(iris_scene *sc)
{
    arena_destroy(sc->arena);
}

static bool shoot(const struct accel *a, vec3 o, vec3 d, struct hit *h)
{
    ray r = { o, v3_norm(d) };
    return accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, h);
}

static void assert_vec(vec3 v, vec3 want, double tol)
{
    assert_near(v.x, want.x, tol);
    assert_near(v.y, want.y, tol);
    assert_near(v.z, want.z, tol);
}

/* Sphere: t = distance - radius, unit outward normal, and the hit names
** the object, its texture and its interior. Tolerances: 1e-12 is a few
** thousand ulps of the numbers involved. */
static void test_sphere_hit(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *s = add(sc, sphere(sc, v3(1, 2, 3), 1.5));
    s->interior = &glass;
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(1, 2, -7), v3(0, 0, 1), &h));
    assert_near(h.t, 10 - 1.5, 1e-12);
    assert_vec(h.p, v3(1, 2, 1.5), 1e-12);
    assert_vec(h.n, v3(0, 0, -1), 1e-12);
    assert_vec(h.shading_n, v3(0, 0, -1), 1e-12);
    assert_ptr_equal(h.obj, s);
    assert_ptr_equal(h.top, s);
    assert_ptr_equal(h.texture, &sb_texture);
    assert_ptr_equal(h.interior, &glass);
    /* From inside: the far wall, normal still outward */
    assert_true(shoot(a, v3(1, 2, 3), v3(1, 0, 0), &h));
    assert_near(h.t, 1.5, 1e-12);
    assert_vec(h.n, v3(1, 0, 0), 1e-12);
    /* Misses, and tmax is respected */
    assert_false(shoot(a, v3(1, 4, -7), v3(0, 0, 1), &h));
    ray r = { v3(1, 2, -7), v3(0, 0, 1) };
    assert_false(accel_intersect(a, &r, 0, 8, 0, &h));
    /* Bounds */
    vec3 lo, hi;
    accel_bounds(a, &lo, &hi);
    assert_vec(lo, v3(-0.5, 0.5, 1.5), 1e-12);
    assert_vec(hi, v3(2.5, 3.5, 4.5), 1e-12);
    assert_true(accel_object_bounds(a, s, &lo, &hi));
    accel_destroy(a);
    scene_free(sc);
}

/* A unit sphere scaled by <2,1,1> then rotated 90 degrees about y is the
** ellipsoid z²/4 + x² + y² = 1: its normal at p is along (x, y, z/4). */
static void test_transformed(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *s = add(sc, sphere(sc, v3(0, 0, 0), 1));
    xform x;
    xf_scale(&x, v3(2, 1, 1));
    apply(s, &x);
    xf_rotate(&x, v3(0, 90, 0));
    apply(s, &x);
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(0, 0, -10), v3(0, 0, 1), &h));
    assert_near(h.t, 8, 1e-12);
    assert_vec(h.n, v3(0, 0, -1), 1e-12);
    /* An oblique ray: check the point is on the ellipsoid and the normal */
    assert_true(shoot(a, v3(0.3, 0.2, -10), v3(0.01, 0.02, 1), &h));
    vec3 p = h.p;
    assert_near(p.z * p.z / 4 + p.x * p.x + p.y * p.y, 1, 1e-12);
    assert_vec(h.n, v3_norm(v3(p.x, p.y, p.z / 4)), 1e-12);
    /* Translation */
    iris_scene *sc2 = scene_new();
    iris_object *t = add(sc2, obj(sc2, IRIS_OBJ_TORUS));
    t->u.torus.major = 2;
    t->u.torus.minor = 0.5;
    xf_rotate(&x, v3(90, 0, 0)); /* the torus now lies in the xy plane */
    apply(t, &x);
    xf_translate(&x, v3(0, 0, 5));
    apply(t, &x);
    struct accel *b = build(sc2);
    assert_true(shoot(b, v3(2, 0, 0), v3(0, 0, 1), &h));
    assert_near(h.t, 4.5, 1e-9);
    assert_vec(h.n, v3(0, 0, -1), 1e-9);
    accel_destroy(b);
    scene_free(sc2);
    accel_destroy(a);
    scene_free(sc);
}

/* difference { sphere r=2 at 0, sphere r=1 at z=-2 }: the bite in front.
** Along +z from z=-5 the big sphere's front (z=-2) is inside the small
** one and the small one's front (z=-3) is outside the big one, so the
** first surface is the small sphere's back at z=-1, normal flipped to -z,
** with the small sphere's texture. */
static void test_difference(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *big = sphere(sc, v3(0, 0, 0), 2);
    iris_object *bite = sphere(sc, v3(0, 0, -2), 1);
    bite->texture = &tex_b;
    iris_object *d = add(sc, csg_pair(sc, IRIS_OBJ_DIFFERENCE, big, bite));
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    assert_near(h.t, 4, 1e-12);
    assert_vec(h.n, v3(0, 0, -1), 1e-12);
    assert_ptr_equal(h.obj, bite);
    assert_ptr_equal(h.top, d);
    assert_ptr_equal(h.texture, &tex_b);
    /* Continue: out through the big sphere's back at z=2 */
    assert_true(shoot(a, h.p, v3(0, 0, 1), &h));
    assert_near(h.t, 3, 1e-12);
    assert_ptr_equal(h.obj, big);
    assert_vec(h.n, v3(0, 0, 1), 1e-12);
    /* Inside tests of the difference */
    assert_true(accel_inside(a, d, v3(0, 0, 1)));
    assert_false(accel_inside(a, d, v3(0, 0, -1.5)));
    assert_false(accel_inside(a, d, v3(0, 0, 3)));
    /* The subtracted child still answers for itself */
    assert_true(accel_inside(a, bite, v3(0, 0, -2)));
    assert_false(accel_inside(a, bite, v3(0, 0, 0)));
    accel_destroy(a);
    scene_free(sc);
}

/* intersection { box [-1,1]³, sphere r=1.2 }: a ray along the axis meets
** the box face (inside the sphere) at z=-1; one at y=0.9 meets the sphere
** at z = -sqrt(1.44 - 0.81) because the box face there is outside the
** sphere; one at x=y=0.9 misses (0.81·2 > 1.44). */
static void test_intersection(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *b = box_object(sc, v3(-1, -1, -1), v3(1, 1, 1));
    iris_object *s = sphere(sc, v3(0, 0, 0), 1.2);
    iris_object *i = add(sc, csg_pair(sc, IRIS_OBJ_INTERSECTION, b, s));
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    assert_near(h.t, 4, 1e-12);
    assert_ptr_equal(h.obj, b);
    assert_true(shoot(a, v3(0, 0.9, -5), v3(0, 0, 1), &h));
    assert_near(h.t, 5 - sqrt(1.44 - 0.81), 1e-12);
    assert_ptr_equal(h.obj, s);
    assert_false(shoot(a, v3(0.9, 0.9, -5), v3(0, 0, 1), &h));
    vec3 lo, hi;
    assert_true(accel_object_bounds(a, i, &lo, &hi));
    assert_vec(hi, v3(1, 1, 1), 1e-12); /* the box ∩ the sphere's box */
    assert_true(accel_inside(a, i, v3(0.5, 0.5, 0.5)));
    assert_false(accel_inside(a, i, v3(0.95, 0.95, 0)));
    accel_destroy(a);
    scene_free(sc);
}

/* Two overlapping spheres (centres x=±0.5, r=1): after the first surface
** at x=-1.5, a union shows the second sphere's inner wall at x=-0.5, a
** merge does not (next is x=1.5). */
static void test_merge(void **state)
{
    (void)state;
    for (int merge = 0; merge < 2; merge++) {
        iris_scene *sc = scene_new();
        add(sc, csg_pair(sc, merge ? IRIS_OBJ_MERGE : IRIS_OBJ_UNION,
                    sphere(sc, v3(-0.5, 0, 0), 1),
                    sphere(sc, v3(0.5, 0, 0), 1)));
        struct accel *a = build(sc);
        struct hit h;
        assert_true(shoot(a, v3(-5, 0, 0), v3(1, 0, 0), &h));
        assert_near(h.p.x, -1.5, 1e-12);
        assert_true(shoot(a, h.p, v3(1, 0, 0), &h));
        assert_near(h.p.x, merge ? 1.5 : -0.5, 1e-12);
        accel_destroy(a);
        scene_free(sc);
    }
}

/* inverse: the normal points into the sphere's centre and the inside is
** the outside; an inverted union is the intersection of the inverses. */
static void test_inverse(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *s = add(sc, sphere(sc, v3(0, 0, 0), 1));
    s->inverse = true;
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    assert_vec(h.n, v3(0, 0, 1), 1e-12);
    assert_false(accel_inside(a, s, v3(0, 0, 0)));
    assert_true(accel_inside(a, s, v3(0, 0, 3)));
    accel_destroy(a);
    scene_free(sc);

    sc = scene_new();
    iris_object *u = add(sc, csg_pair(sc, IRIS_OBJ_UNION,
                                 sphere(sc, v3(-0.5, 0, 0), 1),
                                 sphere(sc, v3(0.5, 0, 0), 1)));
    u->inverse = true;
    a = build(sc);
    assert_false(accel_inside(a, u, v3(-1, 0, 0)));
    assert_true(accel_inside(a, u, v3(0, 3, 0)));
    /* Its surfaces: only the outer ones remain (x = -1.5 first) */
    assert_true(shoot(a, v3(-5, 0, 0), v3(1, 0, 0), &h));
    assert_near(h.p.x, -1.5, 1e-12);
    assert_vec(h.n, v3(1, 0, 0), 1e-12);
    assert_true(shoot(a, h.p, v3(1, 0, 0), &h));
    assert_near(h.p.x, 1.5, 1e-12);
    accel_destroy(a);
    scene_free(sc);
}

/* clipped_by: a sphere clipped by the plane y < 0 (its lower half). From
** above, the first surface is the inside of the bowl at y = -1. */
static void test_clip(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *s = add(sc, sphere(sc, v3(0, 0, 0), 1));
    iris_object *pl = obj(sc, IRIS_OBJ_PLANE);
    pl->u.plane.normal = v3(0, 1, 0);
    pl->u.plane.distance = 0;
    s->n_clipped_by = 1;
    s->clipped_by = arena_array(sc->arena, 1, sizeof(iris_object *));
    s->clipped_by[0] = pl;
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(0, 5, 0), v3(0, -1, 0), &h));
    assert_near(h.t, 6, 1e-12);
    assert_vec(h.n, v3(0, -1, 0), 1e-12);
    assert_true(accel_inside(a, s, v3(0, -0.5, 0)));
    assert_false(accel_inside(a, s, v3(0, 0.5, 0)));
    /* The clipped sphere's box is only the lower half */
    vec3 lo, hi;
    assert_true(accel_object_bounds(a, s, &lo, &hi));
    assert_near(hi.y, 0, 1e-12);
    accel_destroy(a);
    scene_free(sc);
}

/* Inside tests of closed shapes, including POV-Ray's plane half-space and
** a mesh with inside_vector. */
static void test_inside(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *pl = add(sc, obj(sc, IRIS_OBJ_PLANE));
    pl->u.plane.normal = v3(0, 1, 0);
    pl->u.plane.distance = -1;
    iris_object *cy = add(sc, obj(sc, IRIS_OBJ_CYLINDER));
    cy->u.cylinder.base = v3(0, 0, 0);
    cy->u.cylinder.cap = v3(0, 0, 2);
    cy->u.cylinder.radius = 0.5;

    /* A unit cube mesh [0,1]³ offset to x = 3, 12 triangles */
    static vec3 cv[8];
    for (int i = 0; i < 8; i++)
        cv[i] = v3(3 + (i & 1), (i >> 1) & 1, (i >> 2) & 1);
    static int32_t ci[36] = { 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5,
                              0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6,
                              0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3 };
    iris_object *m = add(sc, obj(sc, IRIS_OBJ_MESH));
    m->u.mesh.n_vertices = 8;
    m->u.mesh.vertices = cv;
    m->u.mesh.n_triangles = 12;
    m->u.mesh.tri_vertices = ci;
    m->u.mesh.inside_vector = v3(0.2, 0.3, 1);
    iris_object *m2 = add(sc, obj(sc, IRIS_OBJ_MESH));
    m2->u.mesh = m->u.mesh;
    m2->u.mesh.inside_vector = v3(0, 0, 0);

    struct accel *a = build(sc);
    assert_true(accel_inside(a, pl, v3(5, -2, 7)));
    assert_false(accel_inside(a, pl, v3(5, 0, 7)));
    assert_true(accel_inside(a, cy, v3(0.3, 0, 1)));
    assert_false(accel_inside(a, cy, v3(0.3, 0, 2.5)));
    assert_true(accel_inside(a, m, v3(3.5, 0.5, 0.5)));
    assert_true(accel_inside(a, m, v3(3.9, 0.1, 0.8)));
    assert_false(accel_inside(a, m, v3(2.5, 0.5, 0.5)));
    assert_false(accel_inside(a, m, v3(3.5, 1.5, 0.5)));
    /* Without inside_vector a mesh has no inside (POV-Ray) */
    assert_false(accel_inside(a, m2, v3(3.5, 0.5, 0.5)));
    /* An object the accel was not built with still answers */
    iris_object *free_sphere = sphere(sc, v3(0, 0, 0), 1);
    assert_true(accel_inside(a, free_sphere, v3(0.5, 0, 0)));
    /* The plane is unbounded: no object box, and not in the scene box */
    vec3 lo, hi;
    assert_false(accel_object_bounds(a, pl, &lo, &hi));
    accel_bounds(a, &lo, &hi);
    assert_near(lo.y, -0.5, 1e-6);
    /* Mesh hit from outside: face x = 3 (Embree triangles, double t) */
    struct hit h;
    assert_true(shoot(a, v3(0, 0.5, 0.5), v3(1, 0, 0), &h));
    assert_near(h.t, 3, 1e-12);
    assert_ptr_equal(h.obj, m);
    accel_destroy(a);
    scene_free(sc);
}

/* Smooth triangle: uv and shading normal interpolated with barycentrics;
** a degenerate triangle is dropped. */
static void test_mesh_attrs(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *t = add(sc, obj(sc, IRIS_OBJ_TRIANGLE));
    t->u.triangle.p[0] = v3(0, 0, 0);
    t->u.triangle.p[1] = v3(1, 0, 0);
    t->u.triangle.p[2] = v3(0, 1, 0);
    t->u.triangle.smooth = true;
    t->u.triangle.n[0] = v3(0, 0, -1);
    t->u.triangle.n[1] = v3(1, 0, -1);
    t->u.triangle.n[2] = v3(0, 1, -1);
    t->u.triangle.has_uv = true;
    t->u.triangle.uv[1].u = 1;
    t->u.triangle.uv[2].v = 1;
    iris_object *bad = add(sc, obj(sc, IRIS_OBJ_TRIANGLE));
    bad->u.triangle.p[0] = v3(5, 0, 0);
    bad->u.triangle.p[1] = v3(6, 0, 0);
    bad->u.triangle.p[2] = v3(7, 0, 0); /* collinear */
    char *buf = NULL;
    size_t len = 0;
    FILE *log = open_memstream(&buf, &len);
    const char *files[2] = { "", "scene.pov" };
    sc->files = files;
    sc->n_files = 2;
    bad->loc.file = 1;
    bad->loc.line = 12;
    bad->loc.col = 3;
    struct accel *a = NULL;
    char err[128];
    assert_int_equal(accel_build(sc, &a, log, err, sizeof err), IRIS_OK);
    fclose(log);
    assert_non_null(strstr(buf, "scene.pov:12:3: warning: triangle"));
    free(buf);
    struct hit h;
    assert_true(shoot(a, v3(0.25, 0.5, -3), v3(0, 0, 1), &h));
    assert_near(h.t, 3, 1e-12);
    assert_near(h.uv.u, 0.25, 1e-12);
    assert_near(h.uv.v, 0.5, 1e-12);
    /* geometric normal faces the vertex normals' side */
    assert_vec(h.n, v3(0, 0, -1), 1e-12);
    /* the unit vertex normals weighted by the barycentrics (.25,.25,.5);
    ** 1e-6: the triangle is stored in float */
    vec3 want = v3_add(v3_add(v3_scale(v3(0, 0, -1), 0.25),
                              v3_scale(v3_norm(v3(1, 0, -1)), 0.25)),
                       v3_scale(v3_norm(v3(0, 1, -1)), 0.5));
    assert_vec(h.shading_n, v3_norm(want), 1e-6);
    assert_false(shoot(a, v3(6, 0, -3), v3(0, 0, 1), &h));
    accel_destroy(a);
    scene_free(sc);
}

/* Skip flags: a no_shadow sphere in front is passed through by a query
** that skips no_shadow objects, and seen by one that does not. */
static void test_skip(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *front = add(sc, sphere(sc, v3(0, 0, 0), 1));
    front->no_shadow = true;
    iris_object *back = add(sc, sphere(sc, v3(0, 0, 5), 1));
    iris_object *u = add(sc, csg_pair(sc, IRIS_OBJ_MERGE,
                                 sphere(sc, v3(5, 0, 0), 1),
                                 sphere(sc, v3(5, 0, 5), 1)));
    u->no_image = true;
    struct accel *a = build(sc);
    struct hit h;
    ray r = { v3(0, 0, -5), v3(0, 0, 1) };
    assert_true(accel_intersect(a, &r, 0, INFINITY, 0, &h));
    assert_ptr_equal(h.obj, front);
    assert_true(accel_intersect(a, &r, 0, INFINITY, ACCEL_SKIP_NO_SHADOW, &h));
    assert_ptr_equal(h.obj, back);
    assert_true(accel_intersect(a, &r, 0, INFINITY, ACCEL_SKIP_NO_IMAGE, &h));
    assert_ptr_equal(h.obj, front);
    ray r2 = { v3(5, 0, -5), v3(0, 0, 1) };
    assert_true(accel_intersect(a, &r2, 0, INFINITY, 0, &h));
    assert_ptr_equal(h.top, u);
    assert_false(accel_intersect(a, &r2, 0, INFINITY, ACCEL_SKIP_NO_IMAGE,
                                 &h));
    accel_destroy(a);
    scene_free(sc);
}

/* A mixed scene with every object scaled by 's' about the origin. */
static iris_scene *mixed_scene(double s)
{
    iris_scene *sc = scene_new();
    iris_object *o[8];
    int n = 0;
    o[n++] = add(sc, sphere(sc, v3(-2, 0, 0), 1));
    o[n++] = add(sc, box_object(sc, v3(1, -1, -1), v3(2.5, 0.5, 1)));
    iris_object *t = add(sc, obj(sc, IRIS_OBJ_TORUS));
    t->u.torus.major = 1;
    t->u.torus.minor = 0.3;
    xform x;
    xf_rotate(&x, v3(70, 0, 0));
    apply(t, &x);
    xf_translate(&x, v3(0, 1.5, 0));
    apply(t, &x);
    o[n++] = t;
    o[n++] = add(sc, csg_pair(sc, IRIS_OBJ_DIFFERENCE, sphere(sc, v3(0, -1.5, 0), 1),
                         box_object(sc, v3(-2, -1.5, -2), v3(0, 0, 0))));
    iris_object *tri = add(sc, obj(sc, IRIS_OBJ_TRIANGLE));
    tri->u.triangle.p[0] = v3(-3, -3, 2);
    tri->u.triangle.p[1] = v3(3, -3, 2);
    tri->u.triangle.p[2] = v3(0, 3, 2.5);
    o[n++] = tri;
    iris_object *pl = add(sc, obj(sc, IRIS_OBJ_PLANE));
    pl->u.plane.normal = v3(0, 1, 0);
    pl->u.plane.distance = -3;
    o[n++] = pl;
    xf_scale(&x, v3(s, s, s));
    for (int i = 0; i < n; i++) {
        apply(o[i], &x);
        if (o[i]->kind == IRIS_OBJ_DIFFERENCE)
            for (int k = 0; k < 2; k++)
                apply(o[i]->u.csg.children[k], &x);
    }
    return sc;
}

/*
** Scale invariance (issue 7): the scene scaled by 1e-6 and 1e6 gives the
** same hits over a grid of rays, each followed by a continuation ray from
** the hit point (which exercises the epsilon): same object, t/scale equal
** to 1e-9 relative, same normals.
*/
static void test_scale_invariance(void **state)
{
    (void)state;
    const double scales[3] = { 1, 1e-6, 1e6 };
    struct accel *a[3];
    iris_scene *sc[3];
    for (int k = 0; k < 3; k++) {
        sc[k] = mixed_scene(scales[k]);
        a[k] = build(sc[k]);
    }
    /* 1e-6 relative: the triangle's vertices (and so the scene box) are
    ** floats, rounded to 2^-24 ~ 6e-8 relative */
    assert_rel(accel_epsilon(a[1]), accel_epsilon(a[0]) * 1e-6, 1e-6);
    assert_rel(accel_epsilon(a[2]), accel_epsilon(a[0]) * 1e6, 1e-6);
    int n_hits = 0;
    for (int iy = 0; iy < 24; iy++)
        for (int ix = 0; ix < 24; ix++) {
            vec3 d = v3_norm(v3((ix - 11.5) / 24.0, (iy - 11.5) / 24.0, 1));
            int kinds[3][2];
            double ts[3][2];
            vec3 ns[3][2];
            for (int k = 0; k < 3; k++) {
                double s = scales[k];
                ray r = { v3(0.1 * s, 0.05 * s, -8 * s), d };
                for (int bounce = 0; bounce < 2; bounce++) {
                    struct hit h;
                    kinds[k][bounce] = -1;
                    if (!accel_intersect(a[k], &r, accel_epsilon(a[k]),
                                         INFINITY, 0, &h))
                        break;
                    kinds[k][bounce] = (int)h.obj->kind;
                    ts[k][bounce] = h.t / s;
                    ns[k][bounce] = h.n;
                    r.o = h.p;
                }
            }
            for (int k = 1; k < 3; k++)
                for (int b = 0; b < 2; b++) {
                    assert_int_equal(kinds[k][b], kinds[0][b]);
                    if (kinds[0][b] < 0)
                        break;
                    n_hits++;
                    /* Analytic shapes are solved in double: 1e-9. The
                    ** triangle is stored in float, whose rounding of the
                    ** scaled vertices differs by up to 2^-24: 1e-6 for
                    ** its hits and for rays starting on it */
                    bool via_tri = kinds[0][b] == IRIS_OBJ_TRIANGLE ||
                                   (b > 0 && kinds[0][0] == IRIS_OBJ_TRIANGLE);
                    double tol = via_tri ? 1e-6 : 1e-9;
                    assert_rel(ts[k][b], ts[0][b], tol);
                    assert_vec(ns[k][b], ns[0][b], tol);
                }
        }
    assert_true(n_hits > 500); /* the grid really sees the objects */
    for (int k = 0; k < 3; k++) {
        accel_destroy(a[k]);
        scene_free(sc[k]);
    }
}

/* Random rays, from anywhere including inside objects, at a scene of
** every analytic kind: every hit is finite with a unit normal, t > tmin,
** and the point lies on the ray. */
static void test_no_nan(void **state)
{
    (void)state;
    iris_scene *sc = mixed_scene(1);
    iris_object *c = add(sc, obj(sc, IRIS_OBJ_CONE));
    c->u.cone.base = v3(0, 0, 3);
    c->u.cone.cap = v3(0, 2, 3);
    c->u.cone.base_radius = 1;
    iris_object *se = add(sc, obj(sc, IRIS_OBJ_SUPERELLIPSOID));
    se->u.superellipsoid.e = 0.3;
    se->u.superellipsoid.n = 2.5;
    xform x;
    xf_translate(&x, v3(3, 2, 3));
    apply(se, &x);
    iris_object *bl = add(sc, obj(sc, IRIS_OBJ_BLOB));
    iris_blob_component *bc = arena_array(sc->arena, 2, sizeof *bc);
    bc[0].a = v3(-3, 2, 3);
    bc[0].radius = 1;
    bc[0].strength = 1;
    bc[1].kind = 1;
    bc[1].a = v3(-3, 2, 3);
    bc[1].b = v3(-3, 3, 4);
    bc[1].radius = 0.7;
    bc[1].strength = -0.5;
    bl->u.blob.threshold = 0.2;
    bl->u.blob.n_components = 2;
    bl->u.blob.components = bc;
    struct accel *a = build(sc);
    rng g;
    rng_seed(&g, 7, 0, 0);
    int n_hit = 0;
    for (int i = 0; i < 20000; i++) {
        vec3 o = v3(8 * rng_uniform(&g) - 4, 8 * rng_uniform(&g) - 4,
                    8 * rng_uniform(&g) - 4);
        vec3 d = v3_norm(v3(rng_uniform(&g) - 0.5, rng_uniform(&g) - 0.5,
                            rng_uniform(&g) - 0.5));
        ray r = { o, d };
        struct hit h;
        if (!accel_intersect(a, &r, 1e-9, INFINITY, 0, &h))
            continue;
        n_hit++;
        assert_true(isfinite(h.t) && h.t > 1e-9);
        assert_near(v3_len(h.n), 1, 1e-9);
        assert_near(v3_len(h.shading_n), 1, 1e-9);
        assert_true(isfinite(h.uv.u) && isfinite(h.uv.v));
        assert_near(v3_len(v3_sub(h.p, v3_madd(o, d, h.t))), 0, 1e-9);
        assert_non_null(h.texture);
    }
    assert_true(n_hit > 10000); /* the plane and the rest are hit */
    /* Degenerate queries: zero direction, NaN origin, empty interval */
    struct hit h;
    ray bad = { v3(NAN, 0, 0), v3(0, 0, 1) };
    assert_false(accel_intersect(a, &bad, 0, INFINITY, 0, &h));
    ray zero = { v3(0, 0, -5), v3(0, 0, 0) };
    assert_false(accel_intersect(a, &zero, 0, INFINITY, 0, &h));
    ray ok = { v3(0, 0, -5), v3(0, 0, 1) };
    assert_false(accel_intersect(a, &ok, 5, 5, 0, &h));
    accel_destroy(a);
    scene_free(sc);
}

/* Grazing rays at a sphere never return garbage: a ray tangent within
** rounding may hit or miss, but a hit has t near the tangent point. */
static void test_grazing(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    add(sc, sphere(sc, v3(0, 0, 0), 1));
    struct accel *a = build(sc);
    for (int k = -3; k <= 3; k++) {
        double y = 1 + k * 1e-15;
        struct hit h;
        if (shoot(a, v3(0, y, -5), v3(0, 0, 1), &h)) {
            assert_near(h.t, 5, 1e-6);
            assert_near(v3_len(h.n), 1, 1e-12);
        }
    }
    /* Unsupported shapes and empty CSG are skipped, never fatal */
    add(sc, obj(sc, IRIS_OBJ_JULIA_FRACTAL));
    iris_object *e = add(sc, obj(sc, IRIS_OBJ_UNION));
    (void)e;
    accel_destroy(a);
    a = build(sc);
    accel_destroy(a);
    accel_destroy(NULL);
    scene_free(sc);
}

/* x² + y² + z² - c as a compiled function (fn.h stack code). */
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

/* Isosurface x²+y²+z² = 1 in the box [-2,2]³ (|grad| <= 2·sqrt(12) < 7).
** POV-Ray's root (isosurface.cpp, Function_Find_Root_R) is the far end of
** the first interval of the halving of the container interval [3, 7]
** shorter than accuracy 0.001 (4/4096) where the function is negative:
** for the root t = 4 that is 3 + 1025/1024 (t = 4 itself gives exactly
** 0, not inside), for t = 4.2 it is 3 + 1229/1024; both are exact binary
** fractions, hence 1e-12. The normal is POV-Ray's forward difference of
** step 0.001: its x and y parts are 0.001²/(2·0.001) = 5e-4 of the z part,
** hence 1e-3. With x²+y²+z² = 9 the whole box is inside and its wall at
** z=-2 shows. */
static void test_isosurface(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *iso = add(sc, obj(sc, IRIS_OBJ_ISOSURFACE));
    iso->u.isosurface.fn = sphere_fn(sc, 1);
    iso->u.isosurface.lo = v3(-2, -2, -2);
    iso->u.isosurface.hi = v3(2, 2, 2);
    iso->u.isosurface.max_gradient = 7;
    iso->u.isosurface.accuracy = 1e-3;
    iso->u.isosurface.max_trace = 1;
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    assert_near(h.t, 3 + 1025.0 / 1024, 1e-12);
    assert_vec(h.n, v3(0, 0, -1), 1e-3);
    assert_true(shoot(a, v3(0.6, 0, -5), v3(0, 0, 1), &h));
    assert_near(h.t, 3 + 1229.0 / 1024, 1e-12);
    assert_true(accel_inside(a, iso, v3(0.5, 0.5, 0.5)));
    assert_false(accel_inside(a, iso, v3(0.5, 1, 0.5)));
    /* From the surface outwards nothing is found again */
    assert_false(shoot(a, v3(0, 0, -1), v3(0, 0, -1), &h));
    accel_destroy(a);

    iso->u.isosurface.fn = sphere_fn(sc, 9);
    a = build(sc);
    assert_true(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    assert_near(h.t, 3, 1e-12);
    assert_vec(h.n, v3(0, 0, -1), 0);
    accel_destroy(a);
    iso->open = true;
    a = build(sc);
    assert_false(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    accel_destroy(a);
    scene_free(sc);
}

/* A 3x3 grey image, white in the middle, is a height field pyramid in
** the unit square, of POV-Ray's height 65535/65536 (heights are 16-bit
** values over 65536 units); its inside is below the surface. */
static void test_height_field(void **state)
{
    (void)state;
    char path[] = "/tmp/iris-hf-XXXXXX.pgm";
    int fd = mkstemps(path, 4);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "wb");
    const unsigned char px[9] = { 0, 0, 0, 0, 255, 0, 0, 0, 0 };
    fprintf(f, "P5\n3 3\n255\n");
    fwrite(px, 1, 9, f);
    fclose(f);
    iris_scene *sc = scene_new();
    iris_object *hf = add(sc, obj(sc, IRIS_OBJ_HEIGHT_FIELD));
    iris_image_ref ref = { .path = path };
    hf->u.height_field.image = &ref;
    struct accel *a = NULL;
    char err[128];
    enum iris_status st = accel_build(sc, &a, NULL, err, sizeof err);
    remove(path);
    assert_int_equal(st, IRIS_OK);
    struct hit h;
    /* Straight down onto the peak, and halfway down its slope (the
    ** triangles are planar: height 0.5 at x = 0.25 on the z = 0.5 line) */
    const double top = 65535.0 / 65536.0;
    assert_true(shoot(a, v3(0.5, 5, 0.5), v3(0, -1, 0), &h));
    assert_near(h.t, 5 - top, 1e-6);
    assert_true(shoot(a, v3(0.25, 5, 0.5), v3(0, -1, 0), &h));
    assert_near(h.p.y, 0.5 * top, 1e-6);
    assert_true(accel_inside(a, hf, v3(0.5, 0.8, 0.5)));
    assert_false(accel_inside(a, hf, v3(0.25, 0.6, 0.5)));
    assert_false(accel_inside(a, hf, v3(1.5, 0.1, 0.5)));
    accel_destroy(a);
    scene_free(sc);
}

/* A blob hit shows the texture of the component that dominates there. */
static void test_blob_texture(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *b = add(sc, obj(sc, IRIS_OBJ_BLOB));
    iris_blob_component *bc = arena_array(sc->arena, 2, sizeof *bc);
    bc[0].a = v3(-1, 0, 0);
    bc[0].radius = 1.5;
    bc[0].strength = 1;
    bc[1] = bc[0];
    bc[1].a = v3(1, 0, 0);
    bc[1].texture = &tex_b;
    b->u.blob.threshold = 0.3;
    b->u.blob.n_components = 2;
    b->u.blob.components = bc;
    struct accel *a = build(sc);
    struct hit h;
    assert_true(shoot(a, v3(-1, 0, -5), v3(0, 0, 1), &h));
    assert_ptr_equal(h.texture, &sb_texture); /* no own texture: the blob's */
    assert_true(shoot(a, v3(1, 0, -5), v3(0, 0, 1), &h));
    assert_ptr_equal(h.texture, &tex_b);
    accel_destroy(a);
    scene_free(sc);
}

/* A mesh inside CSG: intersection of a unit-cube mesh (with
** inside_vector) and a sphere of radius 0.6 at the cube's corner (0,0,0):
** along the cube's edge direction the first surface is the sphere. */
static void test_mesh_csg(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    static vec3 cv[8];
    for (int i = 0; i < 8; i++)
        cv[i] = v3(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    static int32_t ci[36] = { 0, 1, 3, 0, 3, 2, 4, 6, 7, 4, 7, 5,
                              0, 4, 5, 0, 5, 1, 2, 3, 7, 2, 7, 6,
                              0, 2, 6, 0, 6, 4, 1, 5, 7, 1, 7, 3 };
    iris_object *m = obj(sc, IRIS_OBJ_MESH);
    m->u.mesh.n_vertices = 8;
    m->u.mesh.vertices = cv;
    m->u.mesh.n_triangles = 12;
    m->u.mesh.tri_vertices = ci;
    m->u.mesh.inside_vector = v3(0.3, 0.2, 1);
    iris_object *s = sphere(sc, v3(0, 0, 0), 0.6);
    add(sc, csg_pair(sc, IRIS_OBJ_INTERSECTION, m, s));
    struct accel *a = build(sc);
    struct hit h;
    /* Along z at x=y=0.2: enters the cube at z=0 (inside the sphere) */
    assert_true(shoot(a, v3(0.2, 0.2, -3), v3(0, 0, 1), &h));
    assert_near(h.t, 3, 1e-9);
    assert_ptr_equal(h.obj, m);
    /* ... and leaves through the sphere */
    assert_true(shoot(a, h.p, v3(0, 0, 1), &h));
    assert_near(h.p.z, sqrt(0.36 - 0.08), 1e-9);
    assert_ptr_equal(h.obj, s);
    /* At x=y=0.5 the cube's face is outside the sphere: miss */
    assert_false(shoot(a, v3(0.5, 0.5, -3), v3(0, 0, 1), &h));
    accel_destroy(a);
    scene_free(sc);
}

/* Broken objects of every kind: the build warns and skips them, nothing
** crashes, and queries through what remains stay finite. */
static void test_bad_input(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    add(sc, sphere(sc, v3(0, 0, 0), NAN));
    add(sc, sphere(sc, v3(0, 0, 0), -1));
    add(sc, sphere(sc, v3(INFINITY, 0, 0), 1));
    add(sc, box_object(sc, v3(NAN, 0, 0), v3(1, 1, 1)));
    iris_object *o = add(sc, obj(sc, IRIS_OBJ_CYLINDER));
    o->u.cylinder.radius = 1; /* zero length */
    o = add(sc, obj(sc, IRIS_OBJ_TORUS)); /* zero radii */
    o = add(sc, sphere(sc, v3(0, 0, 0), 1));
    xform x;
    xf_identity(&x);
    x.m[0][0] = 0; /* singular transform: its inverse is not finite */
    x.inv[0][0] = INFINITY;
    apply(o, &x);
    o = add(sc, obj(sc, IRIS_OBJ_MESH));
    static vec3 v[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
    static int32_t ix[6] = { 0, 1, 7, -1, 2, 1 }; /* out of range */
    o->u.mesh.n_vertices = 3;
    o->u.mesh.vertices = v;
    o->u.mesh.n_triangles = 2;
    o->u.mesh.tri_vertices = ix;
    o = add(sc, obj(sc, IRIS_OBJ_MESH)); /* no data at all */
    o->u.mesh.n_triangles = 5;
    o = add(sc, obj(sc, IRIS_OBJ_POLY));
    o->u.poly.order = 20;
    o = add(sc, obj(sc, IRIS_OBJ_PRISM));
    o->u.prism.n_points = 2;
    o = add(sc, obj(sc, IRIS_OBJ_LATHE));
    o->u.lathe.n_points = 3;
    o->u.lathe.points = arena_array(sc->arena, 3, sizeof(iris_vec2));
    o->u.lathe.points[1].u = NAN;
    o = add(sc, obj(sc, IRIS_OBJ_BLOB));
    o->u.blob.n_components = 3; /* components NULL */
    o = add(sc, obj(sc, IRIS_OBJ_TEXT));
    o->u.text.font = "/no/such/font.ttf";
    o->u.text.string = "x";
    o = add(sc, obj(sc, IRIS_OBJ_SUPERELLIPSOID));
    o = add(sc, obj(sc, IRIS_OBJ_POLYGON));
    o->u.polygon.n_points = 2;
    o = add(sc, obj(sc, IRIS_OBJ_DISC));
    o->u.disc.radius = 1;
    o = add(sc, obj(sc, IRIS_OBJ_PLANE));
    o = add(sc, obj(sc, IRIS_OBJ_ISOSURFACE));
    o = add(sc, obj(sc, IRIS_OBJ_HEIGHT_FIELD));
    o = add(sc, obj(sc, IRIS_OBJ_DIFFERENCE));
    o->u.csg.n_children = 2; /* children NULL */
    o = add(sc, csg_pair(sc, IRIS_OBJ_INTERSECTION, NULL, NULL));
    iris_object *cyc = add(sc, csg_pair(sc, IRIS_OBJ_MERGE, NULL, NULL));
    cyc->u.csg.children[0] = cyc; /* contains itself */
    cyc->u.csg.children[1] = sphere(sc, v3(5, 5, 5), 1);
    iris_object *good = add(sc, sphere(sc, v3(0, 0, 3), 1));

    char *buf = NULL;
    size_t len = 0;
    FILE *log = open_memstream(&buf, &len);
    struct accel *a = NULL;
    char err[128];
    assert_int_equal(accel_build(sc, &a, log, err, sizeof err), IRIS_OK);
    fclose(log);
    int warnings = 0;
    for (const char *p = buf; (p = strstr(p, "warning:")); p++)
        warnings++;
    free(buf);
    assert_true(warnings >= 20);
    struct hit h;
    assert_true(shoot(a, v3(0, 0, -5), v3(0, 0, 1), &h));
    assert_ptr_equal(h.obj, good);
    assert_true(shoot(a, v3(5, 5, -5), v3(0, 0, 1), &h)); /* cycle's sphere */
    rng g;
    rng_seed(&g, 3, 0, 0);
    for (int i = 0; i < 2000; i++) {
        ray r = { v3(8 * rng_uniform(&g) - 4, 8 * rng_uniform(&g) - 4, -6),
                  v3_norm(v3(rng_uniform(&g) - 0.5, rng_uniform(&g) - 0.5,
                             1)) };
        if (accel_intersect(a, &r, 0, INFINITY, 0, &h)) {
            assert_true(isfinite(h.t));
            assert_near(v3_len(h.n), 1, 1e-9);
        }
        (void)accel_inside(a, cyc, r.o);
    }
    accel_destroy(a);
    scene_free(sc);
}

/*
** Self-intersection: rays leaving a hit point (reflected outwards or
** refracted inwards, random directions) started at accel_epsilon() never
** meet the same surface again at a tiny distance. Every shape kind is in
** the scene; "tiny" is 1e-6 of the scene (10 units), a thousand times the
** epsilon, so a miss here is a real self-hit, not a thin feature.
*/
static void self_hit_at(double scale)
{
    iris_scene *sc = mixed_scene(scale);
    int first_extra = sc->n_objects;
    iris_object *c = add(sc, obj(sc, IRIS_OBJ_CONE));
    c->u.cone.base = v3(0, 0, 3);
    c->u.cone.cap = v3(0, 2, 3);
    c->u.cone.base_radius = 1;
    iris_object *se = add(sc, obj(sc, IRIS_OBJ_SUPERELLIPSOID));
    se->u.superellipsoid.e = 0.3;
    se->u.superellipsoid.n = 2.5;
    xform x;
    xf_translate(&x, v3(3, 2, 3));
    apply(se, &x);
    iris_object *bl = add(sc, obj(sc, IRIS_OBJ_BLOB));
    iris_blob_component *bc = arena_array(sc->arena, 1, sizeof *bc);
    bc[0].a = v3(-3, 2, 3);
    bc[0].radius = 1.5;
    bc[0].strength = 1;
    bl->u.blob.threshold = 0.2;
    bl->u.blob.n_components = 1;
    bl->u.blob.components = bc;
    iris_object *iso = add(sc, obj(sc, IRIS_OBJ_ISOSURFACE));
    iso->u.isosurface.fn = sphere_fn(sc, 0.5);
    iso->u.isosurface.centre = v3(0, 0, 0);
    iso->u.isosurface.radius = 1;
    iso->u.isosurface.contained_kind = 1;
    iso->u.isosurface.max_gradient = 2.5;
    iso->u.isosurface.max_trace = 1;
    /* POV-Ray's accuracy is a distance along the ray, not in the shape's
    ** units: a scene scaled by 'scale' scales it too (isosurface.c) */
    iso->u.isosurface.accuracy = 1e-3 * scale;
    xf_translate(&x, v3(-3, -2, 5));
    apply(iso, &x);
    xf_scale(&x, v3(scale, scale, scale));
    for (int i = first_extra; i < sc->n_objects; i++)
        apply(sc->objects[i], &x);
    struct accel *a = build(sc);
    double eps = accel_epsilon(a);
    rng g;
    rng_seed(&g, 11, 0, 0);
    int n = 0, bad = 0;
    for (int i = 0; i < 20000; i++) {
        ray r = { v3_scale(v3(8 * rng_uniform(&g) - 4,
                              8 * rng_uniform(&g) - 4, -9), scale),
                  v3_norm(v3(rng_uniform(&g) - 0.5, rng_uniform(&g) - 0.5,
                             1)) };
        struct hit h, h2;
        if (!accel_intersect(a, &r, eps, INFINITY, 0, &h))
            continue;
        vec3 d = v3_norm(v3(rng_uniform(&g) - 0.5, rng_uniform(&g) - 0.5,
                            rng_uniform(&g) - 0.5));
        /* Out of the surface or into it, never along it */
        if (fabs(v3_dot(d, h.n)) < 1e-3)
            continue;
        ray r2 = { h.p, d };
        n++;
        if (accel_intersect(a, &r2, eps, INFINITY, 0, &h2) && h2.t < 1e-5 * scale &&
            h2.obj == h.obj)
            bad++;
    }
    assert_true(n > 5000);
    if (bad > 0)
        fail_msg("scale %g: %d of %d secondary rays met their own surface "
                 "again", scale, bad, n);
    accel_destroy(a);
    scene_free(sc);
}

/* ... at the scene's own size and scaled by 1e-6 and 1e6 (issue 7). */
static void test_self_hit(void **state)
{
    (void)state;
    self_hit_at(1);
    self_hit_at(1e-6);
    self_hit_at(1e6);
}

struct par_ctx {
    const struct accel *a;
    double *t;
};

static void par_shoot(void *ctx, int64_t item, int thread)
{
    (void)thread;
    struct par_ctx *c = ctx;
    double u = (item % 100) / 100.0 - 0.5, v = (item / 100) / 100.0 - 0.5;
    ray r = { v3(0.1, 0.05, -8), v3_norm(v3(u, v, 1)) };
    struct hit h;
    c->t[item] = accel_intersect(c->a, &r, 1e-9, INFINITY, 0, &h) ? h.t : -1;
}

/* Queries from two threads at once give exactly the single-thread
** answers: the accel is read-only after the build. */
static void test_threads(void **state)
{
    (void)state;
    iris_scene *sc = mixed_scene(1);
    struct accel *a = build(sc);
    static double t1[10000], t2[10000];
    struct par_ctx c1 = { a, t1 }, c2 = { a, t2 };
    par_for(1, 10000, par_shoot, &c1);
    par_for(2, 10000, par_shoot, &c2);
    assert_memory_equal(t1, t2, sizeof t1);
    accel_destroy(a);
    scene_free(sc);
}

/* One face of test_csg_polytope's polytope: inside is n·x < d (POV-Ray's
** plane), n a unit world normal. */
struct face {
    vec3 n;
    double d;
};

/*
** The nearest crossing t > tmin of ray o + t·dir with the convex polytope
** that is the intersection of the half-spaces 'f', solved here without
** src/accel or src/geometry: the ray is inside face i for t beyond its
** crossing where n·dir < 0 (entering) and before it where n·dir > 0
** (leaving), so it is inside the polytope between the largest entry and
** the smallest exit. *face_out is the face crossed there. Returns
** INFINITY for a miss, NAN when the answer is too close to call in
** double (an edge, where two faces cross within 1e-7, or a graze).
*/
static double brute_polytope(const struct face *f, int nf, vec3 o, vec3 dir,
                             double tmin, int *face_out)
{
    double t_in = -INFINITY, t_out = INFINITY, t_in2 = -INFINITY,
           t_out2 = INFINITY;
    int f_in = -1, f_out = -1;
    for (int i = 0; i < nf; i++) {
        double dn = v3_dot(f[i].n, dir), num = f[i].d - v3_dot(f[i].n, o);
        if (fabs(dn) < 1e-9) {
            if (!(num > 1e-9))
                return fabs(num) < 1e-9 ? NAN : INFINITY;
            continue;
        }
        double t = num / dn;
        if (dn < 0) {
            if (t > t_in) {
                t_in2 = t_in;
                t_in = t;
                f_in = i;
            } else if (t > t_in2) {
                t_in2 = t;
            }
        } else {
            if (t < t_out) {
                t_out2 = t_out;
                t_out = t;
                f_out = i;
            } else if (t < t_out2) {
                t_out2 = t;
            }
        }
    }
    if (t_out - t_in < 1e-7)
        return t_out - t_in > -1e-7 ? NAN : INFINITY;
    if (fabs(t_in - tmin) < 1e-7 || fabs(t_out - tmin) < 1e-7)
        return NAN;
    if (t_in > tmin) {
        if (t_in - t_in2 < 1e-7)
            return NAN;
        *face_out = f_in;
        return t_in;
    }
    if (t_out > tmin) {
        if (t_out2 - t_out < 1e-7)
            return NAN;
        *face_out = f_out;
        return t_out;
    }
    return INFINITY;
}

/*
** A cut stone: the intersection of many planes, each rotated and moved
** as the parser leaves the leaves of a transformed CSG (the facets of
** scenes/gem.pov). The query keeps the nearest crossing that lies inside
** every other child, testing the crossings in order of t until one
** passes (node.c lazy_nearest); more than 64 children take the general
** path. For a truncated cube of 14 faces and a random polytope of 70,
** rays from outside and from inside must meet the face and t that
** brute_polytope() computes from the world planes (relative 1e-9:
** both solve the same linear equations, iris in each plane's object
** space; rays where two faces or the entry and exit come within 1e-7 are
** left out, as their face is not determined in double).
*/
static void test_csg_polytope(void **state)
{
    (void)state;
    const int counts[2] = { 14, 70 };
    for (int k = 0; k < 2; k++) {
        int nf = counts[k];
        iris_scene *sc = scene_new();
        rng g;
        rng_seed(&g, 21, (uint64_t)k, 0);
        iris_object *cut = add(sc, obj(sc, IRIS_OBJ_INTERSECTION));
        cut->u.csg.n_children = nf;
        cut->u.csg.children = arena_array(sc->arena, (size_t)nf,
                                          sizeof(iris_object *));
        struct face f[70];
        vec3 rot = v3(360 * rng_uniform(&g), 360 * rng_uniform(&g),
                      360 * rng_uniform(&g));
        vec3 move = v3(2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1,
                       2 * rng_uniform(&g) - 1);
        xform r, m;
        xf_rotate(&r, rot);
        xf_translate(&m, move);
        for (int i = 0; i < nf; i++) {
            vec3 n;
            double d;
            if (k == 0 && i < 6) { /* the cube's faces */
                double c[3] = { 0, 0, 0 };
                c[i / 2] = i % 2 ? -1 : 1;
                n = v3(c[0], c[1], c[2]);
                d = 1;
            } else if (k == 0) { /* its eight corners cut */
                int j = i - 6;
                n = v3_norm(v3(j & 1 ? -1 : 1, j & 2 ? -1 : 1, j & 4 ? -1 : 1));
                d = 1.4;
            } else { /* a random facet at distance 1 to 1.2 */
                do
                    n = v3(2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1,
                           2 * rng_uniform(&g) - 1);
                while (v3_len2(n) > 1 || v3_len2(n) < 0.01);
                n = v3_norm(n);
                d = 1 + 0.2 * rng_uniform(&g);
            }
            iris_object *pl = obj(sc, IRIS_OBJ_PLANE);
            pl->u.plane.normal = n;
            pl->u.plane.distance = d;
            apply(pl, &r);
            apply(pl, &m);
            cut->u.csg.children[i] = pl;
            /* The world plane: the rotated normal, moved along itself */
            f[i].n = v3_norm(xf_dir(&r, n));
            f[i].d = d + v3_dot(f[i].n, move);
        }
        struct accel *a = build(sc);
        int checked = 0, hits = 0, inside = 0;
        for (int i = 0; i < 4000; i++) {
            /* half the rays from a shell around it, half from within */
            bool from_in = i % 2;
            double rad = from_in ? 0.5 * rng_uniform(&g) : 4;
            vec3 o;
            do
                o = v3(2 * rng_uniform(&g) - 1, 2 * rng_uniform(&g) - 1,
                       2 * rng_uniform(&g) - 1);
            while (v3_len2(o) > 1 || v3_len2(o) < 0.01);
            o = v3_add(move, v3_scale(v3_norm(o), rad));
            vec3 aim = v3_add(move, v3(2.4 * rng_uniform(&g) - 1.2,
                                       2.4 * rng_uniform(&g) - 1.2,
                                       2.4 * rng_uniform(&g) - 1.2));
            vec3 dir = v3_norm(v3_sub(aim, o));
            if (!(v3_len2(dir) > 0))
                continue;
            double tmin = accel_epsilon(a);
            int face = -1;
            double want = brute_polytope(f, nf, o, dir, tmin, &face);
            if (isnan(want))
                continue;
            checked++;
            struct hit h;
            bool got = shoot(a, o, dir, &h);
            if (isinf(want)) {
                assert_false(got);
                continue;
            }
            assert_true(got);
            hits++;
            inside += from_in;
            assert_near(h.t, want, 1e-9 * (1 + want));
            assert_vec(h.n, f[face].n, 1e-9);
            assert_ptr_equal(h.obj, cut->u.csg.children[face]);
        }
        /* Most rays are decided, most of those hit, from both sides */
        assert_true(checked > 3900);
        assert_true(hits > 2500);
        assert_true(inside > 1500);
        accel_destroy(a);
        scene_free(sc);
    }
}

/* A stretched sphere for test_fast_paths: unit sphere at 'c' scaled by
** 's', rotated by 'rot' degrees, translated by 't'. */
static iris_object *ellipsoid(iris_scene *sc, vec3 c, double r, vec3 s,
                              vec3 rot, vec3 t)
{
    iris_object *o = sphere(sc, c, r);
    xform x;
    xf_scale(&x, s);
    apply(o, &x);
    xf_rotate(&x, rot);
    apply(o, &x);
    xf_translate(&x, t);
    apply(o, &x);
    return o;
}

/* The nearest crossing of world ray o + t·d with transformed sphere 'o',
** t > tmin, solved here independently of src/geometry: the ray taken to
** object space by the inverse matrix, then the textbook quadratic. */
static double brute_sphere(const iris_object *s, vec3 o, vec3 d, double tmin)
{
    vec3 lo = xf_inv_point(&s->transform, o);
    vec3 ld = xf_inv_dir(&s->transform, d);
    vec3 oc = v3_sub(lo, s->u.sphere.centre);
    double a = v3_dot(ld, ld), b = 2 * v3_dot(oc, ld);
    double c = v3_dot(oc, oc) - s->u.sphere.radius * s->u.sphere.radius;
    double disc = b * b - 4 * a * c;
    if (disc < 0)
        return INFINITY;
    double t0 = (-b - sqrt(disc)) / (2 * a), t1 = (-b + sqrt(disc)) / (2 * a);
    return t0 > tmin ? t0 : t1 > tmin ? t1 : INFINITY;
}

/*
** The query's fast paths give the exact nearest hit: a scene of at most
** LINEAR_MAX (8) primitives is searched without Embree, a larger one
** through Embree with the box test left to it, and a rotated, stretched
** sphere gets the exact box of an ellipsoid instead of the box of its
** rotated box. For 6 and 24 random ellipsoids, rays aimed at points on
** their surfaces (many grazing, where a box too tight would lose the
** hit) must meet the same sphere at the same t as a brute-force search
** over every sphere (relative 1e-9: both solve the same quadratic in
** double, with different but stable formulas near tangency, where t is
** ill-conditioned: a grazing miss by 1e-9 may be a hit, so those rays
** are left out by requiring a clear discriminant).
** The box of a sphere scaled <4, 0.3, 0.3> and rotated 30 degrees about y
** has the half widths sqrt((4 cos 30)² + (0.3 sin 30)²) in x, 0.3 in y
** and sqrt((4 sin 30)² + (0.3 cos 30)²) in z (the rows of the matrix
** times the radius), to rounding.
** A hit on a sphere carries POV-Ray's uv: +x on the equator is (0, 1/2).
*/
static void test_fast_paths(void **state)
{
    (void)state;
    iris_scene *one = scene_new();
    iris_object *e = add(one, ellipsoid(one, v3(0, 0, 0), 1, v3(4, 0.3, 0.3),
                                        v3(0, 30, 0), v3(1, 2, 3)));
    struct accel *a1 = build(one);
    vec3 lo, hi;
    assert_true(accel_object_bounds(a1, e, &lo, &hi));
    double c30 = cos(M_PI / 6), s30 = 0.5;
    vec3 half = v3(sqrt(16 * c30 * c30 + 0.09 * s30 * s30), 0.3,
                   sqrt(16 * s30 * s30 + 0.09 * c30 * c30));
    assert_vec(lo, v3_sub(v3(1, 2, 3), half), 1e-12);
    assert_vec(hi, v3_add(v3(1, 2, 3), half), 1e-12);
    accel_destroy(a1);
    scene_free(one);

    iris_scene *uvs = scene_new();
    iris_object *us = add(uvs, ellipsoid(uvs, v3(0, 0, 0), 1, v3(2, 2, 2),
                                         v3(0, 0, 0), v3(0, 1, 0)));
    us->texture = &uv_tex;
    struct accel *au = build(uvs);
    struct hit h;
    assert_true(shoot(au, v3(10, 1, 0), v3(-1, 0, 0), &h));
    assert_near(h.t, 8, 1e-12);
    assert_near(h.uv.u, 0, 1e-12);
    assert_near(h.uv.v, 0.5, 1e-12);
    accel_destroy(au);
    scene_free(uvs);

    /* The uv is computed only where the texture may read it, that is
    ** where a pattern it reaches has uv_mapping: a plain pigment never
    ** does (uv stays 0), nor a checker without uv_mapping; a uv_mapped
    ** checker does (POV-Ray's uv again: +x on the equator is (0, 1/2)),
    ** and so does one inside a pigment_map entry, or in a normal_map
    ** entry of a later layer */
    static iris_pigment plain_pig, checker_pig, xyz_pig, map_pig;
    static iris_texture plain_tex, checker_tex, xyz_tex, map_tex, layer_tex;
    static iris_normal bumps_n, nmap_n;
    static iris_map_entry map_e[2], nmap_e[1];
    checker_pig.pattern.kind = IRIS_PAT_CHECKER;
    checker_pig.pattern.uv_mapping = true;
    xyz_pig.pattern.kind = IRIS_PAT_CHECKER;
    map_pig.pattern.kind = IRIS_PAT_GRADIENT;
    map_pig.is_pigment_map = true;
    map_pig.n_entries = 2;
    map_pig.entries = map_e;
    map_e[0].pigment = &xyz_pig;
    map_e[1].pigment = &checker_pig;
    bumps_n.pattern.kind = IRIS_PAT_GRADIENT;
    bumps_n.pattern.uv_mapping = true;
    nmap_n.pattern.kind = IRIS_PAT_GRADIENT;
    nmap_n.n_entries = 1;
    nmap_n.entries = nmap_e;
    nmap_e[0].normal = &bumps_n;
    plain_tex.pigment = &plain_pig;
    checker_tex.pigment = &checker_pig;
    xyz_tex.pigment = &xyz_pig;
    map_tex.pigment = &map_pig;
    layer_tex.pigment = &xyz_pig;
    layer_tex.next = &xyz_tex;
    const iris_texture *texs[5] = { &plain_tex, &checker_tex, &xyz_tex,
                                    &map_tex, &layer_tex };
    const bool reads[5] = { false, true, false, true, true };
    for (int k = 0; k < 5; k++) {
        if (k == 4)
            xyz_tex.normal = &nmap_n; /* the layer below: a normal_map */
        iris_scene *ps = scene_new();
        iris_object *s = add(ps, ellipsoid(ps, v3(0, 0, 0), 1, v3(2, 2, 2),
                                           v3(0, 0, 0), v3(0, 1, 0)));
        s->texture = (iris_texture *)texs[k];
        struct accel *ap = build(ps);
        assert_true(shoot(ap, v3(10, 1, 0), v3(-1, 0, 0), &h));
        assert_near(h.t, 8, 1e-12);
        assert_ptr_equal(h.texture, s->texture);
        if (reads[k]) {
            assert_near(h.uv.u, 0, 1e-12);
            assert_near(h.uv.v, 0.5, 1e-12);
        } else {
            assert_true(h.uv.u == 0 && h.uv.v == 0);
        }
        accel_destroy(ap);
        scene_free(ps);
    }

    const int counts[2] = { 6, 24 };
    for (int k = 0; k < 2; k++) {
        iris_scene *sc = scene_new();
        rng g;
        rng_seed(&g, 11, (uint64_t)k, 0);
        iris_object *sp[24];
        for (int i = 0; i < counts[k]; i++) {
            vec3 c = v3(12 * rng_uniform(&g) - 6, 12 * rng_uniform(&g) - 6,
                        12 * rng_uniform(&g) - 6);
            vec3 sc3 = v3(0.2 + 2 * rng_uniform(&g), 0.2 + 2 * rng_uniform(&g),
                          0.2 + 2 * rng_uniform(&g));
            vec3 rot = v3(360 * rng_uniform(&g), 360 * rng_uniform(&g),
                          360 * rng_uniform(&g));
            sp[i] = add(sc, ellipsoid(sc, v3(0, 0, 0), 1, sc3, rot, c));
        }
        struct accel *a = build(sc);
        int n_hits = 0;
        for (int r = 0; r < 4000; r++) {
            /* a point on a random sphere's surface, approached from afar */
            const iris_object *target = sp[rng_u32(&g) % (uint32_t)counts[k]];
            vec3 u = v3_norm(v3(rng_uniform(&g) - 0.5, rng_uniform(&g) - 0.5,
                                rng_uniform(&g) - 0.5));
            vec3 p = xf_point(&target->transform, u);
            vec3 o = v3(40 * rng_uniform(&g) - 20, 40 * rng_uniform(&g) - 20,
                        40 * rng_uniform(&g) - 20);
            vec3 d = v3_norm(v3_sub(p, o));
            double tmin = accel_epsilon(a);
            double best = INFINITY;
            const iris_object *bo = NULL;
            bool clear = true;
            for (int i = 0; i < counts[k]; i++) {
                double t = brute_sphere(sp[i], o, d, tmin);
                if (t < best) {
                    best = t;
                    bo = sp[i];
                }
                /* near-tangent rays are left out (see above) */
                vec3 lo2 = xf_inv_point(&sp[i]->transform, o);
                vec3 ld2 = xf_inv_dir(&sp[i]->transform, d);
                double aa = v3_dot(ld2, ld2), bb = v3_dot(lo2, ld2);
                double dd = bb * bb - aa * (v3_dot(lo2, lo2) - 1);
                if (fabs(dd) < 1e-6 * bb * bb)
                    clear = false;
            }
            if (!clear)
                continue;
            ray ry = { o, d };
            bool got = accel_intersect(a, &ry, tmin, INFINITY, 0, &h);
            assert_int_equal(got, bo != NULL);
            if (!got)
                continue;
            n_hits++;
            assert_ptr_equal(h.obj, bo);
            assert_rel(h.t, best, 1e-9);
        }
        /* every ray aims at a surface: most must be kept and hit */
        assert_true(n_hits > 2000);
        accel_destroy(a);
        scene_free(sc);
    }
}

/* The nearest crossing of world ray o + t·d with transformed box 'b',
** t > tmin, solved here with the textbook slab method in object space
** (independently of src/geometry); INFINITY for none. *enters: whether
** the ray enters the box there. */
static double brute_box(const iris_object *b, vec3 o, vec3 d, double tmin,
                        bool *enters)
{
    vec3 lo = xf_inv_point(&b->transform, o);
    vec3 ld = xf_inv_dir(&b->transform, d);
    const double ol[3] = { lo.x, lo.y, lo.z }, dl[3] = { ld.x, ld.y, ld.z };
    const double bl[3] = { b->u.box.lo.x, b->u.box.lo.y, b->u.box.lo.z };
    const double bh[3] = { b->u.box.hi.x, b->u.box.hi.y, b->u.box.hi.z };
    double t0 = -INFINITY, t1 = INFINITY;
    for (int k = 0; k < 3; k++) {
        double ta = (bl[k] - ol[k]) / dl[k], tb = (bh[k] - ol[k]) / dl[k];
        t0 = fmax(t0, fmin(ta, tb));
        t1 = fmin(t1, fmax(ta, tb));
    }
    *enters = t0 > tmin;
    if (t0 > t1)
        return INFINITY;
    return t0 > tmin ? t0 : t1 > tmin ? t1 : INFINITY;
}

/*
** Moves 'o' by a random scale (0.5-1.5 on each axis), rotation and
** translation (within 6 of the origin), drawn from 'g' in that order, and
** in the clipped variant clips it by a sphere holding the whole scene:
** the fast-path tests below build each scene twice, plain and clipped
** (the clipped one takes the general path), and compare hit for hit.
*/
static void place_randomly(iris_scene *sc, iris_object *o, rng *g,
                           bool clipped)
{
    xform x;
    xf_scale(&x, v3(0.5 + rng_uniform(g), 0.5 + rng_uniform(g),
                    0.5 + rng_uniform(g)));
    apply(o, &x);
    xf_rotate(&x, v3(360 * rng_uniform(g), 360 * rng_uniform(g),
                     360 * rng_uniform(g)));
    apply(o, &x);
    xf_translate(&x, v3(12 * rng_uniform(g) - 6, 12 * rng_uniform(g) - 6,
                        12 * rng_uniform(g) - 6));
    apply(o, &x);
    if (clipped) {
        o->n_clipped_by = 1;
        o->clipped_by = arena_array(sc->arena, 1, sizeof(iris_object *));
        o->clipped_by[0] = sphere(sc, v3(0, 0, 0), 100);
    }
}

/* A ray from a random point of the cube [-20, 20]^3 through 'p'. */
static ray ray_from_afar(rng *g, vec3 p)
{
    vec3 org = v3(40 * rng_uniform(g) - 20, 40 * rng_uniform(g) - 20,
                  40 * rng_uniform(g) - 20);
    ray ry = { org, v3_norm(v3_sub(p, org)) };
    return ry;
}

/*
** The nearest hits of 'ry' in a[0] (shapes sh[0], the fast path) and
** a[1] (the same shapes sh[1], clipped: the general path), which must
** agree: on whether there is one, on the shape, and to the bit on t and
** the normal, a unit vector. Returns the shape's index, -1 for no hit.
*/
static int same_nearest(struct accel *const a[2], const ray *ry,
                        iris_object *const sh[2][12], int n, struct hit h[2])
{
    bool got[2];
    for (int v = 0; v < 2; v++)
        got[v] = accel_intersect(a[v], ry, accel_epsilon(a[v]), INFINITY, 0,
                                 &h[v]);
    assert_int_equal(got[0], got[1]);
    if (!got[0])
        return -1;
    int j = 0;
    while (j < n && sh[0][j] != h[0].obj)
        j++;
    assert_true(j < n);
    assert_ptr_equal(h[1].obj, sh[1][j]);
    assert_true(h[0].t == h[1].t);
    assert_true(h[0].n.x == h[1].n.x && h[0].n.y == h[1].n.y &&
                h[0].n.z == h[1].n.z);
    assert_near(v3_len(h[0].n), 1, 1e-12);
    return j;
}

/*
** A box leaf without clipping takes node.c's box_nearest(), which must
** give what the general path (the crossing list of geom_box_hits, then
** shape_hits' world normals) gives: the same crossing, t, normal and uv
** to the bit. The same random boxes (rotated, stretched, one inverted)
** are built twice, once plain and once clipped by a sphere holding them
** all (a clipped leaf takes the general path; the clip cuts nothing),
** with 5 boxes (the linear search) and 12 (Embree). Rays are aimed at
** points on the boxes' faces from afar; each must also meet the box and
** the t of a brute-force slab search in the test (relative 1e-9: the
** same slabs, divided where the library multiplies), rays within 1e-6
** of an edge left out (there the nearest face is ill-conditioned).
*/
static void test_box_fast_path(void **state)
{
    (void)state;
    const int counts[2] = { 5, 12 };
    for (int k = 0; k < 2; k++) {
        iris_scene *sc[2];
        iris_object *bx[2][12];
        rng g;
        for (int v = 0; v < 2; v++) {
            sc[v] = scene_new();
            rng_seed(&g, 23, (uint64_t)k, 0); /* the same boxes twice */
            for (int i = 0; i < counts[k]; i++) {
                vec3 lo = v3(-rng_uniform(&g) - 0.2, -rng_uniform(&g) - 0.2,
                             -rng_uniform(&g) - 0.2);
                vec3 hi = v3(rng_uniform(&g) + 0.2, rng_uniform(&g) + 0.2,
                             rng_uniform(&g) + 0.2);
                iris_object *b = box_object(sc[v], lo, hi);
                b->inverse = i == 1;
                place_randomly(sc[v], b, &g, v == 1);
                bx[v][i] = add(sc[v], b);
            }
        }
        struct accel *a[2] = { build(sc[0]), build(sc[1]) };
        int n_hits = 0, n_rays = 0;
        for (int r = 0; r < 4000; r++) {
            /* a point on a random face of a random box */
            int i = (int)(rng_u32(&g) % (uint32_t)counts[k]);
            const iris_object *b = bx[0][i];
            int axis = (int)(rng_u32(&g) % 3u);
            double f[3] = { rng_uniform(&g), rng_uniform(&g),
                            rng_uniform(&g) };
            f[axis] = rng_uniform(&g) < 0.5 ? 0.0 : 1.0;
            vec3 pl = v3(b->u.box.lo.x + f[0] * (b->u.box.hi.x - b->u.box.lo.x),
                         b->u.box.lo.y + f[1] * (b->u.box.hi.y - b->u.box.lo.y),
                         b->u.box.lo.z + f[2] * (b->u.box.hi.z - b->u.box.lo.z));
            bool edge = false;
            for (int c = 0; c < 3; c++)
                if (c != axis && (f[c] < 1e-6 || f[c] > 1 - 1e-6))
                    edge = true;
            vec3 p = xf_point(&b->transform, pl);
            vec3 o = v3(40 * rng_uniform(&g) - 20, 40 * rng_uniform(&g) - 20,
                        40 * rng_uniform(&g) - 20);
            vec3 d = v3_norm(v3_sub(p, o));
            double tmin = accel_epsilon(a[0]);
            double best = INFINITY;
            int bi = -1;
            bool enters = false;
            for (int j = 0; j < counts[k]; j++) {
                bool e;
                double t = brute_box(bx[0][j], o, d, tmin, &e);
                if (t < best) {
                    best = t;
                    bi = j;
                    enters = e;
                }
            }
            if (edge)
                continue;
            n_rays++;
            ray ry = { o, d };
            struct hit h[2];
            bool got[2];
            for (int v = 0; v < 2; v++)
                got[v] = accel_intersect(a[v], &ry, tmin, INFINITY, 0, &h[v]);
            assert_int_equal(got[0], got[1]);
            assert_int_equal(got[0], bi >= 0);
            if (!got[0])
                continue;
            n_hits++;
            assert_ptr_equal(h[0].obj, bx[0][bi]);
            assert_ptr_equal(h[1].obj, bx[1][bi]);
            assert_rel(h[0].t, best, 1e-9);
            /* the fast path's crossing is the general path's, to the bit */
            assert_true(h[0].t == h[1].t);
            assert_true(h[0].n.x == h[1].n.x && h[0].n.y == h[1].n.y &&
                        h[0].n.z == h[1].n.z);
            assert_true(h[0].uv.u == h[1].uv.u && h[0].uv.v == h[1].uv.v);
            /* a unit normal out of the box: against the ray where it
            ** enters, along it where it leaves (the other way round for
            ** the inverted box, whose outside is its inside) */
            assert_near(v3_len(h[0].n), 1, 1e-12);
            double facing = v3_dot(h[0].n, d);
            assert_true((bi == 1) != enters ? facing < 0 : facing > 0);
        }
        /* most rays are kept and hit what they aim at */
        assert_true(n_rays > 3900);
        assert_true(n_hits > 3000);
        for (int v = 0; v < 2; v++) {
            accel_destroy(a[v]);
            scene_free(sc[v]);
        }
    }
}

/*
** Cylinders and cones without clipping take node.c's cone_nearest(),
** which must give the general path's crossing (the list of
** geom_cone_hits, then shape_hits' world normals) to the bit: t, normal
** and uv (the side's uv is an atan2, asked for the kept crossing only).
** As in test_box_fast_path, the same random shapes (cylinders, cones, a
** cone to an apex, an open cylinder, one inverted) are built plain and
** clipped by a sphere holding them all; rays are aimed at points on
** their sides and caps from afar, through the linear search (6 shapes)
** and Embree (12). Every ray aims at a surface, so most must hit.
*/
static void test_cone_fast_path(void **state)
{
    (void)state;
    const int counts[2] = { 6, 12 };
    for (int k = 0; k < 2; k++) {
        iris_scene *sc[2];
        iris_object *sh[2][12];
        rng g;
        for (int v = 0; v < 2; v++) {
            sc[v] = scene_new();
            rng_seed(&g, 29, (uint64_t)k, 0); /* the same shapes twice */
            for (int i = 0; i < counts[k]; i++) {
                double r0 = 0.3 + rng_uniform(&g), r1 = 0.3 + rng_uniform(&g);
                iris_object *o;
                if (i % 3 == 0) {
                    o = obj(sc[v], IRIS_OBJ_CYLINDER);
                    o->u.cylinder.base = v3(0, -1, 0);
                    o->u.cylinder.cap = v3(0, 1, 0);
                    o->u.cylinder.radius = r0;
                    o->open = i == 3;
                } else {
                    o = obj(sc[v], IRIS_OBJ_CONE);
                    o->u.cone.base = v3(0, -1, 0);
                    o->u.cone.cap = v3(0, 1, 0);
                    o->u.cone.base_radius = r0;
                    o->u.cone.cap_radius = i % 3 == 2 ? 0 : r1;
                }
                o->inverse = i == 1;
                o->texture = &uv_tex; /* the side's uv is compared */
                place_randomly(sc[v], o, &g, v == 1);
                sh[v][i] = add(sc[v], o);
            }
        }
        struct accel *a[2] = { build(sc[0]), build(sc[1]) };
        int n_hits = 0, n_side = 0;
        for (int r = 0; r < 4000; r++) {
            /* a point on a random shape's side or cap, in its own frame */
            int i = (int)(rng_u32(&g) % (uint32_t)counts[k]);
            const iris_object *o = sh[0][i];
            double r0 = o->kind == IRIS_OBJ_CONE ? o->u.cone.base_radius
                                                 : o->u.cylinder.radius;
            double r1 = o->kind == IRIS_OBJ_CONE ? o->u.cone.cap_radius : r0;
            double y = 2 * rng_uniform(&g) - 1, phi = 2 * M_PI * rng_uniform(&g);
            double rad = r0 + (r1 - r0) * (y + 1) / 2;
            if (rng_uniform(&g) < 0.25) { /* a cap */
                y = rng_uniform(&g) < 0.5 ? -1 : 1;
                rad = (y < 0 ? r0 : r1) * rng_uniform(&g);
            }
            vec3 p = xf_point(&o->transform,
                              v3(rad * cos(phi), y, rad * sin(phi)));
            ray ry = ray_from_afar(&g, p);
            struct hit h[2];
            if (same_nearest(a, &ry, sh, counts[k], h) < 0)
                continue;
            n_hits++;
            assert_true(h[0].uv.u == h[1].uv.u && h[0].uv.v == h[1].uv.v);
            if (h[0].uv.u != 0 || h[0].uv.v != 0)
                n_side++;
        }
        /* most rays hit, and many on a side (a uv of its own) */
        assert_true(n_hits > 3000);
        assert_true(n_side > 1000);
        for (int v = 0; v < 2; v++) {
            accel_destroy(a[v]);
            scene_free(sc[v]);
        }
    }
}

/*
** Tori without clipping take node.c's torus_nearest(), which solves for
** the first root of the quartic only; it must give the general path's
** crossing (every root, geom_torus_hits' list, then shape_hits' world
** normals) to the bit: t, normal and uv. As in test_cone_fast_path, the
** same random tori (one inverted, one whose minor radius exceeds its
** major, a spindle) are built plain and clipped by a sphere holding them
** all, and rays are aimed from afar at points on their surfaces, through
** the linear search (6 tori) and Embree (12). Their texture reads uv
** (uv_tex), except one torus's plain texture, which reads none: its
** hits on the fast path must carry uv 0 (its two atan2 are skipped),
** and are left out of the uv comparison.
*/
static void test_torus_fast_path(void **state)
{
    (void)state;
    static iris_pigment plain_pig;
    static iris_texture plain_tex = { .pigment = &plain_pig };
    const int counts[2] = { 6, 12 };
    for (int k = 0; k < 2; k++) {
        iris_scene *sc[2];
        iris_object *sh[2][12];
        rng g;
        for (int v = 0; v < 2; v++) {
            sc[v] = scene_new();
            rng_seed(&g, 31, (uint64_t)k, 0); /* the same tori twice */
            for (int i = 0; i < counts[k]; i++) {
                iris_object *o = obj(sc[v], IRIS_OBJ_TORUS);
                o->u.torus.major = 0.6 + rng_uniform(&g);
                o->u.torus.minor = i == 4 ? o->u.torus.major * 1.2
                                          : 0.1 + 0.4 * rng_uniform(&g);
                o->inverse = i == 1;
                /* uv compared; one torus's plain texture reads none */
                o->texture = i == 2 ? &plain_tex : &uv_tex;
                place_randomly(sc[v], o, &g, v == 1);
                sh[v][i] = add(sc[v], o);
            }
        }
        struct accel *a[2] = { build(sc[0]), build(sc[1]) };
        int n_hits = 0, n_uv = 0, n_plain = 0;
        for (int r = 0; r < 4000; r++) {
            /* a point on a random torus, in its own frame */
            int i = (int)(rng_u32(&g) % (uint32_t)counts[k]);
            const iris_object *o = sh[0][i];
            double R = o->u.torus.major, rm = o->u.torus.minor;
            double pu = 2 * M_PI * rng_uniform(&g),
                   pv = 2 * M_PI * rng_uniform(&g);
            vec3 pl = v3((R + rm * cos(pv)) * cos(pu), rm * sin(pv),
                         (R + rm * cos(pv)) * sin(pu));
            vec3 p = xf_point(&o->transform, pl);
            ray ry = ray_from_afar(&g, p);
            struct hit h[2];
            int j = same_nearest(a, &ry, sh, counts[k], h);
            if (j < 0)
                continue;
            n_hits++;
            if (j == 2) { /* plain texture: no uv computed */
                assert_true(h[0].uv.u == 0 && h[0].uv.v == 0);
                n_plain++;
                continue;
            }
            assert_true(h[0].uv.u == h[1].uv.u && h[0].uv.v == h[1].uv.v);
            if (h[0].uv.u != 0 || h[0].uv.v != 0)
                n_uv++;
        }
        /* most rays hit, with a uv of their own, some on the plain one */
        assert_true(n_hits > 3000);
        assert_true(n_uv > 2000);
        assert_true(n_plain > 100);
        for (int v = 0; v < 2; v++) {
            accel_destroy(a[v]);
            scene_free(sc[v]);
        }
    }
}

int main(void)
{
    glass.ior = 1.5;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_hit),
        cmocka_unit_test(test_transformed),
        cmocka_unit_test(test_difference),
        cmocka_unit_test(test_intersection),
        cmocka_unit_test(test_merge),
        cmocka_unit_test(test_inverse),
        cmocka_unit_test(test_clip),
        cmocka_unit_test(test_inside),
        cmocka_unit_test(test_mesh_attrs),
        cmocka_unit_test(test_skip),
        cmocka_unit_test(test_scale_invariance),
        cmocka_unit_test(test_no_nan),
        cmocka_unit_test(test_grazing),
        cmocka_unit_test(test_isosurface),
        cmocka_unit_test(test_height_field),
        cmocka_unit_test(test_mesh_csg),
        cmocka_unit_test(test_blob_texture),
        cmocka_unit_test(test_bad_input),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_self_hit),
        cmocka_unit_test(test_fast_paths),
        cmocka_unit_test(test_box_fast_path),
        cmocka_unit_test(test_cone_fast_path),
        cmocka_unit_test(test_torus_fast_path),
        cmocka_unit_test(test_csg_polytope),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
