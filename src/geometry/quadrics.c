/* SPDX-License-Identifier: MIT */
/*
** quadrics.c: sphere, plane, box, cylinder, cone, disc and polygon.
**
** Closed-form intersections in object space. Quadratics use the
** numerically stable form (no subtraction of nearly equal numbers); the
** sphere's chord is sphere_span()'s (POV-Ray's sums for unit directions).
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/sphere_span.h"

#include <math.h>

/*
** Real roots of a·t² + b·t + c = 0 into r[0] <= r[1]; returns the count.
** When |a| is negligible against the other terms the equation is treated
** as linear: 1e-14 relative is a few hundred ulps, below which the
** quadratic root at "infinity" is only rounding noise.
*/
static int quadratic(double a, double b, double c, double scale, double r[2])
{
    if (fabs(a) <= 1e-14 * scale) {
        if (b == 0)
            return 0;
        r[0] = -c / b;
        return 1;
    }
    double disc = b * b - 4 * a * c;
    if (disc < 0)
        return 0;
    double q = -0.5 * (b + copysign(sqrt(disc), b));
    double x0 = q / a, x1 = q != 0 ? c / q : x0;
    r[0] = fmin(x0, x1);
    r[1] = fmax(x0, x1);
    return 2;
}

void geom_sphere_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                      double t1, struct isect_list *out)
{
    vec3 c = o->u.sphere.centre;
    double rad = o->u.sphere.radius;
    vec3 oc = v3_sub(ro, c);
    double tc, h;
    if (!sphere_span(oc, rd, v3_len2(rd), rad, &tc, &h))
        return;
    for (int k = 0; k < 2; k++) {
        double t = k ? tc + h : tc - h;
        if (t > t0 && t < t1) {
            /* uv is left to geom_sphere_uv(), asked for the one crossing
            ** that is shaded: two inverse trigonometric functions per
            ** crossing cost as much as the rest of the test */
            vec3 n = v3_scale(v3_madd(oc, rd, t), 1.0 / rad);
            isect_push(out, t, n, 0, 0);
        }
    }
}

iris_vec2 geom_sphere_uv(const iris_object *o, vec3 p)
{
    vec3 n = v3_scale(v3_sub(p, o->u.sphere.centre), 1.0 / o->u.sphere.radius);
    /* POV-Ray's sphere uv: u around y from +x towards +z (acos(x), and
    ** 2 pi minus it where z < 0), v from the pole */
    double u = atan2(n.z, n.x) / (2 * M_PI);
    if (u < 0)
        u += 1;
    double v = 0.5 + asin(fmax(-1, fmin(1, n.y))) / M_PI;
    iris_vec2 uv = { isfinite(u) ? u : 0, isfinite(v) ? v : 0 };
    return uv;
}

void geom_plane_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out)
{
    vec3 n = v3_norm(o->u.plane.normal);
    double dn = v3_dot(n, rd);
    if (dn == 0)
        return;
    double t = (o->u.plane.distance - v3_dot(n, ro)) / dn;
    if (t > t0 && t < t1)
        isect_push(out, t, n, 0, 0);
}

/*
** POV-Ray's box uv (Box::UVCoord): the box unfolded as a cube cross, each
** face a quarter of u and a third of v, with 'p' (object space) taken
** relative to the box, [0,1] per axis. 'axis' is the face's axis and
** 'side' -1 for its low face (POV-Ray's X0, Y0, Z0), +1 for the high one.
** The faces read the right way round seen from outside.
*/
/* A crossing's uv as isect_push() keeps it: 0 where not finite (the
** fast paths of accel/node.c ask for one crossing's uv alone) */
static inline iris_vec2 uv_finite(iris_vec2 uv)
{
    uv.u = isfinite(uv.u) ? uv.u : 0;
    uv.v = isfinite(uv.v) ? uv.v : 0;
    return uv;
}

static iris_vec2 box_uv(vec3 lo, vec3 hi, vec3 p, int axis, double side)
{
    /* Only the two coordinates a face uses: divisions are most of it */
#define BOX_P(c) ((p.c - lo.c) / (hi.c - lo.c))
    iris_vec2 uv;
    switch (axis * 2 + (side > 0)) {
    case 0: uv.u = BOX_P(z) / 4; uv.v = (1 + BOX_P(y)) / 3; break; /* X0 */
    case 1: uv.u = 0.75 - BOX_P(z) / 4; uv.v = (1 + BOX_P(y)) / 3; break;
    case 2: uv.u = 0.25 + BOX_P(x) / 4; uv.v = BOX_P(z) / 3; break; /* Y0 */
    case 3: uv.u = 0.25 + BOX_P(x) / 4; uv.v = 1 - BOX_P(z) / 3; break;
    case 4: uv.u = 1 - BOX_P(x) / 4; uv.v = (1 + BOX_P(y)) / 3; break;
    default: uv.u = 0.25 + BOX_P(x) / 4; uv.v = (1 + BOX_P(y)) / 3; break;
    }
#undef BOX_P
    return uv; /* a flat box's 0/0 is NaN: isect_push() makes it 0 */
}

int geom_box_crossings(const iris_object *o, vec3 ro, vec3 rd, double t0,
                       double t1, struct geom_box_cross c[2])
{
    vec3 lo = v3_min(o->u.box.lo, o->u.box.hi);
    vec3 hi = v3_max(o->u.box.lo, o->u.box.hi);
    double tin = -INFINITY, tout = INFINITY;
    int ain = -1, aout = -1;
    double sin_ = 0, sout = 0;
    for (int k = 0; k < 3; k++) {
        double ok = v3_comp(ro, k), dk = v3_comp(rd, k);
        double l = v3_comp(lo, k), h = v3_comp(hi, k);
        if (dk == 0) {
            if (ok < l || ok > h)
                return 0;
            continue;
        }
        double ta = (l - ok) / dk, tb = (h - ok) / dk;
        /* Entering through the low face when moving +, else the high one */
        double sa = -1, sb = 1;
        if (ta > tb) {
            double s = ta;
            ta = tb;
            tb = s;
            sa = 1;
            sb = -1;
        }
        if (ta > tin) {
            tin = ta;
            ain = k;
            sin_ = sa;
        }
        if (tb < tout) {
            tout = tb;
            aout = k;
            sout = sb;
        }
    }
    if (!(tin <= tout) || ain < 0 || aout < 0)
        return 0;
    int nc = 0;
    if (tin > t0 && tin < t1)
        c[nc++] = (struct geom_box_cross){ tin, ain, sin_ };
    if (tout > t0 && tout < t1 && tout > tin)
        c[nc++] = (struct geom_box_cross){ tout, aout, sout };
    return nc;
}

vec3 geom_box_normal(const struct geom_box_cross *c)
{
    double n[3] = { 0, 0, 0 };
    n[c->axis] = c->side;
    return v3(n[0], n[1], n[2]);
}

iris_vec2 geom_box_uv(const iris_object *o, vec3 ro, vec3 rd,
                      const struct geom_box_cross *c)
{
    vec3 lo = v3_min(o->u.box.lo, o->u.box.hi);
    vec3 hi = v3_max(o->u.box.lo, o->u.box.hi);
    iris_vec2 uv = box_uv(lo, hi, v3_madd(ro, rd, c->t), c->axis, c->side);
    return uv_finite(uv);
}

void geom_box_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                   double t1, struct isect_list *out)
{
    struct geom_box_cross c[2];
    int nc = geom_box_crossings(o, ro, rd, t0, t1, c);
    /* uv for every crossing: a dozen flops, cheaper than asking later */
    for (int k = 0; k < nc; k++) {
        iris_vec2 uv = geom_box_uv(o, ro, rd, &c[k]);
        isect_push(out, c[k].t, geom_box_normal(&c[k]), uv.u, uv.v);
    }
}

/*
** A cone's radii as POV-Ray's Cone::Compute_Cone_Data takes them: the
** radius runs linearly from base to cap with its sign, and the surface
** is x² + y² = r(z)², so radii of opposite signs make a double cone
** meeting at the point where r(z) = 0 ('cone { 0, -0.5, y, 1 }' is
** an hourglass). The larger radius ends the cone in POV-Ray's frame;
** when it is negative that frame turns the cone into a cylinder of its
** size, and when it is 0 (the other negative) into nothing.
*/
static void cone_radii(const iris_object *o, struct geom_cone_frame *f)
{
    double ra = o->u.cone.base_radius, rb = o->u.cone.cap_radius;
    double hi = fmax(ra, rb);
    f->empty = false;
    if (fabs(ra - rb) < 1e-10) {
        ra = rb = fabs(rb);          /* POV-Ray: "really a cylinder" */
    } else if (hi < 0) {
        ra = rb = -hi;
    } else if (hi == 0) {
        f->empty = true;
    }
    f->ra = ra;
    f->rb = rb;
}

void geom_cone_frame(const iris_object *o, struct geom_cone_frame *f)
{
    vec3 b;
    if (o->kind == IRIS_OBJ_CYLINDER) {
        f->a = o->u.cylinder.base;
        b = o->u.cylinder.cap;
        f->ra = f->rb = o->u.cylinder.radius;
        f->empty = false;
    } else {
        f->a = o->u.cone.base;
        b = o->u.cone.cap;
        cone_radii(o, f);
    }
    vec3 ax = v3_sub(b, f->a);
    f->len = v3_len(ax);
    f->w = v3_scale(ax, 1.0 / f->len);
    v3_basis(f->w, &f->u, &f->v);
}

/* isect_push()'s test of a crossing's normal: finite and not zero */
static bool normal_kept(vec3 n)
{
    return isfinite(n.x) && isfinite(n.y) && isfinite(n.z) &&
           !(n.x == 0 && n.y == 0 && n.z == 0);
}

int geom_cone_crossings(const iris_object *o, vec3 ro, vec3 rd, double t0,
                        double t1, struct geom_cone_cross c[4])
{
    struct geom_cone_frame f;
    geom_cone_frame(o, &f);
    return geom_cone_crossings_in(o, &f, ro, rd, t0, t1, c);
}

int geom_cone_crossings_in(const iris_object *o,
                           const struct geom_cone_frame *fp, vec3 ro,
                           vec3 rd, double t0, double t1,
                           struct geom_cone_cross c[4])
{
    const struct geom_cone_frame f = *fp;
    if (f.empty)
        return 0;
    int nc = 0;
    vec3 q = v3_sub(ro, f.a);
    double ox = v3_dot(q, f.u), oy = v3_dot(q, f.v), oz = v3_dot(q, f.w);
    double dx = v3_dot(rd, f.u), dy = v3_dot(rd, f.v), dz = v3_dot(rd, f.w);
    double k = (f.rb - f.ra) / f.len;

    /* Side: x² + y² = (ra + k·z)², 0 <= z <= len */
    double ro_ = f.ra + k * oz;
    double A = dx * dx + dy * dy - k * k * dz * dz;
    double B = 2 * (ox * dx + oy * dy - ro_ * k * dz);
    double C = ox * ox + oy * oy - ro_ * ro_;
    double r[2];
    int n = quadratic(A, B, C, dx * dx + dy * dy + k * k * dz * dz, r);
    for (int i = 0; i < n; i++) {
        double t = r[i], z = oz + t * dz;
        double rz = f.ra + k * z;
        /* both nappes: rz < 0 is the far side of a double cone */
        if (!(t > t0 && t < t1) || z < 0 || z > f.len)
            continue;
        double x = ox + t * dx, y = oy + t * dy;
        vec3 nn = v3_add(v3_add(v3_scale(f.u, x), v3_scale(f.v, y)),
                         v3_scale(f.w, -rz * k));
        if (normal_kept(nn))
            c[nc++] = (struct geom_cone_cross){ t, nn, true, x, y, z, f.len };
    }

    /* End caps */
    if (o->open || dz == 0)
        return nc;
    for (int end = 0; end < 2; end++) {
        double zc = end ? f.len : 0, rc = fabs(end ? f.rb : f.ra);
        double t = (zc - oz) / dz;
        if (!(t > t0 && t < t1) || rc <= 0)
            continue;
        double x = ox + t * dx, y = oy + t * dy;
        vec3 nn = end ? f.w : v3_neg(f.w);
        if (x * x + y * y <= rc * rc && normal_kept(nn))
            c[nc++] = (struct geom_cone_cross){ t, nn, false, 0, 0, 0, 0 };
    }
    return nc;
}

iris_vec2 geom_cone_uv(const struct geom_cone_cross *c)
{
    iris_vec2 uv = { 0, 0 };
    if (c->side) {
        uv.u = atan2(c->y, c->x) / (2 * M_PI) + 0.5;
        uv.v = c->z / c->len;
    }
    return uv_finite(uv);
}

void geom_cone_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out)
{
    struct geom_cone_cross c[4];
    int nc = geom_cone_crossings(o, ro, rd, t0, t1, c);
    for (int i = 0; i < nc; i++) {
        iris_vec2 uv = geom_cone_uv(&c[i]);
        isect_push(out, c[i].t, c[i].n, uv.u, uv.v);
    }
}

/*
** Inside test with POV-Ray's tolerance (Cone::Inside). POV-Ray tests in
** the shape's unit frame: a cylinder runs from z = 0 to 1 with radius 1;
** a cone has its apex at the origin and its wider end at z = 1 with
** radius 1 (the narrower at z = dist, the ratio of the radii, negative
** for a double cone), and it is inside where w² <= z². A closed shape is
** shrunk by EPSILON (1e-10) in those units, an open one grown by it: so
** a point on a closed cylinder's cap is outside it, whatever the last
** bit of its computed coordinates. shapes3.inc's Round_Conic_Prism merges
** a cylinder whose cap lies in a box's face: POV-Ray keeps the box's
** face (outside the cylinder by the margin) and drops the cap (inside
** the closed box); an exact test dropped both where rounding put the
** point inside the cylinder, and left a hole in the end face.
*/
bool geom_cone_inside(const iris_object *o, vec3 p)
{
    const double eps = 1e-10;  /* POV-Ray's EPSILON */
    struct geom_cone_frame f;
    geom_cone_frame(o, &f);
    if (f.empty)
        return false;
    double off = o->open ? eps : -eps;
    vec3 q = v3_sub(p, f.a);
    double z = v3_dot(q, f.w);
    double x = v3_dot(q, f.u), y = v3_dot(q, f.v);
    if (f.ra == f.rb) {                         /* a cylinder */
        double zn = z / f.len, r = fabs(f.ra);
        double w2 = (x * x + y * y) / (r * r);
        return !(w2 > 1 + off || zn < -off || zn > 1 + off);
    }
    /* The wider end (larger signed radius) at zw, the other at zs */
    bool cap_wide = f.rb > f.ra;
    double rw = cap_wide ? f.rb : f.ra, rs = cap_wide ? f.ra : f.rb;
    double s = cap_wide ? z : f.len - z;        /* from the narrow end */
    double tlen = f.len * rw / (rw - rs);       /* apex to wide end */
    double dist = rs / rw;
    double zn = dist + s / tlen;                /* apex 0, wide end 1 */
    double w2 = (x * x + y * y) / (rw * rw);
    return !(w2 > zn * zn + off || zn < dist - off || zn > 1 + off);
}

void geom_disc_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out)
{
    vec3 n = v3_norm(o->u.disc.normal);
    double dn = v3_dot(n, rd);
    if (dn == 0)
        return;
    double t = v3_dot(v3_sub(o->u.disc.centre, ro), n) / dn;
    if (!(t > t0 && t < t1))
        return;
    double r2 = v3_len2(v3_sub(v3_madd(ro, rd, t), o->u.disc.centre));
    double ro2 = o->u.disc.radius * o->u.disc.radius;
    double ri2 = o->u.disc.hole_radius * o->u.disc.hole_radius;
    if (r2 <= ro2 && r2 >= ri2)
        isect_push(out, t, n, 0, 0);
}

/* Newell's normal of the polygon's points (robust for concave outlines). */
static vec3 polygon_normal(const iris_object *o)
{
    vec3 n = v3(0, 0, 0);
    const vec3 *p = o->u.polygon.points;
    int m = o->u.polygon.n_points;
    for (int i = 0; i < m; i++) {
        vec3 a = p[i], b = p[(i + 1) % m];
        n.x += (a.y - b.y) * (a.z + b.z);
        n.y += (a.z - b.z) * (a.x + b.x);
        n.z += (a.x - b.x) * (a.y + b.y);
    }
    return v3_norm(n);
}

/* 2-D crossing test of the half-open edge (a, b) with the +u ray from q. */
static int crosses(double qu, double qv, double au, double av, double bu,
                   double bv)
{
    if ((av > qv) == (bv > qv))
        return 0;
    double u = au + (qv - av) * (bu - au) / (bv - av);
    return u > qu;
}

void geom_polygon_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                       double t1, struct isect_list *out)
{
    const vec3 *p = o->u.polygon.points;
    int m = o->u.polygon.n_points;
    vec3 n = polygon_normal(o);
    double dn = v3_dot(n, rd);
    if (dn == 0 || !(v3_len2(n) > 0))
        return;
    double t = v3_dot(v3_sub(p[0], ro), n) / dn;
    if (!(t > t0 && t < t1))
        return;
    vec3 x = v3_madd(ro, rd, t);

    /* Project on the plane of the two axes the normal is least along */
    int drop = fabs(n.x) > fabs(n.y) ? (fabs(n.x) > fabs(n.z) ? 0 : 2)
                                     : (fabs(n.y) > fabs(n.z) ? 1 : 2);
    int iu = drop == 0 ? 1 : 0, iv = drop == 2 ? 1 : 2;
    double qu = v3_comp(x, iu), qv = v3_comp(x, iv);

    /* Even-odd over every edge; a point equal to its sub-polygon's first
    ** point closes that sub-polygon (POV-Ray's rule) */
    int parity = 0, start = 0;
    for (int i = 1; i < m; i++) {
        vec3 a = p[i - 1], b = p[i];
        parity ^= crosses(qu, qv, v3_comp(a, iu), v3_comp(a, iv),
                          v3_comp(b, iu), v3_comp(b, iv));
        if (b.x == p[start].x && b.y == p[start].y && b.z == p[start].z) {
            start = i + 1;
            i++;
        }
    }
    if (start < m) {
        vec3 a = p[m - 1], b = p[start];
        parity ^= crosses(qu, qv, v3_comp(a, iu), v3_comp(a, iv),
                          v3_comp(b, iu), v3_comp(b, iv));
    }
    if (parity)
        isect_push(out, t, n, 0, 0);
}
