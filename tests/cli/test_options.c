/* SPDX-License-Identifier: MIT */
/*
** test_options.c: the command line as POV-Ray users and GNU users type it.
*/
#include "config.h"

#include "testutil.h"

#include <stdlib.h>
#include <string.h>

#include "cli/options.h"

static int parse(struct cli_options *o, char *err, int argc, ...)
{
    static char buf[16][128];
    char *argv[17];
    va_list ap;
    va_start(ap, argc);
    argv[0] = (char *)"iris";
    for (int i = 0; i < argc; i++) {
        snprintf(buf[i], sizeof buf[i], "%s", va_arg(ap, const char *));
        argv[i + 1] = buf[i];
    }
    va_end(ap);
    return cli_parse(argc + 1, argv, o, err, 256);
}

/* POV-Ray switches set what POV-Ray sets, case-insensitively. */
static void test_pov_switches(void **state)
{
    (void)state;
    struct cli_options o;
    char err[256];
    assert_int_equal(parse(&o, err, 9, "+Iball.pov", "+Oout.exr", "+w320",
                           "+H200", "+A0.1", "+AM2", "+R4", "-J", "+WT3"), 0);
    assert_string_equal(o.scene, "ball.pov");
    assert_string_equal(o.output, "out.exr");
    assert_int_equal(o.render.width, 320);
    assert_int_equal(o.render.height, 200);
    assert_int_equal(o.render.aa, IRIS_AA_POV2);
    assert_near(o.render.aa_threshold, 0.1, 0);
    assert_int_equal(o.render.aa_depth, 4);
    assert_false(o.render.jitter);
    assert_int_equal(o.render.threads, 3);

    /* +A alone: method 1 at POV-Ray's default threshold 0.3; -A: off */
    assert_int_equal(parse(&o, err, 2, "s.pov", "+A"), 0);
    assert_int_equal(o.render.aa, IRIS_AA_POV1);
    assert_near(o.render.aa_threshold, 0.3, 0);
    assert_int_equal(parse(&o, err, 3, "s.pov", "+A", "-A"), 0);
    assert_int_equal(o.render.aa, IRIS_AA_NONE);

    /* +Q10 and +Q11 clip to 9 as in POV-Ray; display switches accepted */
    assert_int_equal(parse(&o, err, 5, "s.pov", "+Q11", "-D", "+V", "+L/inc"), 0);
    assert_int_equal(o.render.quality, 9);
    assert_true(o.verbose);
    assert_int_equal(o.n_include_paths, 1);
    assert_string_equal(o.include_paths[0], "/inc");

    /* +UA: output alpha, off by default, case-insensitive, -UA undoes */
    assert_int_equal(parse(&o, err, 1, "s.pov"), 0);
    assert_false(o.render.alpha);
    assert_int_equal(parse(&o, err, 2, "s.pov", "+ua"), 0);
    assert_true(o.render.alpha);
    assert_int_equal(parse(&o, err, 3, "s.pov", "+UA", "-UA"), 0);
    assert_false(o.render.alpha);

    assert_int_equal(parse(&o, err, 2, "s.pov", "Declare=Size=2.5"), 0);
    assert_int_equal(o.n_declares, 1);
    assert_string_equal(o.declares[0].name, "Size");
    assert_string_equal(o.declares[0].value, "2.5");
}

static void test_long_options(void **state)
{
    (void)state;
    struct cli_options o;
    char err[256];
    assert_int_equal(parse(&o, err, 8, "--output=a.png", "--width", "64",
                           "--height=48", "--threads=2", "--seed=99",
                           "--stats=s.json", "x.pov"), 0);
    assert_string_equal(o.output, "a.png");
    assert_int_equal(o.render.width, 64);
    assert_int_equal(o.render.height, 48);
    assert_int_equal(o.render.threads, 2);
    assert_int_equal(o.render.seed, 99);
    assert_string_equal(o.stats_file, "s.json");
    assert_int_equal(parse(&o, err, 1, "--version"), 0);
    assert_int_equal(o.action, CLI_VERSION);
    assert_int_equal(parse(&o, err, 2, "--parse-only", "x.pov"), 0);
    assert_int_equal(o.action, CLI_PARSE_ONLY);
}

/* Bad usage is reported, never guessed at. */
static void test_bad_usage(void **state)
{
    (void)state;
    struct cli_options o;
    char err[256];
    assert_int_equal(parse(&o, err, 2, "s.pov", "+Zfoo"), -1);
    assert_non_null(strstr(err, "+Zfoo"));
    assert_int_equal(parse(&o, err, 2, "s.pov", "--frobnicate"), -1);
    assert_int_equal(parse(&o, err, 2, "s.pov", "+W0"), -1);
    assert_int_equal(parse(&o, err, 2, "s.pov", "+Wabc"), -1);
    assert_int_equal(parse(&o, err, 2, "s.pov", "--width=-5"), -1);
    assert_int_equal(parse(&o, err, 2, "s.pov", "--seed=-1"), -1);
    assert_int_equal(parse(&o, err, 2, "s.pov", "Declare=X"), -1);
    assert_int_equal(parse(&o, err, 2, "a.pov", "b.pov"), -1);
    assert_int_equal(parse(&o, err, 1, "+W100"), -1); /* no scene */
    assert_int_equal(parse(&o, err, 2, "s.pov", "--output"), -1);
}

/* Output names follow POV-Ray: scene base name + .png, +FE gives .exr,
** and a name without extension gets one. */
/* Options that contradict each other or the image (options.c
** check_combination): a checkpoint only a progressive render writes; a
** render window starting past the image or after its end. Legal
** neighbours of each pass. */
static void test_conflicts(void **state)
{
    (void)state;
    struct cli_options o;
    char err[256];
    assert_int_equal(parse(&o, err, 2, "s.pov", "--checkpoint=c"), -1);
    assert_non_null(strstr(err, "only a progressive render"));
    assert_int_equal(parse(&o, err, 3, "s.pov", "--checkpoint=c",
                           "--passes=1"), -1);
    assert_int_equal(parse(&o, err, 3, "s.pov", "--checkpoint=c",
                           "--passes=2"), 0);
    assert_int_equal(parse(&o, err, 3, "s.pov", "--checkpoint=c",
                           "--time-limit=5"), 0);
    assert_int_equal(parse(&o, err, 3, "s.pov", "--checkpoint=c",
                           "--resume=c"), 0);
    /* rows and columns are 1-based: +SR8 is the last row of +H8 */
    assert_int_equal(parse(&o, err, 4, "s.pov", "+W8", "+H8", "+SR8"), 0);
    assert_int_equal(parse(&o, err, 4, "s.pov", "+W8", "+H8", "+SR9"), -1);
    assert_string_equal(err, "+SR9: the image has 8 rows (+H8)");
    assert_int_equal(parse(&o, err, 4, "s.pov", "+SC9", "+W8", "+H8"), -1);
    assert_string_equal(err, "+SC9: the image has 8 columns (+W8)");
    assert_int_equal(parse(&o, err, 4, "s.pov", "+H8", "+SR5", "+ER5"), 0);
    assert_int_equal(parse(&o, err, 4, "s.pov", "+H8", "+SR6", "+ER5"), -1);
    assert_int_equal(parse(&o, err, 4, "s.pov", "+W8", "+SC3", "+EC2"), -1);
    /* +ER past the image is an error, as in POV-Ray 3.7 ("Invalid end
    ** column or row") */
    assert_int_equal(parse(&o, err, 4, "s.pov", "+H8", "+SR2", "+ER100"), -1);
    assert_string_equal(err, "+ER100: the image has 8 rows (+H8)");
    /* fractions of the image (tests/cli/window.sh renders them against
    ** POV-Ray): +SR0.5 of 8 rows is row (int)(8 * 0.5) + 1 = 5, +ER0.75
    ** ends at (int)(8 * 0.75) = 6, +EC1 at the last column, whichever
    ** order +W/+H come in */
    assert_int_equal(parse(&o, err, 6, "s.pov", "+SR0.5", "+ER0.75", "+EC1",
                           "+W8", "+H8"), 0);
    assert_int_equal(o.render.start_row, 5);
    assert_int_equal(o.render.end_row, 6);
    assert_int_equal(o.render.end_col, 8);
    assert_int_equal(o.render.start_col, 0);
    /* -o with an empty name */
    assert_int_equal(parse(&o, err, 3, "s.pov", "-o", ""), -1);
    assert_string_equal(err, "-o needs a file name");
}

static void test_output_name(void **state)
{
    (void)state;
    struct cli_options o;
    char err[256];
    assert_int_equal(parse(&o, err, 1, "dir/glass.ball.pov"), 0);
    char *n = cli_output_name(&o);
    assert_string_equal(n, "glass.ball.png");
    free(n);
    assert_int_equal(parse(&o, err, 2, "scene.pov", "+FE"), 0);
    n = cli_output_name(&o);
    assert_string_equal(n, "scene.exr");
    free(n);
    assert_int_equal(parse(&o, err, 2, "scene.pov", "+Oout/pic"), 0);
    n = cli_output_name(&o);
    assert_string_equal(n, "out/pic.png");
    free(n);
    assert_int_equal(parse(&o, err, 2, "scene.pov", "-ofinal.tif"), 0);
    n = cli_output_name(&o);
    assert_string_equal(n, "final.tif");
    free(n);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pov_switches),
        cmocka_unit_test(test_long_options),
        cmocka_unit_test(test_bad_usage),
        cmocka_unit_test(test_conflicts),
        cmocka_unit_test(test_output_name),
    };
    return cmocka_run_group_tests_name("cli options", tests, NULL, NULL);
}
