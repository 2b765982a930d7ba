/* SPDX-License-Identifier: MIT */
/*
** povbox.c: the box POV-Ray 3.7 bounds a photon target holding a blob by.
**
** Photons are shot in rings at a target's bounding sphere, and with
** 'count' the spacing comes from that sphere's radius (shoot.c,
** spacing_for). iris's boxes are tight; POV-Ray's are its BBox, which
** for a blob (Blob::Compute_BBox, read from 3.7-stable, not copied) is
** the box around its components' bounding spheres: a sphere component's
** own sphere; a cylinder component three elements, the cylinder's sphere
** (centre at mid-axis, radius sqrt(r^2 + (len/2)^2)) and the two end
** hemispheres (radius r); components of negative strength left out. A
** transformed element's radius is the largest side of the box around
** its [0, r]^3 cube under the element's transform (a cylinder's frame:
** z turned onto its axis, then the component's own transform), and the
** blob's transform moves the box's corners. lights/glassthing.pov's
** glass (a blob of a 4.8-long cylinder, radius 0.7, in a merge, cut by a
** plane) is (-5, 0, -5)..(5, 6.2, 5) in POV-Ray, (-3.6, 0, -1.7)..(3.6,
** 6.2, 1.7) in iris: POV-Ray's sphere is 1.53 times iris's, and it
** shoots 77,991 photons (autostop 1) where iris shoots 32,207; the rings
** outside iris's sphere (which holds the whole object) all miss.
**
** So the rings stay on iris's sphere (the same photons meet the glass,
** the image is the same), and only the count estimate takes POV-Ray's
** radius: 'count N' then gives POV-Ray's spacing. CSG nodes combine their
** children's boxes as CSG::Compute_BBox does: a union or merge the box
** around them, an intersection the overlap of its children's that are
** not inverted (a plane with an axis-aligned normal bounds one axis,
** Quadric::Compute_Plane_Min_Max), a difference its first child's (the
** others are inverted). Targets without a blob keep iris's box.
*/
#include "config.h"

#include "photon/povbox.h"

#include <math.h>

#include "math/transform.h"

/* Deeper CSG nesting than this gives up (iris's box stands). */
#define POVBOX_MAX_DEPTH 1000

struct box {
    vec3 lo, hi;
};

static struct box box_all(void)
{
    struct box b = { v3(-INFINITY, -INFINITY, -INFINITY),
                     v3(INFINITY, INFINITY, INFINITY) };
    return b;
}

static void grow(struct box *b, vec3 c, double r)
{
    b->lo = v3_min(b->lo, v3(c.x - r, c.y - r, c.z - r));
    b->hi = v3_max(b->hi, v3(c.x + r, c.y + r, c.z + r));
}

/* The linear part of 'xf' applied to d. */
static vec3 lin(const xform *xf, vec3 d)
{
    return xf ? xf_dir(xf, d) : d;
}

/* The radius POV-Ray gives an element of radius r under the transform
** with columns ex, ey, ez: the largest side of the box around the
** transformed [0, r]^3 cube. */
static double element_radius(double r, vec3 ex, vec3 ey, vec3 ez)
{
    double sx = fabs(ex.x) + fabs(ey.x) + fabs(ez.x);
    double sy = fabs(ex.y) + fabs(ey.y) + fabs(ez.y);
    double sz = fabs(ex.z) + fabs(ey.z) + fabs(ez.z);
    return r * fmax(sx, fmax(sy, sz));
}

/* Adds a blob component's elements (in the blob's space) to *b. */
static void add_component(struct box *b, const iris_blob_component *bc)
{
    const xform *cx = bc->has_transform ? &bc->transform : NULL;
    double r = fabs(bc->radius);
    if (bc->kind == 0) {
        /* a sphere; with a transform POV-Ray's ellipsoid element */
        vec3 c = cx ? xf_point(cx, bc->a) : bc->a;
        if (cx) {
            vec3 ex = lin(cx, v3(1, 0, 0)), ey = lin(cx, v3(0, 1, 0)),
                 ez = lin(cx, v3(0, 0, 1));
            double sx = v3_len(ex), sy = v3_len(ey), sz = v3_len(ez);
            double tol = 1e-9 * fmax(sx, fmax(sy, sz));
            /* moved, turned or scaled alike, POV-Ray keeps a sphere
            ** (Blob::Rotate_Blob_Element, Scale_Blob_Element) */
            if (fabs(sx - sy) <= tol && fabs(sx - sz) <= tol &&
                fabs(v3_dot(ex, ey)) <= tol * sx &&
                fabs(v3_dot(ex, ez)) <= tol * sx &&
                fabs(v3_dot(ey, ez)) <= tol * sx)
                r *= sx;
            else
                r = element_radius(r, ex, ey, ez);
        }
        grow(b, c, r);
        return;
    }
    vec3 axis = v3_sub(bc->b, bc->a);
    double len = v3_len(axis);
    if (!(len > 0.0))
        return;
    vec3 up = v3_scale(axis, 1.0 / len);
    /* The cylinder's frame (Compute_Coordinate_Transform), base at the
    ** origin */
    vec3 e[3];
    xf_axis_frame(up, e);
    for (int i = 0; i < 3; i++)
        e[i] = lin(cx, e[i]);
    /* element centres along local z: base, middle, apex */
    static const double at[3] = { 0.0, 0.5, 1.0 };
    for (int i = 0; i < 3; i++) {
        double rr = i == 1 ? sqrt(r * r + 0.25 * len * len) : r;
        vec3 c = v3_madd(bc->a, up, at[i] * len);
        if (cx)
            c = xf_point(cx, c);
        grow(b, c, element_radius(rr, e[0], e[1], e[2]));
    }
}

/* POV-Ray's world box of blob 'o'; false when it has no positive
** component. */
static bool blob_box(const iris_object *o, struct box *out)
{
    struct box b = { v3(INFINITY, INFINITY, INFINITY),
                     v3(-INFINITY, -INFINITY, -INFINITY) };
    for (int i = 0; i < o->u.blob.n_components; i++)
        if (o->u.blob.components[i].strength > 0.0)
            add_component(&b, &o->u.blob.components[i]);
    if (!(b.lo.x <= b.hi.x))
        return false;
    if (!o->has_transform) {
        *out = b;
        return true;
    }
    for (int c = 0; c < 8; c++) {
        vec3 p = xf_point(&o->transform,
                          v3(c & 1 ? b.hi.x : b.lo.x, c & 2 ? b.hi.y : b.lo.y,
                             c & 4 ? b.hi.z : b.lo.z));
        out->lo = c ? v3_min(out->lo, p) : p;
        out->hi = c ? v3_max(out->hi, p) : p;
    }
    return true;
}

/* The half-space of plane 'o' as a box: bounded along an axis its world
** normal lies on, else everywhere. */
static struct box plane_box(const iris_object *o)
{
    struct box b = box_all();
    vec3 n = o->u.plane.normal;
    double nn = v3_dot(n, n);
    if (!(nn > 0.0))
        return b;
    vec3 p = v3_scale(n, o->u.plane.distance / nn); /* on the plane */
    if (o->has_transform) {
        p = xf_point(&o->transform, p);
        n = xf_normal(&o->transform, n);
    }
    n = v3_norm(n);
    double d = v3_dot(n, p); /* inside: n.x < d */
    double c[3] = { n.x, n.y, n.z };
    for (int k = 0; k < 3; k++) {
        if (fabs(c[(k + 1) % 3]) > 1e-10 || fabs(c[(k + 2) % 3]) > 1e-10)
            continue;
        double *hi = k == 0 ? &b.hi.x : k == 1 ? &b.hi.y : &b.hi.z;
        double *lo = k == 0 ? &b.lo.x : k == 1 ? &b.lo.y : &b.lo.z;
        if (c[k] > 0.0)
            *hi = d;
        else
            *lo = -d;
    }
    return b;
}

struct walk {
    povbox_leaf_fn leaf;
    const void *ctx;
    bool blob;                 /* a blob was met */
};

/* POV-Ray's box of 'o' into *out; false: give up. */
static bool node_box(struct walk *w, const iris_object *o, struct box *out,
                     int depth)
{
    if (depth > POVBOX_MAX_DEPTH || o->n_clipped_by > 0 || o->bounded_by)
        return false;
    switch (o->kind) {
    case IRIS_OBJ_BLOB:
        w->blob = true;
        return blob_box(o, out);
    case IRIS_OBJ_PLANE:
        *out = plane_box(o);
        return true;
    case IRIS_OBJ_UNION:
    case IRIS_OBJ_MERGE:
    case IRIS_OBJ_LIGHT_GROUP: {
        struct box b = { v3(INFINITY, INFINITY, INFINITY),
                         v3(-INFINITY, -INFINITY, -INFINITY) };
        for (int i = 0; i < o->u.csg.n_children; i++) {
            struct box c;
            if (!node_box(w, o->u.csg.children[i], &c, depth + 1))
                return false;
            b.lo = v3_min(b.lo, c.lo);
            b.hi = v3_max(b.hi, c.hi);
        }
        *out = b;
        return o->u.csg.n_children > 0;
    }
    case IRIS_OBJ_INTERSECTION:
    case IRIS_OBJ_DIFFERENCE: {
        struct box b = box_all();
        int n = o->kind == IRIS_OBJ_DIFFERENCE && o->u.csg.n_children > 0
                    ? 1
                    : o->u.csg.n_children;
        for (int i = 0; i < n; i++) {
            const iris_object *ch = o->u.csg.children[i];
            struct box c;
            if (ch->inverse || ch->kind == IRIS_OBJ_HEIGHT_FIELD)
                continue; /* not considered, as POV-Ray's */
            if (!node_box(w, ch, &c, depth + 1))
                return false;
            b.lo = v3_max(b.lo, c.lo);
            b.hi = v3_min(b.hi, c.hi);
        }
        *out = b;
        return true;
    }
    default: {
        vec3 lo, hi;
        if (!w->leaf(w->ctx, o, &lo, &hi))
            return false;
        out->lo = lo;
        out->hi = hi;
        return true;
    }
    }
}

bool povbox_target(const iris_object *t, povbox_leaf_fn leaf,
                   const void *ctx, vec3 *lo, vec3 *hi)
{
    struct walk w = { leaf, ctx, false };
    struct box b;
    if (!t || !node_box(&w, t, &b, 0) || !w.blob)
        return false;
    /* a degenerate or unbounded box is not used (CSG::Compute_BBox) */
    if (!(b.lo.x <= b.hi.x && b.lo.y <= b.hi.y && b.lo.z <= b.hi.z) ||
        !isfinite(b.lo.x) || !isfinite(b.lo.y) || !isfinite(b.lo.z) ||
        !isfinite(b.hi.x) || !isfinite(b.hi.y) || !isfinite(b.hi.z))
        return false;
    *lo = b.lo;
    *hi = b.hi;
    return true;
}

bool povbox_blob(const iris_object *o, vec3 *lo, vec3 *hi)
{
    struct box b;
    if (!o || o->kind != IRIS_OBJ_BLOB || !blob_box(o, &b))
        return false;
    *lo = b.lo;
    *hi = b.hi;
    return true;
}
