/* SPDX-License-Identifier: MIT */
/*
** bound.c: bounded_by as POV-Ray 3.7 applies it to a shape.
**
** Two things happen in POV-Ray. The parser gives the object its bound's
** box when that is smaller than its own (parse.cpp Parse_Object_Mods),
** and the renderer skips an object whose box a ray misses (objects.cpp
** Find_Intersection): so any shape is cut along the box's silhouette as
** seen along each ray. Then, for the shapes whose bound it keeps, the
** object is tested only for rays that meet the bound itself or start
** inside it (Ray_In_Bound), and all its crossings on such a ray count,
** also those outside the bound: the quartic examples show their infinite
** surfaces cut that way. The parser drops the bound of a top-level shape
** that is cheap to intersect (Link_To_Frame, "Unnecessary bounding object
** removed") but not its box; it keeps the bound on polys (quartic, cubic,
** poly) and text. It keeps the bound of every CSG (union, intersection,
** difference, merge): such an object is tested only for rays that meet
** its bound or start inside it (geom_csg_bound_admits, from accel/node.c;
** csg.cpp applies the same test to a bounded CSG child), so shapes2.inc's
** Pyramid2, planes bounded_by a box, ends at the box's silhouette. A
** bounded union is not split into its children (accel.c place()), as
** POV-Ray does not split one unless asked to (split_unions).
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>

#include "math/transform.h"

/* Whether POV-Ray keeps the bound of shape 'o' (Link_To_Frame); quadrics
** find their own box inside the bound's and drop it too. */
static bool bound_kept(const iris_object *o)
{
    return o->kind == IRIS_OBJ_POLY || o->kind == IRIS_OBJ_TEXT;
}

/* The world box of shape 'o' (its object box through its transform, as
** POV-Ray recomputes a box after a transform); false when unbounded. */
static bool world_box(const iris_object *o, const struct geom_profile *prof,
                      vec3 *lo, vec3 *hi)
{
    vec3 a, b;
    if (!geom_bounds(o, prof, &a, &b) || !isfinite(a.x) || !isfinite(a.y) ||
        !isfinite(a.z) || !isfinite(b.x) || !isfinite(b.y) || !isfinite(b.z))
        return false;
    if (!o->has_transform) {
        *lo = a;
        *hi = b;
        return true;
    }
    *lo = v3(INFINITY, INFINITY, INFINITY);
    *hi = v3(-INFINITY, -INFINITY, -INFINITY);
    for (int k = 0; k < 8; k++) {
        vec3 c = xf_point(&o->transform, v3(k & 1 ? b.x : a.x,
                                            k & 2 ? b.y : a.y,
                                            k & 4 ? b.z : a.z));
        *lo = v3_min(*lo, c);
        *hi = v3_max(*hi, c);
    }
    return true;
}

static double volume(vec3 lo, vec3 hi)
{
    return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
}

/* Bounds iris can test by themselves: the shapes without a profile. */
static bool bound_testable(const iris_object *b)
{
    switch (b->kind) {
    case IRIS_OBJ_SPHERE: case IRIS_OBJ_BOX: case IRIS_OBJ_PLANE:
    case IRIS_OBJ_CYLINDER: case IRIS_OBJ_CONE: case IRIS_OBJ_DISC:
    case IRIS_OBJ_TORUS: case IRIS_OBJ_QUADRIC: case IRIS_OBJ_POLY:
    case IRIS_OBJ_SUPERELLIPSOID:
        return true;
    default:
        return false;
    }
}

/* Whether the world box of bound 'b' is smaller than that of shape 'o'
** (or 'o' has none), and so cuts it (POV-Ray's parser keeps the smaller
** box); that box in '*lo', '*hi'. */
static bool box_cut(const iris_object *o, const struct geom_profile *prof,
                    const iris_object *b, vec3 *lo, vec3 *hi)
{
    vec3 olo, ohi;
    return world_box(b, NULL, lo, hi) &&
           (!world_box(o, prof, &olo, &ohi) ||
            volume(*lo, *hi) < volume(olo, ohi));
}

/* POV-Ray's Ray_In_Bound: whether the world ray wo + t·wd (t >= 0) meets
** bound 'b' or starts inside it. */
static bool ray_in_bound(const iris_object *b, vec3 wo, vec3 wd)
{
    vec3 bo = b->has_transform ? xf_inv_point(&b->transform, wo) : wo;
    vec3 bd = b->has_transform ? xf_inv_dir(&b->transform, wd) : wd;
    struct isect_list l;
    isect_list_init(&l);
    geom_intersect(b, NULL, bo, bd, 0, INFINITY, &l);
    bool met = l.n > 0;
    isect_list_fini(&l);
    return met || geom_inside(b, NULL, bo);
}

void geom_bound_prepare(const iris_object *o, struct geom_profile *prof)
{
    const iris_object *b = o->bounded_by;
    prof->bound.ready = true;
    prof->bound.box_cuts = b && !b->inverse && bound_testable(b) &&
                           box_cut(o, prof, b, &prof->bound.lo,
                                   &prof->bound.hi);
}

bool geom_bound_admits(const iris_object *o, const struct geom_profile *prof,
                       vec3 ro, vec3 rd)
{
    const iris_object *b = o->bounded_by;
    if (!b || b->inverse || !bound_testable(b))
        return true;
    /* The boxes come from geom_prepare(); recomputed here only for a
    ** caller without them (they were half the time of a bounded scene) */
    vec3 blo, bhi;
    bool cuts;
    if (prof && prof->bound.ready) {
        cuts = prof->bound.box_cuts;
        blo = prof->bound.lo;
        bhi = prof->bound.hi;
    } else {
        cuts = box_cut(o, prof, b, &blo, &bhi);
    }
    bool kept = bound_kept(o);
    if (!cuts && !kept)
        return true;
    /* The ray in world space; t is the same parameter there. */
    vec3 wo = o->has_transform ? xf_point(&o->transform, ro) : ro;
    vec3 wd = o->has_transform ? xf_dir(&o->transform, rd) : rd;
    if (cuts) {
        double t0 = 0, t1 = INFINITY;
        if (!geom_clip_box(blo, bhi, wo, wd, &t0, &t1))
            return false;
    }
    return !kept || ray_in_bound(b, wo, wd);
}

bool geom_csg_bound_admits(const iris_object *o, vec3 wo, vec3 wd)
{
    const iris_object *b = o->bounded_by;
    if (!b || b->inverse || !bound_testable(b))
        return true;
    return ray_in_bound(b, wo, wd);
}
