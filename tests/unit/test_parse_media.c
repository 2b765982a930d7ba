/* SPDX-License-Identifier: MIT */
/*
** test_parse_media.c: the media{} grammar (povparse/media.c) against
** POV-Ray 3.7's Parse_Media: the defaults of #version 3.5 and later and
** of older scenes, every item, identifiers, several media per interior,
** atmospheric media, densities as patterns with their transforms (the
** media's own and the object's), and POV-Ray's fatal errors reported
** with their line and column.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "parse_util.h"

static const iris_media *first_media(const iris_scene *sc)
{
    assert_true(sc->n_objects >= 1);
    const iris_interior *in = sc->objects[0]->interior;
    assert_non_null(in);
    assert_true(in->n_media >= 1);
    assert_true(in->has_media);
    return in->media[0];
}

/* POV-Ray 3.5+ defaults: method 3, 1 interval, samples 10,10; before
** 3.5 the Media constructor's: method 1, 10 intervals, 1 sample. */
static void test_media_defaults(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        "sphere { 0, 1 hollow interior { media { } } }", NULL);
    const iris_media *m = first_media(sc);
    assert_int_equal(m->method, 3);
    assert_int_equal(m->intervals, 1);
    assert_int_equal(m->min_samples, 10);
    assert_int_equal(m->max_samples, 10);
    assert_near(m->confidence, 0.9, 0);
    assert_near(m->variance, 1.0 / 128, 0);
    assert_near(m->ratio, 0.9, 0);
    assert_near(m->aa_threshold, 0.1, 0);
    assert_int_equal(m->aa_level, 3);
    assert_int_equal(m->scattering_type, IRIS_SCATTER_ISOTROPIC);
    assert_near(m->sc_ext, 1.0, 0);
    assert_int_equal(m->n_densities, 0);
    iris_scene_destroy(sc);

    sc = pt_scene_with("#version 3.1;\n"
                       "sphere { 0, 1 hollow interior { media { } } }", NULL);
    m = first_media(sc);
    assert_int_equal(m->method, 1);
    assert_int_equal(m->intervals, 10);
    assert_int_equal(m->min_samples, 1);
    assert_int_equal(m->max_samples, 1);
    iris_scene_destroy(sc);
}

/* Every item, a declared media reused and changed, two media in one
** interior and two atmospheric media. */
static void test_media_items(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        "#declare M = media { method 2 intervals 4 samples 3, 7\n"
        "  confidence 0.5 variance 0.01 ratio 0.7 jitter 0.25\n"
        "  aa_level 5 aa_threshold 0.2 collect off\n"
        "  absorption rgb <0.1, 0.2, 0.3> emission 0.5\n"
        "  scattering { 5, rgb 0.4 eccentricity -0.3 extinction 0.25 } }\n"
        "box { -1, 1 hollow interior { media { M samples 2 }\n"
        "  media { emission 1 density { spherical } density { rgb 0.5 } } } }\n"
        "media { absorption 0.01 }\n"
        "media { M }\n", NULL);
    const iris_interior *in = sc->objects[0]->interior;
    assert_int_equal(in->n_media, 2);
    const iris_media *m = in->media[0];
    assert_int_equal(m->method, 2);
    assert_int_equal(m->intervals, 4);
    assert_int_equal(m->min_samples, 2);
    assert_int_equal(m->max_samples, 2);
    assert_near(m->confidence, 0.5, 0);
    assert_near(m->variance, 0.01, 0);
    assert_near(m->ratio, 0.7, 0);
    assert_near(m->jitter, 0.25, 0);
    assert_int_equal(m->aa_level, 5);
    assert_near(m->aa_threshold, 0.2, 0);
    assert_true(m->ignore_photons);
    assert_near(m->absorption.g, 0.2, 1e-12);
    assert_near(m->emission.b, 0.5, 1e-12);
    assert_int_equal(m->scattering_type, IRIS_SCATTER_HENYEY_GREENSTEIN);
    assert_near(m->scattering.r, 0.4, 1e-12);
    assert_near(m->eccentricity, -0.3, 1e-12);
    assert_near(m->sc_ext, 0.25, 1e-12);
    const iris_media *m2 = in->media[1];
    assert_int_equal(m2->n_densities, 2);
    assert_int_equal(m2->densities[0]->pattern.kind, IRIS_PAT_SPHERICAL);
    assert_int_equal(m2->densities[1]->pattern.kind, IRIS_PAT_NONE);
    assert_near(m2->densities[1]->colour.r, 0.5, 1e-12);
    assert_int_equal(sc->n_media, 2);
    assert_near(sc->media[0]->absorption.r, 0.01, 1e-12);
    assert_int_equal(sc->media[1]->method, 2);
    iris_scene_destroy(sc);
}

/* World-to-pattern of a density: the media's own transforms move the
** densities written before them only, and the object's transforms after
** the interior move them all (POV-Ray's Transform_Density and
** Interior::Transform). A density identifier and a density_map with
** density entries parse too. */
static void test_media_density_transforms(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        "#declare D = density { boxed scale 2 }\n"
        "sphere { 0, 1 hollow interior { media {\n"
        "  density { spherical } translate x\n"
        "  density { D }\n"
        "  density { gradient y density_map { [0 rgb 0] [1 bozo] } } } }\n"
        "  translate <0, 3, 0> }\n", NULL);
    const iris_media *m = first_media(sc);
    assert_int_equal(m->n_densities, 3);
    /* spherical: translate x, then the object's translate 3y */
    const iris_transform *t0 = &m->densities[0]->pattern.transform;
    assert_near(t0->inv[0][3], -1.0, 1e-12);
    assert_near(t0->inv[1][3], -3.0, 1e-12);
    /* boxed: scale 2 from the identifier, then translate 3y only */
    const iris_transform *t1 = &m->densities[1]->pattern.transform;
    assert_int_equal(m->densities[1]->pattern.kind, IRIS_PAT_BOXED);
    assert_near(t1->inv[0][0], 0.5, 1e-12);
    assert_near(t1->inv[0][3], 0.0, 1e-12);
    assert_near(t1->inv[1][3], -1.5, 1e-12);
    const iris_pigment *d2 = m->densities[2];
    assert_int_equal(d2->n_entries, 2);
    assert_true(d2->is_pigment_map);
    assert_int_equal(d2->entries[1].pigment->pattern.kind, IRIS_PAT_BOZO);
    iris_scene_destroy(sc);
}

/* Parses 'sdl', which must fail; checks the first error's line, column
** and that its message holds 'what'. */
static void expect_error(const char *sdl, unsigned line, unsigned col,
                         const char *what)
{
    iris_scene *sc = NULL;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = iris_parse_string("t.pov", sdl, strlen(sdl), NULL,
                                            &sc, &d);
    assert_int_not_equal(st, IRIS_OK);
    assert_null(sc);
    const iris_diag *e = NULL;
    for (int i = 0; i < d.n && !e; i++)
        if (d.items[i].sev == IRIS_SEV_ERROR)
            e = &d.items[i];
    assert_non_null(e);
    if (e->line != line || e->col != col || !strstr(e->message, what))
        fail_msg("got %u:%u '%s', want %u:%u '%s'", e->line, e->col,
                 e->message, line, col, what);
    iris_diag_list_fini(&d);
}

/* POV-Ray's fatal errors in media, located at the offending keyword. */
static void test_media_errors(void **state)
{
    (void)state;
    expect_error("media {\n  method 4 }", 2, 3, "method must be 1, 2 or 3");
    expect_error("media { intervals 0 }", 1, 9, "at least one interval");
    expect_error("media { samples 5, 2 }", 1, 9, "smaller than the minimum");
    expect_error("media { samples 0 }", 1, 9, "at least one sample");
    expect_error("media { confidence 1 }", 1, 9, "confidence");
    expect_error("media { aa_threshold 0 }", 1, 9, "aa_threshold");
    expect_error("media { aa_level 0 }", 1, 9, "aa_level");
    expect_error("media { scattering { 1, 0.1 eccentricity 0.5 } }", 1, 29,
                 "eccentricity needs scattering type 5");
    expect_error("media { scattering { 5, 0.1 eccentricity 1 } }", 1, 29,
                 "strictly between");
    expect_error("media { fade_power 2 }", 1, 9, "media");
    /* a density_map belongs in a density, not in a pigment */
    expect_error("sphere { 0, 1 pigment { bozo density_map { [0 rgb 0] } } }",
                 1, 30, "pigment");
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_media_defaults),
        cmocka_unit_test(test_media_items),
        cmocka_unit_test(test_media_density_transforms),
        cmocka_unit_test(test_media_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
