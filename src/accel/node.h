/* SPDX-License-Identifier: MIT */
/*
** node.h: the accel's internal object tree (see the DESIGN comment in
** accel.c).
**
** Every scene object becomes a node: a shape leaf (analytic, geometry/),
** a mesh leaf (Embree triangles, mesh.c) or a CSG node. 'inverse' is
** pushed down to the leaves with De Morgan's rules when the tree is built
** (POV-Ray's Invert() does the same), so a CSG node is only a union, merge
** or intersection and a leaf carries one 'inverted' bit.
*/
#ifndef IRIS_ACCEL_NODE_H
#define IRIS_ACCEL_NODE_H

#include <stdbool.h>

#include <embree3/rtcore.h>

#include "accel/accel.h"
#include "geometry/geom.h"
#include "math/transform.h"

/*
** xf_inv_point() and xf_inv_dir() (math/transform.c) inline: the same
** products summed in the same order, hence the same bits. A CSG query
** takes the ray into every child's space and every inside test takes
** a point there; as calls returning a vec3 through memory they were a
** fifth of a query over a cut gem (callgrind).
*/
static inline vec3 anode_inv_point(const xform *t, vec3 p)
{
    const double (*m)[4] = t->inv;
    return v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
              m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
              m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

static inline vec3 anode_inv_dir(const xform *t, vec3 d)
{
    const double (*m)[4] = t->inv;
    return v3(m[0][0] * d.x + m[0][1] * d.y + m[0][2] * d.z,
              m[1][0] * d.x + m[1][1] * d.y + m[1][2] * d.z,
              m[2][0] * d.x + m[2][1] * d.y + m[2][2] * d.z);
}

enum anode_kind { AN_SHAPE, AN_MESH, AN_CSG };
enum anode_op { AN_UNION, AN_MERGE, AN_INTERSECTION };

struct amesh;

struct anode {
    enum anode_kind kind;
    enum anode_op op;              /* AN_CSG */
    bool inverted;                 /* leaves: inside and normals flipped */
    bool under_inverse;            /* an enclosing node is inverted: this
                                      node is not the object's own inside */
    const iris_object *obj;        /* the scene object this node is */
    const iris_object *top;        /* its top-level scene object */
    const struct anode *prim;      /* the node accel.c placed (a user
                                      primitive or an unbounded node)
                                      that this node is in, for
                                      accel_prim_hit(); NULL under a mesh
                                      given to Embree's scene itself */
    unsigned skip;                 /* ACCEL_SKIP_* bits, ancestors' included */
    int n_kids;
    struct anode **kids;
    int n_clips;
    struct anode **clips;          /* clipped_by: keep points inside all */
    bool bounded;                  /* world box lo..hi holds every hit */
    vec3 lo, hi;
    bool vol_bounded;              /* world box vlo..vhi (padded) holds
                                      every point inside: node_inside
                                      rejects the others at once */
    vec3 vlo, vhi;
    int inside_cost;               /* leaves an inside test of this node
                                      may ask: 1 for a leaf, its
                                      children's and clips' sum for CSG */
    bool lazy;                     /* node_nearest_in_box() takes node.c
                                      lazy_nearest() (accel.c build()) */
    double size;                   /* leaves: largest extent of the world
                                      box of the whole surface, before
                                      clipping; 0 = unbounded */
    struct geom_profile *prof;     /* AN_SHAPE: prism, lathe, sor, text */
    vec3 plane_n;                  /* AN_SHAPE plane: its unit normal,
                                      normalised once (shape_nearest,
                                      node_inside) */
    bool plane_fast;               /* a plane leaf without clipping whose
                                      world normal is valid: accel.c
                                      tests it inline (plane_nearest's
                                      answer, plane_wn taken once) */
    vec3 plane_wn;                 /* AN_SHAPE plane: its world normal
                                      at every crossing, as shape_hits
                                      and plane_nearest compute it (sign
                                      of 'inverted'), taken once */
    bool plane_wn_ok;              /* plane_wn is valid (finite, nonzero
                                      length); if not, the plane is never
                                      crossed */
    bool uv_read;                  /* AN_SHAPE: a texture of its hits may
                                      read uv (the nearest-crossing fast
                                      paths compute it only then) */
    bool sphere_uv;                /* AN_SHAPE sphere with uv_read
                                      (accel_intersect computes its uv) */
    const iris_texture *texture;   /* leaves: their hits' texture where
                                      the crossing has none of its own:
                                      obj's, else top's, else the
                                      accel's default (accel.c, set
                                      once after the build) */
    bool has_blob_box;             /* AN_SHAPE blob: geom_blob_bounds() */
    vec3 blob_lo, blob_hi;         /* in object space, computed once */
    struct amesh *mesh;            /* AN_MESH */
    bool sphere_world;             /* AN_SHAPE sphere moved by rotations,
                                      translations and uniform scales
                                      only: solved as an untransformed
                                      sphere at sphere_wc, radius
                                      sphere_wr, as POV-Ray moves its
                                      centre (node_sphere_world_prepare) */
    vec3 sphere_wc;
    double sphere_wr;
    struct geom_cone_frame cone;   /* AN_SHAPE cylinder, cone: its frame,
                                      taken once (accel.c, for node.c
                                      cone_nearest) */
};

/* A surface crossing in world space, before it becomes a 'struct hit'. */
struct ahit {
    double t;
    vec3 n, sn;                    /* unit normal and shading normal */
    iris_vec2 uv;
    const struct anode *leaf;
    const iris_texture *texture;   /* NULL: the leaf's texture */
};

struct ahit_list {
    struct ahit *v;
    int n, cap;
    struct ahit buf[16];
};

void ahit_list_init(struct ahit_list *l);
void ahit_list_fini(struct ahit_list *l);
void ahit_push(struct ahit_list *l, const struct ahit *h);

/*
** Appends every crossing of world ray o + t·d (unit 'd') with the surface
** of 'n' for tmin < t < tmax, after CSG filtering and clipping, leaving
** out leaves whose skip bits meet 'skip'. Thread-safe.
*/
void node_hits(const struct anode *n, vec3 o, vec3 d, double tmin,
               double tmax, unsigned skip, struct ahit_list *out);

/* node_hits() without testing n's own box first (the caller has: the
** box only culls, every crossing lies inside it). */
void node_hits_in_box(const struct anode *n, vec3 o, vec3 d, double tmin,
                      double tmax, unsigned skip, struct ahit_list *out);

/* The nearest crossing, as node_hits; false when none. */
bool node_nearest(const struct anode *n, vec3 o, vec3 d, double tmin,
                  double tmax, unsigned skip, struct ahit *best);
/* The same without testing n's own box (see node_hits_in_box). */
bool node_nearest_in_box(const struct anode *n, vec3 o, vec3 d, double tmin,
                         double tmax, unsigned skip, struct ahit *best);

/* Whether world point 'p' is inside 'n' (clipping included). */
bool node_inside(const struct anode *n, vec3 p);

/*
** The state of one query, handed to Embree's callbacks through the
** intersect context (it must stay the first member). Lives on the
** caller's stack, so queries share nothing.
*/
enum qmode { Q_NEAREST, Q_ALL };
struct qctx {
    struct RTCIntersectContext ec;
    enum qmode mode;
    vec3 o, d;                     /* the ray in double precision */
    double tmin, tmax;             /* Q_NEAREST: tmax shrinks to the best */
    unsigned skip;
    bool found;
    struct ahit best;              /* Q_NEAREST */
    struct ahit_list *all;         /* Q_ALL */
    const void *accel;             /* the user geometry's owner */
};

/* Embree's float ray for query 'q' (mesh.c). */
void qctx_embree_ray(const struct qctx *q, struct RTCRayHit *rh);

/* Mesh leaves (mesh.c). */
void amesh_hits(const struct anode *n, vec3 o, vec3 d, double tmin,
                double tmax, struct ahit_list *out);
bool amesh_inside(const struct anode *n, vec3 p);
/*
** Builds the triangles of mesh leaf 'n' (mesh, mesh2, triangle,
** smooth_triangle, height_field, bicubic_patch) in world space. 'private_scene' also
** builds an Embree scene of its own, needed for CSG and inside tests.
** Returns NULL on success, else the reason to report.
*/
const char *amesh_build(struct anode *n, RTCDevice dev, bool private_scene);
/* Adds the leaf's triangles to 'scene' (the top-level scene). */
bool amesh_attach(struct anode *n, RTCDevice dev, RTCScene scene);
/* World box of the leaf's triangles; false when it has none. */
bool amesh_bounds(const struct anode *n, vec3 *lo, vec3 *hi);
void amesh_free(struct amesh *m);
/* Whether 'kind' is built as triangles. */
bool amesh_kind(enum iris_object_kind kind);

/* Sets n->sphere_world, sphere_wc and sphere_wr of a sphere leaf
** (geometry/sphere_span.h sphere_world_frame). */
void node_sphere_world_prepare(struct anode *n);

#endif
