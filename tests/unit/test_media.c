/* SPDX-License-Identifier: MIT */
/*
** test_media.c: participating media (src/render/media.c) on a scene
** double (render_double.c) whose answers follow from radiative transfer
** in closed form: a homogeneous absorbing slab transmits exp(-σd)
** (Beer-Lambert), an emitting one adds E·d, both together give
** bg·exp(-σd) + E(1 - exp(-σd))/σ; a density linear in x integrates to
** its mean; non-scattering-extinction in-scattering adds σs·L·d; shadow
** rays through an absorbing medium carry exp(-σ·chord).
**
** Tolerances: POV-Ray 3.7.0's method 3 (media.c) takes S = MIN/2 + 1
** pairs of samples at j/(S+1) of an interval, integrates each pair from
** its ends and middle with weights 1/3, and attenuates pair j by the
** depth of the pairs before it: exact for constant absorption alone and
** for emission alone (closed forms to 1e-9, double rounding), and for a
** density linear along the ray over the sampled part [0, S/(S+1)] of the
** interval. With both emission and absorption it is a left Riemann sum,
** within τ/S of the closed form: tested with S = 1001 to τ/S.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "testutil.h"

#include "iris/render.h"
#include "material/material.h"
#include "render/media.h"
#include "render/trace.h"
#include "render_double.h"
#include "util/mem.h"

#define MAX_OBJ 4

struct world {
    iris_scene scene;
    iris_object obj[MAX_OBJ];
    iris_object *objp[MAX_OBJ];
    iris_texture tex[MAX_OBJ];
    iris_pigment pig[MAX_OBJ];
    iris_finish fin[MAX_OBJ];
    iris_interior in[MAX_OBJ];
    iris_media media[MAX_OBJ];
    iris_media *mediap[MAX_OBJ];
    iris_light light[2];
    iris_light *lightp[2];
    iris_map_entry map[2];
    iris_pigment density;
    iris_pigment *densityp;
    struct dbl_scene dbl;
    struct rquery q;
    struct mat_ctx *mat;
    struct tracer tr;
    struct trace_ctx ctx;
};

static struct world *world_new(double bg)
{
    struct world *w = iris_calloc(1, sizeof *w);
    assert_non_null(w);
    iris_scene *s = &w->scene;
    s->version = 3.7;
    iris_global_defaults(&s->settings);
    s->objects = w->objp;
    s->lights = w->lightp;
    s->background = (iris_colour){ bg, bg, bg, 0, 0 };
    s->has_background = true;
    return w;
}

/* A sphere whose surface is invisible (transmit 1, no ambient or
** diffuse), holding a media with POV-Ray's defaults: 'hollow' decides
** whether rays from outside see it. */
static iris_media *media_sphere(struct world *w, vec3 c, double rad,
                                bool hollow)
{
    int i = w->scene.n_objects++;
    iris_object *o = &w->obj[i];
    o->kind = IRIS_OBJ_SPHERE;
    o->u.sphere.centre = c;
    o->u.sphere.radius = rad;
    o->hollow = hollow;
    o->photon_collect = true;
    w->pig[i].colour = (iris_colour){ 1, 1, 1, 0, 1 };
    iris_finish_defaults(&w->fin[i]);
    w->fin[i].ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    w->fin[i].diffuse = 0;
    w->tex[i].pigment = &w->pig[i];
    w->tex[i].finish = &w->fin[i];
    o->texture = &w->tex[i];
    iris_interior_defaults(&w->in[i]);
    iris_media_defaults(&w->media[i], 3.7);
    w->mediap[i] = &w->media[i];
    w->in[i].n_media = 1;
    w->in[i].media = &w->mediap[i];
    w->in[i].has_media = true;
    o->interior = &w->in[i];
    w->objp[i] = o;
    return &w->media[i];
}

/* A white floor y = 0 lit by diffuse 1 only. */
static void floor_plane(struct world *w)
{
    int i = w->scene.n_objects++;
    iris_object *o = &w->obj[i];
    o->kind = IRIS_OBJ_PLANE;
    o->u.plane.normal = v3(0, 1, 0);
    o->u.plane.distance = 0;
    o->photon_collect = true;
    w->pig[i].colour = (iris_colour){ 1, 1, 1, 0, 0 };
    iris_finish_defaults(&w->fin[i]);
    w->fin[i].ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    w->fin[i].diffuse = 1;
    w->tex[i].pigment = &w->pig[i];
    w->tex[i].finish = &w->fin[i];
    o->texture = &w->tex[i];
    w->objp[i] = o;
}

static iris_light *add_light(struct world *w, vec3 at, double c)
{
    int i = w->scene.n_lights++;
    iris_light *l = &w->light[i];
    iris_light_defaults(l);
    l->location = at;
    l->colour = (iris_colour){ c, c, c, 0, 0 };
    w->lightp[i] = l;
    return l;
}

static void world_build(struct world *w)
{
    w->dbl.n = w->scene.n_objects;
    w->dbl.objs = w->objp;
    dbl_query(&w->dbl, &w->q);
    assert_int_equal(mat_ctx_create(&w->scene, NULL, &w->mat), IRIS_OK);
    assert_true(tracer_init(&w->tr, &w->scene, w->mat, &w->q, 9));
    assert_true(trace_ctx_init(&w->ctx, &w->tr));
}

static void world_free(struct world *w)
{
    trace_ctx_fini(&w->ctx);
    tracer_fini(&w->tr);
    mat_ctx_destroy(w->mat);
    iris_free(w);
}

static void shoot(struct world *w, vec3 o, vec3 d, double rgb[3])
{
    dbl_shoot(&w->tr, &w->ctx, o, d, rgb);
}

/* Beer-Lambert: a ray through the centre of a hollow absorbing sphere of
** radius 1.5 crosses d = 3 of it: a white background arrives as
** exp(-σd) per channel. The same sphere without 'hollow' shows no media
** at all (POV-Ray computes media only on rays in hollow interiors). */
static void test_beer_lambert(void **state)
{
    (void)state;
    const double sigma[3] = { 0.1, 0.4, 1.3 }, d = 3.0;
    for (int hollow = 0; hollow < 2; hollow++) {
        struct world *w = world_new(1.0);
        iris_media *m = media_sphere(w, v3(0, 0, 0), d / 2, hollow);
        m->absorption = (iris_colour){ sigma[0], sigma[1], sigma[2], 0, 0 };
        world_build(w);
        double col[3];
        shoot(w, v3(0, 0, -5), v3(0, 0, 1), col);
        for (int k = 0; k < 3; k++)
            assert_near(col[k], hollow ? exp(-sigma[k] * d) : 1.0, 1e-9);
        world_free(w);
    }
}

/* Emission alone adds E·d to the black background; with absorption the
** transfer equation dL/ds = E - σL gives bg·exp(-σd) + E(1-exp(-σd))/σ
** (a white background here), which the Riemann sum of method 3 reaches
** within σd/S for S = 1001 sub-intervals, in one interval or in 7. */
static void test_emission(void **state)
{
    (void)state;
    const double e[3] = { 0.2, 0.5, 0.05 }, sigma[3] = { 0.3, 0.0, 2.0 };
    const double d = 2.0;
    for (int variant = 0; variant < 3; variant++) {
        bool absorb = variant > 0;
        struct world *w = world_new(absorb ? 1.0 : 0.0);
        iris_media *m = media_sphere(w, v3(0, 1, 0), d / 2, true);
        m->emission = (iris_colour){ e[0], e[1], e[2], 0, 0 };
        if (absorb)
            m->absorption = (iris_colour){ sigma[0], sigma[1], sigma[2],
                                           0, 0 };
        if (absorb)
            m->min_samples = m->max_samples = 2000; /* S = 1001 */
        if (variant == 2)
            m->intervals = 7;
        world_build(w);
        double col[3];
        shoot(w, v3(-4, 1, 0), v3(1, 0, 0), col);
        for (int k = 0; k < 3; k++) {
            double want;
            if (!absorb)
                want = e[k] * d;
            else if (sigma[k] == 0.0)
                want = 1.0 + e[k] * d;
            else
                want = exp(-sigma[k] * d) +
                       e[k] * (1.0 - exp(-sigma[k] * d)) / sigma[k];
            assert_near(col[k], want, absorb ? sigma[k] * d / 1001 : 1e-9);
            if (absorb && sigma[k] > 0.0) /* and it is not exact */
                assert_true(fabs(col[k] - want) > 1e-7);
        }
        world_free(w);
    }
}

/* A density pattern: 'gradient x' with colour_map [0 rgb 0][1 rgb 1] is
** the density x on 0 < x < 1. Through a sphere centred at x = 0.5 of
** radius 0.4 along x the chord is 0.8 long, from x = 0.1. Method 3
** (S = 6 with the default 10 samples) samples [0, 6/7] of it, exactly
** for a linear density: the mean density is x at the middle of that
** part, 0.1 + 0.4·6/7, and τ = σ·0.8·(0.1 + 0.4·6/7). With S = 1001 τ
** tends to σ·∫ x dx from 0.1 to 0.9 = 0.4σ (to σ·0.32/1002). */
static void test_density_gradient(void **state)
{
    (void)state;
    const double sigma = 2.5;
    struct world *w = world_new(1.0);
    iris_media *m = media_sphere(w, v3(0.5, 0, 0), 0.4, true);
    m->absorption = (iris_colour){ sigma, sigma, sigma, 0, 0 };
    iris_pigment *dn = &w->density;
    dn->pattern.kind = IRIS_PAT_GRADIENT;
    dn->pattern.vector = (iris_vec3){ 1, 0, 0 };
    dn->pattern.frequency = 1;
    iris_transform_identity(&dn->pattern.transform);
    w->map[0] = (iris_map_entry){ .value = 0,
                                  .colour = { 0, 0, 0, 0, 0 } };
    w->map[1] = (iris_map_entry){ .value = 1,
                                  .colour = { 1, 1, 1, 0, 0 } };
    dn->entries = w->map;
    dn->n_entries = 2;
    w->densityp = dn;
    m->densities = &w->densityp;
    m->n_densities = 1;
    world_build(w);
    double col[3];
    shoot(w, v3(-1, 0, 0), v3(1, 0, 0), col);
    for (int k = 0; k < 3; k++)
        assert_near(col[k], exp(-sigma * 0.8 * (0.1 + 0.4 * 6.0 / 7.0)),
                    1e-9);
    trace_ctx_fini(&w->ctx);
    tracer_fini(&w->tr);
    mat_ctx_destroy(w->mat);
    m->min_samples = m->max_samples = 2000;
    world_build(w);
    shoot(w, v3(-1, 0, 0), v3(1, 0, 0), col);
    for (int k = 0; k < 3; k++)
        assert_near(col[k], exp(-0.4 * sigma), sigma * 0.32 / 1002);
    world_free(w);
}

/* In-scattering: an isotropic scatterer (phase 1 in POV-Ray's units)
** with 'extinction 0' neither dims the background nor the light, so a
** light of colour c adds σs·c·d; POV-Ray's lights do not fall off with
** distance. Rayleigh's phase 0.799372013·(1 + cos²) is checked with the
** light far off to the side (cos ≈ 0 to 1e-6). A shadowless light (a
** fill light) does not interact with media. */
static void test_scattering(void **state)
{
    (void)state;
    const double ss = 0.3, c = 0.8, d = 2.0;
    for (int variant = 0; variant < 3; variant++) {
        struct world *w = world_new(0.0);
        iris_media *m = media_sphere(w, v3(0, 0, 0), d / 2, true);
        m->scattering = (iris_colour){ ss, ss, ss, 0, 0 };
        m->sc_ext = 0.0;
        iris_light *l = add_light(w, v3(0, 1e7, 0), c);
        if (variant == 1)
            m->scattering_type = IRIS_SCATTER_RAYLEIGH;
        if (variant == 2)
            l->shadowless = true;
        world_build(w);
        double col[3];
        shoot(w, v3(0, 0, -5), v3(0, 0, 1), col);
        double k = variant == 1 ? 0.799372013 : 1.0;
        double want = variant == 2 ? 0.0 : k * ss * c * d;
        for (int i = 0; i < 3; i++)
            assert_near(col[i], want, 1e-6);
        world_free(w);
    }
}

/* Shadow rays: the floor point under a hollow absorbing sphere (centre
** (0, 2, 0), radius 1) is lit through a chord of 2 by a light straight
** above: diffuse 1 · cos 0 · exp(-2σ). The eye ray from the side misses
** the sphere. */
static void test_shadow_attenuation(void **state)
{
    (void)state;
    const double sigma[3] = { 0.2, 0.7, 1.1 };
    struct world *w = world_new(0.0);
    floor_plane(w);
    iris_media *m = media_sphere(w, v3(0, 2, 0), 1.0, true);
    m->absorption = (iris_colour){ sigma[0], sigma[1], sigma[2], 0, 0 };
    add_light(w, v3(0, 10, 0), 1.0);
    world_build(w);
    double col[3];
    shoot(w, v3(2, 0.5, 0), v3(-2, -0.5, 0), col);
    for (int k = 0; k < 3; k++)
        assert_near(col[k], exp(-2.0 * sigma[k]), 1e-9);
    world_free(w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_beer_lambert),
        cmocka_unit_test(test_emission),
        cmocka_unit_test(test_density_gradient),
        cmocka_unit_test(test_scattering),
        cmocka_unit_test(test_shadow_attenuation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
