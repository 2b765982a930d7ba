/* SPDX-License-Identifier: MIT */
/*
** test_pwave.c: the wavefront photon tracer (src/photon/wavefront.h)
** against the scalar one (trace.c), its specification.
**
** The two use other random numbers and other precision (float lanes), so
** their maps are two samples of one distribution, not the same records.
** Each check compares a statistic of the two maps with a tolerance taken
** from the maps' own photon counts and powers (see 'sigma' below), five
** standard deviations of the difference: a correct tracer fails a check
** with probability ~6e-7, while a wrong Fresnel term (reflection and
** refraction swapped: ~4% against ~96% of a ball's light through), a lost
** D^2, a wrong index (the caustic's radius moves by cells of the
** histogram), a lost roulette weight or a coloured light's emission read
** at the wrong wavelength (a band's power 0.70 against 0.13, sd 0.004)
** moves them by tens of deviations.
**
** Scenes: bench/caustic_ball.pov's clear ball (parallel light, the fast
** path's scene); the same ball with a dispersive interior (chromatic
** records: the mean wavelength and its spread); a mirror-and-filter scene
** (point light; a grey mirror ball, and a filtering ball without an
** interior that also reflects: the roulettes p, q and p/(p+q)); a water
** slab (a refracting plane) under a mirror ball; the ball and the mirror
** scene under an orange light (a lane per sibling wavelength, three
** records a path, each with the emission at its wavelength: the power in
** four 100 nm bands); coloured filters under the white light, an amber
** glass ball and a tinted filter that also mirrors (its lanes' roulettes
** depend on lambda: power, histogram and bands only). Convex objects
** (session 9): scenes/prism.pov's rotated dispersive prism, lens.pov's
** intersection of two balls, gem.pov's 17 planes and a cylinder, and a
** transformed glass box, dome and mirror box; for these the histogram's
** window follows the light (fit_window), and for every scene the spot's
** size (the window's sum of e·r^2) is compared too. Then: the
** same map for 1 and 2 threads; scenes outside the wavefront's set fall
** back to the scalar tracer (the very same map as with it turned off);
** the kernel for any CPU gives the AVX2 kernel's map;
** the lanes' Fresnel term against pmap_fresnel() from normal incidence to
** grazing and past the critical angle, finite everywhere.
*/
#include "config.h"

#include "testutil.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "material/material.h"
#include "parse_util.h"
#include "scene_world.h"
#include "photon/pmap.h"
#include "photon/wavefront.h"

/* bench/caustic_ball.pov (count 100000: 44,115 photons shot), its light
** of colour 'col' */
#define BALL_HEAD_LIT(col)                                                 \
    "global_settings { assumed_gamma 1 max_trace_level 6\n"                \
    "  photons { count 100000 autostop 0 jitter 0.4 } }\n"                 \
    "light_source { <0, 20, 0> color rgb " col                             \
    " cylinder point_at <0, 0, 0>\n"                                       \
    "  radius 1 falloff 1 tightness 0\n"                                   \
    "  photons { refraction on reflection on } }\n"                        \
    "plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"
#define BALL_HEAD BALL_HEAD_LIT("1")
#define BALL_SPHERE                                                        \
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }\n"        \
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"              \
    "  photons { target refraction on reflection on collect off } }\n"

/* An orange light: its emission relative to D65 rises ~6x from blue to
** red, so each band of wavelengths below holds a very different power */
#define ORANGE "<1, 0.5, 0.15>"

static const char *const BALL = BALL_HEAD BALL_SPHERE;

/* the ball under the orange light: every record chromatic, three a path
** (one per sibling wavelength) */
static const char *const ORANGE_BALL = BALL_HEAD_LIT(ORANGE) BALL_SPHERE;

/* the ball with POV-Ray's dispersion: every record chromatic */
static const char *const DISPERSIVE =
    BALL_HEAD
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 }\n"
    "  interior { ior 1.5 dispersion 1.05 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* A point light over a grey mirror ball (p = 0.7) and a ball without an
** interior that filters half the light and mirrors 0.3 of it
** (q = 0.5, p = 0.3: reflection with probability 3/8, power x 0.8). */
#define MIRROR_WITH(col, filter)                                           \
    "global_settings { max_trace_level 5\n"                                \
    "  photons { spacing 0.008 autostop 0 } }\n"                           \
    "light_source { <0, 6, -2> color rgb " col "\n"                        \
    "  photons { refraction on reflection on } }\n"                        \
    "plane { y, 0 pigment { color rgb 0.8 } finish { diffuse 1 } }\n"      \
    "sphere { <-1.2, 1.2, 0>, 0.8 pigment { color rgb 0.2 }\n"             \
    "  finish { diffuse 0 reflection { 0.7 } }\n"                          \
    "  photons { target reflection on collect off } }\n"                   \
    "sphere { <1.2, 1.5, 0.3>, 0.7\n"                                      \
    "  pigment { color " filter " }\n"                                     \
    "  finish { diffuse 0 reflection { 0.3 } }\n"                          \
    "  photons { target reflection on refraction on collect off } }\n"
#define GREY_FILTER "rgbt <1, 1, 1, 0.5>"
static const char *const MIRROR = MIRROR_WITH("1", GREY_FILTER);
/* the same under the orange light: the siblings' lanes share their
** roulettes (one random key), as the scalar siblings share a path */
static const char *const ORANGE_MIRROR = MIRROR_WITH(ORANGE, GREY_FILTER);
/* the white light through a coloured filter without an interior that
** also mirrors (q(lambda) = 0.6·(its reflectance curve), p = 0.3): the
** siblings' lanes make their own roulette p/(p + q(lambda)) */
static const char *const TINTED_MIRROR =
    MIRROR_WITH("1", "rgbf <0.2, 0.5, 1, 0.6>");

/* a ball of amber glass (filter 0.9 of rgb <1, 0.6, 0.3>) under the white
** light: white records off its outside, three chromatic records a path
** through it, each with the transmittance at its wavelength */
static const char *const AMBER_BALL =
    BALL_HEAD
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 0.6, 0.3, 0.9> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* A slab of water (a refracting plane, ior 1.33, the glass's one medium)
** over a floor inside it, lit through a grey mirror ball: the plane's
** entering refraction, its Fresnel reflection, a lane inside a plane. */
static const char *const WATER =
    "global_settings { max_trace_level 6\n"
    "  photons { spacing 0.006 autostop 0 } }\n"
    "light_source { <1, 6, -1> color rgb 1\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, -1 pigment { color rgb 0.8 } finish { diffuse 1 } }\n"
    "plane { y, 0 pigment { color rgbf <1, 1, 1, 1> } finish { diffuse 0 }\n"
    "  interior { ior 1.33 } }\n"
    "sphere { <0, 2, 0>, 0.7 pigment { color rgb 0.2 }\n"
    "  finish { diffuse 0 reflection { 0.8 } }\n"
    "  photons { target reflection on collect off } }\n";

/* Convex objects (wavefront.c: intersections of half-spaces and balls,
** transforms folded into world space). scenes/prism.pov: a cylinder
** light through a rotated and translated dispersive prism of F2 (a
** linear prism: three walls and two caps) onto a floor; its spectrum
** lands 2-5 units off the origin (the histogram's window follows the
** map, 'same_distribution'). */
static const char *const PRISM =
    "global_settings { max_trace_level 10\n"
    "  photons { spacing 0.0007 autostop 0 } }\n"
    "light_source { <-4.154, -0.562, 0> color rgb 3\n"
    "  cylinder point_at <-0.5, 1.066, 0> radius 0.05 falloff 0.08\n"
    "  tightness 0 photons { refraction on reflection off } }\n"
    "plane { y, -1 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }\n"
    "prism { linear_sweep linear_spline -1.5, 1.5, 4,\n"
    "  <-1, 0>, <1, 0>, <0, 1.732>, <-1, 0>\n"
    "  rotate -90*x translate <0, 0.2, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }\n"
    "  interior { ior 1.62 dispersion 1.04 glass \"F2\" }\n"
    "  photons { target refraction on reflection off collect off } }\n";

/* scenes/lens.pov (spacing 0.02, not 0.01: a quarter of the photons): a
** parallel light through a biconvex lens of N-BK7, the intersection of
** two spheres translated, focused onto the floor */
static const char *const LENS =
    "global_settings { max_trace_level 10\n"
    "  photons { spacing 0.02 autostop 0 } }\n"
    "light_source { <0, 20, 0> color rgb 1 parallel point_at <0, 0, 0>\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 0.9 } }\n"
    "intersection {\n"
    "  sphere { <0, -3.7, 0>, 4 } sphere { <0, 3.7, 0>, 4 }\n"
    "  translate <0, 2.4, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 }\n"
    "  interior { ior 1.52 dispersion 1.02 glass \"N-BK7\" }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* A glass box (ior 1.5) rotated about two axes and scaled unevenly (an
** affine map: its faces stay planes) under the ball's light, beside a
** dome (a ball cut by a plane: a ball and a half-space in one object)
** scaled uniformly (a similarity: the ball stays a ball), and a mirror
** box (p = 0.7, a convex object's mirror roulette) */
static const char *const BOXES =
    BALL_HEAD
    "box { <-0.5, -0.5, -0.5>, <0.5, 0.5, 0.5> scale <1.2, 0.8, 1>\n"
    "  rotate <20, 35, 0> translate <-0.6, 2.5, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n"
    "intersection { sphere { 0, 0.5 } plane { -y, -0.1 }\n"
    "  scale 1.2 translate <1.0, 2.0, 0.3>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.6 }\n"
    "  photons { target refraction on reflection on collect off } }\n"
    "box { <-0.3, 1.5, 0.6>, <0.3, 1.8, 1.0> rotate 30*z\n"
    "  pigment { color rgb 0.2 } finish { diffuse 0 reflection { 0.7 } }\n"
    "  photons { target reflection on collect off } }\n";

/* scenes/gem.pov (spacing 0.006, not 0.012: four times the photons): a
** point light into a diamond cut as the intersection of 17 planes and a
** capped cylinder (its girdle), deep internal reflections (ior 2.417,
** max_trace_level 8); its pavilion's tip cuts into the floor (an
** opaque object may) */
static const char *const GEM =
    "global_settings { max_trace_level 8\n"
    "  photons { spacing 0.006 autostop 0 } }\n"
    "light_source { <2, 7, -3> color rgb 1.2\n"
    "  photons { refraction on reflection on } }\n"
    "plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0 diffuse 0.8 } }\n"
    "#declare Gem = intersection {\n"
    "  plane { y, 0.3 }\n"
    "  #for (I, 0, 7) plane { <0, 1.2, -1>, 0.75 rotate (I * 45 + 22.5) * y }\n"
    "  #end\n"
    "  #for (I, 0, 7) plane { <0, -1.05, -1>, 0.72 rotate I * 45 * y } #end\n"
    "  cylinder { <0, -2, 0>, <0, 2, 0>, 1 }\n"
    "}\n"
    "object { Gem translate <0, 0.75, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 reflection { 0.05, 1 fresnel } }\n"
    "  interior { ior 2.417 dispersion 1.06 glass \"diamond\" }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* Outside the wavefront's set: a sphere scaled unevenly (an ellipsoid);
** a glass box touching a glass ball (a lane's medium would not be one
** object); a difference (not convex); a cone (a shape the lanes do not
** intersect); a prism whose profile is not convex. */
static const char *const SCALED =
    BALL_HEAD
    "sphere { 0, 1 scale <1, 0.8, 1> translate <0, 2.5, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

static const char *const BOX_ON_BALL =
    BALL_HEAD BALL_SPHERE
    "box { <-0.7, 0.5, -0.7>, <0.7, 1.5, 0.7>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

static const char *const DIFFERENCE =
    BALL_HEAD
    "difference { sphere { 0, 1 } sphere { <0, 1, 0>, 0.5 }\n"
    "  translate <0, 2.5, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

static const char *const CONE =
    BALL_HEAD
    "intersection { plane { y, 0.3 } plane { -y, 0.5 }\n"
    "  cone { <0, -2, 0>, 1, <0, 2, 0>, 0.5 } translate <0, 2.5, 0>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 2.4 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

static const char *const CONCAVE_PRISM =
    BALL_HEAD
    "prism { linear_sweep linear_spline 2, 3, 5,\n"
    "  <-1, -1>, <1, -1>, <0, 0>, <0, 1>, <-1, -1>\n"
    "  pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* A ground sphere of radius 1e6 beside the ball: float would misplace
** its hits by ~0.1 (wavefront.c's reach rule). */
static const char *const HUGE_GROUND =
    BALL_HEAD
    "sphere { <0, -1e6, 0>, 1e6 - 0.5 pigment { color rgb 1 } }\n"
    "sphere { <0, 2.5, 0>, 1 pigment { color rgbf <1, 1, 1, 1> }\n"
    "  finish { ambient 0 diffuse 0 } interior { ior 1.5 }\n"
    "  photons { target refraction on reflection on collect off } }\n";

/* The caustic map of 'w', by the wavefront tracer unless 'scalar'. */
static struct photon_map *build_pass(const struct world *w, bool scalar,
                                     int threads, uint64_t seed, int pass,
                                     struct photon_stats *st)
{
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = threads;
    o.seed = seed;
    o.pass = pass;
    o.mat = w->mc;
    o.no_wavefront = scalar;
    struct photon_map *m = NULL;
    assert_int_equal(photon_map_build(w->sc, w->a, &o, &m, st), IRIS_OK);
    assert_non_null(m);
    return m;
}

static struct photon_map *build(const struct world *w, bool scalar,
                                int threads, uint64_t seed,
                                struct photon_stats *st)
{
    return build_pass(w, scalar, threads, seed, 0, st);
}

/* What the checks read of a map: records, white ones, power and its sum
** of squares, the floor's coarse histogram (GRID x GRID cells over
** |x|, |z| < HALF), and the chromatic records' wavelengths and their
** power in BANDS bands of 100 nm (narrower than the siblings' spacing,
** 400/3 nm: a path puts at most one record in a band). */
#define GRID 6
#define HALF 1.5
#define BANDS 4
struct summary {
    double n, n_white, power, power2;
    double wx, wz, half;       /* the histogram's window: centre, half
                                  width */
    double cell[GRID][GRID], cell2[GRID][GRID];
    double spread, spread2;    /* the window's sum of e·r^2 (r from its
                                  centre) and of (e·r^2)^2: the spot's
                                  size, finer than the cells (a focus) */
    double lam_n, lam, lam2;
    double band[BANDS], band2[BANDS];
};

/* The histogram's window of map 'm' when the scene's light does not land
** about the origin: centred on the records' power-weighted mean, 2.5 of
** their larger power-weighted sd either side (both maps take the first
** map's window: a fixed grid for the comparison) */
static void fit_window(const struct photon_map *m, struct summary *s)
{
    const struct pstore *ps = &m->store;
    double w = 0, x = 0, z = 0, x2 = 0, z2 = 0;
    for (size_t i = 0; i < ps->n; i++) {
        vec3 p = pstore_position(ps, i);
        double e = ps->ph[i].power;
        w += e;
        x += e * p.x;
        z += e * p.z;
        x2 += e * p.x * p.x;
        z2 += e * p.z * p.z;
    }
    assert_true(w > 0);
    s->wx = x / w;
    s->wz = z / w;
    double sx = sqrt(fmax(x2 / w - s->wx * s->wx, 0.0));
    double sz = sqrt(fmax(z2 / w - s->wz * s->wz, 0.0));
    s->half = 2.5 * fmax(sx, sz);
    assert_true(s->half > 0);
}

/* 'win' (may be NULL: the origin's, HALF) gives the histogram's window */
static void summarise(const struct photon_map *m, struct summary *s,
                      const struct summary *win)
{
    memset(s, 0, sizeof *s);
    s->half = win ? win->half : HALF;
    s->wx = win ? win->wx : 0.0;
    s->wz = win ? win->wz : 0.0;
    const struct pstore *ps = &m->store;
    for (size_t i = 0; i < ps->n; i++) {
        vec3 p = pstore_position(ps, i);
        double e = ps->ph[i].power;
        /* also the grazing and totally reflected lanes: finite records */
        assert_true(isfinite(p.x) && isfinite(p.y) && isfinite(p.z));
        assert_true(isfinite(e) && e > 0.0);
        s->n++;
        s->power += e;
        s->power2 += e * e;
        if (ps->ph[i].lambda_q == PSTORE_WHITE) {
            s->n_white++;
        } else {
            double l = pstore_lambda(ps, i);
            s->lam_n++;
            s->lam += l;
            s->lam2 += l * l;
            int k = (int)floor((l - 380.0) / 100.0);
            k = k < 0 ? 0 : k >= BANDS ? BANDS - 1 : k;
            s->band[k] += e;
            s->band2[k] += e * e;
        }
        int cx = (int)floor((p.x - s->wx + s->half) / (2 * s->half) * GRID);
        int cz = (int)floor((p.z - s->wz + s->half) / (2 * s->half) * GRID);
        if (cx >= 0 && cx < GRID && cz >= 0 && cz < GRID) {
            s->cell[cx][cz] += e;
            s->cell2[cx][cz] += e * e;
            double r2 = ((p.x - s->wx) * (p.x - s->wx) +
                         (p.z - s->wz) * (p.z - s->wz)) /
                        (s->half * s->half);
            s->spread += e * r2;
            s->spread2 += e * r2 * e * r2;
        }
    }
}

/*
** The standard deviation of the difference of two independent sums of
** photon powers. A sum S = sum_i e_i·B_i over the photons shot, B_i
** whether photon i is stored (there), independent with probability q_i,
** has Var S = sum_i e_i^2 q_i (1 - q_i) <= sum_i e_i^2 q_i, the expected
** sum of its records' squared powers: each map's own sum of squares
** bounds its variance. (The emission's stratified jitter only lowers it.)
*/
static double sigma(double sq_a, double sq_b)
{
    return sqrt(sq_a + sq_b);
}

/* The two maps agree in count, power, histogram (and wavelengths when
** chromatic): see the header for the tolerances. 'per' is the records a
** stored chromatic path leaves (3 with siblings: one per sibling).
** 'by_count': whether the counts of records agree too (white and
** chromatic, and the chromatic ones' wavelengths uniform): not where a
** roulette depends on lambda (a coloured filter that also mirrors), which
** the scalar siblings take once with their mean probability and each
** sibling's lane with its own: the same power, other record counts. */
static void same_distribution_in(const char *sdl, uint64_t seed, int pass,
                                 int per, bool by_count, bool fit)
{
    struct world w;
    world_open(&w, sdl);
    struct photon_stats st[2];
    struct photon_map *m[2] = { build_pass(&w, true, 2, seed, pass, &st[0]),
                                build_pass(&w, false, 2, seed, pass,
                                           &st[1]) };
    assert_int_equal(st[0].wavefront, 0);
    assert_int_equal(st[1].wavefront, st[1].shot);
    assert_int_equal(st[0].shot, st[1].shot); /* the same photons shot */
    struct summary a, b, win;
    if (fit)
        fit_window(m[0], &win);
    summarise(m[0], &a, fit ? &win : NULL);
    summarise(m[1], &b, fit ? &win : NULL);
    assert_true(a.n > 5000);
    /* records: each photon's path is stored (mostly once) with
    ** probability q, independently, as one white record or 'per'
    ** chromatic ones: binomial paths, sd <= per·sqrt(shot·q(1-q)) each */
    double q = (a.n_white + a.lam_n / per) / (double)st[0].shot;
    if (q > 1.0)
        q = 1.0;
    double sd_n = per * sqrt(2.0 * (double)st[0].shot * q * (1.0 - q)) + 1.0;
    assert_true(!by_count || fabs(a.n - b.n) <= 5.0 * sd_n);
    /* white records (no dispersion on the path): the same share (a
    ** binomial proportion, 5 sd, + 1e-12 for the shares 0 and 1) */
    double wa = a.n_white / a.n, wb = b.n_white / b.n;
    assert_true(!by_count ||
                fabs(wa - wb) <=
                    5.0 * sqrt(wa * (1 - wa) / a.n + wb * (1 - wb) / b.n) +
                        1e-12);
    /* stored power: 5 sd, plus 1e-4 of the float lanes' rounding (a
    ** D^2 of ~400 in float: 1e-7 relative per record, far less). A path
    ** of 'per' records of powers e_j adds (sum e_j)^2 <= per·sum e_j^2
    ** (Cauchy-Schwarz) to the variance: the sums of squares times per */
    a.power2 *= per;
    b.power2 *= per;
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            a.cell2[i][j] *= per;
            b.cell2[i][j] *= per;
        }
    double sd_p = sigma(a.power2, b.power2);
    assert_true(fabs(a.power - b.power) <= 5.0 * sd_p + 1e-4 * a.power);
    /* the spot's size: a sum of e·r^2 over the window, its variance
    ** bounded as the power's (r^2 in units of the window's half width) */
    a.spread2 *= per;
    b.spread2 *= per;
    double sd_s = sigma(a.spread2, b.spread2);
    if (fabs(a.spread - b.spread) > 5.0 * sd_s + 1e-4 * a.spread)
        fail_msg("spread: %g vs %g (sd %g)", a.spread, b.spread, sd_s);
    /* the floor's coarse histogram, cell by cell */
    for (int i = 0; i < GRID; i++)
        for (int j = 0; j < GRID; j++) {
            double sd = sigma(a.cell2[i][j], b.cell2[i][j]);
            if (fabs(a.cell[i][j] - b.cell[i][j]) >
                5.0 * sd + 1e-4 * a.cell[i][j])
                fail_msg("cell %d %d: %g vs %g (sd %g)", i, j, a.cell[i][j],
                         b.cell[i][j], sd);
        }
    /* wavelengths: uniform on [380, 780] nm in both (mean 580, sd
    ** 400/sqrt(12) = 115.47); the mean's standard error sd/sqrt(n), the
    ** sd's 0.447 sd/sqrt(n) (a uniform's kurtosis 1.8), each map against
    ** the uniform's at 5 of them and against each other */
    if (a.lam_n > 0 || b.lam_n > 0) {
        assert_true(a.lam_n > 1000 && b.lam_n > 1000);
        const double mu = 580.0, sd = 400.0 / sqrt(12.0);
        struct summary *s2[2] = { &a, &b };
        double mean[2], spread[2];
        for (int k = 0; k < 2 && by_count; k++) {
            mean[k] = s2[k]->lam / s2[k]->lam_n;
            spread[k] = sqrt(s2[k]->lam2 / s2[k]->lam_n - mean[k] * mean[k]);
            assert_true(fabs(mean[k] - mu) <= 5.0 * sd / sqrt(s2[k]->lam_n));
            assert_true(fabs(spread[k] - sd) <=
                        5.0 * 0.447 * sd / sqrt(s2[k]->lam_n));
        }
        assert_true(!by_count ||
                    fabs(mean[0] - mean[1]) <=
                        5.0 * sd * sqrt(1.0 / a.lam_n + 1.0 / b.lam_n));
        /* the power by wavelength (a light's emission, a dispersive
        ** path's): each band's sum as the power's above, 5 sd */
        for (int k = 0; k < BANDS; k++) {
            double sdb = sigma(a.band2[k], b.band2[k]);
            if (fabs(a.band[k] - b.band[k]) > 5.0 * sdb + 1e-4 * a.band[k])
                fail_msg("band %d: %g vs %g (sd %g)", k, a.band[k],
                         b.band[k], sdb);
        }
    }
    for (int k = 0; k < 2; k++)
        photon_map_destroy(m[k]);
    world_close(&w);
}

/* The floor's histogram about the origin (the ball's caustic) */
static void same_distribution(const char *sdl, uint64_t seed, int pass,
                              int per, bool by_count)
{
    same_distribution_in(sdl, seed, pass, per, by_count, false);
}

/* The histogram where the map's light lands (fit_window) */
static void same_distribution_fit(const char *sdl, uint64_t seed, int pass)
{
    same_distribution_in(sdl, seed, pass, 1, true, true);
}

static void test_ball(void **state)
{
    (void)state;
    same_distribution(BALL, 1, 0, 1, true);
    same_distribution(BALL, 77, 0, 1, true);
    /* a progressive pass: each photon uniform in its whole cell */
    same_distribution(BALL, 1, 3, 1, true);
}

static void test_dispersive_ball(void **state)
{
    (void)state;
    same_distribution(DISPERSIVE, 5, 0, 1, true);
}

/* A coloured light: a lane per sibling wavelength, each with the
** emission at its wavelength (the bands' powers), three records a path */
static void test_coloured_light(void **state)
{
    (void)state;
    same_distribution(ORANGE_BALL, 2, 0, 3, true);
    same_distribution(ORANGE_BALL, 2, 1, 3, true);
    same_distribution(ORANGE_MIRROR, 6, 0, 3, true);
}

/* Coloured filters under a white light: a lane per sibling wavelength,
** white records from sibling 0 alone until a filter makes the path
** chromatic (the white share), the transmittance at each lane's
** wavelength (the bands' powers) */
static void test_coloured_filter(void **state)
{
    (void)state;
    same_distribution(AMBER_BALL, 4, 0, 3, true);
    same_distribution(AMBER_BALL, 4, 2, 3, true);
    same_distribution(TINTED_MIRROR, 12, 0, 3, false);
}

static void test_mirror_filter(void **state)
{
    (void)state;
    same_distribution(MIRROR, 3, 0, 1, true);
    same_distribution(MIRROR, 91, 0, 1, true);
    /* the point light's cell_uniform */
    same_distribution(MIRROR, 3, 2, 1, true);
    same_distribution(WATER, 8, 0, 1, true);
}

/* Convex objects: the prism's spectrum (dispersive F2: chromatic records,
** their power by band), the lens's focus (two balls in one object, and
** the white records of its outside reflection), a rotated, unevenly
** scaled glass box, a dome (a ball and a half-space) and a mirror box,
** the gem (planes and a cylinder, internal reflections, cutting into the
** floor); pass 0 and a progressive pass (uniform in the cell). */
static void test_convex(void **state)
{
    (void)state;
    same_distribution_fit(PRISM, 21, 0);
    same_distribution_fit(PRISM, 22, 2);
    same_distribution_fit(LENS, 23, 0);
    same_distribution_fit(LENS, 24, 1);
    same_distribution(BOXES, 25, 0, 1, true);
    same_distribution(BOXES, 26, 3, 1, true);
    same_distribution_fit(GEM, 27, 0);
    same_distribution_fit(GEM, 28, 2);
}

/* The wavefront map does not depend on the thread count (random streams
** keyed by photon index, batches concatenated in order). */
static void test_threads(void **state)
{
    (void)state;
    const char *scenes[5] = { BALL, MIRROR, ORANGE_BALL, PRISM, BOXES };
    for (int k = 0; k < 5; k++) {
        struct world w;
        world_open(&w, scenes[k]);
        struct photon_stats st[2];
        struct photon_map *m1 = build(&w, false, 1, 9, &st[0]);
        struct photon_map *m2 = build(&w, false, 2, 9, &st[1]);
        assert_true(st[0].wavefront > 0);
        assert_int_equal(m1->store.n, m2->store.n);
        assert_memory_equal(m1->store.ph, m2->store.ph,
                            m1->store.n * sizeof *m1->store.ph);
        photon_map_destroy(m1);
        photon_map_destroy(m2);
        world_close(&w);
    }
}

/* A scene the wavefront does not take is the scalar tracer's, record for
** record; one it takes gives another sample (else the comparisons above
** compared the scalar map with itself). Outside: an ellipsoid, a scene
** too large for float against its target, a glass box on the floor, a
** difference, a cylinder, a concave prism. */
static void test_fallback(void **state)
{
    (void)state;
    const char *scenes[] = { SCALED, HUGE_GROUND, BOX_ON_BALL, DIFFERENCE,
                             CONE, CONCAVE_PRISM, BALL, LENS, GEM };
    const int n = (int)(sizeof scenes / sizeof *scenes), n_out = 6;
    for (int k = 0; k < n; k++) {
        struct world w;
        world_open(&w, scenes[k]);
        struct photon_stats st[2];
        struct photon_map *m1 = build(&w, false, 2, 4, &st[0]);
        struct photon_map *m2 = build(&w, true, 2, 4, &st[1]);
        assert_true(m1->store.n > 1000);
        bool same = m1->store.n == m2->store.n &&
                    memcmp(m1->store.ph, m2->store.ph,
                           m1->store.n * sizeof *m1->store.ph) == 0;
        if (k < n_out) {
            assert_int_equal(st[0].wavefront, 0);
            assert_true(same);
        } else {
            assert_int_equal(st[0].wavefront, st[0].shot);
            assert_false(same);
        }
        photon_map_destroy(m1);
        photon_map_destroy(m2);
        world_close(&w);
    }
}

/* The environment variable turns the wavefront off as the option does. */
static void test_environment(void **state)
{
    (void)state;
    struct world w;
    world_open(&w, BALL);
    struct photon_stats st;
    assert_int_equal(setenv("IRIS_NO_WAVEFRONT", "1", 1), 0);
    struct photon_map *m = build(&w, false, 1, 2, &st);
    assert_int_equal(st.wavefront, 0);
    photon_map_destroy(m);
    assert_int_equal(setenv("IRIS_NO_WAVEFRONT", "0", 1), 0);
    m = build(&w, false, 1, 2, &st);
    assert_int_equal(st.wavefront, st.shot);
    photon_map_destroy(m);
    assert_int_equal(unsetenv("IRIS_NO_WAVEFRONT"), 0);
    world_close(&w);
}

/* The kernel for any CPU gives the AVX2 kernel's map, record for record
** (the same float operations, none contracted). */
static void test_generic_kernel(void **state)
{
    (void)state;
    const char *scenes[7] = { BALL,  MIRROR, ORANGE_BALL, AMBER_BALL,
                              PRISM, BOXES,  GEM };
    for (int k = 0; k < 7; k++) {
        struct world w;
        world_open(&w, scenes[k]);
        struct photon_stats st[2];
        struct photon_map *m1 = build(&w, false, 2, 6, &st[0]);
        assert_int_equal(setenv("IRIS_WAVEFRONT_KERNEL", "generic", 1), 0);
        assert_string_equal(wf_kernel_name(), "generic");
        struct photon_map *m2 = build(&w, false, 2, 6, &st[1]);
        assert_int_equal(unsetenv("IRIS_WAVEFRONT_KERNEL"), 0);
        assert_true(st[1].wavefront > 0);
        assert_int_equal(m1->store.n, m2->store.n);
        assert_memory_equal(m1->store.ph, m2->store.ph,
                            m1->store.n * sizeof *m1->store.ph);
        photon_map_destroy(m1);
        photon_map_destroy(m2);
        world_close(&w);
    }
}

/*
** The lanes' Fresnel term against pmap_fresnel() (double): cos_i from 1
** to exactly 0 (grazing), relative indices into glass, out of it (the
** critical angle of 1.5 is cos_i = 0.745) and of a diamond, and 1. Float
** rounding of terms near 1: within 2e-6; past the critical angle exactly
** 1 and cos_t 0; every value finite, also for a NaN cosine (1).
*/
static void test_fresnel_lanes(void **state)
{
    (void)state;
    const float etas[6] = { 1.0f / 1.5f, 1.5f, 1.0f, 2.417f, 1.0f / 2.417f,
                            1.333f };
    enum { N = 101 };
    float ci[N], eta[N], f[N], ct[N];
    for (int e = 0; e < 6; e++) {
        for (int i = 0; i < N; i++) {
            ci[i] = (float)i / (N - 1);
            eta[i] = etas[e];
        }
        ci[3] = 1e-7f; /* just off grazing */
        wf_fresnel_lanes(ci, eta, f, ct, N);
        for (int i = 0; i < N; i++) {
            double ref_ct, ref = pmap_fresnel(ci[i], eta[i], &ref_ct);
            assert_true(isfinite(f[i]) && isfinite(ct[i]));
            assert_true(f[i] >= 0.0f && f[i] <= 1.0f);
            if (fabs(f[i] - ref) > 2e-6 || fabs(ct[i] - ref_ct) > 2e-6)
                fail_msg("eta %g cos_i %g: F %.9g vs %.9g, cos_t %.9g vs "
                         "%.9g", eta[i], ci[i], f[i], ref, ct[i], ref_ct);
            if (ref == 1.0 && ref_ct == 0.0) /* total internal reflection */
                assert_true(f[i] == 1.0f && ct[i] == 0.0f);
        }
    }
    float nan_ci = NAN, one = 1.5f, fn, ctn;
    wf_fresnel_lanes(&nan_ci, &one, &fn, &ctn, 1);
    assert_true(isfinite(fn) && isfinite(ctn));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ball),
        cmocka_unit_test(test_dispersive_ball),
        cmocka_unit_test(test_coloured_light),
        cmocka_unit_test(test_coloured_filter),
        cmocka_unit_test(test_mirror_filter),
        cmocka_unit_test(test_convex),
        cmocka_unit_test(test_threads),
        cmocka_unit_test(test_fallback),
        cmocka_unit_test(test_environment),
        cmocka_unit_test(test_generic_kernel),
        cmocka_unit_test(test_fresnel_lanes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
