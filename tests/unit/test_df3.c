/* SPDX-License-Identifier: MIT */
/*
** test_df3.c: .df3 density files and the density_file pattern
** (src/image/df3.c) against POV-Ray 3.7.0.10's own values.
**
** Every row was printed by POV-Ray from
**
**   #declare R = seed(5);
**   #declare F<I> = function { pigment { density_file df3
**       "maps/ring16.df3" interpolate <I> color_map { [0 rgb 0] [1 rgb 1] } } }
**   #debug concat(str(X,0,12), ", ", str(Y,0,12), ", ", str(Z,0,12), ", ",
**                 str(F<I>(X, Y, Z).red,0,12))
**
** for interpolate 0, 1 and 2, six points each, X, Y, Z drawn by rand(R)
** (the first point of each moved to x 0.03, z 0.1, next to the near faces
** where the tricubic's index wrap matters). ring16.df3 is the 16-bit 6 x
** 5 x 3 file of tests/render/scenes/maps/mkdf3.py. The colour map from
** black to white returns the density itself in a single-precision colour
** channel (error below 1.2e-7; the tricubic runs in float too), so the
** tolerance is 1e-6. tests/render/scenes/113_density_file.pov compares
** whole images.
*/
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "testutil.h"

#include "image/df3.h"

#define POV_TOL 1e-6

struct df3_ref {
    int interpolate;
    double x, y, z, value;
};

static const struct df3_ref refs[] = {
    {0, 0.030000000000, 0.569351252999, 0.100000000000, 0.064209967852},
    {0, 0.015155356614, 0.281391564356, 0.234645291985, 0.931609034538},
    {0, 0.753944431607, 0.440797723234, 0.249775479140, 0.499641418457},
    {0, 0.072258460119, 0.900534052611, 0.031835424023, 0.927305996418},
    {0, 0.108684630624, 0.587421422728, 0.829281347997, 0.599008142948},
    {0, 0.852216852329, 0.568066366615, 0.523817756102, 0.964431226254},
    {1, 0.030000000000, 0.316617481717, 0.100000000000, 0.412298083305},
    {1, 0.581540491335, 0.215243400125, 0.783884692421, 0.401472449303},
    {1, 0.730991846586, 0.116493969019, 0.174262031953, 0.412657141685},
    {1, 0.374115405924, 0.998705951264, 0.618116008029, 0.433650106192},
    {1, 0.902322455519, 0.931241536031, 0.084955040851, 0.491277903318},
    {1, 0.012295384661, 0.013495324183, 0.302998248791, 0.528332352638},
    {2, 0.030000000000, 0.086359627332, 0.100000000000, 0.724799156189},
    {2, 0.360150038581, 0.842142763278, 0.583008120671, 0.846680283546},
    {2, 0.426563095401, 0.426849613298, 0.992077195782, 0.709598898888},
    {2, 0.760065523852, 0.566908906346, 0.044004594219, 0.523363709450},
    {2, 0.828572393122, 0.462930501314, 0.213435972159, 0.814895510674},
    {2, 0.237527028014, 0.959162525590, 0.006594765700, 0.809669196606},
};

static void test_df3_matches_povray(void **state)
{
    (void)state;
    const char *top = getenv("top_srcdir");
    char path[1024];
    snprintf(path, sizeof path, "%s/tests/render/scenes/maps/ring16.df3",
             top ? top : "..");
    iris_df3 d;
    char err[256];
    if (iris_df3_read(path, &d, err, sizeof err) != IRIS_OK)
        fail_msg("%s (set top_srcdir)", err);
    assert_int_equal(d.nx, 6);
    assert_int_equal(d.ny, 5);
    assert_int_equal(d.nz, 3);
    for (size_t i = 0; i < sizeof refs / sizeof refs[0]; i++)
        assert_near(iris_df3_density(&d, refs[i].interpolate, refs[i].x,
                                     refs[i].y, refs[i].z),
                    refs[i].value, POV_TOL);
    /* outside the unit cube, and the cube's far faces, read 0 */
    assert_near(iris_df3_density(&d, 1, -0.01, 0.5, 0.5), 0.0, 0.0);
    assert_near(iris_df3_density(&d, 2, 0.5, 1.0, 0.5), 0.0, 0.0);
    assert_near(iris_df3_density(&d, 0, 0.5, 0.5, NAN), 0.0, 0.0);
    iris_df3_fini(&d);
}

/* Writes 'n' bytes after a header of nx, ny, nz into a temporary file. */
static void write_df3(const char *path, int nx, int ny, int nz,
                      const unsigned char *v, size_t n)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    const unsigned char h[6] = { nx >> 8, nx & 255, ny >> 8, ny & 255,
                                 nz >> 8, nz & 255 };
    assert_int_equal(fwrite(h, 1, 6, f), 6);
    if (n)
        assert_int_equal(fwrite(v, 1, n, f), n);
    fclose(f);
}

/* The voxel size follows from the length (1, 2 or 4 bytes, big-endian);
** any other length, a short header or a missing file is an error with
** a message, never a crash. */
static void test_df3_sizes_and_bad_files(void **state)
{
    (void)state;
    char path[] = "/tmp/iris-df3-XXXXXX";
    int fd = mkstemp(path);
    assert_true(fd >= 0);
    close(fd);
    const unsigned char v[8] = { 0, 255, 0x80, 0x00, 0xff, 0xff, 1, 2 };
    iris_df3 d;
    char err[256];
    int nx, ny, nz, bytes;
    /* 2 x 1 x 1 of 4 bytes: 0x00ff8000 and 0xffff0102 over 2^32 - 1 */
    write_df3(path, 2, 1, 1, v, 8);
    assert_int_equal(iris_df3_check(path, &nx, &ny, &nz, &bytes, err,
                                    sizeof err), IRIS_OK);
    assert_int_equal(bytes, 4);
    assert_int_equal(iris_df3_read(path, &d, err, sizeof err), IRIS_OK);
    assert_near(iris_df3_density(&d, 0, 0.25, 0.5, 0.5),
                16744448.0 / 4294967295.0, 1e-7);
    assert_near(iris_df3_density(&d, 0, 0.75, 0.5, 0.5),
                4294902018.0 / 4294967295.0, 1e-7);
    iris_df3_fini(&d);
    /* 4 x 1 x 1 of 2 bytes: 0x00ff, 0x8000 (x 0.3: voxel 1), ... */
    write_df3(path, 4, 1, 1, v, 8);
    assert_int_equal(iris_df3_read(path, &d, err, sizeof err), IRIS_OK);
    assert_near(iris_df3_density(&d, 0, 0.3, 0.5, 0.5), 32768.0 / 65535.0,
                1e-7);
    iris_df3_fini(&d);
    /* 8 x 1 x 1 of 1 byte: x 0.3 falls in voxel 2 (0x80) */
    write_df3(path, 8, 1, 1, v, 8);
    assert_int_equal(iris_df3_read(path, &d, err, sizeof err), IRIS_OK);
    assert_near(iris_df3_density(&d, 0, 0.3, 0.5, 0.5), 128.0 / 255.0,
                1e-7);
    iris_df3_fini(&d);
    /* 3 x 1 x 1 with 8 bytes: no voxel size fits */
    write_df3(path, 3, 1, 1, v, 8);
    assert_int_equal(iris_df3_read(path, &d, err, sizeof err), IRIS_EINVAL);
    assert_non_null(strstr(err, "invalid density file size"));
    /* a truncated header */
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(v, 1, 3, f), 3);
    fclose(f);
    assert_int_equal(iris_df3_check(path, &nx, &ny, &nz, &bytes, err,
                                    sizeof err), IRIS_EINVAL);
    assert_non_null(strstr(err, "truncated"));
    unlink(path);
    assert_int_equal(iris_df3_read(path, &d, err, sizeof err), IRIS_EIO);
    assert_null(d.v);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_df3_matches_povray),
        cmocka_unit_test(test_df3_sizes_and_bad_files),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
