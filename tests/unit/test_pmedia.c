/* SPDX-License-Identifier: MIT */
/*
** test_pmedia.c: photons in participating media (src/photon/pmedia.c)
** against closed forms: Beer-Lambert extinction of the photons crossing a
** medium, at each photon's wavelength, and the single-scattering radiance
** of a parallel beam in a homogeneous medium estimated from the media
** photons.
**
** The transport runs against the analytic test double of photon_world.c,
** so the path lengths are exact: a parallel light straight down through a
** box (the photon target, ior 1 so that nothing bends or reflects) holding
** the medium, onto a white floor.
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "photon/pmap.h"
#include "photon/pmedia.h"
#include "photon/trace.h"
#include "photon_world.h"
#include "render/plan.h"
#include "spectrum/spectrum.h"

static const iris_colour WHITE = { 1, 1, 1, 0, 0 };
static const iris_colour CLEAR = { 1, 1, 1, 0, 1 };

static struct tw_scene tw;
static iris_media med;
static iris_media *med_list[1];
static iris_pigment dens;
static iris_pigment *dens_list[1];

/* A medium with POV-Ray's defaults (#version 3.7) and these coefficients. */
static iris_media *medium(iris_colour absorption, iris_colour scattering,
                         int type, double g)
{
    iris_media_defaults(&med, 3.7);
    med.absorption = absorption;
    med.scattering = scattering;
    med.scattering_type = type;
    med.eccentricity = g;
    med_list[0] = &med;
    return &med;
}

/* The box [-h,h] x [y0,y1] x [-h,h], clear, ior 1 (no refraction, no
** Fresnel reflection), the photon target, holding medium 'm' (NULL:
** none). */
static iris_object *media_box(double h, double y0, double y1,
                              iris_media *m, bool hollow)
{
    iris_object *b = tw_box(&tw, v3(-h, y0, -h), v3(h, y1, h), CLEAR, 0, 1.0);
    b->photon_target = true;
    b->photon_collect = false;
    b->hollow = hollow;
    if (m) {
        b->interior->media = med_list;
        b->interior->n_media = 1;
        b->interior->has_media = true;
    }
    return b;
}

/* One wavelength per photon (photon_options.no_siblings) in build(). */
static bool one_wavelength;
static uint64_t build_seed = 12345;

static struct photon_map *build(int threads)
{
    struct pmap_world w = tw_world(&tw);
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = threads;
    o.no_siblings = one_wavelength;
    o.seed = build_seed;
    struct photon_map *m = NULL;
    struct photon_stats st;
    assert_int_equal(pmap_build(&tw.scene, &w, &o, &m, &st), IRIS_OK);
    assert_non_null(m);
    return m;
}

/* The slab scene: parallel white light down, the box y in [1, 1+d], a
** white floor at y = 0 that stores the photons (after the box: level 3). */
static struct photon_map *slab_map(double d, iris_media *m, bool hollow)
{
    tw_init(&tw, 0.02, 100);
    tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    media_box(1.0, 1.0, 1.0 + d, m, hollow);
    tw_plane(&tw, v3(0, 1, 0), 0, WHITE, 1);
    return build(2);
}

/* Both maps hold the same photons at the same places (the media draw no
** random numbers in a constant medium without media photons). */
static void assert_same_places(const struct photon_map *a,
                               const struct photon_map *b)
{
    assert_true(a->store.n > 1000);
    assert_int_equal(a->store.n, b->store.n);
    for (size_t i = 0; i < a->store.n; i++)
        assert_true(a->store.ph[i].pos == b->store.ph[i].pos);
}

/*
** Grey absorption sigma = 0.7 over d = 1.25: every photon under the slab
** carries exp(-sigma·d) of its power (Beer-Lambert), the same at every
** wavelength, so the photons stay white. The estimate is linear in the
** powers of the same photons at the same places: the caustic under the
** slab dims by exactly exp(-0.875), up to the float rounding of the
** stored powers (1e-7; tolerance 1e-5).
*/
static void test_grey_extinction(void **state)
{
    (void)state;
    const double d = 1.25, sigma = 0.7;
    struct photon_map *clear = slab_map(d, NULL, true);
    struct photon_map *dim = slab_map(
        d, medium((iris_colour){ sigma, sigma, sigma, 0, 0 },
                  (iris_colour){ 0, 0, 0, 0, 0 }, 1, 0), true);
    assert_same_places(clear, dim);
    for (size_t i = 0; i < dim->store.n; i++) {
        assert_int_equal(dim->store.ph[i].lambda_q, PSTORE_WHITE);
        assert_near(dim->store.ph[i].power / clear->store.ph[i].power,
                    exp(-sigma * d), 1e-6);
    }
    double a[3], b[3];
    tw_floor_mean(clear, a);
    tw_floor_mean(dim, b);
    for (int c = 0; c < 3; c++) {
        /* the flux check of test_photon.c's slab: E = 1 under clear glass
        ** of ior 1 (no Fresnel loss), to the estimate's 2% */
        assert_near(a[c], 1.0, 0.02);
        assert_near(b[c] / a[c], exp(-sigma * d), 1e-5);
    }
    photon_map_destroy(clear);
    photon_map_destroy(dim);
}

/*
** Coloured absorption rgb (0.2, 0.9, 2.0) over d = 1: the extinction
** depends on the wavelength, sigma(lambda) = Burns' upsampling of the rgb
** coefficient (linear in rgb, as iris upsamples every rgb coefficient),
** and each stored photon carries exp(-sigma(lambda_j)·d) of its power at
** its own wavelength lambda_j. Tolerance 5e-4 relative: the stored
** wavelength is quantised to 0.006 nm (pstore.h), off by up to 0.003 nm,
** and Burns' curves change by at most 0.055 per nm, so sigma read back
** differs by up to 2.0·0.055·0.003 = 3.3e-4 from the one applied (float
** rounding of the powers: 1e-7). The caustic's colour is then, per channel, the
** mean over the spectrum of exp(-sigma(lambda)·d)·w_c(lambda) (the rgb
** weight of a wavelength, mean 1 for white), integrated here by the
** midpoint rule over 0.1 nm; the photons sample the spectrum on a
** stratified lattice (shoot.c), 2% (the estimate's bound in
** test_photon.c's slab test). The record-by-record check takes one
** wavelength a photon (the same records in both maps); the caustic's
** colour is checked with sibling wavelengths too (three records a path
** under the medium, each dimmed at its own wavelength: the same 2%).
*/
static void test_spectral_extinction(void **state)
{
    (void)state;
    const double d = 1.0;
    const double ab[3] = { 0.2, 0.9, 2.0 };
    one_wavelength = true;
    struct photon_map *clear = slab_map(d, NULL, true);
    struct photon_map *dim = slab_map(
        d, medium((iris_colour){ ab[0], ab[1], ab[2], 0, 0 },
                  (iris_colour){ 0, 0, 0, 0, 0 }, 1, 0), true);
    one_wavelength = false;
    assert_same_places(clear, dim);
    for (size_t i = 0; i < dim->store.n; i++) {
        assert_true(dim->store.ph[i].lambda_q != PSTORE_WHITE);
        double lambda = pstore_lambda(&dim->store, i);
        double sigma = spec_reflectance(ab, lambda);
        double t = exp(-sigma * d);
        assert_near(dim->store.ph[i].power / clear->store.ph[i].power, t,
                    5e-4 * t);
    }
    double expect[3] = { 0, 0, 0 };
    const int steps = 4000;
    for (int i = 0; i < steps; i++) {
        double lambda = 380.0 + 400.0 * (i + 0.5) / steps, w[3];
        spec_lambda_rgb_weight(lambda, w);
        double t = exp(-spec_reflectance(ab, lambda) * d);
        for (int c = 0; c < 3; c++)
            expect[c] += t * w[c] / steps;
    }
    double a[3], b[3];
    tw_floor_mean(clear, a);
    tw_floor_mean(dim, b);
    for (int c = 0; c < 3; c++)
        assert_near(b[c] / a[c], expect[c], 0.02 * expect[c]);
    /* red passes far more than blue: exp(-0.2) vs exp(-2) at the ends */
    assert_true(b[0] / a[0] > 2.0 * (b[2] / a[2]));
    photon_map_destroy(dim);
    /* siblings: three chromatic records a path, the same caustic */
    dim = slab_map(d, medium((iris_colour){ ab[0], ab[1], ab[2], 0, 0 },
                             (iris_colour){ 0, 0, 0, 0, 0 }, 1, 0), true);
    assert_int_equal(dim->store.n, 3 * clear->store.n);
    for (size_t i = 0; i < dim->store.n; i++)
        assert_true(dim->store.ph[i].lambda_q != PSTORE_WHITE);
    tw_floor_mean(dim, b);
    for (int c = 0; c < 3; c++)
        assert_near(b[c] / a[c], expect[c], 0.02 * expect[c]);
    photon_map_destroy(clear);
    photon_map_destroy(dim);
}

/*
** A density (a solid colour 0.5: the sampled path of pmedia.c, with
** stratified, jittered steps) halves the coefficient: exp(-0.5·sigma·d)
** exactly, the steps' Riemann sum being exact for a constant density
** (1e-5). A slab that is not hollow has no media at all (POV-Ray's
** IsHollowRay), and its photons pass undimmed.
*/
static void test_density_and_hollow(void **state)
{
    (void)state;
    const double d = 1.0, sigma = 1.2;
    struct photon_map *clear = slab_map(d, NULL, true);
    iris_media *m = medium((iris_colour){ sigma, sigma, sigma, 0, 0 },
                           (iris_colour){ 0, 0, 0, 0, 0 }, 1, 0);
    memset(&dens, 0, sizeof dens);
    dens.colour = (iris_colour){ 0.5, 0.5, 0.5, 0, 0 };
    dens_list[0] = &dens;
    m->densities = dens_list;
    m->n_densities = 1;
    struct photon_map *half = slab_map(d, m, true);
    assert_same_places(clear, half);
    for (size_t i = 0; i < half->store.n; i++)
        assert_near(half->store.ph[i].power / clear->store.ph[i].power,
                    exp(-0.5 * sigma * d), 1e-5);
    m->n_densities = 0;
    struct photon_map *solid = slab_map(d, m, false);
    assert_same_places(clear, solid);
    for (size_t i = 0; i < solid->store.n; i++)
        assert_true(solid->store.ph[i].power == clear->store.ph[i].power);
    photon_map_destroy(clear);
    photon_map_destroy(half);
    photon_map_destroy(solid);
}

/*
** Single scattering. A parallel white beam (irradiance E = 1, POV-Ray's
** photon normalisation) enters the box y in [0, 2] from above; the medium
** scatters sigma_s = 0.3 and absorbs sigma_a = 0.1 (extinction sigma_t =
** 0.4). At depth x below the top the beam's irradiance is E·exp(-sigma_t
** x), and the light scattered towards the eye per unit length is
**     L_s = sigma_s · p(omega) · E · exp(-sigma_t·x),
** with POV-Ray's unnormalised phase p (isotropic: 1, i.e. 4·pi times the
** physical sigma_s·E/(4·pi)), the units of media.c's direct
** in-scattering. The estimate from the media photons is checked at three
** depths, each the mean over 8 x 8 points of the slice |x|, |z| <= 0.5
** (each estimate gathers 100 photons: ~10% noise alone, 64 of them
** overlapping estimates: a few %); tolerance 5%. Then Henyey-Greenstein
** g = 0.5: looking up into the beam (cos = 1) the phase is (1+g)/(1-g)^2
** = 6, across it (cos = 0) (1-g^2)/(1+g^2)^1.5.
*/
static double slice_mean(const struct pmedia_map *pm, double y, vec3 dir,
                         const double sca[3], int ch)
{
    const iris_media *ml[1] = { &med };
    double sum = 0;
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            double emi[3] = { 0, 0, 0 };
            vec3 p = v3(-0.5 + (i + 0.5) / 8, y, -0.5 + (j + 0.5) / 8);
            pmedia_gather(pm, ml, 1, p, dir, sca, emi);
            sum += emi[ch] / 64;
        }
    return sum;
}

static struct photon_map *beam_map(int type, double g, int threads)
{
    tw_init(&tw, 0.04, 100);
    tw.scene.settings.photons.media_max_steps = 100;
    tw.scene.settings.photons.media_factor = 1.0;
    tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    iris_media *m = medium((iris_colour){ 0.1, 0.1, 0.1, 0, 0 },
                           (iris_colour){ 0.3, 0.3, 0.3, 0, 0 }, type, g);
    media_box(1.0, 0.0, 2.0, m, true);
    return build(threads);
}

static void test_single_scattering(void **state)
{
    (void)state;
    const double sigma_s = 0.3, sigma_t = 0.4;
    const double sca[3] = { sigma_s, sigma_s, sigma_s };
    struct photon_map *m = beam_map(IRIS_SCATTER_ISOTROPIC, 0, 2);
    const struct pmedia_map *pm = pmedia_of(m);
    assert_non_null(pm);
    /* steps of spread·factor = 0.04 over 2 units: 50 a photon */
    assert_true(pm->store.n > 40 * 2000);
    /* a grey medium under a white light: nothing depends on lambda, the
    ** siblings' media photons are white records of their summed power */
    for (size_t i = 0; i < pm->store.n; i++)
        assert_true(pm->store.ph[i].lambda_q == PSTORE_WHITE);
    for (int k = 0; k < 3; k++) {
        double x = 0.5 + 0.5 * k;
        double expect = sigma_s * exp(-sigma_t * x);
        for (int c = 0; c < 3; c++) {
            double got = slice_mean(pm, 2.0 - x, v3(1, 0, 0), sca, c);
            assert_near(got, expect, 0.05 * expect);
        }
    }
    /* no light outside the beam's box */
    double emi[3] = { 0, 0, 0 };
    const iris_media *ml[1] = { &med };
    pmedia_gather(pm, ml, 1, v3(5, 1, 0), v3(1, 0, 0), sca, emi);
    assert_true(emi[1] == 0.0);

    /* the same media photons for any thread count */
    struct photon_map *m1 = beam_map(IRIS_SCATTER_ISOTROPIC, 0, 1);
    const struct pmedia_map *pm1 = pmedia_of(m1);
    assert_int_equal(pm1->store.n, pm->store.n);
    assert_memory_equal(pm1->store.ph, pm->store.ph,
                        pm->store.n * sizeof(struct pstore_photon));
    photon_map_destroy(m1);
    photon_map_destroy(m);

    const double g = 0.5, x = 1.0;
    m = beam_map(IRIS_SCATTER_HENYEY_GREENSTEIN, g, 2);
    pm = pmedia_of(m);
    double up = (1 + g) / ((1 - g) * (1 - g));
    double side = (1 - g * g) / pow(1 + g * g, 1.5);
    double base = sigma_s * exp(-sigma_t * x);
    assert_near(slice_mean(pm, 2.0 - x, v3(0, 1, 0), sca, 1), up * base,
                0.05 * up * base);
    assert_near(slice_mean(pm, 2.0 - x, v3(1, 0, 0), sca, 1), side * base,
                0.05 * side * base);
    photon_map_destroy(m);
}

/*
** Sibling wavelengths through a coloured medium (trace.h, pmedia.c). The
** beam of test_single_scattering (white, E = 1) in a medium of coloured
** scattering sigma_s = rgb <0.6, 0.3, 0.1> (upsampled by Burns' curves:
** sigma_s(lambda)) and grey absorption 0.05, extinction sigma_t(lambda) =
** 0.05 + sigma_s(lambda). Every path inside is chromatic. At depth x the
** light the media photons scatter (isotropic phase 1), per channel c, is
**     L_c = mean over lambda of w_c(lambda)·sigma_s(lambda)·
**           exp(-sigma_t(lambda)·x)
** (w_c the rgb weight of a wavelength, mean 1 for white), integrated by
** the midpoint rule over 0.1 nm; a map of one wavelength a photon and
** one of three siblings (one media record per sibling a step) must both
** match it, and the siblings must lower the colour noise: the rms over
** the points of the chromaticity (r, b over r + g + b) about its mean,
** as test_psib.c measures it.
**
** Measured (22 Nov 2026, 4 seeds, 12 x 12 points of the slice, k = 100):
** at depth 0.5 the mean rgb one 0.4350 0.2531 0.0951, three 0.4344
** 0.2508 0.0948 against 0.4372 0.2532 0.0954; at 1.5 one 0.2287 0.1793
** 0.0856, three 0.2295 0.1799 0.0850 against 0.2312 0.1799 0.0851 (all
** within 1.1%). One seed's slice mean spreads by ~1.5% (the mean of 4 by
** ~0.8%), and the k-nearest estimate over the photons' regular lattice is
** ~1% low on its own (a lattice-like kNN bias: 3% low with k = 34):
** tolerance 3%. The chromaticity rms fell from 0.150 to 0.044 (depth
** 0.5) and 0.160 to 0.050 (1.5), every seed's in 0.040-0.054 against
** 0.141-0.168: it must more than halve. Both maps store one media record
** a step (the siblings take the steps in turn, pmedia.c), so the counts
** are equal.
*/
#define SIB_GRID 12
#define SIB_SEEDS 4

static const double SIB_SCA[3] = { 0.6, 0.3, 0.1 };
static const double SIB_ABS = 0.05;

/* The gathered rgb at SIB_GRID^2 points of the slice |x|, |z| <= 0.6 at
** depth 'x' below the top: its mean 'mean' and chromaticity rms. */
static void sib_slice(const struct pmedia_map *pm, double x, double mean[3],
                      double *chroma_rms)
{
    const int n = SIB_GRID * SIB_GRID;
    static double pt[SIB_GRID * SIB_GRID][3];
    const iris_media *ml[1] = { &med };
    for (int i = 0; i < n; i++) {
        vec3 p = v3(-0.6 + 1.2 * (i % SIB_GRID + 0.5) / SIB_GRID, 2.0 - x,
                    -0.6 + 1.2 * (i / SIB_GRID + 0.5) / SIB_GRID);
        pt[i][0] = pt[i][1] = pt[i][2] = 0;
        pmedia_gather(pm, ml, 1, p, v3(1, 0, 0), SIB_SCA, pt[i]);
        assert_true(pt[i][0] + pt[i][1] + pt[i][2] > 0.0);
    }
    tw_chroma_stats((const double (*)[3])pt, n, mean, chroma_rms);
}

static struct photon_map *sib_beam_map(bool one, uint64_t seed)
{
    tw_init(&tw, 0.04, 100);
    tw.scene.settings.photons.media_max_steps = 100;
    tw.scene.settings.photons.media_factor = 1.0;
    tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    medium((iris_colour){ SIB_ABS, SIB_ABS, SIB_ABS, 0, 0 },
           (iris_colour){ SIB_SCA[0], SIB_SCA[1], SIB_SCA[2], 0, 0 },
           IRIS_SCATTER_ISOTROPIC, 0);
    media_box(1.0, 0.0, 2.0, &med, true);
    one_wavelength = one;
    build_seed = seed;
    struct photon_map *m = build(2);
    one_wavelength = false;
    build_seed = 12345;
    return m;
}

static void test_sibling_media(void **state)
{
    (void)state;
    const double depth[2] = { 0.5, 1.5 };
    for (int k = 0; k < 2; k++) {
        double x = depth[k], e[3] = { 0, 0, 0 };
        const int steps = 4000;
        for (int i = 0; i < steps; i++) {
            double lambda = 380.0 + 400.0 * (i + 0.5) / steps, w[3];
            spec_lambda_rgb_weight(lambda, w);
            double ss = spec_reflectance(SIB_SCA, lambda);
            double st = SIB_ABS + med.sc_ext * ss;
            for (int c = 0; c < 3; c++)
                e[c] += w[c] * ss * exp(-st * x) / steps;
        }
        double m1[3] = { 0 }, m3[3] = { 0 }, c1 = 0, c3 = 0;
        size_t n1 = 0, n3 = 0;
        for (int sd = 0; sd < SIB_SEEDS; sd++) {
            double a[3], b[3], ca, cb;
            struct photon_map *one = sib_beam_map(true, (uint64_t)sd + 1);
            struct photon_map *three = sib_beam_map(false, (uint64_t)sd + 1);
            sib_slice(pmedia_of(one), x, a, &ca);
            sib_slice(pmedia_of(three), x, b, &cb);
            n1 += pmedia_of(one)->store.n;
            n3 += pmedia_of(three)->store.n;
            print_message("# depth %.1f seed %d: chromaticity rms one %.5f "
                          "three %.5f; mean one %.4f %.4f %.4f three %.4f "
                          "%.4f %.4f\n", x, sd + 1, ca, cb, a[0], a[1],
                          a[2], b[0], b[1], b[2]);
            c1 += ca / SIB_SEEDS;
            c3 += cb / SIB_SEEDS;
            for (int c = 0; c < 3; c++) {
                m1[c] += a[c] / SIB_SEEDS;
                m3[c] += b[c] / SIB_SEEDS;
            }
            photon_map_destroy(one);
            photon_map_destroy(three);
        }
        print_message("# depth %.1f: media records %zu / %zu; mean rgb one "
                      "%.4f %.4f %.4f, three %.4f %.4f %.4f, expected %.4f "
                      "%.4f %.4f; chromaticity rms one %.5f three %.5f\n",
                      x, n1, n3, m1[0], m1[1], m1[2], m3[0], m3[1], m3[2],
                      e[0], e[1], e[2], c1, c3);
        /* one media record a step either way (the siblings in turn) */
        assert_int_equal(n3, n1);
        for (int c = 0; c < 3; c++) {
            assert_near(m1[c], e[c], 0.03 * e[c]);
            assert_near(m3[c], e[c], 0.03 * e[c]);
            assert_near(m3[c], m1[c], 0.03 * m1[c]);
        }
        assert_true(c3 < 0.5 * c1);
    }
}

/*
** What a scene without media, or without 'media MAX_STEPS', gets: no
** media path in the combos (the transport's one test per segment), and
** no media map; nor does a medium with 'collect off' (POV-Ray's
** ignore_photons) get media photons.
*/
static void test_no_media(void **state)
{
    (void)state;
    struct photon_map *m = slab_map(1.0, NULL, true);
    assert_null(pmedia_of(m));
    assert_false(pmedia_scene_has_media(&tw.scene));
    struct pmedia_path mp;
    pmedia_setup(&mp, &tw.scene, 0.01);
    assert_null(mp.scene);
    photon_map_destroy(m);
    /* media without media photons: dimmed photons, no map */
    m = slab_map(1.0, medium((iris_colour){ 0, 0, 0, 0, 0 },
                             (iris_colour){ 0.5, 0.5, 0.5, 0, 0 }, 1, 0),
                 true);
    assert_true(pmedia_scene_has_media(&tw.scene));
    assert_false(pmedia_scene_wants_photons(&tw.scene));
    assert_null(pmedia_of(m));
    photon_map_destroy(m);
    tw_init(&tw, 0.04, 100);
    tw.scene.settings.photons.media_max_steps = 100;
    tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    medium((iris_colour){ 0, 0, 0, 0, 0 },
           (iris_colour){ 0.3, 0.3, 0.3, 0, 0 }, 1, 0)->ignore_photons = true;
    media_box(1.0, 0.0, 2.0, &med, true);
    tw_plane(&tw, v3(0, 1, 0), -1, WHITE, 1);
    m = build(1);
    assert_true(m->store.n > 1000); /* the floor's photons, dimmed */
    assert_null(pmedia_of(m));
    photon_map_destroy(m);
}

/* The render plan (--plan) says whether media photons are kept, and why
** not: the beam scene keeps them; without 'media MAX_STEPS', or without
** a photon pass, it does not. */
static void test_plan(void **state)
{
    (void)state;
    struct photon_map *m = beam_map(IRIS_SCATTER_ISOTROPIC, 0, 1);
    photon_map_destroy(m);
    iris_render_options o;
    iris_render_defaults(&o);
    o.width = 8;
    o.height = 6;
    o.quality = 9;
    o.use_photons = true;
    struct render_plan p;
    plan_compute(&tw.scene, &o, &p);
    assert_true(p.caustic_photons);
    assert_true(p.media_photons);
    assert_int_equal(p.media_max_steps, 100);
    tw.scene.settings.photons.media_max_steps = 0;
    plan_compute(&tw.scene, &o, &p);
    assert_false(p.media_photons);
    assert_non_null(strstr(p.media_photon_reason, "MAX_STEPS"));
    tw.scene.settings.photons.media_max_steps = 100;
    o.use_photons = false;
    plan_compute(&tw.scene, &o, &p);
    assert_false(p.media_photons);
    assert_non_null(strstr(p.media_photon_reason, "no caustic photon pass"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_grey_extinction),
        cmocka_unit_test(test_spectral_extinction),
        cmocka_unit_test(test_density_and_hollow),
        cmocka_unit_test(test_single_scattering),
        cmocka_unit_test(test_sibling_media),
        cmocka_unit_test(test_no_media),
        cmocka_unit_test(test_plan),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
