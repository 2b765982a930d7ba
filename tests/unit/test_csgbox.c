/* SPDX-License-Identifier: MIT */
/*
** test_csgbox.c: the boxes of CSG intersections of planes and quadrics
** (src/accel/csgbox.c) and what the accel does with them: the box of a
** hyperboloid stem and of a bevelled frame wedge against their analytic
** extents, soundness (no point inside every child falls outside the box,
** sampled under rotation and scaling), empty intersections, and rays
** through the intersections hitting what they hit without a box.
*/
#include "config.h"

#include "testutil.h"

#include <math.h>

#include "accel/accel.h"
#include "accel/csgbox.h"
#include "geometry/geom.h"
#include "math/transform.h"
#include "util/arena.h"
#include "util/rng.h"

#include "scene_builder.h"

static iris_object *plane(iris_scene *sc, vec3 n, double d)
{
    iris_object *o = obj(sc, IRIS_OBJ_PLANE);
    o->u.plane.normal = n;
    o->u.plane.distance = d;
    return o;
}

/* quadric {<A,B,C>,<D,E,F>,<G,H,I>,J} as written in SDL */
static iris_object *quadric(iris_scene *sc, const double k[10])
{
    iris_object *o = obj(sc, IRIS_OBJ_QUADRIC);
    o->u.poly.order = 2;
    o->u.poly.n_coeffs = 10;
    o->u.poly.coeffs = arena_array(sc->arena, 10, sizeof(double));
    for (int i = 0; i < 10; i++)
        o->u.poly.coeffs[i] = k[i];
    return o;
}

static iris_object *intersection(iris_scene *sc, iris_object **kids, int n)
{
    iris_object *o = obj(sc, IRIS_OBJ_INTERSECTION);
    o->texture = NULL;
    o->u.csg.n_children = n;
    o->u.csg.children = arena_array(sc->arena, (size_t)n, sizeof *kids);
    for (int i = 0; i < n; i++)
        o->u.csg.children[i] = kids[i];
    return o;
}

/* The world inside test of one leaf, as node_inside makes it. */
static bool leaf_inside(const iris_object *o, vec3 p)
{
    vec3 lp = o->has_transform ? xf_inv_point(&o->transform, p) : p;
    return geom_inside(o, NULL, lp);
}

/* Narrows the infinite box by every child, three rounds as accel.c. */
static bool narrow_all(iris_object **k, int n, vec3 *lo, vec3 *hi)
{
    *lo = v3(-INFINITY, -INFINITY, -INFINITY);
    *hi = v3(INFINITY, INFINITY, INFINITY);
    for (int r = 0; r < 3; r++)
        for (int i = 0; i < n; i++)
            if (!csgbox_narrow(k[i], lo, hi))
                return false;
    return true;
}

static const double hyperboloid_y[10] = { 1, -1, 1, 0, 0, 0, 0, 0, 0, -1 };

/* chess2.pov's pawn stem: Hyperboloid_Y (x² - y² + z² < 1, shapes.inc)
** between y = 2.5 and y = 5.5. Its widest circle is at y = 5.5, radius
** sqrt(1 + 5.5²): the box is exact, up to rounding (1e-12). */
static void test_hyperboloid_stem(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *k[3] = { plane(sc, v3(0, 1, 0), 5.5),
                          quadric(sc, hyperboloid_y),
                          plane(sc, v3(0, -1, 0), -2.5) };
    vec3 lo, hi;
    assert_true(narrow_all(k, 3, &lo, &hi));
    double r = sqrt(1 + 5.5 * 5.5);
    assert_near(lo.y, 2.5, 1e-12);
    assert_near(hi.y, 5.5, 1e-12);
    assert_near(lo.x, -r, 1e-12);
    assert_near(hi.x, r, 1e-12);
    assert_near(lo.z, -r, 1e-12);
    assert_near(hi.z, r, 1e-12);
    arena_destroy(sc->arena);
}

/* chess2.pov's frame piece as five planes: -3 < y < -0.15, z > -35,
** z < x, z < -x. */
static void frame_planes(iris_scene *sc, iris_object *k[5])
{
    k[0] = plane(sc, v3(0, 1, 0), -0.15);
    k[1] = plane(sc, v3(0, -1, 0), 3);
    k[2] = plane(sc, v3(0, 0, -1), 35);
    k[3] = plane(sc, v3(-1, 0, 1), 0);
    k[4] = plane(sc, v3(1, 0, 1), 0);
}

/* chess2.pov's frame piece: -3 < y < -0.15, z > -35, z < x, z < -x, a
** triangular prism with x in (-35, 35), z in (-35, 0). Box narrowing
** axis by axis finds x exactly and a z bound of 35 (from z < x < 35),
** wider than the prism but finite, which is all the accel needs. */
static void test_frame_wedge(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *k[5];
    frame_planes(sc, k);
    vec3 lo, hi;
    assert_true(narrow_all(k, 5, &lo, &hi));
    assert_near(lo.y, -3, 1e-12);
    assert_near(hi.y, -0.15, 1e-12);
    assert_near(lo.x, -35, 1e-12);
    assert_near(hi.x, 35, 1e-12);
    assert_near(lo.z, -35, 1e-12);
    assert_true(hi.z >= 0 && hi.z <= 35 + 1e-12);
    arena_destroy(sc->arena);
}

/* Two planes facing apart share no point: the intersection is empty. */
static void test_empty(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *k[2] = { plane(sc, v3(0, 1, 0), 0),
                          plane(sc, v3(0, -1, 0), -1) };
    vec3 lo, hi;
    assert_false(narrow_all(k, 2, &lo, &hi));
    /* an ellipsoid quadric x² + y² + z² < 1 cannot reach y > 2 either */
    const double ball[10] = { 1, 1, 1, 0, 0, 0, 0, 0, 0, -1 };
    iris_object *b[2] = { quadric(sc, ball), plane(sc, v3(0, -1, 0), -2) };
    assert_false(narrow_all(b, 2, &lo, &hi));
    arena_destroy(sc->arena);
}

/*
** Soundness: points sampled in a cube, kept when inside every child
** (the shapes' own inside tests), must lie in the narrowed box. The
** children are rotated, scaled and translated (a quadric with a linear
** term, a paraboloid; planes at odd angles), so both the diagonal and
** the corner paths of the box transforms are taken. No tolerance: the
** box is conservative or the test fails.
*/
static void test_sound_under_transforms(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    /* paraboloid y > x² + z² (x² + z² - y < 0), scaled and moved */
    const double para[10] = { 1, 0, 1, 0, 0, 0, 0, -1, 0, 0 };
    iris_object *q = quadric(sc, para);
    xform x;
    xf_scale(&x, v3(0.7, 2, 1.3));
    apply(q, &x);
    xf_translate(&x, v3(0.3, -1, 0.2));
    apply(q, &x);
    /* a cap turned about y (its normal stays +y) bounds y, then the
    ** paraboloid x and z; a tilted cap, a hyperboloid turned about y and
    ** a tilted floor narrow that finite box further */
    iris_object *cap = plane(sc, v3(0, 1, 0), 3);
    xf_rotate(&x, v3(0, 35, 0));
    apply(cap, &x);
    iris_object *tilt = plane(sc, v3(0.1, 1, -0.2), 2.5);
    xf_rotate(&x, v3(20, 35, -10));
    apply(tilt, &x);
    iris_object *h = quadric(sc, hyperboloid_y);
    xf_rotate(&x, v3(0, 30, 0));
    apply(h, &x);
    iris_object *floor = plane(sc, v3(0.2, -1, 0.1), 0.5);
    iris_object *k[5] = { q, cap, tilt, h, floor };
    vec3 lo, hi;
    assert_true(narrow_all(k, 5, &lo, &hi));
    assert_true(isfinite(lo.x) && isfinite(hi.x) && isfinite(lo.y) &&
                isfinite(hi.y) && isfinite(lo.z) && isfinite(hi.z));
    rng r;
    rng_seed(&r, 7, 0, 0);
    int inside = 0;
    for (int i = 0; i < 200000; i++) {
        vec3 p = v3(-8 + 16 * rng_uniform(&r), -8 + 16 * rng_uniform(&r),
                    -8 + 16 * rng_uniform(&r));
        bool in = true;
        for (int j = 0; j < 5 && in; j++)
            in = leaf_inside(k[j], p);
        if (!in)
            continue;
        inside++;
        assert_true(p.x >= lo.x && p.x <= hi.x && p.y >= lo.y &&
                    p.y <= hi.y && p.z >= lo.z && p.z <= hi.z);
    }
    /* the sample did reach the inside (a small part of the cube) */
    assert_true(inside > 100);
    arena_destroy(sc->arena);
}

/* Through the accel: the frame wedge gets a finite box, and rays hit it
** where the planes put the hits (the box only culls). A ray down the
** middle of the prism meets the top face y = -0.15; one from the side
** meets the bevel z = x at x = -10 when aimed along +x at z = -10, and
** one beside the prism (z = 5 > 0 is outside) misses. 1e-9 is rounding. */
static void test_accel_frame(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *k[5];
    frame_planes(sc, k);
    iris_object *w = add(sc, intersection(sc, k, 5));
    struct accel *a = build(sc);
    vec3 lo, hi;
    assert_true(accel_object_bounds(a, w, &lo, &hi));
    struct hit h;
    ray r = { v3(0, 10, -20), v3(0, -1, 0) };
    assert_true(accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h));
    assert_near(h.t, 10.15, 1e-9);
    r.o = v3(-50, -1, -10);
    r.d = v3(1, 0, 0);
    assert_true(accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h));
    assert_near(h.p.x, -10, 1e-9);
    r.o = v3(-50, -1, 5);
    assert_false(accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h));
    assert_true(accel_inside(a, w, v3(0, -1, -20)));
    assert_false(accel_inside(a, w, v3(0, -1, 20)));
    accel_destroy(a);
    arena_destroy(sc->arena);
}

/* A disc's inside is the half-space behind it (POV-Ray), not its thin
** box: intersection { sphere r 1, disc at 0 facing +y } is the lower half
** ball, so a ray from below at x = 0.1 meets the sphere at
** y = -sqrt(1 - 0.01). 1e-9 is rounding. */
static void test_accel_disc_half_ball(void **state)
{
    (void)state;
    iris_scene *sc = scene_new();
    iris_object *d = obj(sc, IRIS_OBJ_DISC);
    d->u.disc.centre = v3(0, 0, 0);
    d->u.disc.normal = v3(0, 1, 0);
    d->u.disc.radius = 2;
    iris_object *k[2] = { sphere(sc, v3(0, 0, 0), 1), d };
    add(sc, intersection(sc, k, 2));
    struct accel *a = build(sc);
    struct hit h;
    ray r = { v3(0.1, -5, 0), v3(0, 1, 0) };
    assert_true(accel_intersect(a, &r, accel_epsilon(a), INFINITY, 0, &h));
    assert_near(h.p.y, -sqrt(1 - 0.01), 1e-9);
    accel_destroy(a);
    arena_destroy(sc->arena);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_hyperboloid_stem),
        cmocka_unit_test(test_frame_wedge),
        cmocka_unit_test(test_empty),
        cmocka_unit_test(test_sound_under_transforms),
        cmocka_unit_test(test_accel_frame),
        cmocka_unit_test(test_accel_disc_half_ball),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
