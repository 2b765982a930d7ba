/* SPDX-License-Identifier: MIT */
/*
** test_srgb8.c: image/srgb8's recognition of texel values decoded from
** 8-bit data, on which the image shading's table lookups rest (pigment.c
** re-encodes texels by them instead of pow()). The property that matters
** is exactness: a recognised value's table answer is the computation's
** to the bit, and nothing else is recognised. The reference is the
** computation itself (iris_srgb_encode), and the texel values are those
** iris_image_read() makes of a PNG holding every 8-bit level, so the test
** fails if image_io.c's decoding and the table's ever part.
*/
#include "config.h"

#include "testutil.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "image/srgb8.h"
#include "iris/image.h"

static bool same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Every 8-bit level written to a PNG and read back: each texel is
** recognised as its level (libpng's scaling), and its encoding is
** iris_srgb_encode()'s to the bit, and within 1e-7 of level / 255 (the
** float rounding of the decoded value). */
static void test_png_levels(void **state)
{
    (void)state;
    char path[] = "/tmp/iris-srgb8-XXXXXX.png";
    int fd = mkstemps(path, 4);
    assert_true(fd >= 0);
    close(fd);
    iris_image img;
    assert_int_equal(iris_image_init(&img, 256, 1), IRIS_OK);
    for (int b = 0; b < 256; b++)
        for (int c = 0; c < 3; c++)
            img.pixels[b * 4 + c] = (float)iris_srgb_decode(b / 255.0);
    char err[256];
    assert_int_equal(iris_image_write(&img, path, 8, IRIS_ENC_SRGB, err,
                                      sizeof err), IRIS_OK);
    iris_image_fini(&img);
    iris_image back;
    assert_int_equal(iris_image_read(&back, path, err, sizeof err), IRIS_OK);
    remove(path);
    assert_int_equal(back.width, 256);
    for (int b = 0; b < 256; b++) {
        float v = back.pixels[b * 4];
        assert_int_equal(srgb8_index(v), b);
        assert_true(srgb8_value(b) == v);
        assert_true(same_bits(srgb8_encode(v), iris_srgb_encode(v)));
        assert_near(srgb8_encode(v), b / 255.0, 1e-7);
    }
    iris_image_fini(&back);
}

/* Both scalings of every level: recognised, and the table's encoding
** the computation's to the bit; their neighbouring floats (one ulp
** either side) are not recognised and still encode to the bit. */
static void test_all_values_exact(void **state)
{
    (void)state;
    for (int k = 0; k < SRGB8_N; k++) {
        float v = srgb8_value(k);
        int i = srgb8_index(v);
        assert_true(i >= 0);
        /* the two scalings may give the same float: either index */
        assert_true(srgb8_value(i) == v);
        assert_true(same_bits(srgb8_encode(v), iris_srgb_encode(v)));
        if (v > 0) {
            float nb[2] = { nextafterf(v, 0), nextafterf(v, 2) };
            for (int j = 0; j < 2; j++) {
                bool known = false;
                for (int m = 0; m < SRGB8_N; m++)
                    known |= srgb8_value(m) == nb[j];
                if (!known)
                    assert_int_equal(srgb8_index(nb[j]), -1);
                assert_true(same_bits(srgb8_encode(nb[j]),
                                      iris_srgb_encode(nb[j])));
            }
        }
    }
}

/* Any other value (16-bit and float data, out of range, NaN): not
** recognised, or recognised only when it equals a table value, and the
** encoding is always the computation's. 10^6 random floats over
** [-0.5, 1.5] and some special values. */
static void test_other_values(void **state)
{
    (void)state;
    uint64_t s = 0x9e3779b97f4a7c15u;
    int recognised = 0;
    for (int i = 0; i < 1000000; i++) {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        float v = (float)((double)(s >> 11) / 9007199254740992.0 * 2 - 0.5);
        int k = srgb8_index(v);
        if (k >= 0) {
            assert_true(srgb8_value(k) == v);
            recognised++;
        }
        assert_true(same_bits(srgb8_encode(v), iris_srgb_encode(v)));
    }
    /* a random float is almost never one of 512 values */
    assert_true(recognised < 10);
    const float special[] = { -0.0f, 1e-30f, 1e-4f, 1.0f, 2.0f, 1e30f,
                              INFINITY, -1.0f };
    for (size_t i = 0; i < sizeof special / sizeof special[0]; i++)
        assert_true(same_bits(srgb8_encode(special[i]),
                              iris_srgb_encode(special[i])));
    assert_int_equal(srgb8_index(NAN), -1);
    assert_int_equal(srgb8_index(-1.0f), -1);
    assert_int_equal(srgb8_index(2.0f), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_png_levels),
        cmocka_unit_test(test_all_values_exact),
        cmocka_unit_test(test_other_values),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
