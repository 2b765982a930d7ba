/* SPDX-License-Identifier: MIT */
/*
** test_pfilter.c: photons through filtering surfaces that have no
** interior{} (src/photon/trace.c, the mirror branch), as in POV-Ray's
** advanced/optics.pov, whose colour-splitting mirrors are boxes with a
** 'filter 1' pigment and a coloured 'reflection' and no interior.
** POV-Ray gives every object a default interior (ior 1), so photons pass
** such a surface straight on, filtered; iris takes either the mirror
** reflection or that passage by Russian roulette on the spectral
** reflectivity and transmittance.
**
** Expectation: the spectral transmittance of the path, integrated
** against the rgb weights of the wavelengths (the photons' colour
** science, spectrum.h) by quadrature here.
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <string.h>

#include "photon/pmap.h"
#include "photon_world.h"
#include "spectrum/spectrum.h"

static const iris_colour WHITE = { 1, 1, 1, 0, 0 };

static struct tw_scene tw;

/* A parallel white light straight down through the plate y in [1, 1.1]
** of pigment 'col' and reflection colour 'refl', without an interior,
** onto the white floor; the floor's mean photon light. */
static void plate(iris_colour col, iris_colour refl, double out[3])
{
    tw_init(&tw, 0.02, 100);
    iris_light *l = tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    l->photon_reflection = IRIS_ON; /* as optics.pov's spotlight */
    iris_object *p = tw_box(&tw, v3(-1, 1, -1), v3(1, 1.1, 1), col, 0, 0);
    assert_null(p->interior);
    p->photon_target = true;
    p->photon_collect = false;
    iris_finish *f = p->texture->finish;
    f->reflection_max = f->reflection_min = refl;
    f->reflection_falloff = 1;
    tw_plane(&tw, v3(0, 1, 0), 0, WHITE, 1);
    struct pmap_world w = tw_world(&tw);
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = 2;
    o.seed = 7;
    struct photon_map *m = NULL;
    struct photon_stats st;
    assert_int_equal(pmap_build(&tw.scene, &w, &o, &m, &st), IRIS_OK);
    assert_non_null(m);
    tw_floor_mean(m, out);
    photon_map_destroy(m);
}

/* The rgb of white light (E = 1) after the spectral transmittance
** t(lambda) = q^2·(1 + p^2): q the filter's transmittance, p the
** mirror's reflectivity (Burns' curves of the rgb colours), each
** wavelength's rgb weight averaged over the spectrum (midpoint rule,
** 0.1 nm). */
static void expected(const double filt[3], const double mirror[3],
                     double out[3])
{
    const int steps = 4000;
    out[0] = out[1] = out[2] = 0;
    for (int i = 0; i < steps; i++) {
        double lambda = 380.0 + 400.0 * (i + 0.5) / steps, w[3];
        spec_lambda_rgb_weight(lambda, w);
        double q = spec_reflectance(filt, lambda);
        double p = spec_reflectance(mirror, lambda);
        for (int c = 0; c < 3; c++)
            out[c] += q * q * (1 + p * p) * w[c] / steps;
    }
}

/*
** White light of irradiance E = 1 straight down through the plate: the
** floor gets what crosses its top and bottom faces, filtered at each as
** POV-Ray filters (q^2), and with a mirror finish also what reflects off
** the bottom face, then off the top one from inside, and crosses the
** bottom face (q^2·p^2: photon max_trace_level 5 stops the next round).
** A yellow filter (rgb 1, 1, 0, filter 1) alone; the same with a blue
** mirror finish (optics.pov's BlueMirrorTex: it splits white into a
** yellow beam through and a blue one back); a grey 'transmit 0.4',
** 0.4^2 exactly. Tolerance 2% of the value + 0.005: the estimate's 2%
** (test_photon.c's slab test) and the colour noise of single-wavelength
** photons in a channel near 0.
*/
static void test_filter_plate(void **state)
{
    (void)state;
    const iris_colour none = { 0, 0, 0, 0, 0 };
    const iris_colour yellow = { 1, 1, 0, 1, 0 };
    const iris_colour blue = { 0, 0, 1, 0, 0 };
    const iris_colour grey = { 1, 1, 1, 0, 0.4 };
    const double y[3] = { 1, 1, 0 }, b[3] = { 0, 0, 1 }, z[3] = { 0, 0, 0 };
    double rgb[3], e[3];
    plate(yellow, none, rgb);
    expected(y, z, e);
    /* the yellow stays yellow: green and red pass, blue does not */
    assert_true(e[0] > 0.9 && e[1] > 0.9 && e[2] < 0.05);
    for (int c = 0; c < 3; c++)
        assert_near(rgb[c], e[c], 0.02 * fabs(e[c]) + 0.005);
    plate(yellow, blue, rgb);
    expected(y, b, e);
    for (int c = 0; c < 3; c++)
        assert_near(rgb[c], e[c], 0.02 * fabs(e[c]) + 0.005);
    plate(grey, none, rgb);
    for (int c = 0; c < 3; c++)
        assert_near(rgb[c], 0.16, 0.02 * 0.16);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_filter_plate),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
