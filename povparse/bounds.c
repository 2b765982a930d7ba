/* SPDX-License-Identifier: MIT */
/*
** bounds.c: the boxes min_extent and max_extent return, POV-Ray's
** bounding boxes as its shapes compute them when they are parsed
** (Compute_BBox of each shape, CSG::Compute_BBox), not the renderer's
** tighter ones: a cylinder boxed in its own frame, a rotated CSG by its
** rotated box, and so on. Shapes the parser cannot bound (text, blobs,
** isosurfaces, ...) are left to the renderer through the geometry
** callbacks (expr.c).
*/
#include "config.h"

#include <math.h>

#include "math/transform.h"
#include "math/vec3.h"
#include "pp.h"

/* The box POV-Ray gives a cylinder or cone (Cone::Compute_BBox): in
** its own frame, where the axis from 'base' to 'cap' is z, the box
** [-r, r]^2 x [0, 1] with r the larger radius, taken to world space by
** the rotation that turns z onto the axis about (-d.y, d.x, 0) (POV-Ray's
** Compute_Coordinate_Transform) and then by the object's transform. Its
** world box is tight along the axis: a cylinder from 0 to 2y has
** max_extent y = 2, not 2 + r. */
static void axial_bounds(const iris_object *o, vec3 base, vec3 cap, double r,
                         vec3 *lo, vec3 *hi)
{
    vec3 d = v3_sub(cap, base);
    double len = v3_len(d);
    vec3 e[3] = { v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 1) };
    if (len > 0)
        xf_axis_frame(v3_scale(d, 1 / len), e);
    /* the box is symmetric in the frame's x and y: a half turn of the
    ** frame (an axis along -z) gives the same corners */
    vec3 u = e[0], w = e[1];
    *lo = v3(1e30, 1e30, 1e30);
    *hi = v3(-1e30, -1e30, -1e30);
    for (int i = 0; i < 8; i++) {
        vec3 p = v3_add(i & 4 ? cap : base,
                        v3_add(v3_scale(u, i & 1 ? r : -r),
                               v3_scale(w, i & 2 ? r : -r)));
        if (o->has_transform)
            p = xf_point(&o->transform, p);
        *lo = v3_min(*lo, p);
        *hi = v3_max(*hi, p);
    }
}

/* The scale s when the linear part of 't' is s times a rotation, else 0:
** POV-Ray moves a sphere's centre and radius under such a transform and
** keeps its box tight; any other makes it an ellipsoid boxed by the
** transformed corners (Sphere::Transform). */
static double similarity_scale(const iris_transform *t)
{
    double c[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            c[i][j] = 0;
            for (int k = 0; k < 3; k++)
                c[i][j] += t->m[k][i] * t->m[k][j];
        }
    double s2 = c[0][0];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (fabs(c[i][j] - (i == j ? s2 : 0)) > 1e-9 * s2)
                return 0;
    return sqrt(s2);
}

/* POV-Ray's SMALL_TOLERANCE: the half thickness it gives flat boxes. */
#define POV_SMALL_TOLERANCE 0.001

/* The largest radius of a sor's profile (Sor::Compute_Sor): POV-Ray fits
** r^2(y) on each segment P[i+1]..P[i+2] with the cubic through both ends
** whose slopes come from the neighbours, and bounds the segment by the
** largest of r at its ends and at the cubic's turning points inside it,
** so the box can pass the control points' radii. 'y_lo'/'y_hi' get the
** heights of the first and last segment ends. */
static double sor_radius(const iris_vec2 *P, int n, double *y_lo,
                         double *y_hi)
{
    double rmax = 0;
    *y_lo = 1e30;
    *y_hi = -1e30;
    for (int i = 0; i + 3 < n; i++) {
        double y0 = P[i + 1].v, y1 = P[i + 2].v, h = y1 - y0;
        double k0 = P[i + 1].u * P[i + 1].u, k1 = P[i + 2].u * P[i + 2].u;
        double d0 = 2 * P[i + 1].u * (P[i + 2].u - P[i].u) /
                    (P[i + 2].v - P[i].v);
        double d1 = 2 * P[i + 2].u * (P[i + 3].u - P[i + 1].u) /
                    (P[i + 3].v - P[i + 1].v);
        *y_lo = fmin(*y_lo, y0);
        *y_hi = fmax(*y_hi, y1);
        rmax = fmax(rmax, fmax(fabs(P[i + 1].u), fabs(P[i + 2].u)));
        if (!(fabs(h) > 0) || !isfinite(d0) || !isfinite(d1))
            continue;   /* the parser rejects these profiles */
        /* The Hermite cubic in t = (y - y0)/h; its derivative's roots in
        ** [0, 1] are the turning points of r^2 on the segment. */
        double m0 = d0 * h, m1 = d1 * h;
        double a = 6 * k0 + 3 * m0 - 6 * k1 + 3 * m1;
        double b = -6 * k0 - 4 * m0 + 6 * k1 - 2 * m1;
        double c = m0;
        double t[2];
        int nt = 0;
        if (fabs(a) < 1e-12 * (fabs(b) + fabs(c) + 1e-300)) {
            if (b != 0)
                t[nt++] = -c / b;
        } else {
            double disc = b * b - 4 * a * c;
            if (disc >= 0) {
                double q = sqrt(disc);
                t[nt++] = (-b - q) / (2 * a);
                t[nt++] = (-b + q) / (2 * a);
            }
        }
        for (int j = 0; j < nt; j++) {
            double u = t[j];
            if (!(u >= 0 && u <= 1))
                continue;
            double u2 = u * u, u3 = u2 * u;
            double r2 = (2 * u3 - 3 * u2 + 1) * k0 + (u3 - 2 * u2 + u) * m0 +
                        (-2 * u3 + 3 * u2) * k1 + (u3 - u2) * m1;
            rmax = fmax(rmax, sqrt(fmax(r2, 0)));
        }
    }
    return rmax;
}

/* A prism's box in its own frame (Prism::Compute_Prism and Compute_BBox):
** the rectangle of its points (a linear spline's vertices, a bezier
** spline's control points) on x and z, its two heights on y; a conic
** sweep scales the rectangle by both heights. The quadratic and cubic
** splines, bounded by their curves' extrema, are left to the renderer. */
static bool prism_box(const iris_object *o, vec3 *a, vec3 *b)
{
    int n = o->u.prism.n_points;
    const iris_vec2 *p = o->u.prism.points;
    if (n < 2 || (o->u.prism.spline != IRIS_SPLINE_LINEAR &&
                  o->u.prism.spline != IRIS_SPLINE_BEZIER))
        return false;
    double x1 = 1e300, x2 = -1e300, z1 = 1e300, z2 = -1e300;
    for (int i = 0; i < n; i++) {
        x1 = fmin(x1, p[i].u);
        x2 = fmax(x2, p[i].u);
        z1 = fmin(z1, p[i].v);
        z2 = fmax(z2, p[i].v);
    }
    double h1 = fmin(o->u.prism.height1, o->u.prism.height2);
    double h2 = fmax(o->u.prism.height1, o->u.prism.height2);
    if (o->u.prism.sweep == 1) {
        double xs[4] = { x1 * h1, x1 * h2, x2 * h1, x2 * h2 };
        double zs[4] = { z1 * h1, z1 * h2, z2 * h1, z2 * h2 };
        x1 = z1 = 1e300;
        x2 = z2 = -1e300;
        for (int i = 0; i < 4; i++) {
            x1 = fmin(x1, xs[i]);
            x2 = fmax(x2, xs[i]);
            z1 = fmin(z1, zs[i]);
            z2 = fmax(z2, zs[i]);
        }
    }
    *a = v3(x1, h1, z1);
    *b = v3(x2, h2, z2);
    return true;
}

/* POV-Ray's BOUND_HUGE and CRITICAL_LENGTH: a box larger than the latter
** on any axis becomes the infinite box, -BOUND_HUGE/2 .. BOUND_HUGE/2. */
#define POV_BOUND_HUGE 2.0e10
#define POV_CRITICAL_LENGTH 1.0e6

static bool object_bounds(const iris_object *o, vec3 *lo, vec3 *hi);

/* A quadric's box in its own frame (POV-Ray 3.7's Quadric::Compute_BBox
** as Parse_Quadric calls it, before the object's modifiers): with the
** coefficients below 1e-10 set to 0, a quadric without mixed terms is
** moved to its centre (completing the squares of the linear terms) and,
** when it is then an ellipsoid A x^2 + E y^2 + H z^2 + J = 0 (A, E, H
** of one sign, J of the other), boxed by its semi-axes sqrt(-J/A), ...
** POV-Ray also bounds cylinders, cones, hyperboloids and paraboloids in
** this form, but against its parse-time clip box of +-BOUND_HUGE, so
** each of those comes out longer than CRITICAL_LENGTH on some axis and
** becomes the infinite box, as does any quadric with mixed terms
** (measured with povray 3.7.0.10: min_extent of a y cylinder, a cone, a
** paraboloid are all <-1e10, -1e10, -1e10>). */
static void quadric_box(const iris_object *o, vec3 *a, vec3 *b)
{
    const double *k = o->u.poly.coeffs;
    double c[10];
    for (int i = 0; i < 10; i++)
        c[i] = fabs(k[i]) < 1e-10 ? 0 : k[i];
    /* POV-Ray halves the mixed and linear terms before testing them */
    for (int i = 3; i < 9; i++)
        if (fabs(k[i] / 2) < 1e-10)
            c[i] = 0;
    double A = c[0], E = c[1], H = c[2], J = c[9];
    double D = c[6] / 2, G = c[7] / 2, I = c[8] / 2;
    double h = POV_BOUND_HUGE / 2;
    *a = v3(-h, -h, -h);
    *b = v3(h, h, h);
    if (c[3] != 0 || c[4] != 0 || c[5] != 0 || A == 0 || E == 0 || H == 0)
        return;
    /* the centre, where the linear terms vanish */
    vec3 t = v3(-D / A, -G / E, -I / H);
    J -= A * t.x * t.x + E * t.y * t.y + H * t.z * t.z;
    if (A < 0) {
        A = -A;
        E = -E;
        H = -H;
        J = -J;
    }
    if (!(E > 0 && H > 0 && J < 0))
        return;
    vec3 r = v3(sqrt(-J / A), sqrt(-J / E), sqrt(-J / H));
    if (2 * r.x > POV_CRITICAL_LENGTH || 2 * r.y > POV_CRITICAL_LENGTH ||
        2 * r.z > POV_CRITICAL_LENGTH)
        return;
    *a = v3_sub(t, r);
    *b = v3_add(t, r);
}

/* The half-space box of a plane in an intersection (POV-Ray's
** Quadric::Compute_Plane_Min_Max): bounded on one axis when the normal
** lies on that axis, infinite otherwise. POV-Ray folds a plane's
** transform into its normal and distance, so the world-space plane is
** used here. */
static void plane_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    vec3 n = o->u.plane.normal;
    double len = v3_len(n);
    double d = 0;
    if (len > 0) {
        /* a point of the plane, moved with the plane */
        vec3 p = v3_scale(n, o->u.plane.distance / (len * len));
        if (o->has_transform) {
            p = xf_point(&o->transform, p);
            n = xf_normal(&o->transform, n);
            len = v3_len(n);
        }
        if (len > 0) {
            n = v3_scale(n, 1 / len);
            d = v3_dot(n, p);
        }
    }
    double h = POV_BOUND_HUGE / 2, *l = &lo->x, *u = &hi->x;
    const double nv[3] = { n.x, n.y, n.z };
    *lo = v3(-h, -h, -h);
    *hi = v3(h, h, h);
    for (int k = 0; k < 3; k++) {
        /* POV-Ray's EPSILON, 1e-10, on the other two components */
        if (fabs(nv[(k + 1) % 3]) >= 1e-10 || fabs(nv[(k + 2) % 3]) >= 1e-10)
            continue;
        if (nv[k] > 0)
            u[k] = d;
        else
            l[k] = -d;
    }
}

/*
** CSG::Compute_BBox: a union or merge is the box of its children's
** boxes; an intersection (a difference is one whose later children are
** inverted) the overlap of its children's boxes, leaving out the
** inverted ones (an 'inverse' child, or a subtracted one that is not
** inverted twice) and height fields, a plane counting as its half-space.
** An empty overlap keeps the infinite box, and so does a box longer than
** CRITICAL_LENGTH. False when a child is one the parser cannot bound.
*/
static bool csg_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    bool isect = o->kind == IRIS_OBJ_INTERSECTION ||
                 o->kind == IRIS_OBJ_DIFFERENCE;
    double h = isect ? POV_BOUND_HUGE : -POV_BOUND_HUGE;
    *lo = v3(-h, -h, -h);
    *hi = v3(h, h, h);
    bool known = true;
    for (int i = 0; i < o->u.csg.n_children; i++) {
        const iris_object *c = o->u.csg.children[i];
        vec3 cl, ch;
        if (isect) {
            bool inverted = c->inverse !=
                            (o->kind == IRIS_OBJ_DIFFERENCE && i > 0);
            if (inverted || c->kind == IRIS_OBJ_HEIGHT_FIELD)
                continue;
            if (c->kind == IRIS_OBJ_PLANE)
                plane_bounds(c, &cl, &ch);
            else if (!object_bounds(c, &cl, &ch))
                known = false;
            *lo = v3_max(*lo, cl);
            *hi = v3_min(*hi, ch);
        } else {
            if (!object_bounds(c, &cl, &ch))
                known = false;
            *lo = v3_min(*lo, cl);
            *hi = v3_max(*hi, ch);
        }
    }
    double H = POV_BOUND_HUGE / 2;
    vec3 size = v3_sub(*hi, *lo);
    if (!known || lo->x > hi->x || lo->y > hi->y || lo->z > hi->z ||
        size.x > POV_CRITICAL_LENGTH || size.y > POV_CRITICAL_LENGTH ||
        size.z > POV_CRITICAL_LENGTH) {
        *lo = v3(-H, -H, -H);
        *hi = v3(H, H, H);
    }
    return known;
}

/* The object bounds used by min_extent/max_extent: the world-space box
** POV-Ray gives the shape (its own box, transformed as a box unless the
** shape moves its defining points), or a CSG's from its members (made
** once when the CSG is read, pp_obj.has_box). False (and POV-Ray's
** infinite box, +-1e10) when the parser cannot bound 'o' itself. */
/* The world box of the box a..b in the object's frame: its 8 corners
** transformed (POV-Ray's Recompute_BBox). */
static void corners(const iris_object *o, vec3 a, vec3 b, vec3 *lo, vec3 *hi)
{
    *lo = v3(1e30, 1e30, 1e30);
    *hi = v3(-1e30, -1e30, -1e30);
    for (int i = 0; i < 8; i++) {
        vec3 p = v3(i & 1 ? b.x : a.x, i & 2 ? b.y : a.y, i & 4 ? b.z : a.z);
        if (o->has_transform)
            p = xf_point(&o->transform, p);
        *lo = v3_min(*lo, p);
        *hi = v3_max(*hi, p);
    }
}

static bool object_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    vec3 a, b;
    const pp_obj *po = (const pp_obj *)o;
    if (po->has_box) {
        *lo = po->box_lo;
        *hi = po->box_hi;
        return true;
    }
    switch (o->kind) {
    case IRIS_OBJ_SPHERE: {
        double r = o->u.sphere.radius, sc;
        if (o->has_transform && !po->sphere_trans &&
            (sc = similarity_scale(&o->transform)) > 0) {
            vec3 c = xf_point(&o->transform, o->u.sphere.centre);
            r *= sc;
            *lo = v3_sub(c, v3(r, r, r));
            *hi = v3_add(c, v3(r, r, r));
            return true;
        }
        a = v3_add(o->u.sphere.centre, v3(-r, -r, -r));
        b = v3_add(o->u.sphere.centre, v3(r, r, r));
        break;
    }
    case IRIS_OBJ_BOX:
        a = v3_min(o->u.box.lo, o->u.box.hi);
        b = v3_max(o->u.box.lo, o->u.box.hi);
        break;
    case IRIS_OBJ_CYLINDER:
        axial_bounds(o, o->u.cylinder.base, o->u.cylinder.cap,
                     o->u.cylinder.radius, lo, hi);
        return true;
    case IRIS_OBJ_CONE:
        /* Cone::Compute_Cone_Data turns the cone so that its axis runs
        ** from the smaller end to the larger: the frame (and so the box
        ** of a slanted cone) follows that axis */
        if (o->u.cone.base_radius > o->u.cone.cap_radius)
            axial_bounds(o, o->u.cone.cap, o->u.cone.base,
                         o->u.cone.base_radius, lo, hi);
        else
            axial_bounds(o, o->u.cone.base, o->u.cone.cap,
                         o->u.cone.cap_radius, lo, hi);
        return true;
    case IRIS_OBJ_DISC: {
        /* Disc::Compute_BBox: [-r, r]^2 x [-0.001, 0.001] in the disc's
        ** frame (normal on z, the same rotation as a cylinder's axis). */
        vec3 n = o->u.disc.normal, c = o->u.disc.centre;
        double nl = v3_len(n);
        if (nl > 0)
            n = v3_scale(n, POV_SMALL_TOLERANCE / nl);
        axial_bounds(o, v3_sub(c, n), v3_add(c, n), o->u.disc.radius,
                     lo, hi);
        return true;
    }
    case IRIS_OBJ_POLYGON: {
        /* Polygon::Compute_BBox: the transformed vertices' box, a flat
        ** side widened to +-0.001. */
        int n = o->u.polygon.n_points;
        if (n < 1)
            break;
        *lo = v3(1e30, 1e30, 1e30);
        *hi = v3(-1e30, -1e30, -1e30);
        for (int i = 0; i < n; i++) {
            vec3 p = o->u.polygon.points[i];
            if (o->has_transform)
                p = xf_point(&o->transform, p);
            *lo = v3_min(*lo, p);
            *hi = v3_max(*hi, p);
        }
        double *l = &lo->x, *h = &hi->x;
        for (int k = 0; k < 3; k++)
            if (fabs(h[k] - l[k]) < POV_SMALL_TOLERANCE) {
                l[k] -= POV_SMALL_TOLERANCE;
                h[k] += POV_SMALL_TOLERANCE;
            }
        return true;
    }
    case IRIS_OBJ_SUPERELLIPSOID:
        /* Superellipsoid::Compute_BBox: +-1.0001 whatever e and n are */
        a = v3(-1.0001, -1.0001, -1.0001);
        b = v3(1.0001, 1.0001, 1.0001);
        break;
    case IRIS_OBJ_SOR: {
        double y0, y1;
        double r = sor_radius(o->u.lathe.points, o->u.lathe.n_points,
                              &y0, &y1);
        if (o->u.lathe.n_points < 4)
            goto unknown;
        a = v3(-r, y0, -r);
        b = v3(r, y1, r);
        break;
    }
    case IRIS_OBJ_SPHERE_SWEEP: {
        /* SphereSweep::Compute_BBox in 3.7: every control sphere, its
        ** radius doubled for a cubic_spline (Catmull-Rom) sweep, which
        ** can overshoot them. */
        int n = o->u.sphere_sweep.n_spheres;
        double f = o->u.sphere_sweep.spline == 2 ? 2 : 1;
        if (n < 1)
            goto unknown;
        a = v3(1e30, 1e30, 1e30);
        b = v3(-1e30, -1e30, -1e30);
        for (int i = 0; i < n; i++) {
            double r = f * o->u.sphere_sweep.radii[i];
            vec3 c = o->u.sphere_sweep.centres[i];
            a = v3_min(a, v3_sub(c, v3(r, r, r)));
            b = v3_max(b, v3_add(c, v3(r, r, r)));
        }
        break;
    }
    case IRIS_OBJ_TORUS: {
        double R = o->u.torus.major + o->u.torus.minor, r = o->u.torus.minor;
        a = v3(-R, -r, -R);
        b = v3(R, r, R);
        break;
    }
    case IRIS_OBJ_MESH: {
        /* Mesh::Compute_BBox: its triangles' corners in the mesh's own
        ** frame, that box then transformed */
        const iris_mesh_data *m = &o->u.mesh;
        if (m->n_triangles < 1 || !m->tri_vertices || !m->vertices)
            goto unknown;
        a = v3(1e300, 1e300, 1e300);
        b = v3(-1e300, -1e300, -1e300);
        for (int i = 0; i < 3 * m->n_triangles; i++) {
            int k = m->tri_vertices[i];
            if (k < 0 || k >= m->n_vertices)
                goto unknown;
            a = v3_min(a, m->vertices[k]);
            b = v3_max(b, m->vertices[k]);
        }
        break;
    }
    case IRIS_OBJ_TRIANGLE: {
        /* a triangle moves its corners: the box of the moved corners */
        *lo = v3(1e300, 1e300, 1e300);
        *hi = v3(-1e300, -1e300, -1e300);
        for (int i = 0; i < 3; i++) {
            vec3 p = o->u.triangle.p[i];
            if (o->has_transform)
                p = xf_point(&o->transform, p);
            *lo = v3_min(*lo, p);
            *hi = v3_max(*hi, p);
        }
        return true;
    }
    case IRIS_OBJ_BICUBIC_PATCH: {
        /* BicubicPatch::Compute_BBox: the box of its 16 control points,
        ** which a transform moves (the hull, not the surface: a bump
        ** whose inner points are at z = 1 is boxed to z = 1) */
        *lo = v3(1e300, 1e300, 1e300);
        *hi = v3(-1e300, -1e300, -1e300);
        for (int i = 0; i < 16; i++) {
            vec3 p = o->u.bicubic.points[i];
            if (o->has_transform)
                p = xf_point(&o->transform, p);
            *lo = v3_min(*lo, p);
            *hi = v3_max(*hi, p);
        }
        return true;
    }
    case IRIS_OBJ_PRISM:
        if (!prism_box(o, &a, &b))
            goto unknown;
        break;
    case IRIS_OBJ_QUADRIC: {
        /* a clipped quadric is boxed against its clip objects (not done
        ** here: left to the renderer) */
        if (o->n_clipped_by)
            goto unknown;
        quadric_box(o, &a, &b);
        /* each transform's Recompute_BBox keeps the box within
        ** +-BOUND_HUGE/2 (the transforms are applied here as one) */
        double h = POV_BOUND_HUGE / 2;
        corners(o, a, b, lo, hi);
        *lo = v3_max(*lo, v3(-h, -h, -h));
        *hi = v3_min(*hi, v3(h, h, h));
        return true;
    }
    case IRIS_OBJ_PLANE:
        /* Plane::Compute_BBox: always the infinite box */
        *lo = v3(-POV_BOUND_HUGE / 2, -POV_BOUND_HUGE / 2, -POV_BOUND_HUGE / 2);
        *hi = v3(POV_BOUND_HUGE / 2, POV_BOUND_HUGE / 2, POV_BOUND_HUGE / 2);
        return true;
    case IRIS_OBJ_UNION: case IRIS_OBJ_MERGE:
    case IRIS_OBJ_INTERSECTION: case IRIS_OBJ_DIFFERENCE:
        return csg_bounds(o, lo, hi);
    default:
    unknown:
        *lo = v3(-1e10, -1e10, -1e10);
        *hi = v3(1e10, 1e10, 1e10);
        return false;
    }
    corners(o, a, b, lo, hi);
    return true;
}

bool pp_object_bounds(const iris_object *o, vec3 *lo, vec3 *hi)
{
    return object_bounds(o, lo, hi);
}

