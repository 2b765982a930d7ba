/* SPDX-License-Identifier: MIT */
/*
** accel.h: ray queries against the built scene (Embree 3).
**
** accel_build() turns the plain-data objects of an iris_scene into an
** Embree scene: meshes become Embree triangles, analytic shapes and CSG
** become user geometry with exact intersection. After the build the
** structure is immutable and every query is thread-safe.
**
** Depends on: util, math, geometry. Used by: render, photon.
*/
#ifndef IRIS_ACCEL_ACCEL_H
#define IRIS_ACCEL_ACCEL_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdio.h>

#include "iris/common.h"
#include "iris/scene.h"
#include "math/vec3.h"

/* A ray in world space; 'd' has unit length. */
typedef struct ray {
    vec3 o, d;
} ray;

/* Objects a query passes through, as POV-Ray's ray kinds do. */
enum accel_skip {
    ACCEL_SKIP_NONE = 0,
    ACCEL_SKIP_NO_IMAGE = 1,      /* camera rays and what they refract into */
    ACCEL_SKIP_NO_SHADOW = 2,     /* shadow rays; photon rays (POV-Ray) */
    ACCEL_SKIP_NO_REFLECTION = 4, /* reflected rays */
    ACCEL_SKIP_NO_RADIOSITY = 8   /* radiosity gather rays (gather.c) */
};

/* The nearest surface a ray meets. */
struct hit {
    double t;                     /* distance along the ray */
    vec3 p;                       /* world point */
    vec3 n;                       /* unit geometric normal, world space,
                                     pointing out of the object (flipped
                                     for 'inverse' and CSG difference) */
    vec3 shading_n;               /* unit shading normal (smooth
                                     triangles, meshes); = n otherwise */
    iris_vec2 uv;                 /* surface uv where the shape has one;
                                     a sphere's only where its texture
                                     may read it (a pattern), else 0 */
    const iris_object *obj;       /* the primitive hit (leaf) */
    const iris_object *top;       /* the top-level scene object it is in */
    const iris_texture *texture;  /* texture at this point (never NULL) */
    const iris_interior *interior;/* interior of 'obj', NULL = none */
    double eps;                   /* tmin for a ray leaving 'p': see
                                     accel_epsilon(); at most that, and
                                     much less for a small object in a
                                     huge scene */
    const void *prim;             /* accel_intersect_prim() only: the
                                     scene primitive the hit is on, for
                                     accel_prim_hit(); NULL when it has
                                     none (a mesh in Embree's own
                                     scene). accel_intersect() leaves
                                     it as it was */
};

struct accel;

/*
** Builds the ray-query structure for 'scene' (borrowed: it must outlive
** the accel). Returns IRIS_OK, IRIS_ENOMEM, or IRIS_EINVAL/
** IRIS_EUNSUPPORTED with a located message in 'err'. 'log' receives
** warnings about objects that cannot be built (skipped with a location).
*/
IRIS_NODISCARD enum iris_status accel_build(const iris_scene *scene,
                                            struct accel **out, FILE *log,
                                            char *err, size_t errlen);

/* Frees the structure. NULL does nothing. */
void accel_destroy(struct accel *a);

/*
** Finds the nearest hit with tmin < t < tmax, passing through objects
** that 'skip' names. Returns false when nothing is hit.
*/
bool accel_intersect(const struct accel *a, const ray *r, double tmin,
                     double tmax, unsigned skip, struct hit *h);
/* accel_intersect() that also sets h->prim ('accel' a struct accel, so
** that it fits struct rquery): for the shadow rays of a shadow cache,
** the others do without that store. */
bool accel_intersect_prim(const void *accel, const ray *r, double tmin,
                          double tmax, unsigned skip, struct hit *h);

/*
** Whether the one primitive 'prim' (a hit's 'prim', of accel 'accel')
** has a crossing with tmin < t < tmax, passing through objects that
** 'skip' names; the crossing's t in '*t'. The test is the one
** accel_intersect() makes of that primitive, so when this is true
** accel_intersect() with the same arguments hits something at or before
** *t. POV-Ray keeps per light the object that last blocked a shadow ray
** and tests it first: this is that test (trace.c point_shadow). 'accel'
** is a struct accel, so the function fits struct rquery.
*/
bool accel_prim_hit(const void *accel, const void *prim, const ray *r,
                    double tmin, double tmax, unsigned skip, double *t);

/*
** Whether testing one primitive before a query (a shadow cache,
** accel_prim_hit) can save more on the rays it answers than it costs on
** the others: when queries go through Embree and no mesh is in Embree's
** own scene (a mesh blocker has no 'prim' to cache). With a few
** primitives the query tests their boxes in turn, and a one-primitive
** test is a large part of it: on 01_sphere_plane (2 primitives, 2716 of
** 69019 shadow rays blocked) a cache made the eye pass 2.6 % more
** instructions; on the mesh scenes 0.25-0.5 % more.
*/
bool accel_prim_cache_pays(const struct accel *a);

/* Whether world point 'p' is inside object 'obj' (POV-Ray's Inside()). */
bool accel_inside(const struct accel *a, const iris_object *obj, vec3 p);
/* A world box (padded) holding every point accel_inside() finds inside
** 'obj'; false when it has none. 'accel' is a struct accel, so the
** function fits struct rquery (render/query.h). */
bool accel_inside_bounds(const void *accel, const iris_object *obj,
                         vec3 *lo, vec3 *hi);

/* World bounding box of finite geometry (infinite planes excluded). */
void accel_bounds(const struct accel *a, vec3 *lo, vec3 *hi);

/* World bounding box of one top-level object; false if unbounded. */
bool accel_object_bounds(const struct accel *a, const iris_object *obj,
                         vec3 *lo, vec3 *hi);

/*
** The distance by which to start a secondary ray from a surface so that it
** does not meet the same surface again. It is relative to the scene's
** scale (issue 7: a scene scaled by 1e-6 or 1e6 renders the same), not an
** absolute constant: 1e-9 of the scene's size. That is safe everywhere
** but coarse where the scene is much larger than the object hit (a sky
** sphere of radius 1e6 makes it 1e-3, thicker than a thin glass wall), so
** each hit also carries its own offset, hit.eps = 1e-9 of the larger of
** |p| (max norm) and the size of the leaf hit, capped by this value.
** Start a ray that leaves hit 'h' with tmin = h.eps.
*/
double accel_epsilon(const struct accel *a);

/*
** The offset for a ray leaving world point 'p' on a surface of world size
** 'size' (0: unbounded), at most the scene's 'scene_eps': 1e-9 of the
** larger of the size and |p| (accel.c explains why). Inline: it is asked
** once per hit, and the photon fast path (src/photon/fastpath.c) must
** give the same value to the bit.
*/
static inline double accel_hit_epsilon(double size, vec3 p, double scene_eps)
{
    if (!(size > 0))
        return scene_eps;
    /* Comparisons, not fmax/fmin (library calls); a NaN p makes the hit
    ** rejected by the caller anyway */
    double s = size, ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
    if (ax > s)
        s = ax;
    if (ay > s)
        s = ay;
    if (az > s)
        s = az;
    double e = 1e-9 * s;
    if (!(e > 1e-290))
        e = 1e-290;
    return e < scene_eps ? e : scene_eps;
}

/*
** The offset for a ray that starts on no surface (a camera ray, a photon
** leaving its light) at world point 'o': 1e-9 of |o| (max norm), at most
** the scene's 'scene_eps'. Such a ray needs no offset against a surface
** of its own, and the scene's epsilon, 1e-9 of its extent, would make it
** skip everything that near: one huge object (a hidden sphere of radius
** 1e10) makes that 10 units.
*/
static inline double accel_origin_epsilon(vec3 o, double scene_eps)
{
    return accel_hit_epsilon(1e-300, o, scene_eps);
}

#endif
