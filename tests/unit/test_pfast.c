/* SPDX-License-Identifier: MIT */
/*
** test_pfast.c: the photon fast path (src/photon/fastpath.c) against
** accel_intersect(), its specification.
**
** The fast path claims accel's answer to the bit (uv only where a texture
** may read it), so the comparisons here are exact, no tolerance: t, p,
** both normals and eps with ==, and the same object, texture and interior. Rays are random
** (origins in a box around the objects, uniform directions) and each is
** followed for a few bounces from its hit with the hit's own eps, which
** is where a query most easily disagrees (a ray leaving a surface must
** not meet it again, or must meet it the same way). Then the photon maps
** built through either query must hold the same photons, record for
** record, with and without the material context, caustic and global.
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "material/material.h"
#include "parse_util.h"
#include "photon/fastpath.h"
#include "photon/pmap.h"
#include "pmap_same.h"
#include "util/rng.h"

/* The caustic ball of bench/caustic_ball.pov (small count). */
static const char *const BALL =
    "global_settings { photons { count 20000 autostop 0 jitter 0.4 } }\n"
    "light_source { <0, 20, 0> color rgb 1 cylinder point_at <0, 0, 0>\n"
    "  radius 1 falloff 1 tightness 0\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* Transforms (a similarity among them), inverse, no_shadow, a tilted
** plane, overlapping spheres. */
static const char *const MIXED =
    "light_source { <3, 9, -4> color rgb 1 }\n"
    "plane { <0.3, 1, 0.1>, -0.5 pigment { color rgb 0.8 } "
    "rotate <5, 10, 0> translate <0, 0.2, 0> }\n"
    "sphere { 0, 1 scale <1, 2, 0.5> rotate <30, 40, 0> translate <1, 1, 0>\n"
    "  pigment { color rgbf <1, 0.9, 0.8, 0.9> } interior { ior 1.33 } }\n"
    "sphere { <-1, 0.5, 0.5>, 0.7 inverse pigment { color rgb 1 } }\n"
    "sphere { <-0.5, 0.8, 0>, 0.6 no_shadow\n"
    "  pigment { uv_mapping checker color rgb 1 color rgb 0 } }\n"
    "sphere { <0, 3, 0>, 0.01 pigment { color rgb 1 } }\n"
    /* turned and scaled uniformly: solved about its moved centre */
    "sphere { <0.2, 0, 0>, 0.5 rotate <10, 20, 30> scale 1.5\n"
    "  translate <-1.5, 1.2, 1> pigment { color rgb 0.7 } }\n"
    "plane { x, 6 inverse pigment { color rgb 0.5 } }\n";

static vec3 random_dir(rng *r)
{
    double z = 2.0 * rng_uniform(r) - 1.0, ph = 2.0 * M_PI * rng_uniform(r);
    double s = sqrt(fmax(0.0, 1.0 - z * z));
    return v3(s * cos(ph), s * sin(ph), z);
}

static void same_hit(const struct hit *a, const struct hit *f)
{
    /* exact: the fast path repeats accel's arithmetic */
    assert_true(a->t == f->t);
    assert_true(a->p.x == f->p.x && a->p.y == f->p.y && a->p.z == f->p.z);
    assert_true(a->n.x == f->n.x && a->n.y == f->n.y && a->n.z == f->n.z);
    assert_true(a->shading_n.x == f->shading_n.x &&
                a->shading_n.y == f->shading_n.y &&
                a->shading_n.z == f->shading_n.z);
    assert_true(a->eps == f->eps);
    assert_ptr_equal(a->obj, f->obj);
    assert_ptr_equal(a->top, f->top);
    assert_ptr_equal(a->texture, f->texture);
    assert_ptr_equal(a->interior, f->interior);
    /* uv: accel's wherever the texture may read it (a patterned sphere),
    ** else 0 */
    if (a->obj->kind == IRIS_OBJ_SPHERE &&
        a->obj->texture->pigment->pattern.kind != IRIS_PAT_NONE)
        assert_true(a->uv.u == f->uv.u && a->uv.v == f->uv.v);
    else
        assert_true(f->uv.u == 0 && f->uv.v == 0);
}

/* 'n' random rays, each followed for up to 4 bounces, through both
** queries; returns how many hits were compared. */
static int compare_queries(const char *sdl, int n)
{
    iris_scene *sc = pt_scene_with(sdl, NULL);
    struct accel *a = NULL;
    char err[256];
    assert_int_equal(accel_build(sc, &a, stderr, err, sizeof err), IRIS_OK);
    struct pfast *f = pfast_build(sc, a);
    assert_non_null(f);
    rng r;
    rng_seed(&r, 42, 0, 0);
    int hits = 0;
    for (int i = 0; i < n; i++) {
        ray ry = { v3(8 * rng_uniform(&r) - 4, 6 * rng_uniform(&r) - 1,
                      8 * rng_uniform(&r) - 4),
                   random_dir(&r) };
        double tmin = accel_epsilon(a);
        unsigned skip = i % 2 ? ACCEL_SKIP_NO_SHADOW : ACCEL_SKIP_NONE;
        for (int b = 0; b < 4; b++) {
            struct hit ha, hf;
            memset(&ha, 0, sizeof ha);
            memset(&hf, 0, sizeof hf);
            bool ka = accel_intersect(a, &ry, tmin, INFINITY, skip, &ha);
            bool kf = pfast_intersect(f, &ry, tmin, INFINITY, skip, &hf);
            assert_int_equal(ka, kf);
            if (!ka)
                break;
            same_hit(&ha, &hf);
            hits++;
            /* on from the hit: mirror or straight through, by chance */
            vec3 d = rng_uniform(&r) < 0.5 ? v3_reflect(ry.d, ha.n) : ry.d;
            ry.o = ha.p;
            ry.d = v3_norm(d);
            tmin = ha.eps > 0 ? ha.eps : accel_epsilon(a);
        }
    }
    fprintf(stderr, "# %d rays, %d hits compared\n", n, hits);
    pfast_destroy(f);
    accel_destroy(a);
    iris_scene_destroy(sc);
    return hits;
}

/* Untransformed spheres and planes only, no uv read: the plain scan
** (fastpath.c query_plain), with several of each kind, an overlap, an
** inverse sphere and plane, a no_shadow sphere and a tiny one. */
static const char *const PLAIN =
    "light_source { <3, 9, -4> color rgb 1 }\n"
    "plane { <0.3, 1, 0.1>, -0.5 pigment { color rgb 0.8 } }\n"
    "sphere { <1, 1, 0>, 1 pigment { color rgbf <1, 0.9, 0.8, 0.9> }\n"
    "  interior { ior 1.33 } }\n"
    "sphere { <-1, 0.5, 0.5>, 0.7 inverse pigment { color rgb 1 } }\n"
    "sphere { <-0.5, 0.8, 0>, 0.6 no_shadow pigment { color rgb 1 } }\n"
    "sphere { <0, 3, 0>, 0.01 pigment { color rgb 1 } }\n"
    "plane { x, 6 inverse pigment { color rgb 0.5 } }\n"
    "plane { -z, 5 pigment { color rgb 0.5 } }\n";

/* Whether the scan of scene 'sdl' is the plain one. */
static bool takes_plain(const char *sdl)
{
    iris_scene *sc = pt_scene_with(sdl, NULL);
    struct accel *a = NULL;
    char err[256];
    assert_int_equal(accel_build(sc, &a, stderr, err, sizeof err), IRIS_OK);
    struct pfast *f = pfast_build(sc, a);
    assert_non_null(f);
    bool plain = pfast_plain(f);
    pfast_destroy(f);
    accel_destroy(a);
    iris_scene_destroy(sc);
    return plain;
}

/* Each scan is the one meant, so the comparisons below test both: the
** ball and PLAIN take the plain scan, MIXED (transforms, a patterned
** sphere) the general one. */
static void test_which_scan(void **state)
{
    (void)state;
    assert_true(takes_plain(BALL));
    assert_true(takes_plain(PLAIN));
    assert_false(takes_plain(MIXED));
    /* one patterned sphere, untransformed, is enough to need uv */
    assert_false(takes_plain(
        "sphere { 0, 1 pigment { uv_mapping checker color rgb 1 "
        "color rgb 0 } }\n"));
    assert_false(takes_plain(
        "plane { y, 0 translate 1 pigment { color rgb 1 } }\n"));
}

static void test_same_hits_plain(void **state)
{
    (void)state;
    assert_true(compare_queries(PLAIN, 20000) > 10000);
}

static void test_same_hits_ball(void **state)
{
    (void)state;
    /* a ray from the box around the ball (-1 <= y <= 5) meets the floor
    ** unless it heads away from it, about half of them: the comparison
    ** must not be vacuous */
    assert_true(compare_queries(BALL, 20000) > 10000);
}

static void test_same_hits_mixed(void **state)
{
    (void)state;
    assert_true(compare_queries(MIXED, 20000) > 10000);
}

/* Scenes with anything but top-level spheres and planes keep accel. */
static void test_not_eligible(void **state)
{
    (void)state;
    const char *const cases[] = {
        "box { 0, 1 pigment { color rgb 1 } }\n",
        "union { sphere { 0, 1 } sphere { 1, 1 } pigment { color rgb 1 } }\n",
        "sphere { 0, 1 clipped_by { plane { y, 0 } } "
        "pigment { color rgb 1 } }\n",
        "#for (i, 0, 8) sphere { <i, 0, 0>, 0.4 pigment { color rgb 1 } } "
        "#end\n",
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        iris_scene *sc = pt_scene_with(cases[i], NULL);
        struct accel *a = NULL;
        char err[256];
        assert_int_equal(accel_build(sc, &a, stderr, err, sizeof err),
                         IRIS_OK);
        assert_null(pfast_build(sc, a));
        accel_destroy(a);
        iris_scene_destroy(sc);
    }
}

/* A diffuse room for the global map (radiosity{}): its photons bounce
** off the floor, the walls and a ball, through the same queries. */
static const char *const ROOM =
    "global_settings { radiosity { recursion_limit 20 } }\n"
    "light_source { <0, 3, 0> color rgb 1 }\n"
    "plane { y, 0 pigment { color rgb 0.8 } }\n"
    "plane { -y, -4 pigment { color rgb 0.7 } }\n"
    "plane { x, -3 pigment { color rgb <0.8, 0.2, 0.2> } }\n"
    "plane { -x, -3 pigment { color rgb <0.2, 0.8, 0.2> } }\n"
    "sphere { <0.5, 1, 0.5>, 0.8 pigment { color rgb 0.9 } }\n";

/* The second map's options: the fast-path way turned off. */
static void no_fastpath(struct photon_options *o)
{
    o->no_fastpath = true;
}

/* The photon maps built through either query: the same records. */
static void same_map(const char *sdl, bool with_mat)
{
    iris_scene *sc = pt_scene_with(sdl, NULL);
    struct accel *a = NULL;
    char err[256];
    assert_int_equal(accel_build(sc, &a, stderr, err, sizeof err), IRIS_OK);
    struct pfast *f = pfast_build(sc, a); /* else the test is vacuous */
    assert_non_null(f);
    pfast_destroy(f);
    struct mat_ctx *mc = NULL;
    if (with_mat)
        assert_int_equal(mat_ctx_create(sc, stderr, &mc), IRIS_OK);
    struct photon_map *m[2];
    struct photon_stats st[2];
    build_photon_map_pair(sc, a, mc, 7, no_fastpath, m, st);
    assert_int_equal(st[0].shot, st[1].shot);
    assert_int_equal(st[0].shot_global, st[1].shot_global);
    assert_same_photon_maps(m[0], m[1]);
    for (int k = 0; k < 2; k++)
        photon_map_destroy(m[k]);
    mat_ctx_destroy(mc);
    accel_destroy(a);
    iris_scene_destroy(sc);
}

static void test_same_map(void **state)
{
    (void)state;
    same_map(BALL, false);
}

static void test_same_map_material(void **state)
{
    (void)state;
    same_map(BALL, true);
}

static void test_same_global_map(void **state)
{
    (void)state;
    same_map(ROOM, true);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_hits_ball),
        cmocka_unit_test(test_same_hits_mixed),
        cmocka_unit_test(test_which_scan),
        cmocka_unit_test(test_same_hits_plain),
        cmocka_unit_test(test_not_eligible),
        cmocka_unit_test(test_same_map),
        cmocka_unit_test(test_same_map_material),
        cmocka_unit_test(test_same_global_map),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
