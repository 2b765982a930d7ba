/* SPDX-License-Identifier: MIT */
/*
** gather_sources.c: does a scene hold light that no light source emits?
** (see gather_sources.h). A walk over every texture an object can show,
** after the shape of mat_ctx_create's image walk (texture.c).
*/
#include "config.h"

#include "render/gather_sources.h"

/* Textures may be shared and, in a malformed scene, cyclic: a walk
** deeper than this stops and answers "light" (the safe side). */
#define WALK_DEPTH 64

struct walk {
    bool ambient_counts;       /* finish ambient adds light (#version < 3.7) */
    bool ambient_light;        /* global ambient_light is not black */
    bool media_seen;           /* gather rays see media */
};

static bool colour_nonzero(const iris_colour *c)
{
    return c->r != 0.0 || c->g != 0.0 || c->b != 0.0;
}

static bool finish_glows(const struct walk *w, const iris_finish *f)
{
    if (!f)
        return false;
    return colour_nonzero(&f->emission) ||
           (w->ambient_counts && w->ambient_light &&
            colour_nonzero(&f->ambient));
}

static bool texture_glows(const struct walk *w, const iris_texture *t,
                          int depth)
{
    for (; t; t = t->next, depth++) {
        if (depth > WALK_DEPTH || finish_glows(w, t->finish))
            return true;
        for (int i = 0; i < t->n_entries; i++)
            if (texture_glows(w, t->entries[i].texture, depth + 1))
                return true;
    }
    return false;
}

static bool interior_glows(const struct walk *w, const iris_interior *in)
{
    return in && w->media_seen && in->n_media > 0;
}

static bool object_glows(const struct walk *w, const iris_object *o,
                         int depth)
{
    if (!o)
        return false;
    if (depth > WALK_DEPTH || texture_glows(w, o->texture, 0) ||
        texture_glows(w, o->interior_texture, 0) ||
        interior_glows(w, o->interior))
        return true;
    switch (o->kind) {
    case IRIS_OBJ_UNION: case IRIS_OBJ_MERGE: case IRIS_OBJ_INTERSECTION:
    case IRIS_OBJ_DIFFERENCE: case IRIS_OBJ_LIGHT_GROUP:
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (object_glows(w, o->u.csg.children[i], depth + 1))
                return true;
        break;
    case IRIS_OBJ_MESH:
        for (int i = 0; i < o->u.mesh.n_textures; i++)
            if (texture_glows(w, o->u.mesh.textures[i], 0))
                return true;
        break;
    case IRIS_OBJ_BLOB:
        for (int i = 0; i < o->u.blob.n_components; i++)
            if (texture_glows(w, o->u.blob.components[i].texture, 0))
                return true;
        break;
    default:
        break;
    }
    return false;
}

bool gather_scene_has_unlit_light(const iris_scene *sc, bool ambient_counts,
                                  bool media_seen)
{
    if (!sc)
        return true;
    /* what a ray that escapes or crosses the air adds */
    if (colour_nonzero(&sc->background) || sc->sky_sphere ||
        sc->n_fogs > 0 || sc->n_rainbows > 0 ||
        (media_seen && sc->n_media > 0))
        return true;
    struct walk w = { ambient_counts,
                      colour_nonzero(&sc->settings.ambient_light),
                      media_seen };
    for (int i = 0; i < sc->n_objects; i++)
        if (object_glows(&w, sc->objects[i], 0))
            return true;
    for (int i = 0; i < sc->n_lights; i++)
        if (sc->lights[i] && object_glows(&w, sc->lights[i]->looks_like, 0))
            return true;
    return false;
}
