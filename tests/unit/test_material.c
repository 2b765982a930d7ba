/* SPDX-License-Identifier: MIT */
/*
** test_material.c: noise, patterns, colour maps, texture stacks and the
** optical helpers of src/material against independent expectations.
**
** The noise-based expectations are POV-Ray 3.7.0.10's own output: each
** pattern was rendered on the plane z = 0 through an 8 x 8 orthographic
** camera with
**
**   camera { orthographic location <0,0,-1> direction z right 8*x up 8*y }
**   plane { z, 0 pigment { PATTERN color_map {[0 rgb 0][1 rgb 1]}
**           translate <0.123,0.456,0.789> scale 0.7 }
**           finish { ambient 1 diffuse 0 } }
**
** (+FE, linear half-float OpenEXR) and pixel (i, j) read back with
** oiiotool --dumpdata. Pixel (i, j) sees world point (8 x0, 8 y0, 0) with
** x0 = (i + .5)/8 - .5, y0 = .5 - (j + .5)/8, i.e. pattern point
** (8 x0/0.7 - 0.123, 8 y0/0.7 - 0.456, -0.789). Half floats carry 11
** significant bits, so values below 1 are exact to 2.5e-4; the tolerance
** is 5e-4.
*/
#include "config.h"

#include <string.h>

#include "testutil.h"

#include "material/mat_internal.h"
#include "material/material.h"
#include "material/noise.h"
#include "math/transform.h"

#define HALF_TOL 5e-4

/* The pattern-space point of pixel (i, j) of the reference renders. */
static vec3 ref_point(int i, int j)
{
    double x0 = (i + 0.5) / 8 - 0.5, y0 = 0.5 - (j + 0.5) / 8;
    return v3(8 * x0 / 0.7 - 0.123, 8 * y0 / 0.7 - 0.456, -0.789);
}

struct ref_value {
    int i, j;
    double v;
};

static double eval_kind(enum iris_pattern_kind kind, int gen, double turb,
                        enum iris_wave wave, double param0, vec3 q)
{
    iris_pattern pat;
    iris_warp w;
    memset(&pat, 0, sizeof pat);
    memset(&w, 0, sizeof w);
    pat.kind = kind;
    pat.noise_generator = gen;
    pat.frequency = 1;
    pat.wave = wave;
    pat.params[0] = param0;
    if (turb > 0) {
        w.kind = IRIS_WARP_TURBULENCE;
        w.turbulence = v3(turb, turb, turb);
        w.octaves = 6;
        w.omega = 0.5;
        w.lambda = 2;
        pat.n_warps = 1;
        pat.warps = &w;
    }
    double v = pat_eval_at(NULL, &pat, pat_space(NULL, &pat, q), NULL);
    return v > 1 ? 1 : v; /* the colour map clamps above its last entry */
}

static void check_refs(enum iris_pattern_kind kind, int gen, double turb,
                       enum iris_wave wave, double param0,
                       const struct ref_value *refs, int n)
{
    for (int k = 0; k < n; k++)
        assert_near(eval_kind(kind, gen, turb, wave, param0,
                              ref_point(refs[k].i, refs[k].j)),
                    refs[k].v, HALF_TOL);
}

static void test_noise_generators(void **state)
{
    (void)state;
    static const struct ref_value g1[] = {
        { 0, 0, 0.36523 }, { 3, 2, 0.55811 }, { 4, 4, 0.46606 },
        { 5, 7, 0.63867 } };
    static const struct ref_value g2[] = {
        { 0, 0, 0.44946 }, { 3, 2, 0.54395 }, { 4, 4, 0.49902 },
        { 5, 7, 0.58350 } };
    static const struct ref_value g3[] = {
        { 0, 0, 0.37817 }, { 3, 2, 0.21716 }, { 4, 4, 0.75146 },
        { 5, 7, 0.89307 } };
    check_refs(IRIS_PAT_BOZO, 1, 0, IRIS_WAVE_RAMP, 0, g1, 4);
    check_refs(IRIS_PAT_BOZO, 2, 0, IRIS_WAVE_RAMP, 0, g2, 4);
    check_refs(IRIS_PAT_BOZO, 3, 0, IRIS_WAVE_RAMP, 0, g3, 4);
}

static void test_noise_patterns(void **state)
{
    (void)state;
    static const struct ref_value granite[] = {
        { 0, 0, 0.50098 }, { 3, 2, 0.30493 }, { 4, 4, 0.31470 },
        { 5, 7, 0.44751 } };
    static const struct ref_value wrinkles[] = {
        { 0, 0, 0.51025 }, { 3, 2, 0.59668 }, { 4, 4, 0.44751 },
        { 5, 7, 0.64990 } };
    /* marble turbulence 0.5 (classic turbulence, triangle wave) */
    static const struct ref_value marble[] = {
        { 0, 0, 0.76367 }, { 3, 2, 0.49121 }, { 4, 4, 0.06464 },
        { 5, 7, 0.66992 } };
    static const struct ref_value agate[] = {
        { 0, 0, 0.73535 }, { 3, 2, 0.11621 }, { 4, 4, 0.99365 },
        { 5, 7, 0.07471 } };
    static const struct ref_value ripples[] = {
        { 0, 0, 0.40332 }, { 3, 2, 0.45825 }, { 4, 4, 0.48145 },
        { 5, 7, 0.42456 } };
    check_refs(IRIS_PAT_GRANITE, 2, 0, IRIS_WAVE_RAMP, 0, granite, 4);
    check_refs(IRIS_PAT_WRINKLES, 2, 0, IRIS_WAVE_RAMP, 0, wrinkles, 4);
    check_refs(IRIS_PAT_MARBLE, 2, 0.5, IRIS_WAVE_TRIANGLE, 0, marble, 4);
    check_refs(IRIS_PAT_AGATE, 2, 0, IRIS_WAVE_RAMP, 1.0, agate, 4);
    check_refs(IRIS_PAT_RIPPLES, 2, 0, IRIS_WAVE_RAMP, 0, ripples, 4);
}

/* cells and crackle read POV-Ray's MT19937 table through the noise hash. */
static void test_cells_crackle(void **state)
{
    (void)state;
    static const struct ref_value cells[] = {
        { 0, 0, 0.85938 }, { 3, 2, 0.09271 }, { 4, 4, 0.57373 },
        { 5, 7, 0.11560 } };
    static const struct ref_value crackle[] = {
        { 0, 0, 0.07715 }, { 3, 2, 0.55078 }, { 4, 4, 0.00662 },
        { 5, 7, 0.60059 } };
    check_refs(IRIS_PAT_CELLS, 2, 0, IRIS_WAVE_RAMP, 0, cells, 4);
    check_refs(IRIS_PAT_CRACKLE, 2, 0, IRIS_WAVE_RAMP, 0, crackle, 4);
    /* MT19937 seeded 5489: the first output is 3499211612 (the reference
    ** value of the generator's specification). */
    assert_near(pat_rand(0), 3499211612.0 / 4294967296.0, 1e-15);
}

/* The pattern's value without the colour map's clamp at 1. */
static double simple(enum iris_pattern_kind kind, vec3 p)
{
    iris_pattern pat;
    memset(&pat, 0, sizeof pat);
    pat.kind = kind;
    pat.frequency = 1;
    return pat_eval_at(NULL, &pat, p, NULL);
}

/* Checker, brick and hexagon are exact tilings: values by hand from the
** definitions in the POV-Ray documentation. */
static void test_list_patterns(void **state)
{
    (void)state;
    assert_near(simple(IRIS_PAT_CHECKER, v3(0.5, 0.5, 0.5)), 0, 0);
    assert_near(simple(IRIS_PAT_CHECKER, v3(1.5, 0.5, 0.5)), 1, 0);
    assert_near(simple(IRIS_PAT_CHECKER, v3(-0.5, 0.5, 0.5)), 1, 0);
    assert_near(simple(IRIS_PAT_CHECKER, v3(-0.5, -0.5, 0.5)), 0, 0);
    /* the epsilon puts exact integers in the upper cell */
    assert_near(simple(IRIS_PAT_CHECKER, v3(1.0, 0.5, 0.5)), 1, 0);

    iris_pattern brick;
    memset(&brick, 0, sizeof brick);
    brick.kind = IRIS_PAT_BRICK;
    brick.brick_size = v3(8, 3, 4.5);
    brick.mortar = 0.5;
    /* mortar layer: y just above a multiple of the brick height */
    assert_near(pat_eval_at(NULL, &brick, v3(2, 2.8, 1), NULL), 0, 0);
    /* inside the first brick course, away from the vertical joints */
    assert_near(pat_eval_at(NULL, &brick, v3(2, 1.5, 1), NULL), 1, 0);
    /* odd course: the vertical joint at x = 0 (x + mortar in [0, m]) */
    assert_near(pat_eval_at(NULL, &brick, v3(-0.3, 1.5, 1), NULL), 0, 0);
    /* even course (y in [3,6)): joints shifted by half a brick, x = 4 */
    assert_near(pat_eval_at(NULL, &brick, v3(3.8, 4.5, 1), NULL), 0, 0);
    assert_near(pat_eval_at(NULL, &brick, v3(-0.3, 4.5, 2.0), NULL), 1, 0);

    /* hexagon: colours checked point by point against POV-Ray 3.7.0.10
    ** (plane y=0, pigment { hexagon }, its blue/green/red default map,
    ** seen by a 1-pixel orthographic camera above each point) */
    assert_near(simple(IRIS_PAT_HEXAGON, v3(0.01, 0, 0.01)), 0, 0);
    assert_near(simple(IRIS_PAT_HEXAGON, v3(1.5, 0, 0.866)), 2, 0);
    assert_near(simple(IRIS_PAT_HEXAGON, v3(-1.5, 0, 0.866)), 2, 0);
    assert_near(simple(IRIS_PAT_HEXAGON, v3(0, 0, 1.732)), 1, 0);
    assert_near(simple(IRIS_PAT_HEXAGON, v3(3.0, 0, 0.01)), 0, 0);
    assert_near(simple(IRIS_PAT_HEXAGON, v3(0.7, 0, -0.5)), 0, 0);
}

static void test_value_patterns(void **state)
{
    (void)state;
    iris_pattern g;
    memset(&g, 0, sizeof g);
    g.kind = IRIS_PAT_GRADIENT;
    g.vector = v3(1, 0, 0);
    g.frequency = 1;
    assert_near(pat_eval_at(NULL, &g, v3(0.25, 7, 7), NULL), 0.25, 1e-12);
    assert_near(pat_eval_at(NULL, &g, v3(1.25, 7, 7), NULL), 0.25, 1e-12);
    /* negative values wrap into [0, 1) */
    assert_near(pat_eval_at(NULL, &g, v3(-0.25, 7, 7), NULL), 0.75, 1e-12);
    /* frequency 2, phase 0.1 */
    g.frequency = 2;
    g.phase = 0.1;
    assert_near(pat_eval_at(NULL, &g, v3(0.2, 0, 0), NULL), 0.5, 1e-12);
    /* sine wave: 0.5 (1 + sin(2 pi v)) */
    g.frequency = 1;
    g.phase = 0;
    g.wave = IRIS_WAVE_SINE;
    assert_near(pat_eval_at(NULL, &g, v3(0.25, 0, 0), NULL), 1.0, 1e-12);
    g.wave = IRIS_WAVE_TRIANGLE;
    assert_near(pat_eval_at(NULL, &g, v3(0.25, 0, 0), NULL), 0.5, 1e-12);
    assert_near(pat_eval_at(NULL, &g, v3(0.75, 0, 0), NULL), 0.5, 1e-12);

    /* density patterns are 1 at the centre and 0 from radius 1 on */
    assert_near(simple(IRIS_PAT_SPHERICAL, v3(0.6, 0, 0.8)), 0.0, 1e-12);
    assert_near(simple(IRIS_PAT_SPHERICAL, v3(0.3, 0, 0.4)), 0.5, 1e-12);
    assert_near(simple(IRIS_PAT_BOXED, v3(0.25, -0.5, 0.1)), 0.5, 1e-12);
    assert_near(simple(IRIS_PAT_CYLINDRICAL, v3(0.3, 9, 0.4)), 0.5, 1e-12);
    assert_near(simple(IRIS_PAT_PLANAR, v3(5, -0.25, 5)), 0.75, 1e-12);
    assert_near(simple(IRIS_PAT_ONION, v3(0, 2.5, 0)), 0.5, 1e-12);
    /* radial: 0.25 + (atan2(x, z) + pi) / 2 pi */
    assert_near(simple(IRIS_PAT_RADIAL, v3(0, 0, 1)), 0.75, 1e-12);
    assert_near(simple(IRIS_PAT_RADIAL, v3(-1, 0, 0)), 0.5, 1e-12);
}

/* A pattern transform maps world to pattern space with 'inv'. */
static void test_pattern_transform(void **state)
{
    (void)state;
    iris_pattern g;
    memset(&g, 0, sizeof g);
    g.kind = IRIS_PAT_GRADIENT;
    g.vector = v3(1, 0, 0);
    g.has_transform = true;
    xf_identity(&g.transform);
    /* scale 4: m = diag(4), inv = diag(1/4) */
    for (int i = 0; i < 3; i++) {
        g.transform.m[i][i] = 4;
        g.transform.inv[i][i] = 0.25;
    }
    assert_near(pat_value(NULL, &g, v3(1, 0, 0), NULL), 0.25, 1e-12);
}

static iris_colour rgb(double r, double g, double b)
{
    iris_colour c = { r, g, b, 0, 0 };
    return c;
}

/* Colour map: linear blend between neighbours, ends held. */
static void test_colour_map(void **state)
{
    (void)state;
    iris_map_entry e[3];
    memset(e, 0, sizeof e);
    e[0].value = 0.2; e[0].colour = rgb(1, 0, 0);
    e[1].value = 0.6; e[1].colour = rgb(0, 1, 0);
    e[2].value = 0.6; e[2].colour = rgb(0, 0, 1);
    iris_pigment pig;
    memset(&pig, 0, sizeof pig);
    pig.pattern.kind = IRIS_PAT_GRADIENT;
    pig.pattern.vector = v3(1, 0, 0);
    pig.n_entries = 3;
    pig.entries = e;
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    iris_colour c;
    pt.p = v3(0.1, 0, 0); /* below the first entry */
    assert_true(mat_eval_pigment(NULL, &pig, &pt, &c));
    assert_near(c.r, 1, 1e-12);
    pt.p = v3(0.3, 0, 0); /* a quarter of the way from 0.2 to 0.6 */
    mat_eval_pigment(NULL, &pig, &pt, &c);
    assert_near(c.r, 0.75, 1e-12);
    assert_near(c.g, 0.25, 1e-12);
    pt.p = v3(0.7, 0, 0); /* past the sharp step at 0.6 */
    mat_eval_pigment(NULL, &pig, &pt, &c);
    assert_near(c.b, 1, 1e-12);
    assert_near(c.g, 0, 1e-12);
    /* checker without a map: POV-Ray's blue/green default */
    iris_pigment ck;
    memset(&ck, 0, sizeof ck);
    ck.pattern.kind = IRIS_PAT_CHECKER;
    pt.p = v3(0.5, 0.5, 0.5);
    mat_eval_pigment(NULL, &ck, &pt, &c);
    assert_near(c.b, 1, 0);
    pt.p = v3(1.5, 0.5, 0.5);
    mat_eval_pigment(NULL, &ck, &pt, &c);
    assert_near(c.g, 1, 0);
}

/*
** checker() takes its floors by truncation to an integer (pattern.c
** checker_floor): the pattern must be POV-Ray's definition, the parity of
** floor(x + 1e-10) + floor(y + 1e-10) + floor(z + 1e-10) with libm's
** floor, at every point: cell edges and the points a hair either side
** (where truncation and floor part for negatives), -0, magnitudes up to
** 2^52 (the last with fractions), past it (integers only) and past 2^62
** (floor() itself), and a pseudo-random sweep over 40 octaves.
*/
static double checker_def(vec3 p)
{
    double s = floor(p.x + 1e-10) + floor(p.y + 1e-10) + floor(p.z + 1e-10);
    return ((long long)s & 1) ? 1.0 : 0.0;
}

static void test_checker_exact(void **state)
{
    (void)state;
    const double edge[] = { 0.0, -0.0, 1.0, -1.0, 2.0, -3.0, 1e-10, -1e-10,
                            0.5, -0.5, 1e6 + 0.5, -1e6 - 0.5,
                            0x1p52, -0x1p52, 0x1p52 - 0.5, -0x1p52 + 0.5,
                            0x1p53 + 2.0, -0x1p53 - 2.0, 1e17, -1e17,
                            0x1p62, -0x1p62, 0x1p61 + 1024.0, 5e18, -5e18 };
    const int ne = (int)(sizeof edge / sizeof edge[0]);
    int ones = 0, n = 0;
    for (int a = 0; a < ne; a++)
        for (int b = 0; b < ne; b++) {
            /* the sum of the three stays inside long long's range */
            if (fabs(edge[a]) > 1e18 && fabs(edge[b]) > 1e18)
                continue;
            bool big = fabs(edge[a]) > 1e18 || fabs(edge[b]) > 1e18;
            for (int k = -1; k <= 1; k++) {
                /* a hair below, at and above the value: the epsilon
                ** moves the cell edge to -1e-10 */
                double x = edge[a] + k * 1e-10 - 1e-10;
                vec3 p = v3(x, edge[b], big ? 0.25 : -7.75);
                double want = checker_def(p);
                assert_true(simple(IRIS_PAT_CHECKER, p) == want);
                p = v3(nextafter(edge[b] - 1e-10, -INFINITY), x, 0.5);
                assert_true(simple(IRIS_PAT_CHECKER, p) == checker_def(p));
                ones += want == 1.0;
                n++;
            }
        }
    /* both values occur (21 % ones: most edges are even) */
    assert_true(ones > n / 10 && ones < 9 * n / 10);
    uint64_t r = 88172645463325252u;
    for (int i = 0; i < 200000; i++) {
        double c[3];
        for (int k = 0; k < 3; k++) {
            r ^= r << 13;
            r ^= r >> 7;
            r ^= r << 17;
            double u = (double)(r >> 11) * 0x1p-53;
            int oct = (int)(r % 40) - 8;      /* 2^-8 .. 2^31 */
            c[k] = ldexp(u, oct) * ((r >> 5) & 1 ? -1.0 : 1.0);
        }
        vec3 p = v3(c[0], c[1], c[2]);
        assert_true(simple(IRIS_PAT_CHECKER, p) == checker_def(p));
    }
}

/*
** A texture_map whose value falls on an entry, or a material_map, takes
** that entry whole (texture.c eval_entry_whole): over no layers the
** entry's own evaluation is the result, one stack of weight 1 holding its
** layers top first; an entry that blends (a texture_map of its own) keeps
** its two stacks and weights; with a plain layer on top of the map that
** layer heads every stack. Expectations from the texture_map rules
** (entry value v: weight 1 at v exactly, (v - v0) / (v1 - v0) between).
*/
static void test_map_entry_whole(void **state)
{
    (void)state;
    iris_finish f;
    memset(&f, 0, sizeof f);
    f.diffuse = 0.6;
    iris_pigment pr, pg, pb, pt_top;
    memset(&pr, 0, sizeof pr);
    memset(&pg, 0, sizeof pg);
    memset(&pb, 0, sizeof pb);
    memset(&pt_top, 0, sizeof pt_top);
    pr.colour = rgb(1, 0, 0);
    pr.colour.t = 0.5;          /* see-through: the layer below counts */
    pg.colour = rgb(0, 1, 0);
    pb.colour = rgb(0, 0, 1);
    pt_top.colour.f = 0.25;
    iris_texture tr, tg, tb, inner, map, top;
    memset(&tr, 0, sizeof tr);
    memset(&tg, 0, sizeof tg);
    memset(&tb, 0, sizeof tb);
    memset(&inner, 0, sizeof inner);
    memset(&map, 0, sizeof map);
    memset(&top, 0, sizeof top);
    tr.pigment = &pr; tr.finish = &f; tr.next = &tg; /* 2 plain layers */
    tg.pigment = &pg; tg.finish = &f;
    tb.pigment = &pb; tb.finish = &f;
    /* inner: gradient y, green at 0, blue at 1 */
    iris_map_entry ie[2];
    memset(ie, 0, sizeof ie);
    ie[0].value = 0; ie[0].texture = &tg;
    ie[1].value = 1; ie[1].texture = &tb;
    inner.map_pattern.kind = IRIS_PAT_GRADIENT;
    inner.map_pattern.vector = v3(0, 1, 0);
    inner.n_entries = 2;
    inner.entries = ie;
    /* map: gradient x, the 2-layer list at 0, inner at 0.5, blue at 1 */
    iris_map_entry e[3];
    memset(e, 0, sizeof e);
    e[0].value = 0; e[0].texture = &tr;
    e[1].value = 0.5; e[1].texture = &inner;
    e[2].value = 1; e[2].texture = &tb;
    map.map_pattern.kind = IRIS_PAT_GRADIENT;
    map.map_pattern.vector = v3(1, 0, 0);
    map.n_entries = 3;
    map.entries = e;
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.n = v3(0, 1, 0);
    struct mat_eval ev;

    /* x = 0: the list entry whole, red over green */
    pt.p = v3(0, 0.3, 0);
    mat_eval_texture(NULL, &map, &pt, &ev);
    assert_int_equal(ev.n_stacks, 1);
    assert_true(ev.stacks[0].weight == 1.0);
    assert_int_equal(ev.stacks[0].first, 0);
    assert_int_equal(ev.stacks[0].n, 2);
    assert_int_equal(ev.n_layers, 2);
    assert_true(ev.layers[0].pigment.r == 1 && ev.layers[0].pigment.t == 0.5);
    assert_true(ev.layers[1].pigment.g == 1);
    assert_true(ev.layers[0].finish == &f && ev.layers[0].valid);

    /* x = 0.5: the inner map whole, at y = 0.3 green 0.7, blue 0.3 */
    pt.p = v3(0.5, 0.3, 0);
    mat_eval_texture(NULL, &map, &pt, &ev);
    assert_int_equal(ev.n_stacks, 2);
    double wg = 0, wb = 0;
    for (int s = 0; s < 2; s++) {
        assert_int_equal(ev.stacks[s].n, 1);
        const struct mat_layer *l = &ev.layers[ev.stacks[s].first];
        if (l->pigment.g == 1) wg = ev.stacks[s].weight;
        if (l->pigment.b == 1) wb = ev.stacks[s].weight;
    }
    assert_near(wg, 0.7, 1e-12);
    assert_near(wb, 0.3, 1e-12);
    assert_near(ev.stacks[0].weight, 0.7, 1e-12); /* heaviest first */

    /* a plain layer over the map: on top of the entry's layers */
    top.pigment = &pt_top; top.finish = &f; top.next = &map;
    pt.p = v3(0, 0.3, 0);
    mat_eval_texture(NULL, &top, &pt, &ev);
    assert_int_equal(ev.n_stacks, 1);
    assert_true(ev.stacks[0].weight == 1.0);
    assert_int_equal(ev.stacks[0].n, 3);
    assert_true(ev.layers[ev.stacks[0].first].pigment.f == 0.25);
    assert_true(ev.layers[ev.stacks[0].first + 1].pigment.r == 1);
    assert_true(ev.layers[ev.stacks[0].first + 2].pigment.g == 1);

    /* and between two entries both are kept: x = 0.75, inner 0.5 and
    ** blue 0.5, the inner one split 0.7 / 0.3 */
    pt.p = v3(0.75, 0.3, 0);
    mat_eval_texture(NULL, &map, &pt, &ev);
    assert_int_equal(ev.n_stacks, 3);
    double sum = 0;
    for (int s = 0; s < 3; s++)
        sum += ev.stacks[s].weight;
    assert_near(sum, 1.0, 1e-12);
    assert_near(ev.stacks[0].weight, 0.5, 1e-12);
}

/* A texture_map splits into two weighted stacks; layers stack on top. */
static void test_texture_stacks(void **state)
{
    (void)state;
    iris_finish f;
    memset(&f, 0, sizeof f);
    f.diffuse = 0.6;
    iris_pigment pa, pb, pc;
    memset(&pa, 0, sizeof pa);
    memset(&pb, 0, sizeof pb);
    memset(&pc, 0, sizeof pc);
    pa.colour = rgb(1, 0, 0);
    pb.colour = rgb(0, 0, 1);
    pc.colour.t = 0.5;
    iris_texture ta, tb, top, map;
    memset(&ta, 0, sizeof ta);
    memset(&tb, 0, sizeof tb);
    memset(&top, 0, sizeof top);
    memset(&map, 0, sizeof map);
    ta.pigment = &pa; ta.finish = &f;
    tb.pigment = &pb; tb.finish = &f;
    iris_map_entry e[2];
    memset(e, 0, sizeof e);
    e[0].value = 0; e[0].texture = &ta;
    e[1].value = 1; e[1].texture = &tb;
    map.map_pattern.kind = IRIS_PAT_GRADIENT;
    map.map_pattern.vector = v3(1, 0, 0);
    map.n_entries = 2;
    map.entries = e;
    top.pigment = &pc; top.finish = &f; top.next = &map;
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(0.25, 0, 0);
    pt.n = v3(0, 1, 0);
    struct mat_eval ev;
    mat_eval_texture(NULL, &top, &pt, &ev);
    assert_int_equal(ev.n_stacks, 2);
    double wa = 0, wb = 0;
    for (int s = 0; s < ev.n_stacks; s++) {
        assert_int_equal(ev.stacks[s].n, 2);
        const struct mat_layer *l0 = &ev.layers[ev.stacks[s].first];
        const struct mat_layer *l1 = &ev.layers[ev.stacks[s].first + 1];
        assert_near(l0->pigment.t, 0.5, 0); /* the top layer first */
        if (l1->pigment.r == 1) wa = ev.stacks[s].weight;
        if (l1->pigment.b == 1) wb = ev.stacks[s].weight;
    }
    assert_near(wa, 0.75, 1e-12);
    assert_near(wb, 0.25, 1e-12);
}

/*
** A list of plain layers (mat_eval_layers' own loop, not eval_layer()):
** one stack, top first, ending at the first opaque layer (the one below
** it is never evaluated); a layer's normal{} perturbs the raw normal for
** that layer only, and quality below 8 (skip_normals) leaves it raw.
** Each layer must equal the layer evaluated alone.
*/
static void test_plain_layers(void **state)
{
    (void)state;
    iris_finish f;
    memset(&f, 0, sizeof f);
    f.diffuse = 0.6;
    iris_normal bumps;
    memset(&bumps, 0, sizeof bumps);
    bumps.pattern.kind = IRIS_PAT_BUMPS;
    bumps.amount = 0.5;
    iris_pigment p[4];
    memset(p, 0, sizeof p);
    p[0].colour = rgb(1, 0, 0);
    p[0].colour.t = 0.5;
    p[1].colour = rgb(0, 1, 0);
    p[1].colour.f = 0.3;
    p[2].colour = rgb(0, 0, 1);
    p[3].colour = rgb(1, 1, 1);
    iris_texture t[4];
    memset(t, 0, sizeof t);
    for (int i = 0; i < 4; i++) {
        t[i].pigment = &p[i];
        t[i].finish = &f;
        t[i].next = i < 3 ? &t[i + 1] : NULL;
    }
    t[0].normal = &bumps;
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(0.3, 0.1, 0.7);
    pt.n = v3(0, 1, 0);
    struct mat_eval ev;
    mat_eval_texture(NULL, &t[0], &pt, &ev);
    assert_int_equal(ev.n_stacks, 1);
    assert_int_equal(ev.n_layers, 3); /* t[3], below opaque t[2]: unused */
    assert_int_equal(ev.stacks[0].first, 0);
    assert_int_equal(ev.stacks[0].n, 3);
    assert_near(ev.stacks[0].weight, 1, 0);
    vec3 bumped = mat_perturb_normal(NULL, &bumps, &pt, pt.n);
    assert_true(fabs(bumped.y - 1) > 1e-6); /* the bumps do tilt it here */
    for (int i = 0; i < 3; i++) {
        const struct mat_layer *l = &ev.layers[i];
        assert_true(l->valid);
        assert_ptr_equal(l->finish, &f);
        assert_near(l->pigment.r, p[i].colour.r, 0);
        assert_near(l->pigment.g, p[i].colour.g, 0);
        assert_near(l->pigment.f, p[i].colour.f, 0);
        assert_near(l->pigment.t, p[i].colour.t, 0);
        vec3 n = i == 0 ? bumped : pt.n;
        assert_near(l->n.x, n.x, 0);
        assert_near(l->n.y, n.y, 0);
        assert_near(l->n.z, n.z, 0);
    }
    pt.skip_normals = true;
    mat_eval_texture(NULL, &t[0], &pt, &ev);
    assert_int_equal(ev.n_layers, 3);
    assert_near(ev.layers[0].n.y, 1, 0);
}

/* mat_fmax() and mat_fmin() give what libm's fmax() and fmin() give,
** bit for bit, on ordinary numbers, infinities, zeros and NaNs. */
static void test_fmax_fmin(void **state)
{
    (void)state;
    const double v[] = { 0.0, -0.0, 1.0, -1.0, 0.25, 1e308, -1e-308,
                         HUGE_VAL, -HUGE_VAL, NAN };
    int n = (int)(sizeof v / sizeof v[0]);
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            double a = v[i], b = v[j];
            double mx = mat_fmax(a, b), mn = mat_fmin(a, b);
            if (isnan(a) && isnan(b)) {
                assert_true(isnan(mx) && isnan(mn));
                continue;
            }
            /* both zeros: fmax/fmin may give either sign (C11 F.10.9.2),
            ** any other pair one value */
            if (a == 0 && b == 0) {
                assert_true(mx == 0 && mn == 0);
                continue;
            }
            assert_memory_equal(&mx, &(double){ fmax(a, b) }, sizeof mx);
            assert_memory_equal(&mn, &(double){ fmin(a, b) }, sizeof mn);
        }
}

/* POV-Ray's fresnel formula is the exact unpolarised Fresnel reflectance
** of a dielectric: compare with Rs and Rp from Snell's law. */
static void test_fresnel(void **state)
{
    (void)state;
    assert_near(mat_fresnel(1.0, 1.5), 0.04, 1e-12);
    assert_near(mat_fresnel(0.0, 1.5), 1.0, 1e-12);
    for (double deg = 5; deg < 89; deg += 7) {
        double ti = deg * M_PI / 180, n = 1.5;
        double tt = asin(sin(ti) / n);
        double rs = pow(sin(ti - tt) / sin(ti + tt), 2);
        double rp = pow(tan(ti - tt) / tan(ti + tt), 2);
        assert_near(mat_fresnel(cos(ti), n), 0.5 * (rs + rp), 1e-12);
    }
    /* inside glass past the critical angle: total reflection */
    assert_near(mat_fresnel(cos(60 * M_PI / 180), 1 / 1.5), 1.0, 0);
}

static void test_reflectivity(void **state)
{
    (void)state;
    iris_finish f;
    memset(&f, 0, sizeof f);
    f.reflection_max = rgb(0.8, 0.8, 0.8);
    f.reflection_min = rgb(0.2, 0.2, 0.2);
    f.reflection_falloff = 1;
    struct mat_layer l;
    memset(&l, 0, sizeof l);
    l.finish = &f;
    double r[3], w;
    /* standard: (1 - c) max + c min */
    assert_true(mat_layer_reflectivity(&l, 0.25, 1, r, &w));
    assert_near(r[0], 0.75 * 0.8 + 0.25 * 0.2, 1e-12);
    assert_near(w, 0.8, 1e-12);
    /* fresnel at normal incidence into n = 1.5: 0.04 max + 0.96 min */
    f.reflection_fresnel = true;
    mat_layer_reflectivity(&l, 1.0, 1.5, r, &w);
    assert_near(r[1], 0.04 * 0.8 + 0.96 * 0.2, 1e-12);
    assert_near(w, r[1], 1e-12);
    /* metallic 1 at normal incidence tints by the pigment: F(0) = 0 */
    f.reflection_fresnel = false;
    f.reflection_metallic = 1;
    l.pigment = rgb(1, 0.5, 0);
    mat_layer_reflectivity(&l, 1.0, 1, r, &w);
    assert_near(r[0], 0.2, 1e-12);
    assert_near(r[1], 0.1, 1e-12);
    assert_near(r[2], 0.0, 1e-12);
}

static void test_transmittance(void **state)
{
    (void)state;
    iris_colour c = { 1, 0.5, 0.25, 0.4, 0.2 };
    double t[3];
    mat_rgb_transm(&c, t);
    assert_near(t[0], 0.6, 1e-12);
    assert_near(t[1], 0.4, 1e-12);
    assert_near(t[2], 0.3, 1e-12);
    assert_near(mat_opacity(NULL, &c), 0.4, 1e-12);
    const double w[3] = { 1, 1, 1 };
    assert_near(mat_greyscale(w), 1.0, 1e-12);
}

/* Bumps: displaced by DNoise in pattern space, still a unit normal on the
** ray's side; amount 0 leaves it alone. */
static void test_normals(void **state)
{
    (void)state;
    iris_normal nrm;
    memset(&nrm, 0, sizeof nrm);
    nrm.pattern.kind = IRIS_PAT_BUMPS;
    nrm.amount = 0.5;
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(0.3, 0.1, 0.7);
    vec3 n0 = v3(0, 1, 0);
    vec3 n = mat_perturb_normal(NULL, &nrm, &pt, n0);
    assert_near(v3_len(n), 1, 1e-12);
    vec3 d = noise_vector(pt.p);
    vec3 expect = v3_norm(v3_madd(n0, d, 0.5));
    assert_near(n.x, expect.x, 1e-12);
    assert_near(n.z, expect.z, 1e-12);
    nrm.amount = 0;
    n = mat_perturb_normal(NULL, &nrm, &pt, n0);
    assert_near(n.y, 1, 1e-12);
    /* gradient x on the tetrahedron: sum_i v(q + d p_i) p_i = d (4/3) x,
    ** times -5 amount 0.02/d: a displacement of -(4/3) 5 (0.5) 0.02 x */
    iris_normal g;
    memset(&g, 0, sizeof g);
    g.pattern.kind = IRIS_PAT_GRADIENT;
    g.pattern.vector = v3(1, 0, 0);
    g.amount = 0.5;
    pt.p = v3(0.5, 0, 0);
    n = mat_perturb_normal(NULL, &g, &pt, n0);
    double a = 4.0 / 3.0 * 5 * 0.5 * 0.02;
    /* POV-Ray's tetrahedron is given to 9 digits */
    assert_near(n.x, -a / sqrt(1 + a * a), 1e-8);
    assert_near(n.y, 1 / sqrt(1 + a * a), 1e-8);
}

/* The mapping warps by hand from their definitions (POV-Ray's
** warp_planar, warp_cylindrical, warp_spherical, warp_toroidal): the
** angle around y from +x as a fraction of a turn, the height or latitude,
** and the distance. */
static vec3 warped(enum iris_warp_kind kind, vec3 orient, double off,
                   double major, vec3 p)
{
    iris_pattern pat;
    iris_warp w;
    memset(&pat, 0, sizeof pat);
    memset(&w, 0, sizeof w);
    w.kind = kind;
    w.orientation = orient;
    w.offset.x = off;
    w.major_radius = major;
    pat.kind = IRIS_PAT_GRADIENT;
    pat.n_warps = 1;
    pat.warps = &w;
    return pat_space(NULL, &pat, p);
}

static void test_mapping_warps(void **state)
{
    (void)state;
    vec3 z = v3(0, 0, 1);
    /* planar: z becomes the offset */
    vec3 q = warped(IRIS_WARP_PLANAR, z, 0.7, 0, v3(1, 2, 3));
    assert_near(q.x, 1, 1e-12); assert_near(q.y, 2, 1e-12);
    assert_near(q.z, 0.7, 1e-12);
    /* planar facing x: (o.x z, o.x y, -o.x x) */
    q = warped(IRIS_WARP_PLANAR, v3(2, 0, 0), 0, 0, v3(1, 2, 3));
    assert_near(q.x, 0, 1e-12); assert_near(q.y, 2, 1e-12);
    assert_near(q.z, -1, 1e-12);
    /* cylindrical: (0, .5, 2) is a quarter turn from +x at radius 2 */
    q = warped(IRIS_WARP_CYLINDRICAL, z, 0, 0, v3(0, 0.5, 2));
    assert_near(q.x, 0.25, 1e-12); assert_near(q.y, 0.5, 1e-12);
    assert_near(q.z, 2, 1e-12);
    /* three quarters of a turn below the x axis */
    q = warped(IRIS_WARP_CYLINDRICAL, z, 0, 0, v3(0, 0, -1));
    assert_near(q.x, 0.75, 1e-12);
    /* spherical: on the equator latitude 0.5; at the north pole 1 */
    q = warped(IRIS_WARP_SPHERICAL, z, 0, 0, v3(0, 0, 2));
    assert_near(q.x, 0.25, 1e-12); assert_near(q.y, 0.5, 1e-12);
    assert_near(q.z, 2, 1e-12);
    q = warped(IRIS_WARP_SPHERICAL, z, 0, 0, v3(0, 3, 0));
    assert_near(q.y, 1, 1e-12); assert_near(q.z, 3, 1e-12);
    /* toroidal, major radius 1: (2, 0, 0) is on the outer equator of the
    ** tube, half a turn around it from the inside, at distance 1 */
    q = warped(IRIS_WARP_TOROIDAL, z, 0, 1, v3(2, 0, 0));
    assert_near(q.x, 0, 1e-12); assert_near(q.y, 0.5, 1e-12);
    assert_near(q.z, 1, 1e-12);
    /* on the axis the angle is undefined: the point stays */
    q = warped(IRIS_WARP_CYLINDRICAL, z, 0, 0, v3(0, 5, 0));
    assert_near(q.y, 5, 0); assert_near(q.x, 0, 0);
}

/* mandel and julia by iterating z^2 + c by hand: (0.5, 0) escapes at the
** fourth step (0.75, 1.0625, 1.6289, 3.1533 > 2), the origin never. */
static void test_fractals(void **state)
{
    (void)state;
    iris_pattern m;
    memset(&m, 0, sizeof m);
    m.kind = IRIS_PAT_MANDEL;
    m.iterations = 10;
    assert_near(pat_eval_at(NULL, &m, v3(0.5, 0, 0), NULL), 0.3, 1e-12);
    assert_near(pat_eval_at(NULL, &m, v3(0, 0, 0), NULL), 1, 0);
    assert_near(pat_eval_at(NULL, &m, v3(2, 2, 0), NULL), 0, 0);
    /* julia with c = 0: the unit circle is the boundary; 1.2 escapes at
    ** the second step (1.44, 2.0736) */
    iris_pattern j = m;
    j.kind = IRIS_PAT_JULIA;
    assert_near(pat_eval_at(NULL, &j, v3(1.2, 0, 0), NULL), 0.1, 1e-12);
    assert_near(pat_eval_at(NULL, &j, v3(0.9, 0, 0), NULL), 1, 0);
}

/* An average texture_map weighs its entries (1 when written without a
** weight); a map pattern's warps move the points its entries see. */
static void test_average_and_entry_warps(void **state)
{
    (void)state;
    iris_finish f;
    memset(&f, 0, sizeof f);
    iris_pigment pa, pb;
    memset(&pa, 0, sizeof pa);
    memset(&pb, 0, sizeof pb);
    pa.colour = rgb(1, 0, 0);
    pb.colour = rgb(0, 0, 1);
    iris_texture ta, tb, map;
    memset(&ta, 0, sizeof ta);
    memset(&tb, 0, sizeof tb);
    memset(&map, 0, sizeof map);
    ta.pigment = &pa; ta.finish = &f;
    tb.pigment = &pb; tb.finish = &f;
    iris_map_entry e[2];
    memset(e, 0, sizeof e);
    e[0].value = 3; e[0].texture = &ta;
    e[1].value = 0; e[1].texture = &tb;
    map.map_pattern.kind = IRIS_PAT_AVERAGE;
    map.n_entries = 2;
    map.entries = e;
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(0.25, 0, 0);
    pt.n = v3(0, 1, 0);
    struct mat_eval ev;
    mat_eval_texture(NULL, &map, &pt, &ev);
    assert_int_equal(ev.n_stacks, 2);
    for (int s = 0; s < 2; s++) {
        const struct mat_layer *l = &ev.layers[ev.stacks[s].first];
        assert_near(ev.stacks[s].weight, l->pigment.r == 1 ? 0.75 : 0.25,
                    1e-12);
    }

    /* checker of two gradient pigments, the checker warped by a repeat
    ** warp of width 1 along x */
    iris_pigment gx, gy, ck;
    memset(&gx, 0, sizeof gx);
    memset(&gy, 0, sizeof gy);
    memset(&ck, 0, sizeof ck);
    gx.pattern.kind = IRIS_PAT_GRADIENT;
    gx.pattern.vector = v3(1, 0, 0);
    gy = gx;
    iris_map_entry ce[2];
    memset(ce, 0, sizeof ce);
    ce[0].value = 0; ce[0].pigment = &gx;
    ce[1].value = 1; ce[1].pigment = &gy;
    iris_warp w;
    memset(&w, 0, sizeof w);
    w.kind = IRIS_WARP_REPEAT;
    w.repeat = v3(1, 0, 0);
    w.flip = v3(0, 0, 0);
    ck.pattern.kind = IRIS_PAT_CHECKER;
    ck.pattern.n_warps = 1;
    ck.pattern.warps = &w;
    ck.n_entries = 2;
    ck.entries = ce;
    ck.is_pigment_map = true;
    /* block k of the repeat is shifted by k * 0.2: x = 3.3 (block 3)
    ** warps to 0.3 + 0.6 = 0.9, where the checker is 0 and the gradient
    ** entry, seeing the warped point, is grey 0.9; unwarped it would be
    ** 3.3 mod 1 = 0.3 */
    w.offset = v3(0.2, 0, 0);
    iris_colour c;
    pt.p = v3(3.3, 0.5, 0.5);
    mat_eval_pigment(NULL, &ck, &pt, &c);
    assert_near(c.r, 0.9, 1e-9);
}

/* The context-free evaluators src/fn calls for pattern functions. */
static void test_pattern_at(void **state)
{
    (void)state;
    iris_pigment g;
    memset(&g, 0, sizeof g);
    g.pattern.kind = IRIS_PAT_GRADIENT;
    g.pattern.vector = v3(0, 1, 0);
    g.pattern.frequency = 1;
    assert_near(mat_pattern_at(&g.pattern, 5, 0.25, 7), 0.25, 1e-12);
    iris_map_entry e[2];
    memset(e, 0, sizeof e);
    e[0].value = 0; e[0].colour = rgb(0, 0, 0);
    e[1].value = 1; e[1].colour = rgb(1, 0.5, 0);
    e[1].colour.t = 1;
    g.n_entries = 2;
    g.entries = e;
    double v[5];
    mat_pigment_at(&g, 0, 0.5, 0, v);
    assert_near(v[0], 0.5, 1e-12);
    assert_near(v[1], 0.25, 1e-12);
    assert_near(v[4], 0.5, 1e-12);
    mat_pigment_at(NULL, 0, 0, 0, v);
    assert_near(v[0], 0, 0);
}

/* Below quality 6 a pigment with a quick_colour is that colour (POV-Ray's
** Q_QUICKC); all zero means none was given. */
static void test_quick_colour(void **state)
{
    (void)state;
    struct mat_ctx *ctx = NULL;
    assert_int_equal(mat_ctx_create(NULL, NULL, &ctx), IRIS_OK);
    iris_pigment ck;
    memset(&ck, 0, sizeof ck);
    ck.pattern.kind = IRIS_PAT_CHECKER;
    ck.quick_colour = rgb(0.2, 0.8, 0.3);
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(0.5, 0.5, 0.5);
    iris_colour c;
    mat_eval_pigment(ctx, &ck, &pt, &c);
    assert_near(c.b, 1, 0); /* the checker's first default colour */
    mat_ctx_set_quick_colour(ctx, true);
    mat_eval_pigment(ctx, &ck, &pt, &c);
    assert_near(c.r, 0.2, 0);
    assert_near(c.g, 0.8, 0);
    memset(&ck.quick_colour, 0, sizeof ck.quick_colour);
    mat_eval_pigment(ctx, &ck, &pt, &c);
    assert_near(c.b, 1, 0);
    mat_ctx_destroy(ctx);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_noise_generators),
        cmocka_unit_test(test_noise_patterns),
        cmocka_unit_test(test_cells_crackle),
        cmocka_unit_test(test_list_patterns),
        cmocka_unit_test(test_checker_exact),
        cmocka_unit_test(test_value_patterns),
        cmocka_unit_test(test_pattern_transform),
        cmocka_unit_test(test_colour_map),
        cmocka_unit_test(test_texture_stacks),
        cmocka_unit_test(test_map_entry_whole),
        cmocka_unit_test(test_plain_layers),
        cmocka_unit_test(test_fmax_fmin),
        cmocka_unit_test(test_fresnel),
        cmocka_unit_test(test_reflectivity),
        cmocka_unit_test(test_transmittance),
        cmocka_unit_test(test_normals),
        cmocka_unit_test(test_mapping_warps),
        cmocka_unit_test(test_fractals),
        cmocka_unit_test(test_average_and_entry_warps),
        cmocka_unit_test(test_pattern_at),
        cmocka_unit_test(test_quick_colour),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
