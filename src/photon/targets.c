/* SPDX-License-Identifier: MIT */
/*
** targets.c: the objects photons are shot at, as POV-Ray 3.7 finds them.
**
** POV-Ray's parser replaces a union by its children in the scene's list
** of objects (Parser::Link_To_Frame: a union or light_group that is not
** a merge, not clipped, not bounded (without the +SU option, which iris
** does not read), without 'split_union off'); this applies again to the
** children. It gives every child of a photon target the target flag and
** the parent's 'target' spacing (Parser::Post_Process; povparse/obj.c
** finalize does the same). Then, for each light, it walks that list
** (PhotonStrategyTask::SearchThroughObjectsCreateUnits): an object with
** the flag is one light x target pair, aimed at its own bounding sphere,
** and its children are not looked at; an object without it that is a
** CSG has its children searched the same way, whatever kind of CSG it
** is (a merge, a difference, an intersection, a union kept whole).
**
** So a glass flagged as a target inside a plain union (a table with a
** glass on it, grouped) is a target of its own, and a flagged split
** union is one target per child, each aimed at the child's sphere: two
** balls 2 apart get two small spheres of photons, not one sphere around
** both. A photon aimed at one child that first meets another stops
** there (photons.cpp, PhotonTrace::TraceRay: the hit must be "in" the
** target, Trace::IsObjectInCSG), so where children's spheres overlap no
** photon is counted twice: ptargets_leaves() gives trace.c that test.
**
** A target in a light_group without 'global_lights on' gets no photons
** from the scene's lights (NO_GLOBAL_LIGHTS_FLAG, which the group gives
** its children), and its children are not searched either.
*/
#include "config.h"

#include "photon/targets.h"

#include <stdint.h>
#include <stdlib.h>

#include "util/mem.h"

/* Deeper CSG nesting than this is not searched: it bounds the
** recursion (a #while loop can wrap a declared object in unions far
** deeper than the parser's own recursion limit, PP_MAX_DEPTH). */
#define TARGETS_MAX_DEPTH 1000

static bool is_csg(const iris_object *o)
{
    return o->kind >= IRIS_OBJ_UNION && o->kind < IRIS_OBJ_KIND_COUNT &&
           o->u.csg.children;
}

/* Whether POV-Ray links the children of 'o' to the scene in its place. */
static bool splits(const iris_object *o)
{
    return (o->kind == IRIS_OBJ_UNION || o->kind == IRIS_OBJ_LIGHT_GROUP) &&
           o->split_union && o->n_clipped_by == 0 && !o->bounded_by;
}

/* Appends 'o' ('top': the 'top' flag to give it when the list keeps
** them, ptargets_find()). */
static bool push(struct ptargets *l, const iris_object *o, bool top,
                 bool with_top)
{
    if (l->n == l->cap) {
        int nc = l->cap ? 2 * l->cap : 8;
        const iris_object **nv = iris_realloc(l->o, (size_t)nc * sizeof *nv);
        if (!nv)
            return false;
        l->o = nv;
        if (with_top) {
            bool *nt = iris_realloc(l->top, (size_t)nc * sizeof *nt);
            if (!nt)
                return false;
            l->top = nt;
        }
        l->cap = nc;
    }
    if (with_top)
        l->top[l->n] = top;
    l->o[l->n++] = o;
    return true;
}

/* SearchThroughObjectsCreateUnits over one object of the scene's list
** (depth 0: a top-level object of iris's scene). */
static bool search(const iris_object *o, struct ptargets *out, int depth)
{
    if (!o || depth > TARGETS_MAX_DEPTH)
        return true;
    if (o->photon_target)
        return o->no_global_lights || push(out, o, depth == 0, true);
    if (is_csg(o))
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!search(o->u.csg.children[i], out, depth + 1))
                return false;
    return true;
}

/* Link_To_Frame: a split union's children take its place. */
static bool link(const iris_object *o, struct ptargets *out, int depth)
{
    if (o && depth <= TARGETS_MAX_DEPTH && is_csg(o) && splits(o)) {
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!link(o->u.csg.children[i], out, depth + 1))
                return false;
        return true;
    }
    return search(o, out, depth);
}

enum iris_status ptargets_find(const iris_scene *sc, struct ptargets *out)
{
    *out = (struct ptargets){ 0 };
    for (int i = 0; i < sc->n_objects; i++)
        if (!link(sc->objects[i], out, 0))
            return IRIS_ENOMEM;
    return IRIS_OK;
}

static bool add_leaves(const iris_object *o, struct ptargets *out, int depth)
{
    if (!o || depth > TARGETS_MAX_DEPTH)
        return true;
    if (!is_csg(o))
        return push(out, o, false, false);
    for (int i = 0; i < o->u.csg.n_children; i++)
        if (!add_leaves(o->u.csg.children[i], out, depth + 1))
            return false;
    return true;
}

static int cmp_ptr(const void *x, const void *y)
{
    uintptr_t a = (uintptr_t)*(const void *const *)x;
    uintptr_t b = (uintptr_t)*(const void *const *)y;
    return a < b ? -1 : a > b;
}

enum iris_status ptargets_leaves(const iris_object *t, struct ptargets *out)
{
    *out = (struct ptargets){ 0 };
    if (!t || !is_csg(t))
        return IRIS_OK;
    if (!add_leaves(t, out, 0))
        return IRIS_ENOMEM;
    qsort(out->o, (size_t)out->n, sizeof *out->o, cmp_ptr);
    return IRIS_OK;
}

bool ptargets_has(const iris_object *const *sorted, int n,
                  const iris_object *o)
{
    int lo = 0, hi = n - 1;
    while (lo <= hi) {
        int mid = lo + (hi - lo) / 2;
        if (sorted[mid] == o)
            return true;
        if ((uintptr_t)sorted[mid] < (uintptr_t)o)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return false;
}
