/* SPDX-License-Identifier: MIT */
/*
** test_psib.c: sibling wavelengths (src/photon/trace.h, ptrace_sibs;
** issue 5). A photon whose path does not depend on its wavelength carries
** three wavelengths u, u + 1/3, u + 2/3 (u its lattice value) along one
** path. Under a coloured light and a coloured mirror every photon is
** chromatic; with one wavelength a k-nearest gather sees the few
** wavelengths of the few direction cells it covers, and the caustic shows
** colour noise (rainbow bands where a curved mirror focuses neighbouring
** cells). The siblings must leave the expected light unchanged and make
** the colour noise smaller.
**
** Scene (the test double, photon_world.c): a parallel light of colour
** rgb <1, 0.84, 0.57> (the ring scene's <3.43, 2.87, 1.95> scaled) along
** +x onto a 45-degree mirror slab of reflection colour <0.52, 0.44, 0.40>
** (the ring's pigment <0.65, 0.55, 0.5> x reflection 0.8 metallic), which
** turns the beam straight down onto a white diffuse floor. A flat mirror
** keeps the beam's cross-section, so the floor's irradiance is the
** light's emission E(lambda) x the reflectivity rho(lambda).
**
** test_sibling_filter: siblings through coloured filters (each keeps its
** own transmittance); test_sibling_disperser: siblings in a scene with a
** dispersive element (they collapse to one where a path meets it, and are
** kept on the paths that do not).
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <string.h>

#include "photon/pmap.h"
#include "photon_world.h"
#include "spectrum/ior.h"
#include "spectrum/spectrum.h"

static struct tw_scene tw;

#define GRID 24
#define SEEDS 8

static const double LIGHT[3] = { 1.0, 0.84, 0.57 };
static const double MIRROR[3] = { 0.52, 0.44, 0.40 };

/* The caustic map of the scene in 'tw' (one wavelength per photon when
** 'no_siblings'); 'stored' gets its record count. */
static struct photon_map *build_map(bool no_siblings, uint64_t seed,
                                    int64_t *stored)
{
    struct pmap_world w = tw_world(&tw);
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = 2;
    o.seed = seed;
    o.no_siblings = no_siblings;
    struct photon_map *map = NULL;
    struct photon_stats st;
    assert_int_equal(pmap_build(&tw.scene, &w, &o, &map, &st), IRIS_OK);
    assert_non_null(map);
    *stored = st.stored;
    return map;
}

/* A black photon target bounded by six planes (normals n, offsets d) whose
** only light is a mirror reflection of colour 'rgb'. */
static iris_object *mirror_slab(const vec3 n[6], const double d[6],
                                const double rgb[3])
{
    const iris_colour black = { 0, 0, 0, 0, 0 };
    iris_object *m = tw_convex(&tw, 6, n, d, black, 0);
    m->photon_target = true;
    m->photon_collect = false;
    iris_finish *f = m->texture->finish;
    f->diffuse = 0;
    f->reflection_max.r = f->reflection_min.r = rgb[0];
    f->reflection_max.g = f->reflection_min.g = rgb[1];
    f->reflection_max.b = f->reflection_min.b = rgb[2];
    f->reflection_falloff = 1;
    return m;
}

/* Builds the scene and its map (one wavelength per photon when
** 'no_siblings'); 'pt' gets the estimate at GRID x GRID points of the
** floor's [-0.8, 0.8]^2 (all under the mirror), 'stored' the records. */
static void mirror_caustic(bool no_siblings, uint64_t seed,
                           double pt[GRID * GRID][3], int64_t *stored)
{
    tw_init(&tw, 0.02, 100);
    iris_light *l = tw_light(&tw, v3(-10, 0, 0), v3(0, 0, 0), true);
    l->colour.r = LIGHT[0];
    l->colour.g = LIGHT[1];
    l->colour.b = LIGHT[2];
    l->photon_reflection = IRIS_ON;
    /* the slab 0 <= x + y <= 0.1, |x| <= 1.2, |z| <= 1 (the test
    ** double's convex solids lie in |x|, |y|, |z| <= 1.5): its face
    ** x + y = 0 sends light along +x straight down to the floor y = -2 */
    const double s = sqrt(0.5);
    const vec3 n[6] = { v3(-1, -1, 0), v3(1, 1, 0), v3(1, 0, 0),
                        v3(-1, 0, 0),  v3(0, 0, 1), v3(0, 0, -1) };
    const double d[6] = { 0, 0.1 * s, 1.2, 1.2, 1, 1 };
    mirror_slab(n, d, MIRROR);
    const iris_colour white = { 1, 1, 1, 0, 0 };
    tw_plane(&tw, v3(0, 1, 0), -2, white, 1);
    struct photon_map *map = build_map(no_siblings, seed, stored);
    static iris_finish fin;
    fin.diffuse = 1;
    fin.brilliance = 1;
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            vec3 p = v3(-0.8 + 1.6 * (i + 0.5) / GRID, -2,
                        -0.8 + 1.6 * (j + 0.5) / GRID);
            struct photon_shade_input in = { p, v3(0, 1, 0), v3(0, 1, 0),
                                             v3(0, -1, 0), { 1, 1, 1 },
                                             1.0, &fin, NULL };
            photon_map_shade(map, &in, pt[i * GRID + j]);
        }
    photon_map_destroy(map);
}

/* The floor's rgb by quadrature: emission E(lambda) (relative to D65, as
** the shooter weighs photons) x rho(lambda) (Burns' curve of the mirror
** colour) x each wavelength's rgb weight, averaged over [380, 780] nm. */
static void expected(double out[3])
{
    iris_light l;
    memset(&l, 0, sizeof l);
    l.colour.r = LIGHT[0];
    l.colour.g = LIGHT[1];
    l.colour.b = LIGHT[2];
    l.spectrum = IRIS_SPEC_D65;
    struct spec_emitter em;
    spec_emitter_init(&em, &l);
    const int steps = 4000;
    out[0] = out[1] = out[2] = 0;
    for (int i = 0; i < steps; i++) {
        double lambda = 380.0 + 400.0 * (i + 0.5) / steps, wt[3];
        spec_lambda_rgb_weight(lambda, wt);
        double e = spec_emitter_eval(&em, lambda) *
                   spec_reflectance(MIRROR, lambda);
        for (int c = 0; c < 3; c++)
            out[c] += e * wt[c] / steps;
    }
}

/* The mean rgb of the points, and the rms over the points of the
** chromaticity (r, b over r + g + b) about its mean: the colour noise. */
static void summarise(double pt[GRID * GRID][3], double mean[3],
                      double *chroma_rms)
{
    for (int i = 0; i < GRID * GRID; i++)
        assert_true(pt[i][0] + pt[i][1] + pt[i][2] > 0.0);
    tw_chroma_stats((const double (*)[3])pt, GRID * GRID, mean, chroma_rms);
}

/*
** The same maps, SEEDS seeds each, with one wavelength per photon and
** with three siblings. Measured (22 Nov 2026): the patch's mean rgb over
** the seeds is within +1.6% (one) and +1.2% (three) of the quadrature;
** one seed's patch mean scatters by ~4% (one) and ~1.7% (three) in red,
** so the mean of 8 by ~1.5% and ~0.6%. Tolerances: 4% (one) and 2.5%
** (three) of the value: ~2.5 sigma plus the estimate's ~1% bias on a
** uniform patch (test_pfilter.c's plate: 2%). The chromaticity rms over
** the points, the colour noise, was 0.095 (one) and 0.051 (three), each
** seed's in 0.088-0.105 and 0.048-0.054: it must fall by more than a
** third. Every path is chromatic, so three records a path: the record
** counts agree with 3:1 within 3% (the mirror's roulette keeps a
** different set of paths in the two maps: ~0.5% binomial noise).
*/
static void test_sibling_mirror(void **state)
{
    (void)state;
    static double one[GRID * GRID][3], three[GRID * GRID][3];
    int64_t n1 = 0, n3 = 0;
    double e[3], m1[3] = { 0 }, m3[3] = { 0 }, c1 = 0, c3 = 0;
    expected(e);
    for (int k = 0; k < SEEDS; k++) {
        int64_t s1, s3;
        double a[3], b[3], ca, cb;
        mirror_caustic(true, (uint64_t)k + 1, one, &s1);
        mirror_caustic(false, (uint64_t)k + 1, three, &s3);
        summarise(one, a, &ca);
        summarise(three, b, &cb);
        print_message("# seed %d: chromaticity rms one %.5f three %.5f; "
                      "mean one %.4f %.4f %.4f three %.4f %.4f %.4f\n",
                      k + 1, ca, cb, a[0], a[1], a[2], b[0], b[1], b[2]);
        n1 += s1;
        n3 += s3;
        c1 += ca / SEEDS;
        c3 += cb / SEEDS;
        for (int c = 0; c < 3; c++) {
            m1[c] += a[c] / SEEDS;
            m3[c] += b[c] / SEEDS;
        }
    }
    print_message("# records %lld / %lld; mean rgb one %.4f %.4f %.4f, "
                  "three %.4f %.4f %.4f, expected %.4f %.4f %.4f; "
                  "chromaticity rms one %.5f three %.5f\n",
                  (long long)n1, (long long)n3, m1[0], m1[1], m1[2], m3[0],
                  m3[1], m3[2], e[0], e[1], e[2], c1, c3);
    /* every record of the single-wavelength map is one path; every
    ** path is chromatic here, so three records each (within the few
    ** records the quantisation box drops) */
    assert_near((double)n3, 3.0 * (double)n1, 0.03 * 3.0 * (double)n1);
    for (int c = 0; c < 3; c++) {
        assert_near(m1[c], e[c], 0.04 * e[c]);
        assert_near(m3[c], e[c], 0.025 * e[c]);
    }
    assert_true(c3 < c1 * 2.0 / 3.0);
}

/* ------------------------------------------------------------------ */

/* The photon light of map 'm' at GRID x GRID points of the square of
** half-size 0.8 about 'ctr' spanned by unit axes 'ax', 'ay', on a white
** diffuse surface of normal 'n'. */
static void patch(const struct photon_map *m, vec3 ctr, vec3 ax, vec3 ay,
                  vec3 n, double pt[GRID * GRID][3])
{
    static iris_finish fin;
    fin.diffuse = 1;
    fin.brilliance = 1;
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            vec3 p = v3_madd(v3_madd(ctr, ax, -0.8 + 1.6 * (i + 0.5) / GRID),
                             ay, -0.8 + 1.6 * (j + 0.5) / GRID);
            struct photon_shade_input in = { p, n, n, v3_neg(n), { 1, 1, 1 },
                                             1.0, &fin, NULL };
            photon_map_shade(m, &in, pt[i * GRID + j]);
        }
}

/* What one map gives over the seeds: the mean rgb and the mean of the
** seeds' chromaticity rms (summarise()). */
struct sib_result {
    double mean[3], chroma;
    int64_t stored;
};

static void add_seed(struct sib_result *r, double pt[GRID * GRID][3],
                     int64_t stored, int seeds)
{
    double m[3], c;
    summarise(pt, m, &c);
    for (int k = 0; k < 3; k++)
        r->mean[k] += m[k] / seeds;
    r->chroma += c / seeds;
    r->stored += stored;
}

/* The white light (E = 1) after the spectral factor t(lambda), each
** wavelength's rgb weight averaged over [380, 780] nm (midpoint rule,
** 0.1 nm). */
static void expected_white(double (*t)(double lambda, const void *ctx),
                           const void *ctx, double out[3])
{
    const int steps = 4000;
    out[0] = out[1] = out[2] = 0;
    for (int i = 0; i < steps; i++) {
        double lambda = 380.0 + 400.0 * (i + 0.5) / steps, wt[3];
        spec_lambda_rgb_weight(lambda, wt);
        double f = t(lambda, ctx);
        for (int c = 0; c < 3; c++)
            out[c] += f * wt[c] / steps;
    }
}

/* ------------------------------------------------------------------ */

static const double FILTER[3] = { 1.0, 0.6, 0.2 };   /* filter 0.9 */
#define FILTER_SEEDS 16
static const double PLATE_REFL[2][3] = { { 0.2, 0.4, 0.8 }, { 0, 0, 0 } };

/* A white parallel light straight down through the plate y in [1, 1.1]
** (no interior) of pigment rgbf <1, 0.6, 0.2, 0.9> and reflection colour
** PLATE_REFL[r], onto the white floor y = 0: every photon meets a
** coloured filter; with the reflection, the branch where the plate both
** reflects and passes (trace.c: reflection with probability P/(P+Q), each
** sibling weighed by its own q_j or p_j), without it passage alone
** (sib_filter). */
static void filter_plate(int r)
{
    tw_init(&tw, 0.02, 100);
    tw.scene.settings.photons.radius = 0.1;
    iris_light *l = tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    l->photon_reflection = IRIS_ON;
    const iris_colour col = { FILTER[0], FILTER[1], FILTER[2], 0.9, 0 };
    iris_object *p = tw_box(&tw, v3(-1, 1, -1), v3(1, 1.1, 1), col, 0, 0);
    assert_null(p->interior);
    p->photon_target = true;
    p->photon_collect = false;
    iris_finish *f = p->texture->finish;
    f->reflection_max.r = f->reflection_min.r = PLATE_REFL[r][0];
    f->reflection_max.g = f->reflection_min.g = PLATE_REFL[r][1];
    f->reflection_max.b = f->reflection_min.b = PLATE_REFL[r][2];
    f->reflection_falloff = 1;
    const iris_colour white = { 1, 1, 1, 0, 0 };
    tw_plane(&tw, v3(0, 1, 0), 0, white, 1);
}

/* The plate's spectral transmittance to the floor, q^2 (1 + p^2) as in
** test_pfilter.c: q = 0.9 rho_filter(lambda) at each face, p the
** reflection's curve (down, then up off the bottom face and down off the
** top one from inside; photon max_trace_level 5 stops the next round);
** 'ctx' is p's rgb. */
static double plate_t(double lambda, const void *ctx)
{
    double q = 0.9 * spec_reflectance(FILTER, lambda);
    double p = spec_reflectance(ctx, lambda);
    return q * q * (1 + p * p);
}

/*
** Siblings through a coloured filter carry each its own transmittance
** (until session 7 they collapsed to sibling 0 there, and the path was
** single-wavelength from the filter on). Expected: the floor's rgb is the
** quadrature of q^2 (1 + p^2), with one wavelength and with three; the
** colour noise (chromaticity rms over the points) falls. The photon
** radius is fixed (0.1): both maps are gathered over the same disc (k =
** 100 records caps the siblings' one). Measured (22 Nov 2026, 16 seeds):
** mean rgb one 0.8274 0.3345 0.0417, three 0.8275 0.3284 0.0413, expected
** 0.8299 0.3330 0.0419 (32 seeds, three: 0.8296 0.3312 0.0415); a seed's
** mean scatters by ~1.5% (the roulette between passage and reflection at
** two faces, binomial over the ~6,400 paths of the patch), so the mean of
** 16 by ~0.4%; chromaticity rms one 0.1419, three 0.0611 (0.43x; when the
** filter collapsed the siblings it was the one-wavelength value).
** Without the reflection (passage alone): one 0.7943 0.2832 0.0166,
** three 0.7928 0.2826 0.0166, expected 0.7943 0.2832 0.0166;
** chromaticity rms 0.0290 and 0.0093.
** Tolerances: 2.5% + 0.002 of the value (the estimate's 2%, test_pfilter,
** plus the roulette's scatter; 0.002 for the blue channel near 0), the
** noise must fall below 0.6x.
*/
static void filter_case(int r);

static void test_sibling_filter(void **state)
{
    (void)state;
    for (int r = 0; r < 2; r++)
        filter_case(r);
}

static void filter_case(int r)
{
    static double pt[GRID * GRID][3];
    struct sib_result one = { { 0 }, 0, 0 }, three = one;
    for (int k = 0; k < FILTER_SEEDS; k++) {
        for (int sib = 0; sib < 2; sib++) {
            int64_t st;
            filter_plate(r);
            struct photon_map *m = build_map(sib == 0, (uint64_t)k + 1, &st);
            patch(m, v3(0, 0, 0), v3(1, 0, 0), v3(0, 0, 1), v3(0, 1, 0),
                  pt);
            photon_map_destroy(m);
            add_seed(sib ? &three : &one, pt, st, FILTER_SEEDS);
        }
    }
    double e[3];
    expected_white(plate_t, PLATE_REFL[r], e);
    print_message("# filter %s: records %lld / %lld; mean one %.4f %.4f %.4f "
                  "three %.4f %.4f %.4f expected %.4f %.4f %.4f; "
                  "chromaticity rms one %.5f three %.5f\n",
                  r ? "alone" : "and mirror",
                  (long long)one.stored, (long long)three.stored,
                  one.mean[0], one.mean[1], one.mean[2], three.mean[0],
                  three.mean[1], three.mean[2], e[0], e[1], e[2], one.chroma,
                  three.chroma);
    for (int c = 0; c < 3; c++) {
        assert_near(one.mean[c], e[c], 0.025 * e[c] + 0.002);
        assert_near(three.mean[c], e[c], 0.025 * e[c] + 0.002);
    }
    assert_true(three.chroma < 0.6 * one.chroma);
}

/* ------------------------------------------------------------------ */

static const double MIRROR2[3] = { 0.9, 0.5, 0.2 };

/*
** A white parallel light straight down onto two targets side by side:
** a mirror slab at z in [-1.4, -0.2] whose face y = x (reflection colour
** <0.9, 0.5, 0.2>) turns the beam to -x, onto the white wall x = -3; and
** an N-SF11 slab (dispersive, Sellmeier) at z in [0.2, 1.4], y in [-1,
** -0.5], which the light crosses at normal incidence onto the white floor
** y = -2. The scene has a dispersive interior, so until session 7 no
** photon carried siblings. The photon radius is fixed (0.1) so that the
** slab's patch of the floor is estimated from the same photons whatever
** the mirror's paths store.
*/
static iris_object *disperser_scene(void)
{
    tw_init(&tw, 0.02, 100);
    tw.scene.settings.photons.radius = 0.1;
    iris_light *l = tw_light(&tw, v3(0, 10, 0), v3(0, 0, 0), true);
    l->photon_reflection = IRIS_ON;
    const double s = sqrt(0.5);
    const vec3 n[6] = { v3(-1, 1, 0), v3(1, -1, 0), v3(1, 0, 0),
                        v3(-1, 0, 0), v3(0, 0, 1),  v3(0, 0, -1) };
    const double d[6] = { 0, 0.1 * s, 1.2, 1.2, -0.2, 1.4 };
    mirror_slab(n, d, MIRROR2);
    const iris_colour clear = { 1, 1, 1, 0, 1 };
    iris_object *slab = tw_box(&tw, v3(-1.2, -1, 0.2), v3(1.2, -0.5, 1.4),
                               clear, 0, 1.5);
    slab->photon_target = true;
    slab->photon_collect = false;
    iris_ior_spec *spec = &tw.spec[0];
    spec->model = IRIS_IOR_SELLMEIER;
    spec->glass_name = "N-SF11";
    slab->interior->spectral_ior = spec;
    const iris_colour white = { 1, 1, 1, 0, 0 };
    tw_plane(&tw, v3(1, 0, 0), -3, white, 1);
    tw_plane(&tw, v3(0, 1, 0), -2, white, 1);
    return slab;
}

static double mirror2_t(double lambda, const void *ctx)
{
    (void)ctx;
    return spec_reflectance(MIRROR2, lambda);
}

/* The slab at normal incidence: (1-R)^2 (1 + R^2), R = ((n-1)/(n+1))^2
** at n(lambda) (one internal round trip within photon max_trace_level 5;
** the next adds R^4 ~ 4e-5). */
static double slab_t(double lambda, const void *ctx)
{
    double n = ior_eval(((const iris_object *)ctx)->interior, lambda);
    double r = (n - 1) / (n + 1);
    r *= r;
    return (1 - r) * (1 - r) * (1 + r * r);
}

/*
** Siblings in a scene with a dispersive element: the mirror's paths never
** meet it and keep their three wavelengths (coloured mirror: a chromatic
** path, three records); the slab's paths collapse to sibling 0 with three
** times its power at the slab's first face (trace.c, sib_collapse), the
** photon's lattice wavelength u, which is what one wavelength per photon
** gives: the same photons. Expected: the wall's patch (y, z about
** (0, -0.8)) is the quadrature of the mirror's curve and its colour noise
** falls as in test_sibling_mirror; the floor's patch under the slab is the
** quadrature of (1-R)^2 (1 + R^2) with either, and the two maps give it
** the same but for the records' quantisation (the quantisation box
** follows all the records, the mirror's too). Measured (22 Nov 2026, 8
** seeds): wall one 0.8973 0.4994 0.1979, three 0.8975 0.4978 0.2001,
** expected 0.9000 0.5000 0.2000 (32 seeds, three: 0.8988 0.5010 0.2000);
** chromaticity rms one 0.1269, three 0.0457; slab 0.8506 0.8487 0.8384
** with both, expected 0.8549 0.8510 0.8436 (-0.5%: the estimate's bias);
** a seed's slab means differ between the maps by at most 5.3e-7.
** Tolerances: 2% (the estimate's, test_pfilter.c), noise below 0.6x,
** the slab's means equal within 1e-5 (a path that kept three wavelengths
** through the slab would differ by its colour noise, ~1e-3).
*/
static void test_sibling_disperser(void **state)
{
    (void)state;
    static double wall[GRID * GRID][3], floor1[GRID * GRID][3],
        floor3[GRID * GRID][3];
    struct sib_result one = { { 0 }, 0, 0 }, three = one;
    double slab1[3] = { 0 }, slab3[3] = { 0 }, maxdiff = 0;
    const iris_object *slab = NULL;
    for (int k = 0; k < SEEDS; k++) {
        for (int sib = 0; sib < 2; sib++) {
            int64_t st;
            slab = disperser_scene();
            struct photon_map *m = build_map(sib == 0, (uint64_t)k + 1, &st);
            patch(m, v3(-3, 0, -0.8), v3(0, 1, 0), v3(0, 0, 0.5 / 0.8),
                  v3(1, 0, 0), wall);
            patch(m, v3(0, -2, 0.8), v3(1, 0, 0), v3(0, 0, 0.4 / 0.8),
                  v3(0, 1, 0), sib ? floor3 : floor1);
            photon_map_destroy(m);
            add_seed(sib ? &three : &one, wall, st, SEEDS);
        }
        double d1[3] = { 0 }, d3[3] = { 0 };
        for (int i = 0; i < GRID * GRID; i++)
            for (int c = 0; c < 3; c++) {
                d1[c] += floor1[i][c] / (GRID * GRID);
                d3[c] += floor3[i][c] / (GRID * GRID);
            }
        for (int c = 0; c < 3; c++) {
            maxdiff = fmax(maxdiff, fabs(d3[c] - d1[c]) / d1[c]);
            slab1[c] += d1[c] / SEEDS;
            slab3[c] += d3[c] / SEEDS;
        }
    }
    double e[3], es[3];
    expected_white(mirror2_t, NULL, e);
    expected_white(slab_t, slab, es);
    print_message("# disperser: records %lld / %lld; wall one %.4f %.4f "
                  "%.4f three %.4f %.4f %.4f expected %.4f %.4f %.4f; "
                  "chromaticity rms one %.5f three %.5f; slab one %.4f "
                  "%.4f %.4f three %.4f %.4f %.4f expected %.4f %.4f "
                  "%.4f; largest relative difference of a seed's slab "
                  "mean %.3g\n",
                  (long long)one.stored, (long long)three.stored,
                  one.mean[0], one.mean[1], one.mean[2], three.mean[0],
                  three.mean[1], three.mean[2], e[0], e[1], e[2], one.chroma,
                  three.chroma, slab1[0], slab1[1], slab1[2], slab3[0],
                  slab3[1], slab3[2], es[0], es[1], es[2], maxdiff);
    for (int c = 0; c < 3; c++) {
        assert_near(one.mean[c], e[c], 0.02 * e[c]);
        assert_near(three.mean[c], e[c], 0.02 * e[c]);
        assert_near(slab3[c], es[c], 0.02 * es[c]);
    }
    assert_true(maxdiff < 1e-5);
    assert_true(three.chroma < 0.6 * one.chroma);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sibling_mirror),
        cmocka_unit_test(test_sibling_filter),
        cmocka_unit_test(test_sibling_disperser),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
