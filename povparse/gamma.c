/* SPDX-License-Identifier: MIT */
/*
** gamma.c: decoding the colours of scenes written for a working gamma
** other than 1 (global_settings { assumed_gamma G }, G != 1).
**
** POV-Ray 3.7 shades such scenes in the gamma-G space and writes the
** result without re-encoding; iris shades in linear light and encodes the
** output as sRGB. Decoding every pigment, light, background, fog and sky
** colour with c^G makes the two agree where the shading is linear in the
** colour (flat lighting, mixes, maps), which is the part the eye judges.
** Filter and transmit are fractions, not colours, and stay as written.
** Shared nodes are decoded once (a pointer set remembers them).
*/
#include "config.h"

#include <math.h>
#include <stdint.h>
#include <string.h>

#include "pp.h"
#include "util/mem.h"

struct seen {
    const void **slot;
    size_t cap, n;
};

/* Returns true the first time 'p' is seen. */
static bool first_visit(pp_state *ps, struct seen *s, const void *p)
{
    if (!p)
        return false;
    if (s->n * 2 >= s->cap) {
        size_t cap = s->cap ? s->cap * 2 : 256;
        const void **slot = pp_salloc(ps, cap * sizeof *slot);
        memset(slot, 0, cap * sizeof *slot);
        for (size_t i = 0; i < s->cap; i++) {
            if (!s->slot[i])
                continue;
            size_t h = ((uintptr_t)s->slot[i] >> 4) & (cap - 1);
            while (slot[h])
                h = (h + 1) & (cap - 1);
            slot[h] = s->slot[i];
        }
        s->slot = slot;
        s->cap = cap;
    }
    size_t h = ((uintptr_t)p >> 4) & (s->cap - 1);
    while (s->slot[h]) {
        if (s->slot[h] == p)
            return false;
        h = (h + 1) & (s->cap - 1);
    }
    s->slot[h] = p;
    s->n++;
    return true;
}

static void colour(iris_colour *c, double g)
{
    c->r = c->r > 0 ? pow(c->r, g) : c->r;
    c->g = c->g > 0 ? pow(c->g, g) : c->g;
    c->b = c->b > 0 ? pow(c->b, g) : c->b;
}

static void texture(pp_state *ps, struct seen *s, iris_texture *t, double g);

static void pigment(pp_state *ps, struct seen *s, iris_pigment *p, double g)
{
    if (!first_visit(ps, s, p))
        return;
    colour(&p->colour, g);
    if (p->entries && first_visit(ps, s, p->entries))
        for (int i = 0; i < p->n_entries; i++) {
            colour(&p->entries[i].colour, g);
            if (p->entries[i].pigment)
                pigment(ps, s, p->entries[i].pigment, g);
        }
}

static void texture(pp_state *ps, struct seen *s, iris_texture *t, double g)
{
    for (; t; t = t->next) {
        if (!first_visit(ps, s, t))
            return;
        if (t->pigment)
            pigment(ps, s, t->pigment, g);
        if (t->entries && first_visit(ps, s, t->entries))
            for (int i = 0; i < t->n_entries; i++)
                texture(ps, s, t->entries[i].texture, g);
    }
}

static void object(pp_state *ps, struct seen *s, iris_object *o, double g)
{
    if (!first_visit(ps, s, o))
        return;
    texture(ps, s, o->texture, g);
    texture(ps, s, o->interior_texture, g);
    if (o->kind == IRIS_OBJ_MESH)
        for (int i = 0; i < o->u.mesh.n_textures; i++)
            texture(ps, s, o->u.mesh.textures[i], g);
    if (o->kind == IRIS_OBJ_BLOB)
        for (int i = 0; i < o->u.blob.n_components; i++)
            texture(ps, s, o->u.blob.components[i].texture, g);
    if (o->kind >= IRIS_OBJ_UNION && o->kind < IRIS_OBJ_KIND_COUNT)
        for (int i = 0; i < o->u.csg.n_children; i++)
            object(ps, s, o->u.csg.children[i], g);
}

void pp_decode_gamma(pp_state *ps)
{
    iris_scene *sc = ps->scene;
    double g = sc->settings.assumed_gamma;
    if (!(g > 0) || fabs(g - 1) < 1e-9)
        return;
    struct seen s = { NULL, 0, 0 };
    for (int i = 0; i < sc->n_objects; i++)
        object(ps, &s, sc->objects[i], g);
    for (int i = 0; i < sc->n_lights; i++)
        if (first_visit(ps, &s, sc->lights[i]))
            colour(&sc->lights[i]->colour, g);
    colour(&sc->background, g);
    for (int i = 0; i < sc->n_fogs; i++)
        if (first_visit(ps, &s, sc->fogs[i]))
            colour(&sc->fogs[i]->colour, g);
    if (sc->sky_sphere)
        for (int i = 0; i < sc->sky_sphere->n_pigments; i++)
            pigment(ps, &s, sc->sky_sphere->pigments[i], g);
}
