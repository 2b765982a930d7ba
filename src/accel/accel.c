/* SPDX-License-Identifier: MIT */
/*
** accel.c: building the Embree scene and answering ray queries.
**
** DESIGN
**
** Tree. accel_build() turns every scene object into a node (node.h):
** analytic shapes become shape leaves solved in object space in double
** precision (geometry/), meshes become triangle leaves (mesh.c), CSG
** becomes a node over its children. 'inverse' is pushed to the leaves with
** De Morgan's rules as POV-Ray's Invert() does: an inverted union is the
** intersection of the inverted children, an inverted intersection the
** merge of them, and difference(A, B, ...) is intersection(A, inv B, ...).
** So a leaf only flips its inside test and its normals.
**
** CSG. A CSG node is one Embree user primitive. Its callback gathers every
** crossing of every child along the ray (meshes inside CSG have a private
** Embree scene whose filter collects all crossings) and keeps those on its
** boundary by inside tests of the other children; clipped_by then keeps
** the crossings inside every clipping object. A top-level union without
** clipping is split into its children (POV-Ray's split_union), so plain
** unions cost nothing extra.
**
** Infinite objects. Nodes whose surface has no finite box (planes,
** quadrics, polys, and CSG built from them) are not given to Embree at
** all: they sit in a separate list tested after the Embree query, with
** the ray's far end shrunk to the nearest Embree hit. An intersection
** of planes and quadrics whose insides bound each other (a bevelled
** frame, a hyperboloid between two planes) gets the box they leave
** (csgbox.c) and goes to Embree like any finite object.
**
** Inside boxes. Each node also keeps a box holding its inside (where the
** shape's inside lies within its surface's box: not a disc's half-space,
** a height field's ground below its triangles, an inverse's outside), and
** node_inside() answers 'no' outside it without a transform or a shape
** test: CSG filtering and the interiors holding a ray's origin ask mostly
** about far points. Finite boxes of
** user primitives are padded by 1e-6 of their size (plus their distance
** from the origin) before becoming floats, so Embree's float traversal
** never culls a primitive the double-precision test would hit.
**
** bounded_by is not used for boxes: every object gets its own exact box
** (a transformed sphere the exact box of its ellipsoid). On the shapes
** where POV-Ray keeps it (polys, text, unbounded quadrics) it cuts rays
** off as POV-Ray's does (geometry/bound.c, from geom_intersect).
**
** Speed. A query costs Embree's set-up and a user-geometry dispatch per
** candidate, which for a handful of primitives is more than testing their
** boxes in turn: a scene of at most LINEAR_MAX bounded primitives and no
** mesh is searched without Embree (same boxes, same exact tests; each
** box's sides packed near-then-far for the query's signs of 1/d, so the
** slab test needs no swap: linear_ordered). Embree's own box test is not
** repeated in double in the callback. Shape leaves without clipping take
** node_nearest's short path (node.c shape_nearest): only the nearest
** crossing's normal is taken to world space, spheres and planes are
** solved inline, boxes, cylinders and cones hand over their few
** crossings without a list (node.c box_nearest, cone_nearest, the
** cone's frame taken at build time), a torus refines only its first
** root (torus_nearest), and the uv of a sphere, a cone's side or a
** torus is computed once, for the hit kept, and only when its texture
** has a uv_mapping pattern (uv_prepare). A leaf's texture (its own, its top-level object's or the default)
** is chosen once at build time (node.h 'texture'). An unbounded plane
** without clipping is tested inside the query itself, its world normal
** taken once at build time (plane_world_normal, plane_prepare); a plane
** inside CSG uses that normal too (node.c plane_hits). The nearest hit
** of a CSG node or a clipped leaf whose filtering asks two or more
** leaves' inside tests per crossing tests its crossings in order of t
** and stops at the first on the boundary (node.c lazy_nearest): a cut
** gem's query asked 19 crossings times up to 17 inside tests, it now
** asks about 25 in all. All of these give the same hits to the bit.
**
** Precision. Embree sees float rays; every decision (tmin, nearest hit)
** is taken in double by the callbacks, from the double ray kept in the
** query context (node.h, struct qctx). accel_epsilon() is therefore 1e-9
** of the scene's size, relative, so a scene scaled by 1e-6 or 1e6 gives
** the same hits; each hit also carries a finer offset of its own, 1e-9 of
** the object hit (hit_epsilon), for thin objects in a huge scene.
**
** Threads. After accel_build() returns nothing is written: queries keep
** their state on the caller's stack and Embree's rtcIntersect1 is
** thread-safe, so any number of threads may query at once. Building is
** single-threaded (Embree may use its own threads inside rtcCommitScene).
*/
#include "config.h"

#include "accel/accel.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/node.h"
#include "accel/csgbox.h"
#include "math/transform.h"
#include "util/mem.h"

/* Deeper CSG nesting than this is refused (a cycle, or a hostile file). */
#define MAX_DEPTH 200

/*
** Up to this many bounded primitives and no mesh, a query tests each
** primitive's box in turn instead of asking Embree: Embree's per-query
** set-up and user-geometry dispatch cost more than a few box tests, and
** most parity and test scenes have a handful of objects. The boxes and
** the exact tests are the same, so the hits are too. Where the crossover
** lies depends on what is measured: in eye-pass instructions (callgrind,
** one thread, 160 x 120, +A0.3 +AM1 +R3) Embree was already cheaper from
** 5 primitives on (34 0.987x, 33 0.947x, 217 0.88x, 175 0.86x, 194
** 0.95x), but Embree's SIMD instructions take longer each: in trace CPU
** time (time_render_cpu_s, 640 x 480, two threads, medians of 7
** alternating runs, session 10) it was 1.07x on 34, 1.04x on 33, 1.08x
** on 194 and 1.02x on 82, 0.96-0.97x only on 175 and 217. So 8 stays;
** from 9 on the linear search costs 1.05-1.5x Embree's instructions
** (130, 94, 166, 176, 196).
*/
#define LINEAR_MAX 8

/* A box that may be empty or infinite. */
struct bbox {
    bool inf, empty;
    vec3 lo, hi;
};

struct accel {
    RTCDevice dev;
    RTCScene scene;
    const iris_scene *sc;
    char embree_err[256];

    struct anode **nodes;          /* every node, for freeing */
    int n_nodes, cap_nodes;
    struct { const iris_object *obj; struct anode *node; } *map;
    int n_map;                     /* sorted by obj, for accel_inside */

    struct anode **roots;          /* per scene object, NULL if skipped */
    struct bbox *root_vol;         /* per scene object, its inside's box */
    struct anode **user;           /* Embree user primitives */
    int n_user;
    struct anode **inf;            /* unbounded, tested outside Embree */
    int n_inf;
    int n_attached;                /* meshes attached to 'scene' */
    bool linear;                   /* few primitives: no Embree query */
    /* linear: a->user[i]'s box, packed for each pattern of signs of
    ** 1/d (bit k set: 1/d < 0 along axis k) with the side a ray of that
    ** pattern enters along axis k (lo, or hi where 1/d < 0) in
    ** lin_box[pattern][i][0][k] and the side it leaves in [1][k] */
    double lin_box[8][LINEAR_MAX][2][3];

    int cap_user, cap_inf;
    const iris_object *stack[MAX_DEPTH + 2]; /* the objects being built */

    bool has_bounds;
    vec3 lo, hi;
    double eps;
    bool oom;
    bool building;                 /* Embree errors are recorded only now */

    /* For leaves the parser left without a texture: black, default finish
    ** (POV-Ray's untextured objects are black) */
    iris_texture default_texture;
    iris_pigment default_pigment;
    iris_finish default_finish;
};

/* ---------------------------------------------------------------- */
/* Boxes                                                              */
/* ---------------------------------------------------------------- */

static struct bbox box_inf(void)
{
    struct bbox b = { .inf = true };
    return b;
}

static struct bbox box_empty(void)
{
    struct bbox b = { .empty = true };
    return b;
}

static struct bbox box_union(struct bbox a, struct bbox b)
{
    if (a.inf || b.inf)
        return box_inf();
    if (a.empty)
        return b;
    if (b.empty)
        return a;
    a.lo = v3_min(a.lo, b.lo);
    a.hi = v3_max(a.hi, b.hi);
    return a;
}

static struct bbox box_meet(struct bbox a, struct bbox b)
{
    if (a.empty || b.empty)
        return box_empty();
    if (a.inf)
        return b;
    if (b.inf)
        return a;
    a.lo = v3_max(a.lo, b.lo);
    a.hi = v3_min(a.hi, b.hi);
    if (a.lo.x > a.hi.x || a.lo.y > a.hi.y || a.lo.z > a.hi.z)
        return box_empty();
    return a;
}

/* World box of object-space box lo..hi under 'xf' (NULL = identity). */
static struct bbox box_xf(vec3 lo, vec3 hi, const xform *xf)
{
    struct bbox b = { .lo = lo, .hi = hi };
    if (!xf)
        return b;
    for (int c = 0; c < 8; c++) {
        vec3 p = xf_point(xf, v3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y,
                                 c & 4 ? hi.z : lo.z));
        b.lo = c ? v3_min(b.lo, p) : p;
        b.hi = c ? v3_max(b.hi, p) : p;
    }
    return b;
}

/*
** The exact world box of a transformed sphere (an ellipsoid): the points
** M(c + r·u), |u| = 1, reach M(c) ± r·|row k of M's linear part| along
** axis k. Eight transformed corners of the object box (box_xf) give a box
** up to sqrt(3) times wider for a rotated, stretched sphere, and every ray
** through the difference costs a callback.
*/
static struct bbox ellipsoid_box(const iris_object *o)
{
    const xform *xf = &o->transform;
    double r = fabs(o->u.sphere.radius);
    vec3 c = xf_point(xf, o->u.sphere.centre);
    vec3 ex = xf_dir(xf, v3(1, 0, 0)), ey = xf_dir(xf, v3(0, 1, 0)),
         ez = xf_dir(xf, v3(0, 0, 1));
    vec3 e = v3(r * sqrt(ex.x * ex.x + ey.x * ey.x + ez.x * ez.x),
                r * sqrt(ex.y * ex.y + ey.y * ey.y + ez.y * ez.y),
                r * sqrt(ex.z * ex.z + ey.z * ey.z + ez.z * ez.z));
    struct bbox b = { .lo = v3_sub(c, e), .hi = v3_add(c, e) };
    return b;
}

/*
** The inside of an axis-aligned plane as a box with infinite sides (the
** usual clipped_by plane), so clipping narrows the object's box.
*/
static struct bbox half_space(const iris_object *o)
{
    vec3 n = v3_norm(o->u.plane.normal);
    double d = o->u.plane.distance;
    struct bbox b = { .lo = v3(-INFINITY, -INFINITY, -INFINITY),
                      .hi = v3(INFINITY, INFINITY, INFINITY) };
    double c[3] = { n.x, n.y, n.z };
    for (int k = 0; k < 3; k++) {
        if (fabs(c[k]) != 1)
            continue;
        /* n = ±e_k: inside is x_k < d (n = +e_k) or x_k > -d */
        if (c[k] > 0)
            b.hi = v3(k == 0 ? d : b.hi.x, k == 1 ? d : b.hi.y,
                      k == 2 ? d : b.hi.z);
        else
            b.lo = v3(k == 0 ? -d : b.lo.x, k == 1 ? -d : b.lo.y,
                      k == 2 ? -d : b.lo.z);
        return b;
    }
    return box_inf();
}

static bool box_finite(struct bbox b)
{
    return !b.inf && !b.empty && isfinite(b.lo.x) && isfinite(b.lo.y) &&
           isfinite(b.lo.z) && isfinite(b.hi.x) && isfinite(b.hi.y) &&
           isfinite(b.hi.z);
}

/*
** Whether the inside of analytic shape 'o' (not inverted) lies within the
** box of its surface, so that box also bounds its inside. Not so for a
** disc (its inside is the half-space behind it, as POV-Ray's), for the
** unbounded kinds, nor for a blob whose threshold is not positive (its
** density 0 far away already exceeds it).
*/
static bool inside_in_surface_box(const iris_object *o)
{
    switch (o->kind) {
    case IRIS_OBJ_DISC:
    case IRIS_OBJ_PLANE:
    case IRIS_OBJ_QUADRIC:
    case IRIS_OBJ_POLY:
        return false;
    case IRIS_OBJ_BLOB:
        return o->u.blob.threshold > 0;
    default:
        return true;
    }
}

/*
** An intersection's children that have no box alone (planes, quadrics)
** still bound its inside together (csgbox.c): each narrows the box the
** others leave, a few rounds over them as each round can let the next
** narrow further. Its crossings lie on the boundary of that inside, so
** the surface box 'S' is narrowed as well.
*/
static void narrow_intersection(const struct anode *n, struct bbox *S,
                                struct bbox *V)
{
    if (V->empty)
        return;
    vec3 lo = V->inf ? v3(-INFINITY, -INFINITY, -INFINITY) : V->lo;
    vec3 hi = V->inf ? v3(INFINITY, INFINITY, INFINITY) : V->hi;
    bool any = false;
    for (int round = 0; round < 3; round++) {
        for (int i = 0; i < n->n_kids; i++) {
            const struct anode *k = n->kids[i];
            if (k->kind != AN_SHAPE || k->inverted)
                continue;
            any = true;
            if (!csgbox_narrow(k->obj, &lo, &hi)) {
                *S = *V = box_empty();
                return;
            }
        }
        if (!any)
            return;
    }
    struct bbox b = { .lo = lo, .hi = hi };
    *V = b;
    *S = box_meet(*S, b);
}

/*
** A quadric clipped by planes or boxes (a paraboloid mirror cut at its
** rim by clipped_by { plane }): its surface lies on the boundary of its
** inside, so the box of its inside narrowed by the clips (csgbox.c, as
** POV-Ray narrows a clipped quadric's box in Quadric::Compute_BBox)
** bounds the clipped surface too. Without it the leaf had no box, and a
** photon target without a box got no photons at all (shoot.c asks for
** its bounding sphere), where POV-Ray shoots them. Only 'S' (the
** surface's box) is narrowed; an inside that stays unbounded (the other
** sign of the same paraboloid) leaves it as it was.
*/
static void clipped_quadric_box(const struct anode *n, bool ninv,
                                struct bbox *S)
{
    if (n->kind != AN_SHAPE || n->obj->kind != IRIS_OBJ_QUADRIC || ninv ||
        box_finite(*S) || S->empty)
        return;
    vec3 lo = S->inf ? v3(-INFINITY, -INFINITY, -INFINITY) : S->lo;
    vec3 hi = S->inf ? v3(INFINITY, INFINITY, INFINITY) : S->hi;
    for (int round = 0; round < 3; round++) {
        if (!csgbox_narrow(n->obj, &lo, &hi))
            return; /* nothing of the quadric inside the clips: keep S */
        for (int i = 0; i < n->n_clips; i++) {
            const struct anode *c = n->clips[i];
            if (c->kind == AN_SHAPE && !c->inverted &&
                !csgbox_narrow(c->obj, &lo, &hi))
                return;
        }
    }
    struct bbox b = { .lo = lo, .hi = hi };
    if (box_finite(b))
        *S = box_meet(*S, b);
}

/*
** A quadric without a box of its own but with a bounded_by (a paraboloid
** or cylinder bounded by a box instead of clipped, as shapes_old.inc's
** users write them): POV-Ray's parser gives it its bound's box (the
** smaller one; parse.cpp Parse_Object_Mods) and skips a ray that misses
** that box, but keeps every crossing of a ray that meets it, also those
** outside it (geometry/bound.c, geom_bound_admits, does the same). So
** that box, not narrowed by the quadric (a narrower one would reject
** rays that meet the bound and see the surface beyond it), is the box
** the leaf's rays are tested in: the same rays as before, and a photon
** target gets a bounding sphere, hence photons (it had none: 0 photons,
** where POV-Ray shoots at the bound).
*/
static void bounded_quadric_box(const struct anode *n, struct bbox *S)
{
    if (n->kind != AN_SHAPE || n->obj->kind != IRIS_OBJ_QUADRIC ||
        box_finite(*S) || S->empty || !n->prof || !n->prof->bound.ready ||
        !n->prof->bound.box_cuts)
        return;
    struct bbox b = { .lo = n->prof->bound.lo, .hi = n->prof->bound.hi };
    if (box_finite(b))
        *S = box_meet(*S, b);
}

/* ---------------------------------------------------------------- */
/* Building the tree                                                  */
/* ---------------------------------------------------------------- */

/*
** The world normal of plane leaf 'n' (node.h plane_wn): node.c
** shape_hits() and plane_nearest() take geom_plane_hits()' normal (the
** unit plane_n) to world space and scale it by sign/length, the same at
** every crossing; this is that expression, so the value is the same to
** the bit. A normal that is not finite or has no length gives no
** crossing there: plane_wn_ok false.
*/
static void plane_world_normal(struct anode *n)
{
    const iris_object *o = n->obj;
    vec3 pn = n->plane_n;
    n->plane_wn_ok = false;
    if (!isfinite(pn.x) || !isfinite(pn.y) || !isfinite(pn.z) ||
        (pn.x == 0 && pn.y == 0 && pn.z == 0))
        return;
    vec3 wn = o->has_transform ? xf_normal(&o->transform, pn) : pn;
    double len = v3_len(wn);
    if (!(len > 0) || !isfinite(len))
        return;
    n->plane_wn = v3_scale(wn, (n->inverted ? -1.0 : 1.0) / len);
    n->plane_wn_ok = true;
}

static const char *kind_name(enum iris_object_kind k)
{
    static const char *const names[] = {
        "sphere", "box", "plane", "cylinder", "cone", "torus", "disc",
        "triangle", "mesh", "polygon", "prism", "lathe", "sor",
        "superellipsoid", "blob", "height_field", "text", "isosurface",
        "quadric", "poly", "julia_fractal", "bicubic_patch", "parametric",
        "sphere_sweep", "ovus", "lemon", "union", "merge", "intersection",
        "difference", "light_group"
    };
    return (unsigned)k < sizeof names / sizeof names[0] ? names[k] : "object";
}

static void warn(struct accel *a, FILE *log, const iris_object *o,
                 const char *why)
{
    if (!log)
        return;
    const char *file = "<unknown>";
    if (o->loc.file > 0 && (int)o->loc.file < a->sc->n_files &&
        a->sc->files && a->sc->files[o->loc.file])
        file = a->sc->files[o->loc.file];
    fprintf(log, "%s:%u:%u: warning: %s skipped: %s\n", file,
            (unsigned)o->loc.line, (unsigned)o->loc.col, kind_name(o->kind),
            why);
}

static struct anode *new_node(struct accel *a)
{
    if (a->n_nodes == a->cap_nodes) {
        int cap = a->cap_nodes ? 2 * a->cap_nodes : 64;
        struct anode **nv = iris_realloc(a->nodes, (size_t)cap * sizeof *nv);
        if (!nv) {
            a->oom = true;
            return NULL;
        }
        a->nodes = nv;
        a->cap_nodes = cap;
    }
    struct anode *n = iris_calloc(1, sizeof *n);
    if (!n) {
        a->oom = true;
        return NULL;
    }
    a->nodes[a->n_nodes++] = n;
    return n;
}

static unsigned own_skip(const iris_object *o)
{
    return (o->no_image ? ACCEL_SKIP_NO_IMAGE : 0) |
           (o->no_shadow ? ACCEL_SKIP_NO_SHADOW : 0) |
           (o->no_reflection ? ACCEL_SKIP_NO_REFLECTION : 0) |
           (o->no_radiosity ? ACCEL_SKIP_NO_RADIOSITY : 0);
}

static bool is_csg(enum iris_object_kind k)
{
    return k == IRIS_OBJ_UNION || k == IRIS_OBJ_MERGE ||
           k == IRIS_OBJ_INTERSECTION || k == IRIS_OBJ_DIFFERENCE ||
           k == IRIS_OBJ_LIGHT_GROUP;
}

/*
** Builds the node of 'o'. 'inv' says whether an odd number of enclosing
** nodes are inverted; 'in_csg' whether the node's crossings will be
** gathered by a CSG parent (meshes then need a private scene). '*surf'
** receives the box holding the node's surface, '*vol' the box holding its
** inside. Returns NULL when the object is skipped (warned on 'log').
*/
static struct anode *build(struct accel *a, FILE *log, const iris_object *o,
                           const iris_object *top, bool inv, unsigned skip,
                           bool in_csg, int depth, struct bbox *surf,
                           struct bbox *vol)
{
    if (depth > MAX_DEPTH) {
        warn(a, log, o, "CSG nested too deeply");
        return NULL;
    }
    /* An object inside itself (a cycle) would recurse without end */
    for (int i = 0; i < depth; i++)
        if (a->stack[i] == o) {
            warn(a, log, o, "it contains itself");
            return NULL;
        }
    a->stack[depth] = o;
    bool ninv = inv != o->inverse;
    struct anode *n = new_node(a);
    if (!n)
        return NULL;
    n->obj = o;
    n->top = top;
    n->under_inverse = inv;
    n->skip = skip | own_skip(o);
    struct bbox S, V;

    if (is_csg(o->kind)) {
        n->kind = AN_CSG;
        bool kinv[2] = { ninv, ninv }; /* first child, the others */
        switch (o->kind) {
        case IRIS_OBJ_MERGE:
            n->op = ninv ? AN_INTERSECTION : AN_MERGE;
            break;
        case IRIS_OBJ_INTERSECTION:
            n->op = ninv ? AN_MERGE : AN_INTERSECTION;
            break;
        case IRIS_OBJ_DIFFERENCE:
            n->op = ninv ? AN_MERGE : AN_INTERSECTION;
            kinv[1] = !ninv;
            break;
        default: /* union, light_group */
            n->op = ninv ? AN_INTERSECTION : AN_UNION;
            break;
        }
        int nk = o->u.csg.children ? o->u.csg.n_children : 0;
        n->kids = nk > 0 ? iris_calloc((size_t)nk, sizeof *n->kids) : NULL;
        if (nk > 0 && !n->kids) {
            a->oom = true;
            return NULL;
        }
        struct bbox *ks = iris_malloc((size_t)(nk > 0 ? nk : 1) * sizeof *ks);
        struct bbox *kv = iris_malloc((size_t)(nk > 0 ? nk : 1) * sizeof *kv);
        if (!ks || !kv) {
            iris_free(ks);
            iris_free(kv);
            a->oom = true;
            return NULL;
        }
        for (int i = 0; i < nk; i++) {
            const iris_object *c = o->u.csg.children[i];
            if (!c)
                continue;
            struct anode *k = build(a, log, c, top, kinv[i > 0], n->skip,
                                    true, depth + 1, &ks[n->n_kids],
                                    &kv[n->n_kids]);
            if (k)
                n->kids[n->n_kids++] = k;
        }
        if (n->n_kids == 0) {
            iris_free(ks);
            iris_free(kv);
            warn(a, log, o, "it has no children that can be built");
            return NULL;
        }
        if (n->op == AN_INTERSECTION) {
            V = box_inf();
            for (int i = 0; i < n->n_kids; i++)
                V = box_meet(V, kv[i]);
            S = box_empty();
            for (int i = 0; i < n->n_kids; i++) {
                struct bbox b = ks[i];
                for (int j = 0; j < n->n_kids; j++)
                    if (j != i)
                        b = box_meet(b, kv[j]);
                S = box_union(S, b);
            }
            narrow_intersection(n, &S, &V);
        } else {
            S = V = box_empty();
            for (int i = 0; i < n->n_kids; i++) {
                S = box_union(S, ks[i]);
                V = box_union(V, kv[i]);
            }
        }
        iris_free(ks);
        iris_free(kv);
    } else if (amesh_kind(o->kind)) {
        n->kind = AN_MESH;
        n->inverted = ninv;
        const char *why = amesh_build(n, a->dev, in_csg || o->n_clipped_by > 0);
        vec3 lo, hi;
        if (why || !amesh_bounds(n, &lo, &hi)) {
            warn(a, log, o, why ? why : "it has no triangles");
            amesh_free(n->mesh);
            n->mesh = NULL;
            return NULL;
        }
        S.inf = S.empty = false;
        S.lo = lo;
        S.hi = hi;
        /* A height field's inside reaches down to its y = 0 below the
        ** lowest triangle (amesh_inside) */
        V = ninv || o->kind == IRIS_OBJ_HEIGHT_FIELD ? box_inf() : S;
    } else if (geom_is_analytic(o->kind)) {
        n->kind = AN_SHAPE;
        n->inverted = ninv;
        const char *why = geom_validate(o);
        if (!why) {
            n->prof = geom_prepare(o, &why);
        }
        if (why) {
            warn(a, log, o, why);
            return NULL;
        }
        if (o->kind == IRIS_OBJ_PLANE) {
            n->plane_n = v3_norm(o->u.plane.normal);
            plane_world_normal(n);
        }
        node_sphere_world_prepare(n);
        if (o->kind == IRIS_OBJ_BLOB)
            n->has_blob_box = geom_blob_bounds(o, &n->blob_lo, &n->blob_hi);
        vec3 lo, hi;
        if (o->kind == IRIS_OBJ_SPHERE && o->has_transform)
            S = ellipsoid_box(o);
        else if (geom_bounds(o, n->prof, &lo, &hi))
            S = box_xf(lo, hi, o->has_transform ? &o->transform : NULL);
        else
            S = box_inf();
        /* A plane's or poly's inside is unbounded, as is an inverse's */
        V = ninv || !inside_in_surface_box(o) ? box_inf() : S;
        if (!ninv && o->kind == IRIS_OBJ_PLANE && !o->has_transform)
            V = half_space(o);
    } else {
        warn(a, log, o, "this shape is not supported");
        return NULL;
    }

    /* The leaf's own size, before clipping shrinks its box (hit_epsilon):
    ** a huge sphere clipped to a small box still rounds at its radius */
    if (n->kind != AN_CSG && box_finite(S))
        n->size = v3_max_comp(v3_sub(S.hi, S.lo));

    /* clipped_by: only points inside every clipping object remain */
    if (o->n_clipped_by > 0 && o->clipped_by) {
        n->clips = iris_calloc((size_t)o->n_clipped_by, sizeof *n->clips);
        if (!n->clips) {
            a->oom = true;
            return NULL;
        }
        for (int i = 0; i < o->n_clipped_by; i++) {
            if (!o->clipped_by[i])
                continue;
            struct bbox cs, cv;
            struct anode *c = build(a, log, o->clipped_by[i], top, false, 0,
                                    true, depth + 1, &cs, &cv);
            if (!c)
                continue;
            n->clips[n->n_clips++] = c;
            S = box_meet(S, cv);
            V = box_meet(V, cv);
        }
        clipped_quadric_box(n, ninv, &S);
    }
    bounded_quadric_box(n, &S);

    /* Capped: it only chooses between two ways to the same answer */
    long cost = n->kind == AN_CSG ? 0 : 1;
    for (int i = 0; i < n->n_kids; i++)
        cost += n->kids[i]->inside_cost;
    for (int i = 0; i < n->n_clips; i++)
        cost += n->clips[i]->inside_cost;
    n->inside_cost = cost < 1000000 ? (int)cost : 1000000;
    /* Filtering every crossing of a CSG node asks the inside tests of
    ** every other child, and of the clips, of each crossing: from two
    ** leaves' tests on, testing them in order of t until one passes
    ** (node.c lazy_nearest) pays for itself. A lens cut from two
    ** spheres (one test a crossing) was 1% slower lazily. */
    long tests = 0;
    if (n->kind == AN_CSG && n->op != AN_UNION && n->n_kids > 0) {
        int least = n->kids[0]->inside_cost;
        for (int i = 0; i < n->n_kids; i++) {
            tests += n->kids[i]->inside_cost;
            if (n->kids[i]->inside_cost < least)
                least = n->kids[i]->inside_cost;
        }
        tests -= least;
    }
    for (int i = 0; i < n->n_clips; i++)
        tests += n->clips[i]->inside_cost;
    n->lazy = tests >= 2;

    n->bounded = box_finite(S) || S.empty;
    if (S.empty) {
        /* Nothing can be hit: a box no ray enters */
        n->lo = v3(1, 1, 1);
        n->hi = v3(-1, -1, -1);
    } else if (n->bounded) {
        n->lo = S.lo;
        n->hi = S.hi;
    }
    /* The inside box, padded as user_bounds pads the surface box so
    ** rounding in the transforms never rejects a point inside */
    n->vol_bounded = box_finite(V) || V.empty;
    if (V.empty) {
        n->vlo = v3(1, 1, 1);
        n->vhi = v3(-1, -1, -1);
    } else if (n->vol_bounded) {
        vec3 ext = v3_sub(V.hi, V.lo);
        double mag = fmax(v3_max_comp(v3(fabs(V.lo.x), fabs(V.lo.y),
                                         fabs(V.lo.z))),
                          v3_max_comp(v3(fabs(V.hi.x), fabs(V.hi.y),
                                         fabs(V.hi.z))));
        double pad = 1e-6 * (v3_max_comp(ext) + mag);
        n->vlo = v3_sub(V.lo, v3(pad, pad, pad));
        n->vhi = v3_add(V.hi, v3(pad, pad, pad));
    }
    *surf = S;
    *vol = V;
    return n;
}

static int cmp_map(const void *x, const void *y)
{
    const iris_object *a = *(const iris_object *const *)x;
    const iris_object *b = *(const iris_object *const *)y;
    return a < b ? -1 : a > b;
}

/* Sorted (object -> node) pairs for accel_inside(). */
static bool build_map(struct accel *a)
{
    a->map = iris_malloc((size_t)(a->n_nodes ? a->n_nodes : 1) *
                         sizeof *a->map);
    if (!a->map)
        return false;
    /* Only nodes that answer for the object itself: not those built
    ** under an inverted parent (a difference's subtracted children) */
    a->n_map = 0;
    for (int i = 0; i < a->n_nodes; i++) {
        if (a->nodes[i]->under_inverse)
            continue;
        a->map[a->n_map].obj = a->nodes[i]->obj;
        a->map[a->n_map].node = a->nodes[i];
        a->n_map++;
    }
    qsort(a->map, (size_t)a->n_map, sizeof *a->map, cmp_map);
    return true;
}

static struct anode *find_node(const struct accel *a, const iris_object *o)
{
    int lo = 0, hi = a->n_map - 1;
    while (lo <= hi) {
        int mid = (lo + hi) / 2;
        if (a->map[mid].obj == o)
            return a->map[mid].node;
        if ((const void *)a->map[mid].obj < (const void *)o)
            lo = mid + 1;
        else
            hi = mid - 1;
    }
    return NULL;
}

static bool push_ptr(struct anode ***arr, int *n, int *cap, struct anode *x)
{
    if (*n == *cap) {
        int nc = *cap ? 2 * *cap : 16;
        struct anode **nv = iris_realloc(*arr, (size_t)nc * sizeof *nv);
        if (!nv)
            return false;
        *arr = nv;
        *cap = nc;
    }
    (*arr)[(*n)++] = x;
    return true;
}

/*
** An unbounded plane leaf without clipping is tested inline by
** accel_intersect() (plane_nearest below), with the world normal the
** build took once (plane_world_normal). A plane whose normal is not
** valid (node.c plane_nearest never hits it) keeps the general path.
*/
static void plane_prepare(struct anode *n)
{
    n->plane_fast = n->kind == AN_SHAPE && n->n_clips == 0 && !n->bounded &&
                    n->obj->kind == IRIS_OBJ_PLANE && n->plane_wn_ok &&
                    !n->obj->bounded_by; /* its box cuts it: geom.c */
}

/* Marks 'n' and every node under it as part of placed node 'prim'. */
static void mark_prim(struct anode *n, const struct anode *prim)
{
    n->prim = prim;
    for (int i = 0; i < n->n_kids; i++)
        mark_prim(n->kids[i], prim);
}

/* Places a top-level node: splits plain unions, routes the rest. */
static bool place(struct accel *a, struct anode *n)
{
    if (n->kind == AN_CSG && n->op == AN_UNION && n->n_clips == 0 &&
        !n->obj->bounded_by) {
        for (int i = 0; i < n->n_kids; i++)
            if (!place(a, n->kids[i]))
                return false;
        return true;
    }
    if (n->kind == AN_MESH && n->n_clips == 0) {
        a->n_attached++;
        return amesh_attach(n, a->dev, a->scene);
    }
    mark_prim(n, n);
    if (n->bounded)
        return push_ptr(&a->user, &a->n_user, &a->cap_user, n);
    plane_prepare(n);
    return push_ptr(&a->inf, &a->n_inf, &a->cap_inf, n);
}

/* ---------------------------------------------------------------- */
/* Embree callbacks                                                   */
/* ---------------------------------------------------------------- */

static void on_embree_error(void *user, enum RTCError code, const char *str)
{
    struct accel *a = user;
    /* During queries the accel is shared and read-only: not written */
    if (a->building && a->embree_err[0] == 0)
        snprintf(a->embree_err, sizeof a->embree_err, "Embree error %d: %s",
                 (int)code, str ? str : "");
}

static void user_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const struct accel *a = args->geometryUserPtr;
    const struct anode *n = a->user[args->primID];
    /* Pad so float rounding of the box and the ray never culls a hit */
    vec3 ext = v3_sub(n->hi, n->lo);
    double mag = fmax(v3_max_comp(v3(fabs(n->lo.x), fabs(n->lo.y),
                                     fabs(n->lo.z))),
                      v3_max_comp(v3(fabs(n->hi.x), fabs(n->hi.y),
                                     fabs(n->hi.z))));
    double pad = 1e-6 * (v3_max_comp(ext) + mag);
    struct RTCBounds *b = args->bounds_o;
    b->lower_x = (float)(n->lo.x - pad);
    b->lower_y = (float)(n->lo.y - pad);
    b->lower_z = (float)(n->lo.z - pad);
    b->upper_x = (float)(n->hi.x + pad);
    b->upper_y = (float)(n->hi.y + pad);
    b->upper_z = (float)(n->hi.z + pad);
    if (n->lo.x > n->hi.x) {
        /* An empty node: a degenerate box far from everything */
        b->lower_x = b->upper_x = b->lower_y = b->upper_y = b->lower_z =
            b->upper_z = 3e38f;
    }
}

static void user_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    if (args->N != 1 || !args->valid[0])
        return;
    const struct accel *a = args->geometryUserPtr;
    struct qctx *q = (struct qctx *)args->context;
    if (q->mode != Q_NEAREST || q->accel != a)
        return;
    const struct anode *n = a->user[args->primID];
    /* Embree has culled by the (padded) box: not tested again. The
    ** node_nearest functions write the hit only when they find one, so it
    ** goes straight into the query (here and in accel_intersect) */
    if (!node_nearest_in_box(n, q->o, q->d, q->tmin, q->tmax, q->skip,
                             &q->best))
        return;
    q->tmax = q->best.t;
    q->found = true;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;
    rh->ray.tfar = (float)q->best.t * (1 + 1e-6f);
    rh->hit.geomID = args->geomID;
    rh->hit.primID = args->primID;
}

/* ---------------------------------------------------------------- */
/* Public entry points                                                */
/* ---------------------------------------------------------------- */

static void compute_epsilon(struct accel *a)
{
    /* 1e-9 of the scene's size: a million times double rounding of the
    ** largest coordinate, and a billionth of the scene, so that nothing
    ** the scene's author could see is ever skipped. */
    double size = 0;
    if (a->has_bounds) {
        vec3 ext = v3_sub(a->hi, a->lo);
        size = v3_max_comp(ext);
        size = fmax(size, v3_max_comp(v3_max(v3(fabs(a->lo.x), fabs(a->lo.y),
                                                 fabs(a->lo.z)),
                                              v3(fabs(a->hi.x), fabs(a->hi.y),
                                                 fabs(a->hi.z)))));
    }
    if (!(size > 0) && a->sc->has_camera)
        size = v3_len(a->sc->camera.location);
    if (!(size > 0) || !isfinite(size))
        size = 1;
    /* A floor far below any scene but above underflow */
    a->eps = fmax(1e-9 * size, 1e-290);
}

/*
** Whether shading with texture 't' may read a hit's uv. Only a pattern
** under uv_mapping does (material/pattern.c pat_input, the one reader of
** struct mat_point's uv), so this looks for one among every pattern the
** texture's evaluation can reach: each layer's texture_map pattern and
** entries, its pigment's pattern and pigment_map (or list pattern)
** entries, its normal's pattern and normal_map entries. Function
** patterns evaluate what they embed at a point of their own, with uv 0
** (fn/fnimages.c). Nesting deeper than MAX_DEPTH answers yes.
*/
static bool pigment_reads_uv(const iris_pigment *p, int depth);
static bool normal_reads_uv(const iris_normal *n, int depth);

static bool texture_reads_uv(const iris_texture *t, int depth)
{
    if (depth > MAX_DEPTH)
        return true;
    for (; t; t = t->next) {
        if (t->map_pattern.uv_mapping ||
            pigment_reads_uv(t->pigment, depth + 1) ||
            normal_reads_uv(t->normal, depth + 1))
            return true;
        for (int i = 0; i < t->n_entries && t->entries; i++)
            if (texture_reads_uv(t->entries[i].texture, depth + 1) ||
                pigment_reads_uv(t->entries[i].pigment, depth + 1) ||
                normal_reads_uv(t->entries[i].normal, depth + 1))
                return true;
    }
    return false;
}

static bool pigment_reads_uv(const iris_pigment *p, int depth)
{
    if (!p)
        return false;
    if (depth > MAX_DEPTH || p->pattern.uv_mapping)
        return true;
    for (int i = 0; i < p->n_entries && p->entries; i++)
        if (pigment_reads_uv(p->entries[i].pigment, depth + 1))
            return true;
    return false;
}

static bool normal_reads_uv(const iris_normal *n, int depth)
{
    if (!n)
        return false;
    if (depth > MAX_DEPTH || n->pattern.uv_mapping)
        return true;
    for (int i = 0; i < n->n_entries && n->entries; i++)
        if (normal_reads_uv(n->entries[i].normal, depth + 1))
            return true;
    return false;
}

/*
** A sphere's uv costs an atan2 and an acos per hit, a cylinder's or a
** cone's side an atan2, a torus's two; few textures read it (only
** uv_mapping patterns do: texture_reads_uv). The nearest-crossing paths
** compute it (accel_intersect for spheres, node.c cone_nearest and
** torus_nearest) only for the leaves whose hits may be shaded with a
** texture that does:
** the hit's texture (the leaf's own, else its top-level object's, else
** the default plain one) or its interior_texture. Photons and shadow
** rays shade the same textures.
*/
static void uv_prepare(struct anode *n)
{
    if (n->kind != AN_SHAPE || !n->obj)
        return;
    const iris_texture *t = n->obj->texture ? n->obj->texture
                            : n->top ? n->top->texture : NULL;
    n->uv_read = texture_reads_uv(t, 0) ||
                 texture_reads_uv(n->obj->interior_texture, 0);
    n->sphere_uv = n->uv_read && n->obj->kind == IRIS_OBJ_SPHERE;
}

enum iris_status accel_build(const iris_scene *scene, struct accel **out,
                             FILE *log, char *err, size_t errlen)
{
    *out = NULL;
    if (err && errlen)
        err[0] = 0;
    struct accel *a = iris_calloc(1, sizeof *a);
    if (!a)
        return IRIS_ENOMEM;
    a->sc = scene;
    a->building = true;
    iris_finish_defaults(&a->default_finish);
    a->default_pigment.colour.t = 0;
    a->default_texture.pigment = &a->default_pigment;
    a->default_texture.finish = &a->default_finish;
    a->dev = rtcNewDevice("verbose=0");
    if (!a->dev) {
        if (err)
            snprintf(err, errlen, "Embree: cannot create a device (error %d)",
                     (int)rtcGetDeviceError(NULL));
        iris_free(a);
        return IRIS_EUNSUPPORTED;
    }
    rtcSetDeviceErrorFunction(a->dev, on_embree_error, a);
    a->scene = rtcNewScene(a->dev);
    if (a->scene)
        rtcSetSceneFlags(a->scene, RTC_SCENE_FLAG_ROBUST);

    int no = scene->n_objects > 0 ? scene->n_objects : 0;
    a->roots = iris_calloc((size_t)(no ? no : 1), sizeof *a->roots);
    a->root_vol = iris_calloc((size_t)(no ? no : 1), sizeof *a->root_vol);
    if (!a->roots || !a->root_vol || !a->scene)
        a->oom = true;

    struct bbox all = box_empty();
    for (int i = 0; i < no && !a->oom; i++) {
        const iris_object *o = scene->objects[i];
        if (!o)
            continue;
        struct bbox s, v;
        struct anode *n = build(a, log, o, o, false, 0, false, 0, &s, &v);
        if (!n)
            continue;
        a->roots[i] = n;
        a->root_vol[i] = v;
        if (box_finite(s))
            all = box_union(all, s);
        if (!place(a, n))
            a->oom = true;
    }

    if (!a->oom && a->n_user > 0) {
        RTCGeometry g = rtcNewGeometry(a->dev, RTC_GEOMETRY_TYPE_USER);
        if (g) {
            rtcSetGeometryUserPrimitiveCount(g, (unsigned)a->n_user);
            rtcSetGeometryUserData(g, a);
            rtcSetGeometryBoundsFunction(g, user_bounds, a);
            rtcSetGeometryIntersectFunction(g, user_intersect);
            rtcCommitGeometry(g);
            rtcAttachGeometry(a->scene, g);
            rtcReleaseGeometry(g);
        }
    }
    if (a->scene)
        rtcCommitScene(a->scene);
    if (!a->oom && !build_map(a))
        a->oom = true;

    if (a->oom) {
        if (err)
            snprintf(err, errlen, "out of memory while building the scene");
        accel_destroy(a);
        return IRIS_ENOMEM;
    }
    if (a->embree_err[0]) {
        if (err)
            snprintf(err, errlen, "%s", a->embree_err);
        accel_destroy(a);
        return IRIS_EINVAL;
    }
    for (int i = 0; i < a->n_nodes; i++) {
        struct anode *n = a->nodes[i];
        uv_prepare(n);
        /* node.c cone_nearest's frame, taken once */
        if (n->kind == AN_SHAPE && n->obj &&
            (n->obj->kind == IRIS_OBJ_CYLINDER ||
             n->obj->kind == IRIS_OBJ_CONE))
            geom_cone_frame(n->obj, &n->cone);
        /* accel_intersect()'s choice for every hit, made once */
        n->texture = n->obj && n->obj->texture   ? n->obj->texture
                     : n->top && n->top->texture ? n->top->texture
                                                 : &a->default_texture;
    }
    a->linear = a->n_attached == 0 && a->n_user <= LINEAR_MAX;
    for (int i = 0; a->linear && i < a->n_user; i++) {
        const struct anode *n = a->user[i];
        const double lo[3] = { n->lo.x, n->lo.y, n->lo.z },
                     hi[3] = { n->hi.x, n->hi.y, n->hi.z };
        for (int k = 0; k < 3; k++) {
            /* An empty node's box (lo > hi: build() gives it 1..-1) is
            ** the box between the two along k to box_may_hit(), which
            ** orders each slab's pair; so it is here */
            double l = lo[k] > hi[k] ? hi[k] : lo[k],
                   h = lo[k] > hi[k] ? lo[k] : hi[k];
            for (int sg = 0; sg < 8; sg++) {
                bool neg = sg >> k & 1;
                a->lin_box[sg][i][0][k] = neg ? h : l;
                a->lin_box[sg][i][1][k] = neg ? l : h;
            }
            /* A bounded node's box is finite (build(): box_finite or
            ** empty); one that is not a number would have no order, and
            ** Embree's query would take it */
            if (isnan(lo[k]) || isnan(hi[k]))
                a->linear = false;
        }
    }
    a->has_bounds = !all.empty && !all.inf;
    if (a->has_bounds) {
        a->lo = all.lo;
        a->hi = all.hi;
    }
    compute_epsilon(a);
    a->building = false;
    *out = a;
    return IRIS_OK;
}

void accel_destroy(struct accel *a)
{
    if (!a)
        return;
    for (int i = 0; i < a->n_nodes; i++) {
        struct anode *n = a->nodes[i];
        amesh_free(n->mesh);
        geom_profile_free(n->prof);
        iris_free(n->kids);
        iris_free(n->clips);
        iris_free(n);
    }
    if (a->scene)
        rtcReleaseScene(a->scene);
    if (a->dev)
        rtcReleaseDevice(a->dev);
    iris_free(a->nodes);
    iris_free(a->map);
    iris_free(a->roots);
    iris_free(a->root_vol);
    iris_free(a->user);
    iris_free(a->inf);
    iris_free(a);
}

/* x·0 is 0 for finite x and NaN for an infinity or NaN, so the sum is 0
** exactly when all three are finite: one test instead of three
** branches, in a function called five times per query. */
static bool finite_v(vec3 v)
{
    return v.x * 0.0 + v.y * 0.0 + v.z * 0.0 == 0.0;
}

/* finite_v() of two vectors in one test. */
static bool finite_v2(vec3 a, vec3 b)
{
    return (a.x * 0.0 + a.y * 0.0 + a.z * 0.0) +
               (b.x * 0.0 + b.y * 0.0 + b.z * 0.0) == 0.0;
}

/*
** The offset for a ray leaving world point 'p' on 'leaf' (see accel.h).
** A secondary ray meets its own surface again at t ~ (rounding error of
** p) / cos: the error comes from solving the leaf in its object space and
** mapping p to world space, a few ulps of the leaf's size and of |p|.
** 1e-9 of the larger of the two leaves a margin of about 1e6 for rounding
** and grazing angles, as the global accel_epsilon() does for the scene.
** The size is the whole leaf's, before clipping (node.h 'size').
** Unbounded leaves (planes, quadrics) have no size: they keep the global
** offset.
*/
static double hit_epsilon(const struct accel *a, const struct anode *leaf,
                          vec3 p)
{
    return accel_hit_epsilon(leaf->size, p, a->eps);
}

/*
** Whether ray o + t·d, t in (t0, t1), may meet box lo..hi, with 'inv' =
** 1/d per axis (infinite where d is 0): the slab test with products
** instead of divisions, for the per-query loop over a few primitives.
** The interval is widened by 1e-12 relative so that the rounding of the
** reciprocal never culls a crossing the exact test would keep; the box
** only culls, the shape's own test decides.
*/
static inline bool box_may_hit(vec3 lo, vec3 hi, vec3 o, vec3 inv, double t0,
                               double t1)
{
    double a = t0, b = t1;
    const double lk[3] = { lo.x, lo.y, lo.z }, hk[3] = { hi.x, hi.y, hi.z },
                 ok[3] = { o.x, o.y, o.z }, ik[3] = { inv.x, inv.y, inv.z };
    for (int k = 0; k < 3; k++) {
        if (isinf(ik[k])) {
            if (ok[k] < lk[k] || ok[k] > hk[k])
                return false;
            continue;
        }
        double ta = (lk[k] - ok[k]) * ik[k], tb = (hk[k] - ok[k]) * ik[k];
        if (ta > tb) {
            double s = ta;
            ta = tb;
            tb = s;
        }
        if (ta > a)
            a = ta;
        if (tb < b)
            b = tb;
        if (a > b + 1e-12 * (fabs(a) + fabs(b)))
            return false;
    }
    return true;
}

/*
** node_nearest() of a plane_fast leaf (plane_prepare): node.c
** plane_nearest() step for step, without its calls and with the normal
** taken once. Planes are met by nearly every query of a scene with a
** floor, shadow rays included.
*/
static inline bool plane_nearest(const struct anode *n, vec3 o, vec3 d,
                                 double tmin, double tmax, unsigned skip,
                                 struct ahit *best)
{
    if (n->skip & skip)
        return false;
    const iris_object *obj = n->obj;
    vec3 lo = o, ld = d;
    if (obj->has_transform) {
        lo = anode_inv_point(&obj->transform, o);
        ld = anode_inv_dir(&obj->transform, d);
    }
    vec3 pn = n->plane_n;
    double dn = v3_dot(pn, ld);
    if (dn == 0)
        return false;
    double t = (obj->u.plane.distance - v3_dot(pn, lo)) / dn;
    /* no isfinite(t): t < tmax fails for +inf, t > tmin for -inf
    ** and NaN, whatever tmin and tmax are */
    if (!(t > tmin && t < tmax))
        return false;
    best->t = t;
    best->n = best->sn = n->plane_wn;
    best->uv.u = best->uv.v = 0;
    best->leaf = n;
    best->texture = NULL;
    return true;
}

/*
** One axis of box_may_hit() with a finite 1/d, for a box whose sides
** along the axis are ordered by the caller: 'near' the side a ray of this
** sign of 1/d enters by (the lower one for 1/d > 0, the higher one for
** 1/d < 0), 'far' the other. Rounding is monotone, so (near - o)·inv <=
** (far - o)·inv, and these are box_may_hit()'s ta and tb after its swap
** (a pair equal in value may differ in the sign of a zero, which no
** comparison below sees). Its emptiness test is asked in two steps:
** a <= b passes at once (the tolerance is >= 0; a, b are never NaN
** here: the box is a number, o and 1/d finite), and most passing axes
** need no tolerance. Hence box_may_hit()'s decision, without its
** comparison and swap of the pair per axis, and with selections the
** compiler makes without branches.
*/
static inline bool slab_ordered(double near, double far, double o,
                                double inv, double *a, double *b)
{
    double tn = (near - o) * inv, tf = (far - o) * inv;
    *a = tn > *a ? tn : *a;
    *b = tf < *b ? tf : *b;
    return !(*a > *b) || !(*a > *b + 1e-12 * (fabs(*a) + fabs(*b)));
}

/*
** The nearest crossing among the bounded primitives of a linear accel
** (a->linear), each box tested in turn, in (tmin, *tmax); *tmax shrinks
** to each crossing kept. For a finite 1/d: the boxes are read from
** a->lin_box's copy for the query's signs of 1/d, whose row 0 is each
** box's near side along each axis and row 1 its far side
** (slab_ordered), with the origin, the interval and 1/d kept in
** registers; the exact test reads the ray from 'r' (a copy made for its
** call before the loop cost the queries that make none). The loop over
** boxes is most of a query in a scene of a few objects:
** 175_extents_stacking tests 1.6 M boxes in 197 k queries, and choosing
** each pair's order by a comparison cost it 5 % of its eye pass.
*/
static inline __attribute__((always_inline)) bool
linear_ordered(const struct accel *a, const ray *r, vec3 inv, double tmin,
               double *tmax, unsigned skip, struct ahit *best)
{
    bool found = false;
    double t1 = *tmax;
    vec3 o = r->o;
    const double(*box)[2][3] =
        a->lin_box[(inv.x < 0) | (inv.y < 0) << 1 | (inv.z < 0) << 2];
    for (int i = 0; i < a->n_user; i++) {
        const double(*bx)[3] = box[i];
        double ta = tmin, tb = t1;
        if (!(slab_ordered(bx[0][0], bx[1][0], o.x, inv.x, &ta, &tb) &&
              slab_ordered(bx[0][1], bx[1][1], o.y, inv.y, &ta, &tb) &&
              slab_ordered(bx[0][2], bx[1][2], o.z, inv.z, &ta, &tb)))
            continue;
        if (node_nearest_in_box(a->user[i], r->o, r->d, tmin, t1, skip,
                                best)) {
            t1 = best->t;
            found = true;
        }
    }
    *tmax = t1;
    return found;
}

/* linear_ordered() for a ray along an axis (an infinite 1/d), rare:
** box_may_hit() on each primitive's own box. */
static bool linear_loop(const struct accel *a, const ray *r, vec3 inv,
                        double tmin, double *tmax, unsigned skip,
                        struct ahit *best)
{
    bool found = false;
    double t1 = *tmax;
    for (int i = 0; i < a->n_user; i++) {
        const struct anode *n = a->user[i];
        if (!box_may_hit(n->lo, n->hi, r->o, inv, tmin, t1))
            continue;
        if (node_nearest_in_box(n, r->o, r->d, tmin, t1, skip, best)) {
            t1 = best->t;
            found = true;
        }
    }
    *tmax = t1;
    return found;
}

/* accel_intersect() and accel_intersect_prim(): 'with_prim' a constant,
** so that the query every other ray makes pays nothing for the prim. */
static inline __attribute__((always_inline)) bool
intersect_body(const struct accel *a, const ray *r, double tmin, double tmax,
               unsigned skip, struct hit *h, bool with_prim)
{
    if (!a || !r || !finite_v2(r->o, r->d) || !(tmax > tmin) || isnan(tmin))
        return false;
    /* The fields of the context the unbounded objects and the linear
    ** search use; the others are set only for Embree's callbacks (a
    ** memset of the whole context, with its inline hit, was a visible
    ** part of a query's cost) */
    struct qctx q;
    q.tmin = tmin;
    q.tmax = tmax;
    q.found = false;

    /* Unbounded objects first, beyond Embree. POV-Ray's bounding tree
    ** queues them at depth -MAX_DISTANCE, ahead of every finite object,
    ** and a later object replaces the best hit only when strictly nearer:
    ** on an exact tie (a box standing on 'plane { y, 0 }': the eye ray
    ** leaves the box's bottom where it meets the floor) the plane is the
    ** hit. Were the box's face kept, the ray leaving it would start on
    ** the floor and pass through it (tests/render/scenes/106). The finite
    ** tests below keep only t < q.tmax, so the order alone decides. */
    for (int i = 0; i < a->n_inf; i++) {
        const struct anode *n = a->inf[i];
        if (n->plane_fast ? plane_nearest(n, r->o, r->d, q.tmin, q.tmax,
                                          skip, &q.best)
                          : node_nearest(n, r->o, r->d, q.tmin, q.tmax, skip,
                                         &q.best)) {
            q.tmax = q.best.t;
            q.found = true;
        }
    }

    if (a->linear) {
        vec3 inv = v3(1 / r->d.x, 1 / r->d.y, 1 / r->d.z);
        /* a direction along an axis has an infinite 1/d: asked once per
        ** query, not per box and axis */
        if (finite_v(inv) ? linear_ordered(a, r, inv, q.tmin, &q.tmax, skip,
                                           &q.best)
                          : linear_loop(a, r, inv, q.tmin, &q.tmax, skip,
                                        &q.best))
            q.found = true;
    } else {
        q.mode = Q_NEAREST;
        q.o = r->o;
        q.d = r->d;
        q.skip = skip;
        q.all = NULL;
        q.accel = a;
        rtcInitIntersectContext(&q.ec);
        struct RTCRayHit rh;
        qctx_embree_ray(&q, &rh);
        rtcIntersect1(a->scene, &q.ec, &rh);
    }

    if (!q.found)
        return false;

    const struct anode *leaf = q.best.leaf;
    h->t = q.best.t;
    h->p = v3_madd(r->o, r->d, q.best.t);
    h->n = q.best.n;
    h->shading_n = q.best.sn;
    h->uv = q.best.uv;
    h->obj = leaf->obj;
    h->top = leaf->top;
    h->texture = q.best.texture ? q.best.texture : leaf->texture;
    if (leaf->sphere_uv) { /* only sphere shape leaves have it */
        /* Asked once, for the hit kept (geom_sphere_uv), and only when
        ** its texture may read it (uv_prepare) */
        const iris_object *o = leaf->obj;
        h->uv = geom_sphere_uv(o, o->has_transform
                                      ? xf_inv_point(&o->transform, h->p)
                                      : h->p);
    }
    h->interior = leaf->obj->interior;
    h->eps = hit_epsilon(a, leaf, h->p);
    if (with_prim)
        h->prim = leaf->prim;
    /* Only t and p are checked here. The normals were checked where the
    ** crossing was made: every ahit's n and sn is a world normal divided
    ** by its length once that length is finite and > 0 (node.c
    ** shape_hits, shape_nearest, sphere_nearest, plane_nearest), a plane's
    ** prepared plane_wn (plane_wn_ok), or a mesh triangle's (mesh.c
    ** tri_hit: the build drops triangles of no or non-finite area, and
    ** takes a smooth normal only where it has a finite length > 0); so
    ** they are finite and of unit length. Testing them again per hit was
    ** 1 % of a simple scene's eye pass (callgrind, 01, 24). */
    if (!(h->t * 0.0 + (h->p.x * 0.0 + h->p.y * 0.0 + h->p.z * 0.0) == 0.0))
        return false;
    if (!isfinite(h->uv.u) || !isfinite(h->uv.v))
        h->uv.u = h->uv.v = 0;
    return true;
}

bool accel_intersect(const struct accel *a, const ray *r, double tmin,
                     double tmax, unsigned skip, struct hit *h)
{
    return intersect_body(a, r, tmin, tmax, skip, h, false);
}

bool accel_intersect_prim(const void *accel, const ray *r, double tmin,
                          double tmax, unsigned skip, struct hit *h)
{
    return intersect_body(accel, r, tmin, tmax, skip, h, true);
}

bool accel_prim_cache_pays(const struct accel *a)
{
    return a && !a->linear && a->n_attached == 0;
}

bool accel_prim_hit(const void *accel, const void *prim, const ray *r,
                    double tmin, double tmax, unsigned skip, double *t)
{
    const struct accel *a = accel;
    const struct anode *n = prim;
    /* accel_intersect()'s entry test */
    if (!a || !n || !r || !finite_v2(r->o, r->d) || !(tmax > tmin) ||
        isnan(tmin))
        return false;
    struct ahit best;
    bool hit;
    if (!n->bounded) {
        /* as accel_intersect()'s loop over a->inf */
        hit = n->plane_fast
                  ? plane_nearest(n, r->o, r->d, tmin, tmax, skip, &best)
                  : node_nearest(n, r->o, r->d, tmin, tmax, skip, &best);
    } else {
        /* a user primitive: the linear query's box test (Embree's padded
        ** float box culls no less), then the same exact test */
        vec3 inv = v3(1 / r->d.x, 1 / r->d.y, 1 / r->d.z);
        hit = box_may_hit(n->lo, n->hi, r->o, inv, tmin, tmax) &&
              node_nearest_in_box(n, r->o, r->d, tmin, tmax, skip, &best);
    }
    if (!hit)
        return false;
    /* accel_intersect()'s test of the hit kept */
    vec3 p = v3_madd(r->o, r->d, best.t);
    if (!(best.t * 0.0 + (p.x * 0.0 + p.y * 0.0 + p.z * 0.0) == 0.0))
        return false;
    *t = best.t;
    return true;
}

/* Inside test of an object the accel was not built with: shapes and CSG
** only (meshes have no inside here), without profiles. */
static bool plain_inside(const iris_object *o, vec3 p, int depth)
{
    if (depth > MAX_DEPTH)
        return false;
    bool in;
    if (is_csg(o->kind)) {
        int nk = o->u.csg.children ? o->u.csg.n_children : 0;
        bool isect = o->kind == IRIS_OBJ_INTERSECTION ||
                     o->kind == IRIS_OBJ_DIFFERENCE;
        in = isect && nk > 0;
        for (int i = 0; i < nk; i++) {
            const iris_object *c = o->u.csg.children[i];
            bool ci = c && plain_inside(c, p, depth + 1);
            if (o->kind == IRIS_OBJ_DIFFERENCE && i > 0)
                ci = !ci;
            if (isect && !ci) {
                in = false;
                break;
            }
            if (!isect && ci) {
                in = true;
                break;
            }
        }
    } else if (geom_is_analytic(o->kind) && !geom_validate(o)) {
        vec3 lp = o->has_transform ? xf_inv_point(&o->transform, p) : p;
        in = geom_inside(o, NULL, lp);
    } else {
        in = false;
    }
    in = in != o->inverse;
    for (int i = 0; in && i < o->n_clipped_by; i++)
        if (o->clipped_by && o->clipped_by[i] &&
            !plain_inside(o->clipped_by[i], p, depth + 1))
            in = false;
    return in;
}

bool accel_inside(const struct accel *a, const iris_object *obj, vec3 p)
{
    if (!a || !obj || !finite_v(p))
        return false;
    const struct anode *n = find_node(a, obj);
    if (n)
        return node_inside(n, p);
    return plain_inside(obj, p, 0);
}

bool accel_inside_bounds(const void *accel, const iris_object *obj,
                         vec3 *lo, vec3 *hi)
{
    const struct accel *a = accel;
    if (!a || !obj)
        return false;
    const struct anode *n = find_node(a, obj);
    if (!n || !n->vol_bounded)
        return false;
    *lo = n->vlo;
    *hi = n->vhi;
    return true;
}

void accel_bounds(const struct accel *a, vec3 *lo, vec3 *hi)
{
    if (a && a->has_bounds) {
        *lo = a->lo;
        *hi = a->hi;
    } else {
        *lo = *hi = v3(0, 0, 0);
    }
}

bool accel_object_bounds(const struct accel *a, const iris_object *obj,
                         vec3 *lo, vec3 *hi)
{
    if (!a)
        return false;
    const struct anode *n = NULL;
    for (int i = 0; i < a->sc->n_objects && !n; i++)
        if (a->sc->objects[i] == obj)
            n = a->roots[i];
    if (!n)
        n = find_node(a, obj);
    /* a difference's subtracted child (built under an inverse, so not in
    ** the map): its own surface's box (a photon target there, POV-Ray
    ** aims at its box as well) */
    for (int i = 0; i < a->n_nodes && !n; i++)
        if (a->nodes[i]->obj == obj && a->nodes[i]->under_inverse)
            n = a->nodes[i];
    if (!n || !n->bounded || n->lo.x > n->hi.x)
        return false;
    *lo = n->lo;
    *hi = n->hi;
    return true;
}

double accel_epsilon(const struct accel *a)
{
    return a ? a->eps : 1e-9;
}
