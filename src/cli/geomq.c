/* SPDX-License-Identifier: MIT */
/*
** geomq.c: see geomq.h. Scenes call trace() thousands of times on the
** same few objects (placing things on a terrain), so the accel built for
** an object is kept, keyed by the object pointer the parser passes (one
** pointer per declared object for the whole parse, parse.h); a few are
** kept, the oldest replaced first.
*/
#include "config.h"

#include "cli/geomq.h"

#include <math.h>
#include <string.h>

#include "accel/accel.h"
#include "geometry/geom.h"
#include "math/transform.h"
#include "photon/povbox.h"
#include "util/mem.h"

#define GEOMQ_SLOTS 8

struct geomq_slot {
    const iris_object *obj;    /* the key; NULL = empty */
    iris_object *list[1];
    iris_scene world;          /* the parsed scene's settings, one object */
    struct accel *accel;       /* NULL when the object could not be built */
};

/* Object-space boxes of text objects: scenes centre the same letters
** hundreds of times (advanced/blocks: six letters on 400 blocks), and
** each box costs a font load and a glyph profile. */
#define GEOMQ_TEXTS 32
struct geomq_text {
    const char *font, *string;     /* NULL = empty */
    double thickness;
    vec3 offset;
    bool ok;
    vec3 lo, hi;
};

struct geomq {
    iris_geometry_queries cb;
    FILE *log;
    struct geomq_slot slot[GEOMQ_SLOTS];
    unsigned next;
    struct geomq_text text[GEOMQ_TEXTS];
    unsigned next_text;
};

static bool same_text(const struct geomq_text *t, const iris_object *o)
{
    return t->font && strcmp(t->font, o->u.text.font) == 0 &&
           strcmp(t->string, o->u.text.string) == 0 &&
           t->thickness == o->u.text.thickness &&
           t->offset.x == o->u.text.offset.x &&
           t->offset.y == o->u.text.offset.y &&
           t->offset.z == o->u.text.offset.z;
}

/* The accel of a world holding only 'obj' (NULL if it cannot be built). */
static struct accel *accel_for(struct geomq *q, const iris_scene *scene,
                               const iris_object *obj)
{
    for (int i = 0; i < GEOMQ_SLOTS; i++)
        if (q->slot[i].obj == obj)
            return q->slot[i].accel;
    struct geomq_slot *s = &q->slot[q->next++ % GEOMQ_SLOTS];
    accel_destroy(s->accel);
    s->accel = NULL;
    s->obj = obj;
    s->list[0] = (iris_object *)obj;
    s->world = *scene;
    s->world.objects = s->list;
    s->world.n_objects = 1;
    s->world.n_lights = 0;
    s->world.lights = NULL;
    s->world.has_camera = false;
    char err[256];
    if (accel_build(&s->world, &s->accel, q->log, err, sizeof err) != IRIS_OK)
        s->accel = NULL;
    return s->accel;
}

/* The box of a plain analytic shape from src/geometry alone, its
** corners through the object's transform: no Embree scene to build
** (scenes centre hundreds of text objects with min_extent/max_extent).
** False when the shape needs accel (CSG, meshes, clipping, inverse) or
** is unbounded. */
static bool shape_box(const iris_object *o, vec3 *a, vec3 *b)
{
    /* a profile (text, prism, lathe) is checked by building it; other
    ** shapes by geom_validate (which would build a profile again) */
    const char *why = NULL;
    struct geom_profile *prof = geom_prepare(o, &why);
    if (!prof && !why)
        why = geom_validate(o);
    bool ok = !why && geom_bounds(o, prof, a, b);
    /* text: POV-Ray's glyph boxes, not the outline's tight one (a
    ** leading space counts, off-curve points widen a letter) */
    if (ok && o->kind == IRIS_OBJ_TEXT && prof && prof->pov_box) {
        a->x = prof->pov_lo.u;
        a->y = prof->pov_lo.v;
        b->x = prof->pov_hi.u;
        b->y = prof->pov_hi.v;
    }
    geom_profile_free(prof);
    return ok;
}

static bool leaf_bounds(struct geomq *q, const iris_object *o,
                        iris_vec3 *lo, iris_vec3 *hi)
{
    if (!geom_is_analytic(o->kind) || o->n_clipped_by || o->inverse)
        return false;
    vec3 a, b;
    bool ok;
    if (o->kind == IRIS_OBJ_TEXT && o->u.text.font && o->u.text.string) {
        struct geomq_text *t = NULL;
        for (int i = 0; i < GEOMQ_TEXTS && !t; i++)
            if (same_text(&q->text[i], o))
                t = &q->text[i];
        if (!t) {
            t = &q->text[q->next_text++ % GEOMQ_TEXTS];
            t->font = o->u.text.font; /* the scene arena's, for the parse */
            t->string = o->u.text.string;
            t->thickness = o->u.text.thickness;
            t->offset = o->u.text.offset;
            t->ok = shape_box(o, &t->lo, &t->hi);
        }
        ok = t->ok;
        a = t->lo;
        b = t->hi;
    } else {
        ok = shape_box(o, &a, &b);
    }
    if (!ok)
        return false;
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (int i = 0; i < 8; i++) {
        vec3 p = v3(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z);
        if (o->has_transform)
            p = xf_point(&o->transform, p);
        *lo = v3_min(*lo, p);
        *hi = v3_max(*hi, p);
    }
    return isfinite(lo->x + lo->y + lo->z + hi->x + hi->y + hi->z);
}

static bool q_bounds(void *user, const iris_scene *scene,
                     const iris_object *obj, iris_vec3 *lo, iris_vec3 *hi)
{
    /* a blob: POV-Ray's box, wider than iris's (its components' spheres;
    ** a blob of a sphere and a cylinder: max_extent 5.25 where iris's
    ** tight box gave 4.24) */
    if (povbox_blob(obj, lo, hi))
        return true;
    if (obj->kind != IRIS_OBJ_SPHERE && leaf_bounds(user, obj, lo, hi))
        return true;
    struct accel *a = accel_for(user, scene, obj);
    return a && accel_object_bounds(a, obj, lo, hi);
}

static bool q_trace(void *user, const iris_scene *scene,
                    const iris_object *obj, iris_vec3 origin, iris_vec3 dir,
                    iris_vec3 *point, iris_vec3 *normal)
{
    struct accel *a = accel_for(user, scene, obj);
    if (!a)
        return false;
    ray r = { origin, dir };
    struct hit h;
    /* any hit in front of the origin (POV-Ray's Find_Intersection), past
    ** accel's self-hit distance, a billionth of the object's size, and
    ** not beyond POV-Ray's MAX_DISTANCE (1e7 along the unit direction the
    ** parser passes): its shapes drop farther hits, so a ray grazing a
    ** plane it starts on misses it (language/tracevines) */
    if (!accel_intersect(a, &r, accel_epsilon(a), 1.0e7,
                         ACCEL_SKIP_NONE, &h))
        return false;
    *point = h.p;
    *normal = h.shading_n;
    return true;
}

static bool q_inside(void *user, const iris_scene *scene,
                     const iris_object *obj, iris_vec3 point)
{
    struct accel *a = accel_for(user, scene, obj);
    return a && accel_inside(a, obj, point);
}

struct geomq *geomq_new(FILE *log)
{
    struct geomq *q = iris_calloc(1, sizeof *q);
    if (!q)
        return NULL;
    q->log = log;
    q->cb.user = q;
    q->cb.bounds = q_bounds;
    q->cb.trace = q_trace;
    q->cb.inside = q_inside;
    return q;
}

const iris_geometry_queries *geomq_callbacks(struct geomq *q)
{
    return q ? &q->cb : NULL;
}

void geomq_free(struct geomq *q)
{
    if (!q)
        return;
    for (int i = 0; i < GEOMQ_SLOTS; i++)
        accel_destroy(q->slot[i].accel);
    iris_free(q);
}
