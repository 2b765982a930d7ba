/* SPDX-License-Identifier: MIT */
/*
** test_render.c: camera rays, light attenuation, refraction, and the
** tracer and eye pass on a scene double (render_double.c) whose answers
** follow from geometry and POV-Ray's shading formulas
** (povray-3.7-semantics.md §3, §4.1).
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "testutil.h"

#include "iris/render.h"
#include "material/material.h"
#include "render/camera.h"
#include "render/eyepass.h"
#include "render/eyespectrum.h"
#include "render/focalblur.h"
#include "render/light.h"
#include "render/trace.h"
#include "math/transform.h"
#include "render_double.h"
#include "spectrum/spectrum.h"
#include "util/rng.h"
#include "util/mem.h"

/* ------------------------------------------------------------------ */
/* A small scene built by hand                                          */
/* ------------------------------------------------------------------ */

#define MAX_OBJ 8

struct world {
    iris_scene scene;
    iris_object obj[MAX_OBJ];
    iris_object *objp[MAX_OBJ];
    iris_texture tex[MAX_OBJ];
    iris_pigment pig[MAX_OBJ];
    iris_finish fin[MAX_OBJ];
    iris_interior in[MAX_OBJ];
    iris_light light[4];
    iris_light *lightp[4];
    struct dbl_scene dbl;
    struct rquery q;
    struct mat_ctx *mat;
    struct tracer tr;
    struct trace_ctx ctx;
};

static void world_init(struct world *w)
{
    memset(w, 0, sizeof *w);
    iris_scene *s = &w->scene;
    s->version = 3.7;
    s->settings.max_trace_level = 5;
    s->settings.adc_bailout = 1.0 / 255;
    s->settings.ambient_light.r = s->settings.ambient_light.g =
        s->settings.ambient_light.b = 1;
    s->settings.noise_generator = 2;
    s->settings.number_of_waves = 10;
    s->objects = w->objp;
    s->lights = w->lightp;
    s->camera.kind = IRIS_CAM_PERSPECTIVE;
    s->camera.location = v3(0, 1, -5);
    s->camera.direction = v3(0, 0, 1);
    s->camera.right = v3(1.33, 0, 0);
    s->camera.up = v3(0, 1, 0);
}

static iris_object *add_obj(struct world *w, enum iris_object_kind kind,
                            double r, double g, double b, double f, double t)
{
    int i = w->scene.n_objects++;
    iris_object *o = &w->obj[i];
    o->kind = kind;
    w->pig[i].colour = (iris_colour){ r, g, b, f, t };
    iris_finish_defaults(&w->fin[i]);
    w->tex[i].pigment = &w->pig[i];
    w->tex[i].finish = &w->fin[i];
    o->texture = &w->tex[i];
    o->photon_collect = true;
    w->objp[i] = o;
    return o;
}

static iris_object *add_sphere(struct world *w, vec3 c, double rad)
{
    iris_object *o = add_obj(w, IRIS_OBJ_SPHERE, 1, 1, 1, 0, 0);
    o->u.sphere.centre = c;
    o->u.sphere.radius = rad;
    return o;
}

static iris_object *add_plane(struct world *w, vec3 n, double d)
{
    iris_object *o = add_obj(w, IRIS_OBJ_PLANE, 1, 1, 1, 0, 0);
    o->u.plane.normal = n;
    o->u.plane.distance = d;
    return o;
}

static iris_finish *fin_of(struct world *w, iris_object *o)
{
    return &w->fin[o - w->obj];
}

static iris_pigment *pig_of(struct world *w, iris_object *o)
{
    return &w->pig[o - w->obj];
}

static iris_interior *glass(struct world *w, iris_object *o, double ior)
{
    iris_interior *in = &w->in[o - w->obj];
    in->ior = ior;
    in->dispersion = 1;
    in->dispersion_samples = 7;
    o->interior = in;
    return in;
}

static iris_light *add_light(struct world *w, vec3 at)
{
    int i = w->scene.n_lights++;
    iris_light *l = &w->light[i];
    memset(l, 0, sizeof *l);
    l->location = at;
    l->point_at = v3(0, 0, 1);
    l->colour = (iris_colour){ 1, 1, 1, 0, 0 };
    l->adaptive = 100;
    w->lightp[i] = l;
    return l;
}

static void world_build(struct world *w, int quality)
{
    w->dbl.n = w->scene.n_objects;
    w->dbl.objs = w->objp;
    dbl_query(&w->dbl, &w->q);
    assert_int_equal(mat_ctx_create(&w->scene, NULL, &w->mat), IRIS_OK);
    assert_true(tracer_init(&w->tr, &w->scene, w->mat, &w->q, quality));
    assert_true(trace_ctx_init(&w->ctx, &w->tr));
}

static void world_fini(struct world *w)
{
    trace_ctx_fini(&w->ctx);
    tracer_fini(&w->tr);
    mat_ctx_destroy(w->mat);
}

/* The shadow scenes: the floor y = 0, a unit sphere at (0, 5, 0) and a
** point light at (0, 10, 0), not yet built; *sphere and *light (either
** may be NULL) get the sphere and the light. */
static struct world *shadow_world(iris_object **sphere, iris_light **light)
{
    struct world *w = iris_calloc(1, sizeof *w);
    assert_non_null(w);
    world_init(w);
    add_plane(w, v3(0, 1, 0), 0);
    iris_object *s = add_sphere(w, v3(0, 5, 0), 1);
    iris_light *l = add_light(w, v3(0, 10, 0));
    if (sphere)
        *sphere = s;
    if (light)
        *light = l;
    return w;
}

/* Traces one ray from 'o' along 'd' (normalised here). */
static void shoot(struct world *w, vec3 o, vec3 d, double rgb[3])
{
    dbl_shoot(&w->tr, &w->ctx, o, d, rgb);
}

/* ------------------------------------------------------------------ */
/* Camera                                                               */
/* ------------------------------------------------------------------ */

/* §3.8: dir = normalize(D + x0 R + y0 U), x0 = (x+.5)/W - .5,
** y0 = .5 - (y+.5)/H; and 'angle' sets |D| = .5 |R| / tan(angle/2), so
** the image's left edge is angle/2 off the axis. */
static void test_camera_perspective(void **state)
{
    (void)state;
    iris_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.kind = IRIS_CAM_PERSPECTIVE;
    cam.location = v3(1, 2, 3);
    cam.right = v3(1.33, 0, 0);
    cam.up = v3(0, 1, 0);
    double angle = 60.0;
    cam.direction = v3(0, 0, 0.5 * 1.33 / tan(angle / 2 * M_PI / 180));
    ray r;
    assert_true(camera_ray(&cam, 80, 60, 0, 0, &r));
    vec3 e = v3_norm(v3(-0.49375 * 1.33, 0.5 - 0.5 / 60, cam.direction.z));
    assert_near(r.d.x, e.x, 1e-12);
    assert_near(r.d.y, e.y, 1e-12);
    assert_near(r.d.z, e.z, 1e-12);
    assert_near(r.o.x, 1, 0);
    /* the left edge of the image, on the horizon: 30 degrees off axis */
    assert_true(camera_ray(&cam, 80, 60, -0.5, 29.5, &r));
    assert_near(acos(r.d.z) * 180 / M_PI, angle / 2, 1e-9);
    assert_true(r.d.x < 0);
}

static void test_camera_orthographic(void **state)
{
    (void)state;
    iris_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.kind = IRIS_CAM_ORTHOGRAPHIC;
    cam.location = v3(0, 0, -1);
    cam.direction = v3(0, 0, 1);
    cam.right = v3(8, 0, 0);
    cam.up = v3(0, 8, 0);
    ray r;
    assert_true(camera_ray(&cam, 8, 8, 0, 0, &r));
    /* pixel (0,0) looks from (8 x0, 8 y0) with x0 = -7/16, y0 = 7/16 */
    assert_near(r.o.x, -3.5, 1e-12);
    assert_near(r.o.y, 3.5, 1e-12);
    assert_near(r.d.z, 1, 1e-12);
}

/* ------------------------------------------------------------------ */
/* Lights                                                               */
/* ------------------------------------------------------------------ */

/* The angular cameras by hand from POV-Ray's formulas (tracepixel.cpp):
** cylinder 1 turns x0 * angle about up and keeps y0 * |up| as height;
** spherical turns direction by -y0 * v_angle about right, then x0 *
** h_angle about up; ultra_wide_angle uses sin/cos of both angles. */
static void test_camera_angular(void **state)
{
    (void)state;
    iris_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.kind = IRIS_CAM_CYLINDER;
    cam.cylinder_type = 1;
    cam.angle = 180;
    cam.location = v3(0, 0, 0);
    cam.direction = v3(0, 0, 2);
    cam.right = v3(1.5, 0, 0);
    cam.up = v3(0, 2, 0);
    ray r;
    /* the right edge of a 4 x 4 image at mid height: x0 = .5, a quarter
    ** turn to the right; y0 = 0 */
    assert_true(camera_ray(&cam, 4, 4, 3.5, 1.5, &r));
    assert_near(r.d.x, 1, 1e-12);
    assert_near(r.d.y, 0, 1e-12);
    /* pixel (2, 0): x0 = 0.125 (22.5 deg), y0 = 0.5 * |up| = 1 */
    assert_true(camera_ray(&cam, 4, 4, 2, -0.5, &r));
    vec3 e = v3_norm(v3(sin(M_PI / 8), 1, cos(M_PI / 8)));
    assert_near(r.d.x, e.x, 1e-12);
    assert_near(r.d.y, e.y, 1e-12);
    assert_near(r.d.z, e.z, 1e-12);
    /* cylinder 3: the height moves the origin instead */
    cam.cylinder_type = 3;
    assert_true(camera_ray(&cam, 4, 4, 2, -0.5, &r));
    assert_near(r.o.y, 1, 1e-12);
    assert_near(r.d.y, 0, 1e-12);

    /* spherical 360 x 180: the image's left edge looks backwards, the
    ** top edge straight up */
    cam.kind = IRIS_CAM_SPHERICAL;
    cam.angle = 360;
    assert_true(camera_ray(&cam, 4, 4, -0.5, 1.5, &r));
    assert_near(r.d.z, -1, 1e-12);
    assert_true(camera_ray(&cam, 4, 4, 1.5, -0.5, &r));
    assert_near(r.d.y, 1, 1e-12);

    /* ultra_wide_angle 180: x0 = .5 is 90 degrees to the right */
    cam.kind = IRIS_CAM_ULTRA_WIDE;
    cam.angle = 180;
    assert_true(camera_ray(&cam, 4, 4, 3.5, 1.5, &r));
    assert_near(r.d.x, 1, 1e-12);
    assert_near(r.d.z, 0, 1e-12);

    /* omnimax: no ray outside the unit circle (an image corner) */
    cam.kind = IRIS_CAM_OMNIMAX;
    cam.right = v3(1, 0, 0);
    cam.up = v3(0, 1, 0);
    assert_false(camera_ray(&cam, 4, 4, -0.5, -0.5, &r));
    assert_true(camera_ray(&cam, 4, 4, 1.5, 1.5, &r));
    assert_near(r.d.z, 1, 1e-12);
}

static void test_light_spot(void **state)
{
    (void)state;
    iris_light l;
    memset(&l, 0, sizeof l);
    l.kind = IRIS_LIGHT_SPOT;
    l.location = v3(0, 10, 0);
    l.point_at = v3(0, 0, 0);
    l.radius = 10;
    l.falloff = 20;
    struct rlight rl;
    light_prepare(&l, &rl);
    /* a point at angle 'a' off the spot axis, 10 units down */
    double angles[] = { 5, 10, 15, 20, 25 };
    double expect[5];
    for (int i = 0; i < 5; i++) {
        double k = cos(angles[i] * M_PI / 180);
        double c10 = cos(10 * M_PI / 180), c20 = cos(20 * M_PI / 180);
        double t = (k - c20) / (c10 - c20);
        expect[i] = k >= c10 ? 1 : k <= c20 ? 0 : 3 * t * t - 2 * t * t * t;
    }
    for (int i = 0; i < 5; i++) {
        double a = angles[i] * M_PI / 180;
        vec3 p = v3(10 * tan(a), 0, 0);
        vec3 L;
        double depth;
        light_ray(&rl, p, v3(0, 0, 0), &L, &depth);
        assert_near(light_attenuation(&rl, p, L, depth), expect[i], 1e-12);
    }
    assert_near(expect[2] > 0 && expect[2] < 1, 1, 0);
    /* tightness 10: kappa^10 inside the cone */
    l.tightness = 10;
    light_prepare(&l, &rl);
    vec3 p = v3(10 * tan(5 * M_PI / 180), 0, 0), L;
    double depth;
    light_ray(&rl, p, v3(0, 0, 0), &L, &depth);
    assert_near(light_attenuation(&rl, p, L, depth),
                pow(cos(5 * M_PI / 180), 10), 1e-12);
}

static void test_light_fade_cylinder(void **state)
{
    (void)state;
    iris_light l;
    memset(&l, 0, sizeof l);
    l.location = v3(0, 4, 0);
    l.fade_distance = 2;
    l.fade_power = 2;
    struct rlight rl;
    light_prepare(&l, &rl);
    vec3 L;
    double depth;
    light_ray(&rl, v3(0, 0, 0), v3(0, 0, 0), &L, &depth);
    assert_near(depth, 4, 1e-12);
    /* 2 / (1 + (4/2)^2) */
    assert_near(light_attenuation(&rl, v3(0, 0, 0), L, depth), 0.4, 1e-12);

    /* cylinder light along -y, radius .5, falloff 1 */
    memset(&l, 0, sizeof l);
    l.kind = IRIS_LIGHT_CYLINDER;
    l.location = v3(0, 10, 0);
    l.point_at = v3(0, 0, 0);
    l.radius = 0.5;
    l.falloff = 1;
    light_prepare(&l, &rl);
    light_ray(&rl, v3(0.2, 0, 0), v3(0, 0, 0), &L, &depth);
    assert_near(L.y, 1, 1e-12);
    assert_near(depth, 10, 1e-12);
    assert_near(light_attenuation(&rl, v3(0.2, 0, 0), L, depth), 1, 1e-12);
    /* 0.75 from the axis: s(t) on [0, 0.5] at 1 - .75 = .25 -> t = .5 */
    assert_near(light_attenuation(&rl, v3(0.75, 0, 0), L, depth), 0.5,
                1e-12);
    assert_near(light_attenuation(&rl, v3(1.5, 0, 0), L, depth), 0, 0);
}

/* ------------------------------------------------------------------ */
/* Refraction                                                           */
/* ------------------------------------------------------------------ */

static void test_refraction_snell(void **state)
{
    (void)state;
    vec3 n = v3(0, 1, 0);
    for (double deg = 0; deg < 89; deg += 11) {
        double a = deg * M_PI / 180;
        vec3 d = v3(sin(a), -cos(a), 0), t;
        assert_true(trace_refract_dir(d, n, 1 / 1.5, &t));
        assert_near(v3_len(t), 1, 1e-12);
        /* sin(theta_t) = sin(theta_i) / 1.5, bent towards the normal */
        assert_near(t.x, sin(a) / 1.5, 1e-12);
        assert_true(t.y < 0);
    }
    /* from glass: total internal reflection past asin(1/1.5) = 41.8 deg */
    vec3 d = v3(sin(0.70), -cos(0.70), 0), t;
    assert_true(trace_refract_dir(d, n, 1.5, &t));
    d = v3(sin(0.75), -cos(0.75), 0);
    assert_false(trace_refract_dir(d, n, 1.5, &t));
}

/* ------------------------------------------------------------------ */
/* Shading                                                              */
/* ------------------------------------------------------------------ */

/* A white plane under a point light: ambient + diffuse |N.L|. */
static void test_diffuse(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    add_plane(w, v3(0, 1, 0), 0);
    add_light(w, v3(0, 10, 0));
    world_build(w, 9);
    double c[3];
    shoot(w, v3(3, 5, -1), v3(0, -5, 1), c);
    double cosl = 10 / sqrt(9 + 100);
    assert_near(c[0], 0.1 + 0.6 * cosl, 1e-9);
    assert_near(c[2], 0.1 + 0.6 * cosl, 1e-9);
    /* brilliance 2 and phong: 0.6 cos^2 + phong (R.L)^40 */
    iris_finish *f = fin_of(w, w->objp[0]);
    f->brilliance = 2;
    f->phong = 0.5;
    shoot(w, v3(3, 5, -1), v3(0, -5, 1), c);
    vec3 d = v3_norm(v3(0, -5, 1));
    vec3 R = v3(d.x, -d.y, d.z);
    vec3 L = v3_norm(v3(-3, 10, 0));
    double rl = v3_dot(R, L);
    assert_near(c[1], 0.1 + 0.6 * cosl * cosl + 0.5 * pow(rl, 40), 1e-9);
    world_fini(w);
    iris_free(w);
}

/* Shadows: an opaque sphere blocks the light; a filtering one tints it by
** rgb*filter + transmit (§3.6). */
static void test_shadows(void **state)
{
    (void)state;
    iris_object *s;
    struct world *w = shadow_world(&s, NULL);
    world_build(w, 9);
    double c[3];
    shoot(w, v3(0, 2, -3), v3(0, -2, 3), c); /* hits the plane at 0 */
    assert_near(c[0], 0.1, 1e-9);
    *pig_of(w, s) = (iris_pigment){ .colour = { 1, 0.5, 0, 0.8, 0.1 } };
    shoot(w, v3(0, 2, -3), v3(0, -2, 3), c);
    /* two surfaces of the sphere filter: (rgb f + t)^2 */
    assert_near(c[0], 0.1 + 0.6 * pow(0.9, 2), 1e-9);
    assert_near(c[1], 0.1 + 0.6 * pow(0.5, 2), 1e-9);
    assert_near(c[2], 0.1 + 0.6 * pow(0.1, 2), 1e-9);
    /* no_shadow objects cast none */
    s->no_shadow = true;
    shoot(w, v3(0, 2, -3), v3(0, -2, 3), c);
    assert_near(c[0], 0.7, 1e-9);
    world_fini(w);
    iris_free(w);
}

/* projected_through (POV-Ray's TracePointLightShadowRay): a light reaches
** a point only if the ray to it meets the projecting object before the
** light, and only objects short of that hit can shadow it. With the
** scene's own query as the projecting object, the floor point under the
** sphere (its ray to the light meets the sphere at t = 4) is lit in full,
** 0.1 + 0.6, where the sphere shadowed it before; a floor point whose ray
** misses the sphere, at (4, 0, 0), keeps only its ambient 0.1 where it was
** lit with cos = 10/sqrt(116) before. */
static void test_projected_through(void **state)
{
    (void)state;
    struct world *w = shadow_world(NULL, NULL);
    world_build(w, 9);
    double c[3];
    shoot(w, v3(0, 2, -3), v3(0, -2, 3), c);
    assert_near(c[0], 0.1, 1e-9);
    shoot(w, v3(4, 2, -3), v3(0, -2, 3), c);
    assert_near(c[0], 0.1 + 0.6 * 10 / sqrt(116.0), 1e-9);
    w->tr.lights[0].through = &w->q;
    shoot(w, v3(0, 2, -3), v3(0, -2, 3), c);
    assert_near(c[0], 0.7, 1e-9);
    shoot(w, v3(4, 2, -3), v3(0, -2, 3), c);
    assert_near(c[0], 0.1, 1e-9);
    world_fini(w);
    iris_free(w);
}

/* projected_through on a 2x2 area light (corners (+-1, 10, +-1), no
** jitter): POV-Ray tests each sample's own ray. From the floor point
** (1.5, 0, 0) the rays to the corners at x = -1 cross y = 5 at 0.56 from
** the sphere's centre (through it, lit), those to x = +1 at 1.35 (past
** it, black): half the light, 0.1 + 0.6 · cos · 1/2 with the centre's
** cos = 10/sqrt(102.25). (The centre ray alone passes through the sphere
** and would light it in full.) */
static void test_projected_through_area(void **state)
{
    (void)state;
    iris_light *l;
    struct world *w = shadow_world(NULL, &l);
    l->area = true;
    l->axis1 = v3(2, 0, 0);
    l->axis2 = v3(0, 0, 2);
    l->size1 = l->size2 = 2;
    world_build(w, 9);
    w->tr.lights[0].through = &w->q;
    double c[3];
    shoot(w, v3(1.5, 2, -3), v3(0, -2, 3), c);
    assert_near(c[0], 0.1 + 0.3 * 10 / sqrt(102.25), 1e-9);
    world_fini(w);
    iris_free(w);
}

/* Alpha output (+UA, semantics §3.4 and §3.7): the transmit channel of a
** ray that misses everything is the background's transmit, and its
** colour shows by 1 - transmit; through a sphere whose pigment transmits
** 0.6 the ray crosses two surfaces, so 0.6 x 0.6 = 0.36 of the background
** is seen (POV-Ray writes alpha 0.64 there). Without +UA the background is
** opaque and its filter and transmit do not count. */
static void test_alpha_transmit(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    w->scene.background = (iris_colour){ 0.2, 0.4, 0.8, 0, 0.25 };
    iris_object *s = add_sphere(w, v3(0, 0, 0), 1);
    *pig_of(w, s) = (iris_pigment){ .colour = { 1, 1, 1, 0, 0.6 } };
    world_build(w, 9);
    w->tr.alpha = true;
    double c[3];
    shoot(w, v3(0, 5, -5), v3(0, 0, 1), c);
    assert_near(w->ctx.transm, 0.25, 1e-12);
    assert_near(c[2], 0.8 * 0.75, 1e-12);
    shoot(w, v3(0, 0, -5), v3(0, 0, 1), c);
    assert_near(w->ctx.transm, 0.6 * 0.6 * 0.25, 1e-12);
    w->tr.alpha = false;
    shoot(w, v3(0, 5, -5), v3(0, 0, 1), c);
    assert_near(w->ctx.transm, 0.0, 0);
    assert_near(c[2], 0.8, 1e-12);
    world_fini(w);
    iris_free(w);
}

/* A shadow ray crossing a transparent object with fade is faded over the
** segment inside it (POV-Ray's shadow rays track the objects they enter,
** §3.6): light from (-4,4,0) to the floor point (1.5,0,0) crosses the box
** x in [-1,0], y in [0.5,1.5] from (0, 12/11) to (-9/16, 1.5). */
static void test_shadow_fade(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    iris_object *pl = add_plane(w, v3(0, 1, 0), 0);
    fin_of(w, pl)->ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    fin_of(w, pl)->diffuse = 1;
    /* the box as the intersection of its faces is beyond the double, so a
    ** sphere stands in: centre (-0.5, 1, 0), radius 0.5 */
    iris_object *s = add_sphere(w, v3(-0.5, 1, 0), 0.5);
    *pig_of(w, s) = (iris_pigment){ .colour = { 1, 1, 1, 0, 1 } };
    iris_interior *in = glass(w, s, 1.0);
    in->fade_distance = 0.8;
    in->fade_power = 2;
    in->fade_colour = (iris_colour){ 0.2, 0.8, 0.3, 0, 0 };
    add_light(w, v3(-4, 4, 0));
    world_build(w, 9);
    /* the chord of the light ray through the sphere */
    vec3 p = v3(1.5, 0, 0), L = v3_norm(v3(-5.5, 4, 0));
    vec3 oc = v3_sub(p, v3(-0.5, 1, 0));
    double b = v3_dot(oc, L), c = v3_dot(oc, oc) - 0.25;
    double chord = 2 * sqrt(b * b - c);
    double cosl = L.y, col[3];
    shoot(w, v3(1.5, 1, -1), v3(0, -1, 1), col);
    double fc[3] = { 0.2, 0.8, 0.3 };
    for (int k = 0; k < 3; k++) {
        double fade = fc[k] + (1 - fc[k]) / (1 + pow(chord / 0.8, 2));
        assert_near(col[k], cosl * fade, 1e-9);
    }
    world_fini(w);
    iris_free(w);
}

/* Dispersion (DESIGN.md): a camera ray meeting a dispersive interior
** splits into wavelengths whose colours are recombined by the
** self-normalised CIE estimate of eyespectrum.h. Through the centre of a
** dispersive sphere no wavelength bends, so a white background must stay
** exactly white, with POV-Ray's default 7 wavelengths, with the minimum 2
** and with 256: the estimate is exact for a flat spectrum, so the
** tolerance is float rounding (1e-9). (A 1/pdf average of 7 uniform
** wavelengths misses white by up to 10%.) */
static void test_dispersion_white(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    w->scene.background = (iris_colour){ 1, 1, 1, 0, 1 };
    iris_object *s = add_sphere(w, v3(0, 0, 0), 1);
    *pig_of(w, s) = (iris_pigment){ .colour = { 1, 1, 1, 0, 1 } };
    fin_of(w, s)->ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    fin_of(w, s)->diffuse = 0;
    iris_interior *in = glass(w, s, 1.5);
    in->dispersion = 1.1;
    world_build(w, 9);
    const int floors[] = { 0, 2, 256 };
    for (int f = 0; f < 3; f++) {
        in->dispersion_samples = f == 1 ? 2 : 7;
        w->tr.spectral_min = floors[f];
        for (int shot = 0; shot < 5; shot++) {
            double c[3];
            shoot(w, v3(0, 0, -5), v3(0, 0, 1), c);
            for (int k = 0; k < 3; k++)
                assert_near(c[k], 1.0, 1e-9);
        }
    }
    world_fini(w);
    iris_free(w);
}

/* The wavelength estimate itself (eyespectrum.h). A flat spectrum r gives
** r·(1,1,1) for any wavelengths drawn (1e-12: rounding). A surface colour
** upsampled with Burns' curves and integrated with 400 strata gives the
** colour back within 2e-3: the curves round-trip within 1e-3 (issue 5's
** spectral test) and 400 strata of a 1 nm-binned density leave ~1e-4.
** The wavelengths follow the strata: wavelength i of n lies where the
** cumulative density is in [i/n, (i+1)/n), so they increase with i. */
static void test_eye_spectrum(void **state)
{
    (void)state;
    rng r;
    rng_seed(&r, 1, 2, 3);
    for (int n = 2; n <= 9; n++) {
        struct eye_spectrum s;
        eye_spectrum_init(&s);
        double prev = 0.0;
        for (int i = 0; i < n; i++) {
            double a[3];
            double l = eye_lambda_sample(i, n, rng_uniform(&r), a);
            assert_true(l >= 380.0 && l <= 780.0 && l > prev);
            prev = l;
            eye_spectrum_add(&s, a, 0.37);
        }
        double c[3];
        eye_spectrum_rgb(&s, c);
        for (int k = 0; k < 3; k++)
            assert_near(c[k], 0.37, 1e-12);
    }
    const double cols[3][3] = { { 0.8, 0.2, 0.1 }, { 0.1, 0.6, 0.3 },
                                { 0.2, 0.3, 0.9 } };
    for (int t = 0; t < 3; t++) {
        struct eye_spectrum s;
        eye_spectrum_init(&s);
        for (int i = 0; i < 400; i++) {
            double a[3];
            double l = eye_lambda_sample(i, 400, rng_uniform(&r), a);
            eye_spectrum_add(&s, a, spec_reflectance(cols[t], l));
        }
        double c[3];
        eye_spectrum_rgb(&s, c);
        for (int k = 0; k < 3; k++)
            assert_near(c[k], cols[t][k], 2e-3);
    }
}

/* Focal blur's confidence test uses the chi-square quantile x with
** P(chi^2_df > x) = p. Reference values: df 2 has the closed form
** -2 ln p; 3.841459 (df 1, p 0.05), 4.865182 (df 10, p 0.9) and
** 20.483177 (df 10, p 0.025) are the standard table values (6-7
** digits, hence 1e-5). */
static void test_chi2_quantile(void **state)
{
    (void)state;
    assert_near(chi2_upper_inv(2, 0.1), -2.0 * log(0.1), 1e-9);
    assert_near(chi2_upper_inv(2, 0.9), -2.0 * log(0.9), 1e-9);
    assert_near(chi2_upper_inv(1, 0.05), 3.841459, 1e-5);
    assert_near(chi2_upper_inv(10, 0.9), 4.865182, 1e-5);
    assert_near(chi2_upper_inv(10, 0.025), 20.483177, 1e-5);
}

/* A blur ray keeps meeting the pinhole ray on the focal plane: for the
** camera at the origin looking along +z with focal point at z = 4, every
** aperture sample of pixel (x, y) passes through the pinhole ray's point
** at z = 4 (the plane's distance over |direction| scales it), and starts
** within aperture/2 · (0.5 + jitter) of the location, across z. */
static void test_focal_blur_ray(void **state)
{
    (void)state;
    iris_camera cam;
    iris_camera_defaults(&cam);
    cam.direction = v3(0, 0, 2);
    cam.aperture = 0.5;
    cam.blur_samples = 19;
    cam.focal_point = v3(1, 0, 4);
    /* the parser resolves the focal distance from focal_point */
    cam.focal_distance = v3_len(v3_sub(cam.focal_point, cam.location));
    struct focal_blur fb;
    assert_true(focal_blur_wanted(&cam));
    assert_true(focal_blur_init(&fb, &cam));
    for (int nr = 0; nr < 19; nr++) {
        ray pin, r;
        vec3 raw;
        assert_true(camera_ray_raw(&cam, 80, 60, 30.3, 12.7, &pin, &raw));
        r = pin;
        focal_blur_ray(&fb, &cam, 30.3, 12.7, nr, raw, &r);
        /* the focal point's distance sqrt(17) over |direction| = 2, as a
        ** multiple of the unnormalised pinhole direction */
        double t = sqrt(17.0) / 2.0;
        vec3 f = v3_madd(pin.o, raw, t);
        vec3 w = v3_sub(f, r.o);
        vec3 c = v3_cross(w, r.d);
        assert_near(v3_len(c), 0.0, 1e-12);
        assert_near(r.o.z, 0.0, 1e-15);
        assert_true(hypot(r.o.x, r.o.y) <= 0.25 * (0.5 + 0.1) * M_SQRT2);
    }
    focal_blur_fini(&fb);
}

/* The output gamut map keeps the luminance Y (sRGB row 0.2126, 0.7152,
** 0.0722) of an out-of-gamut colour and its hue direction from grey, and
** leaves in-gamut colours alone. */
static void test_gamut_map(void **state)
{
    (void)state;
    double c[3] = { 1.3, -0.2, 0.05 };
    double y = 0.2126390058715102 * c[0] + 0.7151686787677560 * c[1] +
               0.0721923153607337 * c[2];
    eye_gamut_map(c);
    assert_near(0.2126390058715102 * c[0] + 0.7151686787677560 * c[1] +
                0.0721923153607337 * c[2], y, 1e-12);
    assert_near(c[1], 0.0, 1e-15);
    assert_true(c[0] > y && c[2] < y && c[2] >= 0.0);
    /* (c - Y) keeps its direction: red and blue offsets scale alike */
    assert_near((c[0] - y) / (1.3 - y), (c[2] - y) / (0.05 - y), 1e-9);
    double d[3] = { 0.5, 0.0, 2.0 };
    eye_gamut_map(d);
    assert_true(d[0] == 0.5 && d[1] == 0.0 && d[2] == 2.0);
    double e[3] = { -0.5, 0.1, -0.1 };   /* Y < 0 */
    eye_gamut_map(e);
    assert_true(e[0] == 0.0 && e[1] == 0.0 && e[2] == 0.0);
}

/* A 2x2 area light without jitter samples its four corners; one blocked
** corner leaves 3/4 of the light (§3.5). */
static void test_area_light(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    iris_object *pl = add_plane(w, v3(0, 1, 0), 0);
    fin_of(w, pl)->ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    fin_of(w, pl)->diffuse = 1;
    add_sphere(w, v3(0.5, 5, 0.5), 0.3);
    iris_light *l = add_light(w, v3(0, 10, 0));
    l->area = true;
    l->axis1 = v3(2, 0, 0);
    l->axis2 = v3(0, 0, 2);
    l->size1 = l->size2 = 2;
    world_build(w, 9);
    double c[3];
    shoot(w, v3(0, 1, -1), v3(0, -1, 1), c);
    assert_near(c[0], 0.75, 1e-9);
    world_fini(w);
    /* the same at quality 4: a point light, the centre ray unblocked */
    world_build(w, 4);
    shoot(w, v3(0, 1, -1), v3(0, -1, 1), c);
    assert_near(c[0], 1.0, 1e-9);
    world_fini(w);
    iris_free(w);
}

/* A mirror returns the background; reflection 0.5 half of it. */
static void test_reflection(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    w->scene.background = (iris_colour){ 0.2, 0.4, 0.6, 0, 1 };
    iris_object *pl = add_plane(w, v3(0, 1, 0), 0);
    iris_finish *f = fin_of(w, pl);
    f->ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    f->diffuse = 0;
    f->reflection_max = f->reflection_min = (iris_colour){ 1, 1, 1, 0, 0 };
    world_build(w, 9);
    double c[3];
    shoot(w, v3(0, 1, 0), v3(0, -1, 1), c);
    assert_near(c[1], 0.4, 1e-12);
    f->reflection_max = f->reflection_min = (iris_colour){ 0.5, 0.5, 0.5, 0, 0 };
    shoot(w, v3(0, 1, 0), v3(0, -1, 1), c);
    assert_near(c[2], 0.3, 1e-12);
    /* quality 7 has no reflection */
    world_fini(w);
    world_build(w, 7);
    shoot(w, v3(0, 1, 0), v3(0, -1, 1), c);
    assert_near(c[2], 0.0, 0);
    world_fini(w);
    iris_free(w);
}

/* A clear glass sphere: through the centre the ray goes straight on and
** sees the background; fade over the 2 units inside gives
** fc + (1 - fc)/(1 + (d/fd)^fp) (§3.3); max_trace_level 1 leaves black. */
static void test_refraction_fade(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    w->scene.background = (iris_colour){ 0.3, 0.6, 0.9, 0, 1 };
    iris_object *s = add_sphere(w, v3(0, 0, 0), 1);
    *pig_of(w, s) = (iris_pigment){ .colour = { 1, 1, 1, 1, 0 } };
    iris_finish *f = fin_of(w, s);
    f->ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    f->diffuse = 0;
    iris_interior *in = glass(w, s, 1.5);
    world_build(w, 9);
    double c[3];
    shoot(w, v3(0, 0, -5), v3(0, 0, 1), c);
    assert_near(c[0], 0.3, 1e-9);
    in->fade_distance = 1;
    in->fade_power = 1;
    in->fade_colour = (iris_colour){ 0.5, 0, 0, 0, 0 };
    shoot(w, v3(0, 0, -5), v3(0, 0, 1), c);
    assert_near(c[0], 0.3 * (0.5 + 0.5 / 3), 1e-9);
    assert_near(c[1], 0.6 / 3, 1e-9);
    world_fini(w);
    /* entering is level 1; the refracted ray would be level 2 > 1 */
    w->scene.settings.max_trace_level = 1;
    world_build(w, 9);
    shoot(w, v3(0, 0, -5), v3(0, 0, 1), c);
    assert_near(c[1], 0, 0);
    world_fini(w);
    iris_free(w);
}

/* Off-centre, the ray is bent twice by Snell's law: compare where it
** meets a gradient-coloured wall with the analytic exit direction. */
static void test_refraction_path(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    iris_object *s = add_sphere(w, v3(0, 0, 0), 1);
    *pig_of(w, s) = (iris_pigment){ .colour = { 1, 1, 1, 0, 1 } };
    fin_of(w, s)->ambient = (iris_colour){ 0, 0, 0, 0, 0 };
    fin_of(w, s)->diffuse = 0;
    glass(w, s, 1.5);
    /* wall z = 10 whose red channel is its x coordinate (ambient 1) */
    iris_object *wall = add_plane(w, v3(0, 0, -1), -10);
    iris_pigment *wp = pig_of(w, wall);
    static iris_map_entry e[2];
    memset(e, 0, sizeof e);
    e[0].value = 0; e[0].colour = (iris_colour){ 0, 0, 0, 0, 0 };
    e[1].value = 1; e[1].colour = (iris_colour){ 1, 1, 1, 0, 0 };
    wp->pattern.kind = IRIS_PAT_GRADIENT;
    wp->pattern.vector = v3(0, 1, 0);
    wp->pattern.has_transform = true;
    /* world y in [-5, 5] maps to the gradient's [0, 1]: y' = y/10 + .5 */
    xf_identity(&wp->pattern.transform);
    wp->pattern.transform.m[1][1] = 10;
    wp->pattern.transform.m[1][3] = -5;
    wp->pattern.transform.inv[1][1] = 0.1;
    wp->pattern.transform.inv[1][3] = 0.5;
    wp->n_entries = 2;
    wp->entries = e;
    iris_finish *wf = fin_of(w, wall);
    wf->ambient = (iris_colour){ 1, 1, 1, 0, 0 };
    wf->diffuse = 0;
    world_build(w, 9);
    double h = 0.3, c[3];
    shoot(w, v3(0, h, -5), v3(0, 0, 1), c);
    /* analytic: entry at (0, h, -sqrt(1-h^2)); refract, exit, refract */
    vec3 p1 = v3(0, h, -sqrt(1 - h * h)), t1, t2;
    assert_true(trace_refract_dir(v3(0, 0, 1), v3_norm(p1), 1 / 1.5, &t1));
    double b = v3_dot(p1, t1);
    vec3 p2 = v3_madd(p1, t1, -2 * b);
    assert_true(trace_refract_dir(t1, v3_neg(v3_norm(p2)), 1.5, &t2));
    double ywall = p2.y + (10 - p2.z) / t2.z * t2.y;
    assert_true(ywall < 0 && ywall > -5); /* crossed the axis */
    assert_near(c[0], ywall / 10 + 0.5, 1e-9);
    world_fini(w);
    iris_free(w);
}

/* ------------------------------------------------------------------ */
/* Eye pass                                                             */
/* ------------------------------------------------------------------ */

static iris_render_options aa_options(int w, int h)
{
    iris_render_options o;
    iris_render_defaults(&o);
    o.width = w;
    o.height = h;
    o.seed = 7;
    return o;
}

static void render(struct world *w, const iris_render_options *o, int threads,
                   iris_image *img, iris_render_stats *st)
{
    img->width = o->width;
    img->height = o->height;
    img->pixels = iris_calloc((size_t)o->width * o->height * 4,
                              sizeof(float));
    assert_non_null(img->pixels);
    assert_int_equal(eyepass_run(&w->tr, o, threads, img, st), IRIS_OK);
}

/* A sphere of ambient 1 and no diffuse (white wherever it is seen, no
** light needed) on a black background: the eye pass tests' world. */
static struct world *white_sphere_world(vec3 centre, double radius)
{
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    w->scene.background = (iris_colour){ 0, 0, 0, 0, 1 };
    iris_object *s = add_sphere(w, centre, radius);
    iris_finish *f = fin_of(w, s);
    f->ambient = (iris_colour){ 1, 1, 1, 0, 0 };
    f->diffuse = 0;
    world_build(w, 9);
    return w;
}

/* Method 1 (§4.1): flat regions keep their single sample; a pixel on the
** sphere's silhouette is averaged to a value between the two sides. The
** image is the same with 1 and 3 threads. */
static void test_eyepass_aa(void **state)
{
    (void)state;
    struct world *w = white_sphere_world(v3(0, 1, 0), 1);
    iris_render_options o = aa_options(40, 30);
    iris_image plain, aa, aa3;
    iris_render_stats st;
    memset(&st, 0, sizeof st);
    render(w, &o, 1, &plain, &st);
    uint64_t plain_rays = st.rays_traced;
    o.aa = IRIS_AA_POV1;
    o.aa_threshold = 0.3;
    o.aa_depth = 3;
    memset(&st, 0, sizeof st);
    render(w, &o, 1, &aa, &st);
    assert_true(st.rays_traced > plain_rays);
    render(w, &o, 3, &aa3, NULL);
    size_t n = (size_t)40 * 30 * 4;
    assert_memory_equal(aa.pixels, aa3.pixels, n * sizeof(float));
    int edge = 0;
    for (size_t i = 0; i < n; i += 4) {
        float p = plain.pixels[i], a = aa.pixels[i];
        assert_true(a >= 0.0f && a <= 1.0f);
        if (p == a)
            continue;
        /* a changed pixel must be a partial coverage value */
        assert_true(a > 0.0f && a < 1.0f);
        edge++;
    }
    assert_true(edge > 0);
    /* corners are pure background: untouched, 0 */
    assert_near(aa.pixels[0], 0, 0);
    /* the centre is inside the sphere: 1 */
    assert_near(aa.pixels[(15 * 40 + 20) * 4], 1, 0);
    /* method 2 and stratified give partial values on the edge too */
    o.aa = IRIS_AA_POV2;
    iris_image m2;
    render(w, &o, 2, &m2, NULL);
    o.aa = IRIS_AA_STRATIFIED;
    iris_image strat;
    render(w, &o, 2, &strat, NULL);
    int partial2 = 0, partial3 = 0;
    for (size_t i = 0; i < n; i += 4) {
        partial2 += m2.pixels[i] > 0.01f && m2.pixels[i] < 0.99f;
        partial3 += strat.pixels[i] > 0.01f && strat.pixels[i] < 0.99f;
    }
    assert_true(partial2 > 0 && partial3 > 0);
    iris_free(plain.pixels);
    iris_free(aa.pixels);
    iris_free(aa3.pixels);
    iris_free(m2.pixels);
    iris_free(strat.pixels);
    world_fini(w);
    iris_free(w);
}

/* Method 1's tiles take the row above and the column left of them from
** their neighbours when these have traced them (eyepass.c, struct
** edge_px). A 100 x 70 image has 4 x 3 tiles of 32; on one thread each
** tile's neighbours are done before it, so every tile boundary inside
** the window is shared: (3 - 1) rows of 100 and (4 - 1) columns of 70,
** 410 samples, while POV-Ray's statistics still count them. The scene has
** no light and no reflection, one ray a camera sample, so rays_traced is
** exactly rays_camera - 410. With 7 threads tiles run side by side and
** some borders are traced twice: the image and POV-Ray's counts must not
** change. */
static void test_eyepass_shared_borders(void **state)
{
    (void)state;
    struct world *w = white_sphere_world(v3(0.3, 1, 0), 1.4);
    iris_render_options o = aa_options(100, 70);
    o.aa = IRIS_AA_POV1;
    o.aa_threshold = 0.3;
    o.aa_depth = 3;
    iris_image one, seven;
    iris_render_stats st1, st7;
    memset(&st1, 0, sizeof st1);
    memset(&st7, 0, sizeof st7);
    render(w, &o, 1, &one, &st1);
    render(w, &o, 7, &seven, &st7);
    assert_memory_equal(one.pixels, seven.pixels,
                        (size_t)100 * 70 * 4 * sizeof(float));
    /* the first samples POV-Ray traces: every pixel and each tile's
    ** border row and column; the silhouette adds R^2 = 9 a supersample */
    uint64_t first = 100 * 70 + 3 * 100 + 4 * 70;
    assert_true(st1.rays_camera > first);
    assert_int_equal((st1.rays_camera - first) % 9, 0);
    assert_int_equal(st1.rays_camera, st7.rays_camera);
    assert_int_equal(st1.rays, st1.rays_camera);
    assert_int_equal(st1.rays_traced, st1.rays_camera - 410);
    assert_true(st7.rays_traced >= st1.rays_traced &&
                st7.rays_traced <= st1.rays_camera);
    iris_free(one.pixels);
    iris_free(seven.pixels);
    world_fini(w);
    iris_free(w);
}

/* An interrupted render stops with IRIS_EINTR. */
static void test_eyepass_interrupt(void **state)
{
    (void)state;
    struct world *w = iris_calloc(1, sizeof *w);
    world_init(w);
    add_sphere(w, v3(0, 1, 0), 1);
    world_build(w, 9);
    iris_render_options o = aa_options(64, 64);
    volatile int stop = 1;
    o.interrupt = &stop;
    iris_image img = { 64, 64, iris_calloc(64 * 64 * 4, sizeof(float)) };
    assert_int_equal(eyepass_run(&w->tr, &o, 2, &img, NULL), IRIS_EINTR);
    iris_free(img.pixels);
    world_fini(w);
    iris_free(w);
}

/* The AA comparison's fast gamma (eye_aa_gamma_apply): its result must
** lie within the error bound it returns of libm's pow(), for every
** channel value, since the eye pass trusts that bound to redo exactly
** the threshold tests it could flip (then the AA decisions are pow()'s).
** Values sweep 1e-8 .. 1e8 with irregular mantissas, for POV-Ray's
** default aa_gamma 2.5 and others; gamma 1 and the values outside the
** fast paths must be exact (bound 0, result = pow()). Exponents below 1
** use the interpolated table, whose bound, e (1 - e) / 8 / 128^2 of the
** value doubled, is the largest error of linear interpolation: the
** worst error seen must come within a factor 20 of it (a bound far
** looser than the error would send many AA tests to the exact pow()). */
static void test_aa_gamma_bound(void **state)
{
    (void)state;
    const double gammas[] = { 2.5, 2.2, 1.0, 0.3, 0.1, 1.8 };
    for (size_t gi = 0; gi < sizeof gammas / sizeof gammas[0]; gi++) {
        struct eye_aa_gamma a;
        eye_aa_gamma_init(&a, gammas[gi]);
        double e = 1.0 / gammas[gi];
        int fast_used = 0;
        double worst = 0.0;    /* largest error / bound seen */
        for (int i = 0; i <= 160000; i++) {
            /* log-uniform with a mantissa that is not a round number */
            double v = pow(10.0, -8.0 + 16.0 * i / 160000.0) *
                       (1.0 + 0.618033988749895 * ((i * 7919) % 1000) / 1000.0);
            double c[3] = { v, v * 0.5, -v }, g[3];
            double err = eye_aa_gamma_apply(&a, c, g);
            double want[3] = { pow(v, e), pow(v * 0.5, e), 0.0 };
            double sum = 0.0;
            for (int k = 0; k < 3; k++)
                sum += fabs(g[k] - want[k]);
            assert_true(sum <= err);
            if (err > 0.0) {
                fast_used++;
                worst = fmax(worst, sum / err);
            }
            /* exact paths (both channels outside [1e-6, 1e6], gamma 1,
            ** exponents past 4): identical to pow() */
            if (e == 1.0 || e > 4.0 || v < 1e-6 || v > 2e6)
                assert_true(err == 0.0 && g[0] == want[0] &&
                            g[1] == want[1]);
            assert_true(g[2] == 0.0); /* negative channels clip to 0 */
        }
        /* the float path is used where it is allowed */
        if (e != 1.0 && e <= 4.0)
            assert_true(fast_used > 1000);
        else
            assert_int_equal(fast_used, 0);
        if (e < 1.0)
            assert_true(worst > 0.05);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_camera_perspective),
        cmocka_unit_test(test_camera_orthographic),
        cmocka_unit_test(test_camera_angular),
        cmocka_unit_test(test_light_spot),
        cmocka_unit_test(test_light_fade_cylinder),
        cmocka_unit_test(test_refraction_snell),
        cmocka_unit_test(test_diffuse),
        cmocka_unit_test(test_shadows),
        cmocka_unit_test(test_shadow_fade),
        cmocka_unit_test(test_projected_through),
        cmocka_unit_test(test_projected_through_area),
        cmocka_unit_test(test_alpha_transmit),
        cmocka_unit_test(test_dispersion_white),
        cmocka_unit_test(test_eye_spectrum),
        cmocka_unit_test(test_gamut_map),
        cmocka_unit_test(test_chi2_quantile),
        cmocka_unit_test(test_focal_blur_ray),
        cmocka_unit_test(test_area_light),
        cmocka_unit_test(test_reflection),
        cmocka_unit_test(test_refraction_fade),
        cmocka_unit_test(test_refraction_path),
        cmocka_unit_test(test_eyepass_aa),
        cmocka_unit_test(test_eyepass_shared_borders),
        cmocka_unit_test(test_eyepass_interrupt),
        cmocka_unit_test(test_aa_gamma_bound),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
