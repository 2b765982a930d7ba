/* SPDX-License-Identifier: MIT */
/*
** maptree.c: the size of a pigment's, normal's or texture's map tree
** (scene.h: map_tree), counted when the parser completes it, from its
** entries' counts: an entry is complete before the map that holds it, so
** a count costs one pass over the entries however often they are
** shared. A tree past IRIS_MAX_MAP_TREE is refused here, with the place
** of the map that passed it; every later walk over a tree (the
** renderer's, the dump's) is then bounded by it. Whether a map's entries
** read a point its transform cannot move is read one level down, from
** the entries' own flags, never by a walk.
*/
#include "config.h"

#include "pp.h"

/* An entry's count; one made outside the parser's bodies counts 1. */
static uint64_t counted(uint32_t n) { return n ? n : 1; }

static uint32_t checked(pp_state *ps, const pp_token *at, uint64_t n,
                        const char *what)
{
    if (n > IRIS_MAX_MAP_TREE)
        pp_error(ps, at, "this %s's map tree holds %llu %ss counted as a "
                 "tree, more than %u: maps whose entries share one map "
                 "double it at each level; declare fewer levels", what,
                 (unsigned long long)n, what, IRIS_MAX_MAP_TREE);
    return (uint32_t)n;
}

/* Whether a pattern reads the point the map's own transform cannot
** move: the surface's uv point, or the world point (slope). */
static bool pointwise(const iris_pattern *p)
{
    return p->uv_mapping || p->kind == IRIS_PAT_SLOPE;
}

/* An entry that reads such a point, or has one under it; one left
** uncounted with entries of its own is taken to have. */
static bool pig_pointwise(const iris_pigment *e)
{
    return e->map_tree_pointwise || pointwise(&e->pattern) ||
           (!e->map_tree && e->n_entries && e->is_pigment_map);
}

static bool nor_pointwise(const iris_normal *e)
{
    return e->map_tree_pointwise || pointwise(&e->pattern) ||
           (!e->map_tree && e->n_entries && !e->is_slope_map);
}

bool pp_pig_entries_pointwise(const iris_pigment *p)
{
    for (int i = 0; p->is_pigment_map && i < p->n_entries; i++)
        if (p->entries[i].pigment && pig_pointwise(p->entries[i].pigment))
            return true;
    return false;
}

bool pp_nor_entries_pointwise(const iris_normal *nr)
{
    for (int i = 0; !nr->is_slope_map && i < nr->n_entries; i++)
        if (nr->entries[i].normal && nor_pointwise(nr->entries[i].normal))
            return true;
    return false;
}

void pp_pig_map_tree(pp_state *ps, iris_pigment *p, const pp_token *at)
{
    uint64_t n = 1;
    for (int i = 0; p->is_pigment_map && i < p->n_entries; i++)
        if (p->entries[i].pigment)
            n += counted(p->entries[i].pigment->map_tree);
    p->map_tree = checked(ps, at, n, "pigment");
    p->map_tree_pointwise = pp_pig_entries_pointwise(p);
}

void pp_nor_map_tree(pp_state *ps, iris_normal *nr, const pp_token *at)
{
    uint64_t n = 1;
    for (int i = 0; !nr->is_slope_map && i < nr->n_entries; i++)
        if (nr->entries[i].normal)
            n += counted(nr->entries[i].normal->map_tree);
    nr->map_tree = checked(ps, at, n, "normal");
    nr->map_tree_pointwise = pp_nor_entries_pointwise(nr);
}

void pp_tex_map_tree(pp_state *ps, iris_texture *t, const pp_token *at)
{
    uint64_t n = 1;
    if (t->pigment)
        n += counted(t->pigment->map_tree);
    if (t->normal)
        n += counted(t->normal->map_tree);
    for (int i = 0; i < t->n_entries; i++)
        if (t->entries[i].texture)
            n += counted(t->entries[i].texture->map_tree);
    t->map_tree = checked(ps, at, n, "texture");
}
