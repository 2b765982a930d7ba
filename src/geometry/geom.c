/* SPDX-License-Identifier: MIT */
/*
** geom.c: the crossing list, the per-kind dispatch of geom.h and the
** parameter checks that keep degenerate shapes out of the solvers.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>
#include <string.h>

#include "util/mem.h"

void isect_list_init(struct isect_list *l)
{
    l->v = l->inline_buf;
    l->n = 0;
    l->cap = GEOM_INLINE;
    l->overflow = false;
    l->first_only = false;
}

void isect_list_fini(struct isect_list *l)
{
    if (l->v != l->inline_buf)
        iris_free(l->v);
    isect_list_init(l);
}

void isect_push(struct isect_list *l, double t, vec3 n, double u, double v)
{
    if (!isfinite(t) || !isfinite(n.x) || !isfinite(n.y) || !isfinite(n.z) ||
        (n.x == 0 && n.y == 0 && n.z == 0))
        return;
    if (l->n == l->cap) {
        int cap = l->cap * 2;
        struct geom_isect *nv = iris_malloc((size_t)cap * sizeof *nv);
        if (!nv) {
            l->overflow = true;
            return;
        }
        memcpy(nv, l->v, (size_t)l->n * sizeof *nv);
        if (l->v != l->inline_buf)
            iris_free(l->v);
        l->v = nv;
        l->cap = cap;
    }
    struct geom_isect *e = &l->v[l->n++];
    e->t = t;
    e->n = n;
    e->uv.u = isfinite(u) ? u : 0;
    e->uv.v = isfinite(v) ? v : 0;
    e->part = -1;
}

bool geom_is_analytic(enum iris_object_kind kind)
{
    switch (kind) {
    case IRIS_OBJ_SPHERE: case IRIS_OBJ_BOX: case IRIS_OBJ_PLANE:
    case IRIS_OBJ_CYLINDER: case IRIS_OBJ_CONE: case IRIS_OBJ_TORUS:
    case IRIS_OBJ_DISC: case IRIS_OBJ_POLYGON: case IRIS_OBJ_PRISM:
    case IRIS_OBJ_LATHE: case IRIS_OBJ_SOR: case IRIS_OBJ_SUPERELLIPSOID:
    case IRIS_OBJ_BLOB: case IRIS_OBJ_TEXT: case IRIS_OBJ_ISOSURFACE:
    case IRIS_OBJ_QUADRIC: case IRIS_OBJ_POLY: case IRIS_OBJ_JULIA_FRACTAL:
    case IRIS_OBJ_OVUS: case IRIS_OBJ_SPHERE_SWEEP: case IRIS_OBJ_PARAMETRIC:
    case IRIS_OBJ_LEMON:
        return true;
    default:
        return false;
    }
}

/* One slab of geom_clip_box(). Plain comparisons instead of fmax/fmin:
** those are library calls here (NaN rules), and this runs for every
** bounded object a ray comes near; nothing here is NaN (finite box,
** finite ray, dk != 0). */
static inline bool clip_slab(double ok, double dk, double l, double h,
                             double *a, double *b)
{
    if (dk == 0)
        return !(ok < l || ok > h);
    double ta = (l - ok) / dk, tb = (h - ok) / dk;
    if (ta > tb) {
        double s = ta;
        ta = tb;
        tb = s;
    }
    if (ta > *a)
        *a = ta;
    if (tb < *b)
        *b = tb;
    return !(*a > *b);
}

bool geom_clip_box(vec3 lo, vec3 hi, vec3 o, vec3 d, double *t0, double *t1)
{
    double a = *t0, b = *t1;
    if (!clip_slab(o.x, d.x, lo.x, hi.x, &a, &b) ||
        !clip_slab(o.y, d.y, lo.y, hi.y, &a, &b) ||
        !clip_slab(o.z, d.z, lo.z, hi.z, &a, &b))
        return false;
    *t0 = a;
    *t1 = b;
    return true;
}

void geom_intersect(const iris_object *o, const struct geom_profile *prof,
                    vec3 ro, vec3 rd, double t0, double t1,
                    struct isect_list *out)
{
    if (o->bounded_by && !geom_bound_admits(o, prof, ro, rd))
        return;
    switch (o->kind) {
    case IRIS_OBJ_SPHERE: geom_sphere_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_PLANE: geom_plane_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_BOX: geom_box_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_CYLINDER:
    case IRIS_OBJ_CONE: geom_cone_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_DISC: geom_disc_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_TORUS: geom_torus_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_QUADRIC:
    case IRIS_OBJ_POLY: geom_poly_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_POLYGON: geom_polygon_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_SUPERELLIPSOID:
        geom_superellipsoid_hits(o, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_BLOB: geom_blob_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_ISOSURFACE:
        geom_isosurface_hits(o, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_JULIA_FRACTAL:
        geom_julia_hits(o, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_OVUS: geom_ovus_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_SPHERE_SWEEP:
        geom_sphere_sweep_hits(o, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_PARAMETRIC:
        geom_parametric_hits(o, prof, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_LEMON: geom_lemon_hits(o, ro, rd, t0, t1, out); break;
    case IRIS_OBJ_LATHE:
    case IRIS_OBJ_SOR:
        if (prof)
            geom_lathe_hits(prof, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_PRISM:
        if (prof)
            geom_extrude_hits(prof, 1, ro, rd, t0, t1, out);
        break;
    case IRIS_OBJ_TEXT:
        if (prof)
            geom_extrude_hits(prof, 2, ro, rd, t0, t1, out);
        break;
    default:
        break;
    }
}

bool geom_inside(const iris_object *o, const struct geom_profile *prof,
                 vec3 p)
{
    switch (o->kind) {
    case IRIS_OBJ_SPHERE:
        return v3_len2(v3_sub(p, o->u.sphere.centre)) <
               o->u.sphere.radius * o->u.sphere.radius;
    case IRIS_OBJ_PLANE:
        /* POV-Ray: the half-space the normal points away from, the plane
        ** itself within EPSILON (1e-10) included (node_inside inverts a
        ** plane as POV-Ray does, by flipping it) */
        return v3_dot(v3_norm(o->u.plane.normal), p) - o->u.plane.distance <
               1e-10;
    case IRIS_OBJ_BOX: {
        vec3 lo = v3_min(o->u.box.lo, o->u.box.hi);
        vec3 hi = v3_max(o->u.box.lo, o->u.box.hi);
        /* closed, as POV-Ray's Box::Inside: a point on a face is inside
        ** (and outside an inverted box), so faces that coincide with
        ** another box's in CSG are kept as POV-Ray keeps them */
        return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y &&
               p.z >= lo.z && p.z <= hi.z;
    }
    case IRIS_OBJ_CYLINDER:
    case IRIS_OBJ_CONE:
        return geom_cone_inside(o, p);
    case IRIS_OBJ_DISC:
        /* POV-Ray: the half-space behind the disc's normal */
        return v3_dot(v3_sub(p, o->u.disc.centre), o->u.disc.normal) < 0;
    case IRIS_OBJ_TORUS: {
        double R = o->u.torus.major, r = o->u.torus.minor;
        double q = sqrt(p.x * p.x + p.z * p.z) - R;
        return q * q + p.y * p.y < r * r;
    }
    case IRIS_OBJ_QUADRIC:
        /* POV-Ray's Quadric::Inside: the surface itself is inside */
        return geom_poly_eval(o, p) <= 0;
    case IRIS_OBJ_POLY:
        /* POV-Ray's Poly::Inside counts values below INSIDE_TOLERANCE
        ** (1e-4) as inside, in the user's own coefficients: a poly
        ** written with small coefficients has a much larger inside in
        ** CSG than its surface encloses */
        return geom_poly_eval(o, p) < 1e-4;
    case IRIS_OBJ_SUPERELLIPSOID:
        return geom_superellipsoid_eval(o, p) < 0;
    case IRIS_OBJ_BLOB:
        /* POV-Ray's Blob::Inside: above the threshold less 1e-6 */
        return geom_blob_density(o, p) > o->u.blob.threshold - 1e-6;
    case IRIS_OBJ_ISOSURFACE:
        return geom_isosurface_inside(o, p);
    case IRIS_OBJ_JULIA_FRACTAL:
        return geom_julia_inside(o, p);
    case IRIS_OBJ_OVUS:
        return geom_ovus_inside(o, p);
    case IRIS_OBJ_SPHERE_SWEEP:
        return geom_sphere_sweep_inside(o, p);
    case IRIS_OBJ_LEMON:
        return geom_lemon_inside(o, p);
    case IRIS_OBJ_LATHE:
    case IRIS_OBJ_SOR:
        return prof && geom_lathe_inside(prof, p);
    case IRIS_OBJ_PRISM:
        return prof && geom_extrude_inside(prof, 1, p);
    case IRIS_OBJ_TEXT:
        return prof && geom_extrude_inside(prof, 2, p);
    default:
        /* polygon and other thin shapes have no inside */
        return false;
    }
}

/* Box of a cone/cylinder: the two end discs' boxes joined. */
static void cone_bounds(vec3 a, vec3 b, double ra, double rb, vec3 *lo,
                        vec3 *hi)
{
    vec3 w = v3_norm(v3_sub(b, a));
    /* A disc of radius r with unit normal w spans r·sqrt(1 - w_k^2) */
    vec3 e = v3(sqrt(fmax(0, 1 - w.x * w.x)), sqrt(fmax(0, 1 - w.y * w.y)),
                sqrt(fmax(0, 1 - w.z * w.z)));
    *lo = v3_min(v3_sub(a, v3_scale(e, ra)), v3_sub(b, v3_scale(e, rb)));
    *hi = v3_max(v3_add(a, v3_scale(e, ra)), v3_add(b, v3_scale(e, rb)));
}

bool geom_bounds(const iris_object *o, const struct geom_profile *prof,
                 vec3 *lo, vec3 *hi)
{
    switch (o->kind) {
    case IRIS_OBJ_SPHERE: {
        double r = fabs(o->u.sphere.radius);
        vec3 c = o->u.sphere.centre;
        *lo = v3_sub(c, v3(r, r, r));
        *hi = v3_add(c, v3(r, r, r));
        return true;
    }
    case IRIS_OBJ_BOX:
        *lo = v3_min(o->u.box.lo, o->u.box.hi);
        *hi = v3_max(o->u.box.lo, o->u.box.hi);
        return true;
    case IRIS_OBJ_CYLINDER:
        /* a negative radius is its size (POV-Ray squares it) */
        cone_bounds(o->u.cylinder.base, o->u.cylinder.cap,
                    fabs(o->u.cylinder.radius), fabs(o->u.cylinder.radius),
                    lo, hi);
        return true;
    case IRIS_OBJ_CONE:
        cone_bounds(o->u.cone.base, o->u.cone.cap, fabs(o->u.cone.base_radius),
                    fabs(o->u.cone.cap_radius), lo, hi);
        return true;
    case IRIS_OBJ_DISC: {
        vec3 c = o->u.disc.centre;
        cone_bounds(c, v3_add(c, v3_scale(v3_norm(o->u.disc.normal), 1e-9 *
                                          o->u.disc.radius)),
                    o->u.disc.radius, o->u.disc.radius, lo, hi);
        return true;
    }
    case IRIS_OBJ_TORUS: {
        double R = fabs(o->u.torus.major), r = fabs(o->u.torus.minor);
        *lo = v3(-R - r, -r, -R - r);
        *hi = v3(R + r, r, R + r);
        return true;
    }
    case IRIS_OBJ_POLYGON: {
        if (o->u.polygon.n_points < 1)
            return false;
        *lo = *hi = o->u.polygon.points[0];
        for (int i = 1; i < o->u.polygon.n_points; i++) {
            *lo = v3_min(*lo, o->u.polygon.points[i]);
            *hi = v3_max(*hi, o->u.polygon.points[i]);
        }
        return true;
    }
    case IRIS_OBJ_SUPERELLIPSOID:
        *lo = v3(-1, -1, -1);
        *hi = v3(1, 1, 1);
        return true;
    case IRIS_OBJ_BLOB:
        return geom_blob_bounds(o, lo, hi);
    case IRIS_OBJ_ISOSURFACE:
        if (o->u.isosurface.contained_kind == 1) {
            double r = fabs(o->u.isosurface.radius);
            *lo = v3_sub(o->u.isosurface.centre, v3(r, r, r));
            *hi = v3_add(o->u.isosurface.centre, v3(r, r, r));
        } else {
            *lo = v3_min(o->u.isosurface.lo, o->u.isosurface.hi);
            *hi = v3_max(o->u.isosurface.lo, o->u.isosurface.hi);
        }
        return true;
    case IRIS_OBJ_OVUS:
        geom_ovus_bounds(o, lo, hi);
        return true;
    case IRIS_OBJ_SPHERE_SWEEP:
        return geom_sphere_sweep_bounds(o, lo, hi);
    case IRIS_OBJ_PARAMETRIC:
        geom_parametric_bounds(o, lo, hi);
        return true;
    case IRIS_OBJ_LEMON:
        geom_lemon_bounds(o, lo, hi);
        return true;
    case IRIS_OBJ_JULIA_FRACTAL: {
        double r = geom_julia_radius(o);
        *lo = v3(-r, -r, -r);
        *hi = v3(r, r, r);
        return r > 0;
    }
    case IRIS_OBJ_LATHE:
    case IRIS_OBJ_SOR:
        if (!prof)
            return false;
        geom_lathe_bounds(prof, lo, hi);
        return true;
    case IRIS_OBJ_PRISM:
    case IRIS_OBJ_TEXT:
        if (!prof)
            return false;
        geom_extrude_bounds(prof, o->kind == IRIS_OBJ_PRISM ? 1 : 2, lo, hi);
        return true;
    default:
        /* plane, quadric, poly: unbounded */
        return false;
    }
}

static bool finite3(vec3 v)
{
    return isfinite(v.x) && isfinite(v.y) && isfinite(v.z);
}

const char *geom_validate(const iris_object *o)
{
    switch (o->kind) {
    case IRIS_OBJ_SPHERE:
        if (!(o->u.sphere.radius > 0) || !finite3(o->u.sphere.centre))
            return "sphere radius is not positive";
        return NULL;
    case IRIS_OBJ_PLANE:
        if (!(v3_len(o->u.plane.normal) > 0) ||
            !isfinite(o->u.plane.distance))
            return "plane normal is zero";
        return NULL;
    case IRIS_OBJ_BOX:
        if (!finite3(o->u.box.lo) || !finite3(o->u.box.hi))
            return "box corner is not finite";
        return NULL;
    case IRIS_OBJ_CYLINDER:
        if (!(fabs(o->u.cylinder.radius) > 0) ||
            !(v3_len(v3_sub(o->u.cylinder.cap, o->u.cylinder.base)) > 0))
            return "cylinder has zero radius or length";
        return NULL;
    case IRIS_OBJ_CONE:
        if (!(fabs(o->u.cone.base_radius) + fabs(o->u.cone.cap_radius) > 0) ||
            !(v3_len(v3_sub(o->u.cone.cap, o->u.cone.base)) > 0))
            return "cone has zero radii or length";
        return NULL;
    case IRIS_OBJ_DISC:
        if (!(o->u.disc.radius > 0) || !(v3_len(o->u.disc.normal) > 0))
            return "disc has zero radius or normal";
        return NULL;
    case IRIS_OBJ_TORUS:
        if (!(o->u.torus.minor > 0) || !(o->u.torus.major >= 0))
            return "torus radius is not positive";
        return NULL;
    case IRIS_OBJ_QUADRIC:
    case IRIS_OBJ_POLY: {
        int n = o->u.poly.order;
        if (n < 1 || n > 15 || !o->u.poly.coeffs ||
            o->u.poly.n_coeffs != (n + 1) * (n + 2) * (n + 3) / 6 ||
            (o->kind == IRIS_OBJ_QUADRIC && n != 2))
            return "poly has a bad order or coefficient count";
        return NULL;
    }
    case IRIS_OBJ_POLYGON:
        if (o->u.polygon.n_points < 3 || !o->u.polygon.points)
            return "polygon has fewer than 3 points";
        return NULL;
    case IRIS_OBJ_SUPERELLIPSOID:
        if (!(o->u.superellipsoid.e > 0) || !(o->u.superellipsoid.n > 0))
            return "superellipsoid exponents must be positive";
        return NULL;
    case IRIS_OBJ_BLOB:
        if (o->u.blob.n_components < 1 || !o->u.blob.components)
            return "blob has no components";
        return NULL;
    case IRIS_OBJ_JULIA_FRACTAL:
        if (!geom_julia_ok(o))
            return "julia_fractal: quaternion supports only sqr and "
                   "cube, and the slice must not be parallel to w";
        return NULL;
    case IRIS_OBJ_OVUS:
        return geom_ovus_check(o);
    case IRIS_OBJ_SPHERE_SWEEP:
        return geom_sphere_sweep_check(o);
    case IRIS_OBJ_PARAMETRIC:
        return geom_parametric_check(o);
    case IRIS_OBJ_LEMON:
        return geom_lemon_check(o);
    case IRIS_OBJ_ISOSURFACE:
        if (!o->u.isosurface.fn)
            return "isosurface has no function";

        return NULL;
    default:
        return NULL;
    }
}
