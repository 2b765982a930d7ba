/* SPDX-License-Identifier: MIT */
/*
** scene.c: the scene's lifetime and POV-Ray's defaults for finish,
** interior, global settings, lights and camera (povray-3.7-semantics.md
** §3.1, §3.5, §3.8). No SDL here: a program may build a scene by hand.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "iris/scene.h"
#include "util/arena.h"

void iris_scene_destroy(iris_scene *scene)
{
    if (!scene)
        return;
    for (iris_scene_cleanup *c = scene->cleanups; c; c = c->next)
        c->free(c->data);
    /* The scene itself lives in its arena. */
    arena_destroy(scene->arena);
}

void iris_finish_defaults(iris_finish *f)
{
    memset(f, 0, sizeof *f);
    f->ambient.r = f->ambient.g = f->ambient.b = 0.1;
    f->diffuse = 0.6;
    f->brilliance = 1;
    f->phong_size = 40;
    f->roughness = 0.05;
    f->reflection_falloff = 1;
    f->reflection_exponent = 1;
    f->legacy_refraction = 1;
}

void iris_interior_defaults(iris_interior *i)
{
    memset(i, 0, sizeof *i);
    i->ior = 0;                /* unset: POV-Ray's Post_Process makes it 1 */
    i->dispersion = 1;
    i->dispersion_samples = 7;
}

void iris_media_defaults(iris_media *m, double version)
{
    memset(m, 0, sizeof *m);
    /* POV-Ray's Media constructor, and Parse_Media's 3.5 defaults */
    bool v35 = !(version > 0) || version >= 3.5;
    m->method = v35 ? 3 : 1;
    m->intervals = v35 ? 1 : 10;
    m->min_samples = m->max_samples = v35 ? 10 : 1;
    m->aa_threshold = 0.1;
    m->aa_level = 3;
    m->confidence = 0.9;
    m->variance = 1.0 / 128.0;
    m->ratio = 0.9;
    m->scattering_type = IRIS_SCATTER_ISOTROPIC;
    m->sc_ext = 1.0;
}

void iris_global_defaults(iris_global_settings *g)
{
    memset(g, 0, sizeof *g);
    g->max_trace_level = 5;
    g->adc_bailout = 1.0 / 255.0;
    g->ambient_light.r = g->ambient_light.g = g->ambient_light.b = 1;
    g->irid_wavelength.x = 0.70;
    g->irid_wavelength.y = 0.52;
    g->irid_wavelength.z = 0.48;
    g->number_of_waves = 10;
    g->noise_generator = 2;
    g->mm_per_unit = 10;
    g->sss_samples_diffuse = g->sss_samples_single = 50;
}

void iris_light_defaults(iris_light *l)
{
    memset(l, 0, sizeof *l);
    l->kind = IRIS_LIGHT_POINT;
    l->colour.r = l->colour.g = l->colour.b = 1;
    l->point_at.z = 1;         /* the code's default, not the docs' 0 */
    l->radius = 30;
    l->falloff = 45;
    l->tightness = 0;
    l->adaptive = 100;
    l->media_interaction = true;
    l->media_attenuation = false;
    l->spectrum = IRIS_SPEC_D65;
}

void iris_camera_defaults(iris_camera *c)
{
    memset(c, 0, sizeof *c);
    c->kind = IRIS_CAM_PERSPECTIVE;
    c->direction.z = 1;
    c->up.y = 1;
    c->right.x = 1.33;
    c->sky.y = 1;
    c->look_at.z = 1;
    c->blur_samples = 0;
    c->blur_samples_min = 0;
    c->focal_point.z = 1;      /* POV-Ray's Camera::Init */
    c->focal_distance = -1;
    c->confidence = 0.9;
    c->variance = 1.0 / 10000;
}
