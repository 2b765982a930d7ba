/* SPDX-License-Identifier: MIT */
/*
** test_ptexcache.c: the photon tracer's cache of textures that are one
** colour everywhere (src/photon/trace.h, struct ptrace_tex) against the
** evaluation at every hit, its specification.
**
** The cache claims the general evaluation's numbers to the bit (it keeps
** what mat_eval_texture(), or the top layer's pigment without a context,
** gives at any point of such a texture, and repeats the lambda-dependent
** and angle-dependent parts at each hit), so the comparison is exact, no
** tolerance: the photon maps built with and without the cache must hold
** the same records, with and without the material context. The scenes
** mix cached and uncached textures: grey and coloured filters, two
** layers, reflection with falloff and with fresnel and metallic, a
** checkered floor and a normal{} (both evaluated at every hit), two
** lights of which one is coloured; and the global map (radiosity{}) of a
** diffuse room, whose photons bounce off its walls many times. The cache
** must have answered some hits (else the comparison would be vacuous)
** and, when turned off, none.
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "material/material.h"
#include "parse_util.h"
#include "photon/pmap.h"
#include "pmap_same.h"

/* The caustic ball of bench/caustic_ball.pov (small count): every
** texture uniform, the fast path's scene. */
static const char *const BALL =
    "global_settings { photons { count 20000 autostop 0 jitter 0.4 } }\n"
    "light_source { <0, 20, 0> color rgb 1 cylinder point_at <0, 0, 0>\n"
    "  radius 1 falloff 1 tightness 0\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* Cached and uncached textures side by side (see the header). */
static const char *const MIXED =
    "global_settings { photons { spacing 0.03 autostop 0 } }\n"
    "light_source { <2, 10, -3> color rgb 1\n"
    "  photons { refraction on reflection on } }\n"
    "light_source { <-3, 8, 2> color rgb <1, 0.8, 0.6>\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, 0 pigment { checker color rgb 1 color rgb 0.5 }\n"
    "  finish { diffuse 1 } }\n"
    "plane { x, -4 pigment { color rgb <0.9, 0.6, 0.3> }\n"
    "  finish { diffuse 0.8 } }\n"
    "sphere { <0, 1.5, 0>, 1 pigment { color rgbf <1, 0.7, 0.4, 0.8> }\n"
    "  finish { diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on } }\n"
    "sphere { <2.5, 1, 0>, 0.8\n"
    "  texture { pigment { color rgbt <1, 1, 1, 0.5> }\n"
    "    finish { diffuse 0 reflection { 0.1, 0.6 falloff 2 } } }\n"
    "  texture { pigment { color rgbf <0.5, 0.9, 0.5, 0.9> } }\n"
    "  interior { ior 1.3 }\n"
    "  photons { target refraction on reflection on } }\n"
    "sphere { <-2, 1, 1>, 0.7 pigment { color rgb <0.9, 0.8, 0.3> }\n"
    "  finish { diffuse 0.2 reflection { 0.2, 1 fresnel on metallic 1 } }\n"
    "  interior { ior 2 } photons { target reflection on } }\n"
    "sphere { <0, 1, -2.5>, 0.6 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  normal { bumps 0.5 scale 0.2 } interior { ior 1.5 }\n"
    "  photons { target refraction on } }\n";

/* A diffuse room for the global map (test_pfast.c's), one wall checkered
** (evaluated at every hit). */
static const char *const ROOM =
    "global_settings { radiosity { recursion_limit 20 } }\n"
    "light_source { <0, 3, 0> color rgb 1 }\n"
    "plane { y, 0 pigment { color rgb 0.8 } }\n"
    "plane { -y, -4 pigment { color rgb 0.7 } }\n"
    "plane { x, -3 pigment { color rgb <0.8, 0.2, 0.2> } }\n"
    "plane { -x, -3 pigment { checker color rgb <0.2, 0.8, 0.2>\n"
    "  color rgb 0.5 } }\n"
    "sphere { <0.5, 1, 0.5>, 0.8 pigment { color rgb 0.9 } }\n";

/* The second map's options: the cached way turned off. */
static void no_cache(struct photon_options *o)
{
    o->no_tex_cache = true;
}

/* The photon maps built with and without the cache: the same records
** (the caustic map, or the global map and its irradiance points). */
static void same_map(const char *sdl, bool with_mat)
{
    iris_scene *sc = pt_scene_with(sdl, NULL);
    struct accel *a = NULL;
    char err[256];
    assert_int_equal(accel_build(sc, &a, stderr, err, sizeof err), IRIS_OK);
    struct mat_ctx *mc = NULL;
    if (with_mat)
        assert_int_equal(mat_ctx_create(sc, stderr, &mc), IRIS_OK);
    struct photon_map *m[2];
    struct photon_stats st[2];
    build_photon_map_pair(sc, a, mc, 11, no_cache, m, st);
    assert_true(st[0].tex_cached > 1000);
    assert_int_equal(st[1].tex_cached, 0);
    assert_int_equal(st[0].shot, st[1].shot);
    assert_int_equal(st[0].shot_global, st[1].shot_global);
    assert_same_photon_maps(m[0], m[1]);
    for (int k = 0; k < 2; k++)
        photon_map_destroy(m[k]);
    mat_ctx_destroy(mc);
    accel_destroy(a);
    iris_scene_destroy(sc);
}

static void test_ball(void **state)
{
    (void)state;
    same_map(BALL, false);
}

static void test_ball_material(void **state)
{
    (void)state;
    same_map(BALL, true);
}

static void test_mixed(void **state)
{
    (void)state;
    same_map(MIXED, false);
}

static void test_mixed_material(void **state)
{
    (void)state;
    same_map(MIXED, true);
}

static void test_global(void **state)
{
    (void)state;
    same_map(ROOM, false);
}

static void test_global_material(void **state)
{
    (void)state;
    same_map(ROOM, true);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ball),
        cmocka_unit_test(test_ball_material),
        cmocka_unit_test(test_mixed),
        cmocka_unit_test(test_mixed_material),
        cmocka_unit_test(test_global),
        cmocka_unit_test(test_global_material),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
