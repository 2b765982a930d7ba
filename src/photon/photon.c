/* SPDX-License-Identifier: MIT */
/*
** photon.c: photon_map_build() over the Embree scene (accel.h); the
** shooter itself sees only struct pmap_world (pmap.h). A scene of a few
** spheres and planes is queried through the fast path (fastpath.h), which
** gives accel's hits at a fraction of the cost.
*/
#include "config.h"

#include "photon/pmap.h"

#include "photon/fastpath.h"

static bool world_intersect(const void *ctx, const ray *r, double tmin,
                            double tmax, unsigned skip, struct hit *h)
{
    return accel_intersect(ctx, r, tmin, tmax, skip, h);
}

static bool world_bounds(const void *ctx, const iris_object *obj, vec3 *lo,
                         vec3 *hi)
{
    return accel_object_bounds(ctx, obj, lo, hi);
}

static bool world_inside(const void *ctx, const iris_object *obj, vec3 p)
{
    return accel_inside(ctx, obj, p);
}

/* The same two over the fast path's context. */
static bool fast_bounds(const void *ctx, const iris_object *obj, vec3 *lo,
                        vec3 *hi)
{
    return accel_object_bounds(pfast_accel(ctx), obj, lo, hi);
}

static bool fast_inside(const void *ctx, const iris_object *obj, vec3 p)
{
    return accel_inside(pfast_accel(ctx), obj, p);
}

bool pmap_world_is_scene(const struct pmap_world *w)
{
    return w->intersect == world_intersect || w->intersect == pfast_intersect;
}

enum iris_status photon_map_build(const iris_scene *scene,
                                  const struct accel *accel,
                                  const struct photon_options *opts,
                                  struct photon_map **out,
                                  struct photon_stats *stats)
{
    struct pmap_world w = { accel, world_intersect, world_bounds,
                            world_inside, accel_epsilon(accel) };
    /* NULL (not a sphere-and-plane scene, or no memory): accel */
    struct pfast *f = opts->no_fastpath ? NULL : pfast_build(scene, accel);
    if (f) {
        w.ctx = f;
        w.intersect = pfast_intersect;
        w.object_bounds = fast_bounds;
        w.inside = fast_inside;
    }
    enum iris_status rc = pmap_build(scene, &w, opts, out, stats);
    pfast_destroy(f);
    return rc;
}
