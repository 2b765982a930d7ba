/* SPDX-License-Identifier: MIT */
/*
** image_roundtrip.c: image files written and read back through OpenImageIO.
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "iris/image.h"

static char dir[256];

static int setup(void **state)
{
    (void)state;
    snprintf(dir, sizeof dir, "/tmp/iris-img-XXXXXX");
    return mkdtemp(dir) ? 0 : -1;
}

static int teardown(void **state)
{
    (void)state;
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
    return system(cmd) == 0 ? 0 : -1;
}

/* The sRGB curve against the values in ../shared/data/srgb.md:
** encode(0.18) = 0.4613561295, decode(0.5) = 0.2140411405. */
static void test_srgb_curve(void **state)
{
    (void)state;
    assert_near(iris_srgb_encode(0.18), 0.4613561295, 1e-9);
    assert_near(iris_srgb_decode(0.5), 0.2140411405, 1e-9);
    for (int i = 0; i <= 1000; i++) {
        double v = i / 1000.0;
        assert_near(iris_srgb_encode(iris_srgb_decode(v)), v, 1e-7);
    }
    assert_near(iris_srgb_encode(-1.0), 0.0, 0);
}

/* EXR keeps linear 32-bit floats, including values far above half's
** 65504 limit; NaN and Inf are written as 0. */
static void test_exr_float(void **state)
{
    (void)state;
    iris_image a, b;
    assert_int_equal(iris_image_init(&a, 3, 2), IRIS_OK);
    a.pixels[0] = 0.25f;
    a.pixels[1] = 1e6f;
    a.pixels[2] = 3.5f;
    a.pixels[4] = (float)NAN;
    a.pixels[5] = (float)INFINITY;
    char path[300], err[256];
    snprintf(path, sizeof path, "%s/a.exr", dir);
    assert_int_equal(iris_image_write(&a, path, 0, IRIS_ENC_SRGB, err, sizeof err), IRIS_OK);
    assert_int_equal(iris_image_read(&b, path, err, sizeof err), IRIS_OK);
    assert_int_equal(b.width, 3);
    assert_int_equal(b.height, 2);
    assert_near(b.pixels[0], 0.25, 0);
    assert_near(b.pixels[1], 1e6, 0);
    assert_near(b.pixels[2], 3.5, 0);
    assert_near(b.pixels[4], 0, 0);
    assert_near(b.pixels[5], 0, 0);
    iris_image_fini(&a);
    iris_image_fini(&b);
}

/* PNG is 8-bit sRGB with POV-Ray's rounding: linear 0.35 -> 159.68 ->
** 160 (semantics §3.9); reading decodes back to linear within the 8-bit
** step (1/255 in sRGB is at most ~0.005 in linear near 1). */
static void test_png_srgb(void **state)
{
    (void)state;
    iris_image a, b;
    assert_int_equal(iris_image_init(&a, 2, 1), IRIS_OK);
    a.pixels[0] = 0.35f;
    a.pixels[1] = 2.0f;  /* clipped to 255 */
    a.pixels[2] = 0.0f;
    a.pixels[4] = 0.5f;
    char path[300], err[256];
    snprintf(path, sizeof path, "%s/a.png", dir);
    assert_int_equal(iris_image_write(&a, path, 8, IRIS_ENC_SRGB, err, sizeof err), IRIS_OK);
    assert_int_equal(iris_image_read(&b, path, err, sizeof err), IRIS_OK);
    assert_near(iris_srgb_encode(b.pixels[0]) * 255, 160, 1e-3);
    assert_near(iris_srgb_encode(b.pixels[1]) * 255, 255, 1e-3);
    assert_near(b.pixels[2], 0, 0);
    assert_near(b.pixels[4], 0.5, 0.005);
    iris_image_fini(&a);
    iris_image_fini(&b);
}

/* A failed write leaves no file and no temporary behind. */
static void test_write_errors(void **state)
{
    (void)state;
    iris_image a;
    assert_int_equal(iris_image_init(&a, 2, 2), IRIS_OK);
    char path[300], err[256] = "";
    snprintf(path, sizeof path, "%s/no/such/dir/a.png", dir);
    assert_int_not_equal(iris_image_write(&a, path, 8, IRIS_ENC_SRGB, err, sizeof err), IRIS_OK);
    assert_true(strlen(err) > 0);
    snprintf(path, sizeof path, "%s/noext", dir);
    assert_int_equal(iris_image_write(&a, path, 8, IRIS_ENC_SRGB, err, sizeof err), IRIS_EINVAL);
    assert_int_not_equal(access(path, F_OK), 0);
    iris_image b;
    assert_int_not_equal(iris_image_init(&b, 0, 5), IRIS_OK);
    iris_image_fini(&a);
}

/* +UA files (iris_image_write_alpha). Pixels hold premultiplied colour.
** PNG: straight alpha as POV-Ray writes it: (0.25 grey, a 0.5) reads back
** as grey 0.5 with alpha 0.5; a transparent pixel as 0; a pixel brighter
** than its alpha (0.9 grey, a 0.2) gets alpha 0.9 (its POV-Ray greyscale,
** weights 0.297 + 0.589 + 0.114 = 1) and colour 1. Tolerance: one 8-bit
** step, 1/255, of the alpha, and of the sRGB code of the colour (slope of
** the decoding <= 1.1 below 1: 1.2/255 in linear terms). EXR: the
** premultiplied floats and alpha, exactly. */
static void test_alpha_files(void **state)
{
    (void)state;
    iris_image a, b;
    assert_int_equal(iris_image_init(&a, 3, 1), IRIS_OK);
    const float px[3][4] = { { 0.25f, 0.25f, 0.25f, 0.5f },
                             { 0, 0, 0, 0 },
                             { 0.9f, 0.9f, 0.9f, 0.2f } };
    memcpy(a.pixels, px, sizeof px);
    char path[300], err[256];
    snprintf(path, sizeof path, "%s/alpha.png", dir);
    assert_int_equal(iris_image_write_alpha(&a, path, 8, IRIS_ENC_SRGB, true,
                                            err, sizeof err), IRIS_OK);
    assert_int_equal(iris_image_read(&b, path, err, sizeof err), IRIS_OK);
    const double want[3][4] = { { 0.5, 0.5, 0.5, 0.5 }, { 0, 0, 0, 0 },
                                { 1, 1, 1, 0.9 } };
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++)
            assert_near(b.pixels[i * 4 + k], want[i][k], 1.2 / 255);
    iris_image_fini(&b);
    snprintf(path, sizeof path, "%s/alpha.exr", dir);
    assert_int_equal(iris_image_write_alpha(&a, path, 0, IRIS_ENC_SRGB, true,
                                            err, sizeof err), IRIS_OK);
    assert_int_equal(iris_image_read(&b, path, err, sizeof err), IRIS_OK);
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 4; k++)
            assert_near(b.pixels[i * 4 + k], px[i][k], 0);
    iris_image_fini(&b);
    iris_image_fini(&a);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_srgb_curve),
        cmocka_unit_test(test_exr_float),
        cmocka_unit_test(test_png_srgb),
        cmocka_unit_test(test_write_errors),
        cmocka_unit_test(test_alpha_files),
    };
    return cmocka_run_group_tests_name("image files", tests, setup, teardown);
}
