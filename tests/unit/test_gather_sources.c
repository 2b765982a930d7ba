/* SPDX-License-Identifier: MIT */
/*
** test_gather_sources.c: gather_scene_has_unlit_light()
** (src/render/gather_sources.c), the proof that lets the recursive final
** gather skip its deeper levels. Each scene below adds one kind of light
** that no light source emits, hidden where the walk must look for it
** (a layer, a texture_map entry, a CSG child, a mesh or blob texture, an
** interior texture, a light's looks_like); each must answer true, and
** the same scenes without it false. A false "no light" would drop light
** from the image; the render tests (tests/render/gather.sh) check that
** a skipped gather changes no pixel.
*/
#include "config.h"

#include <stdio.h>
#include <string.h>

#include "parse_util.h"
#include "render/gather_sources.h"

/* A lit room with radiosity, to which each case adds one thing. */
#define ROOM "global_settings { radiosity { } }\n" \
    "camera { location <0, 1, -3> look_at <0, 1, 0> }\n" \
    "light_source { <0, 2, 0> rgb 1 }\n" \
    "plane { y, 0 pigment { rgb 0.8 } finish { ambient 0.3 } }\n"

/* Parses ROOM with 'extra' after '#version ver;' and asks the walk, with
** ambient counting as the tracer decides (#version < 3.7). */
static bool unlit(const char *ver, const char *extra, bool media_seen)
{
    char sdl[2048];
    snprintf(sdl, sizeof sdl, "#version %s;\n%s%s\n", ver, ROOM, extra);
    iris_scene *sc = pt_scene_with(sdl, NULL);
    bool r = gather_scene_has_unlit_light(sc, sc->version < 3.7, media_seen);
    iris_scene_destroy(sc);
    return r;
}

/* Nothing glows: finish ambient is ignored by 3.7 radiosity. */
static void test_none(void **state)
{
    (void)state;
    assert_false(unlit("3.7", "", false));
    assert_false(unlit("3.7", "sphere { 0, 1 texture { pigment { rgb 1 } "
                       "finish { emission 0 ambient 1 } } }", false));
    /* media that gather rays do not see (radiosity{ media off }) */
    assert_false(unlit("3.7", "sphere { 0, 1 hollow pigment { rgbt 1 } "
                       "interior { media { emission 0.1 } } }", false));
}

/* Emission wherever a surface can show it. */
static void test_emission(void **state)
{
    (void)state;
    static const char *glow[] = {
        "sphere { 0, 1 finish { emission 0.5 } }",
        /* the lower layer of a layered texture */
        "sphere { 0, 1 texture { pigment { rgb 1 } } "
        "texture { pigment { rgbt 1 } finish { emission <0, 0, 0.2> } } }",
        /* an entry of a texture_map */
        "sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } "
        "texture { pigment { rgb 1 } finish { emission 1 } } } }",
        /* a CSG child */
        "union { sphere { 0, 1 } box { 2, 3 finish { emission 1 } } }",
        /* the back side only */
        "sphere { 0, 1 interior_texture { pigment { rgb 1 } "
        "finish { emission 1 } } }",
        /* one triangle's texture */
        "mesh { triangle { 0, x, y texture { pigment { rgb 1 } "
        "finish { emission 1 } } } }",
        /* a blob component's texture */
        "blob { threshold 0.5 sphere { 0, 1, 1 texture { pigment { rgb 1 } "
        "finish { emission 1 } } } }",
        /* a light's looks_like (kept on the light, not in the objects) */
        "light_source { <0, 3, 0> rgb 1 looks_like { sphere { 0, 0.1 "
        "finish { emission 1 } } } }",
    };
    for (size_t i = 0; i < sizeof glow / sizeof glow[0]; i++) {
        if (!unlit("3.7", glow[i], false))
            fail_msg("not found: %s", glow[i]);
    }
}

/* Pre-3.7 scenes count ambient under radiosity, unless ambient_light is
** black. */
static void test_legacy_ambient(void **state)
{
    (void)state;
    assert_true(unlit("3.6", "", false));
    assert_false(unlit("3.6", "global_settings { ambient_light 0 }", false));
}

/* What a ray adds without meeting a surface. */
static void test_air_and_sky(void **state)
{
    (void)state;
    assert_true(unlit("3.7", "background { rgb <0, 0, 0.1> }", false));
    assert_false(unlit("3.7", "background { rgb 0 }", false));
    assert_true(unlit("3.7", "sky_sphere { pigment { rgb 0 } }", false));
    assert_true(unlit("3.7", "fog { distance 10 rgb 0.5 }", false));
    assert_true(unlit("3.7", "rainbow { angle 42 width 5 distance 100 "
                      "direction <0, 0, 1> jitter 0 color_map { "
                      "[0 rgbt 1] [1 rgbt <1, 0, 0, 0.5>] } }", false));
    /* media count when gather rays see them (radiosity{ media on }) */
    assert_true(unlit("3.7", "media { emission 0.01 }", true));
    assert_false(unlit("3.7", "media { emission 0.01 }", false));
    assert_true(unlit("3.7", "sphere { 0, 1 hollow pigment { rgbt 1 } "
                      "interior { media { emission 0.1 } } }", true));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_none),
        cmocka_unit_test(test_emission),
        cmocka_unit_test(test_legacy_ambient),
        cmocka_unit_test(test_air_and_sky),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
