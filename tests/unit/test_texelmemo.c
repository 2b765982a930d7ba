/* SPDX-License-Identifier: MIT */
/*
** test_texelmemo.c: pigment.c's converted-texel memo gives the colours
** the conversion gives, and forgets them with their images.
**
** An image map in a scene with assumed_gamma 2.2 hands each texel to the
** shading as (its sRGB-decoded value)^(1/2.2) (POV-Ray 3.7; semantics
** §3.9). The expectations below compute that from the bytes written
** with the sRGB formula itself, not through iris's tables. The texels
** are read as floats (the decoded 8-bit value rounded to float), so the
** result can differ from the double formula by the float's rounding,
** 2^-24 relative, raised to 1/2.2: 1e-6 relative is a wide margin for
** that and fails for any other byte (neighbouring bytes differ by > 4e-3
** relative).
**
** The memo is keyed by the texel's address. A context destroyed and a
** new one made with another image of the same size usually gets the
** same block back from malloc: the test then checks that the new colours,
** not the remembered old ones, come out (mat_ctx_destroy forgets them).
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "testutil.h"

#include "iris/image.h"
#include "material/mat_internal.h"
#include "material/material.h"
#include "parse_util.h"

#define PNG_PATH "texelmemo_test.png"
#define REL_TOL 1e-6

/* The sRGB decoding of byte 'b' (IEC 61966-2-1), in double. */
static double srgb_byte(int b)
{
    double v = b / 255.0;
    return v <= 0.04045 ? v / 12.92 : pow((v + 0.055) / 1.055, 2.4);
}

/* Writes a 2 x 1 PNG whose texels hold the grey bytes b0, b1 (alpha 1). */
static void write_png(int b0, int b1)
{
    iris_image img;
    assert_int_equal(iris_image_init(&img, 2, 1), IRIS_OK);
    const int b[2] = { b0, b1 };
    for (int i = 0; i < 2; i++) {
        for (int k = 0; k < 3; k++)
            img.pixels[4 * i + k] = (float)srgb_byte(b[i]);
        img.pixels[4 * i + 3] = 1.0f;
    }
    char err[256];
    assert_int_equal(iris_image_write(&img, PNG_PATH, 8, IRIS_ENC_SRGB, err,
                                      sizeof err),
                     IRIS_OK);
    iris_image_fini(&img);
}

/* An image map over the unit square of the plane z = 0 (planar mapping:
** texel i covers x in [i/2, (i+1)/2)), interpolated or not. */
static iris_scene *image_scene(bool interpolate)
{
    char sdl[512];
    snprintf(sdl, sizeof sdl,
             "#version 3.7;\n"
             "global_settings { assumed_gamma 2.2 }\n"
             "plane { z, 0 pigment { image_map { png \"%s\"%s } } }\n",
             PNG_PATH, interpolate ? " interpolate 2" : "");
    return pt_scene_with(sdl, NULL);
}

/* The pigment's red at world point (x, y, 0). */
static double red_at(const struct mat_ctx *ctx, const iris_scene *sc,
                     double x, double y)
{
    const iris_object *o = sc->objects[0];
    struct mat_point pt = { v3(x, y, 0), v3(0, 0, -1), v3(0, 0, 1),
                            { 0, 0 }, o, false };
    iris_colour c;
    assert_true(mat_eval_pigment(ctx, o->texture->pigment, &pt, &c));
    assert_true(c.r == c.g && c.g == c.b);
    return c.r;
}

/* Both texels' centres, in turn and again, against the expectation; the
** repeats (answered by the memo) equal the first evaluation to the bit. */
static void check_texels(const iris_scene *sc, int b0, int b1)
{
    struct mat_ctx *ctx = NULL;
    assert_int_equal(mat_ctx_create(sc, stderr, &ctx), IRIS_OK);
    const double x[2] = { 0.25, 0.75 };
    const int b[2] = { b0, b1 };
    double first[2];
    for (int round = 0; round < 3; round++)
        for (int i = 0; i < 2; i++) {
            double v = red_at(ctx, sc, x[i], 0.5);
            if (round == 0) {
                first[i] = v;
                double want = pow(srgb_byte(b[i]), 1 / 2.2);
                assert_true(fabs(v - want) <= REL_TOL * want);
            } else {
                assert_memory_equal(&v, &first[i], sizeof v);
            }
        }
    mat_ctx_destroy(ctx);
}

static void memo_same_values(void **state)
{
    (void)state;
    write_png(64, 200);
    iris_scene *sc = image_scene(false);
    check_texels(sc, 64, 200);
    iris_scene_destroy(sc);
    sc = image_scene(true);   /* the bilinear path: four texels a lookup */
    check_texels(sc, 64, 200);
    iris_scene_destroy(sc);
    remove(PNG_PATH);
}

/* The texels' address in a context made for 'sc' (to report reuse). */
static const float *pixels_of(const iris_scene *sc)
{
    struct mat_ctx *ctx = NULL;
    assert_int_equal(mat_ctx_create(sc, stderr, &ctx), IRIS_OK);
    const iris_pigment *pg = sc->objects[0]->texture->pigment;
    const iris_image *img = mat_find_image(ctx, pg->pattern.image);
    assert_non_null(img);
    const float *px = img->pixels;
    mat_ctx_destroy(ctx);
    return px;
}

static void memo_forgets_destroyed_images(void **state)
{
    (void)state;
    write_png(64, 200);
    iris_scene *sc = image_scene(false);
    const float *before = pixels_of(sc);
    check_texels(sc, 64, 200);
    iris_scene_destroy(sc);
    /* the same file name and size, other bytes */
    write_png(128, 30);
    sc = image_scene(false);
    const float *after = pixels_of(sc);
    printf("# the new context's texels are at %s address\n",
           before == after ? "the same" : "another");
    check_texels(sc, 128, 30);
    iris_scene_destroy(sc);
    remove(PNG_PATH);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(memo_same_values),
        cmocka_unit_test(memo_forgets_destroyed_images),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
