/* SPDX-License-Identifier: MIT */
/*
** csgbox.c: boxes of CSG intersections whose children are unbounded
** alone: planes and quadrics.
**
** A plane or a quadric has no box of its own, so an intersection of
** planes (a bevelled frame, a wedge) or of a hyperboloid with two
** planes (a chess piece's stem) had none either and was tested against
** every ray outside Embree, with every crossing inside-tested against the
** other children. Its inside is nonetheless bounded: each child's inside
** narrows the box the others leave (interval propagation), as POV-Ray
** narrows a quadric's box by the planes it is intersected with
** (Quadric::Compute_BBox). Every narrowing here is conservative: a point
** inside the child and inside the box before is inside the box after.
** Boxes are axis intervals lo..hi whose sides may be infinite.
*/
#include "config.h"

#include "accel/csgbox.h"

#include <math.h>
#include <stdbool.h>

/* Smallest and largest of c·x over lo <= x <= hi (c finite). */
static void lin_range(double c, double lo, double hi, double *mn, double *mx)
{
    if (c == 0) {
        *mn = *mx = 0;
    } else if (c > 0) {
        *mn = c * lo;
        *mx = c * hi;
    } else {
        *mn = c * hi;
        *mx = c * lo;
    }
}

/* Smallest and largest of (x - c)^2 over lo <= x <= hi. */
static void sq_range(double c, double lo, double hi, double *mn, double *mx)
{
    double a = lo - c, b = hi - c;
    *mn = (a <= 0 && b >= 0) ? 0 : fmin(a * a, b * b);
    *mx = fmax(a * a, b * b);
}

static double axis(vec3 v, int k)
{
    return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

static void set_axis(vec3 *v, int k, double x)
{
    if (k == 0)
        v->x = x;
    else if (k == 1)
        v->y = x;
    else
        v->z = x;
}

static bool box_ok(vec3 lo, vec3 hi)
{
    return lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z;
}

/*
** The box of affine image p -> m·p + t of box lo..hi ('m' rows 0..2,
** column 3 the translation). A diagonal linear part maps each axis alone,
** so infinite sides stay where they are; otherwise the eight corners are
** mapped, which needs a finite box. False when neither applies.
*/
static bool box_affine(const double m[3][4], vec3 lo, vec3 hi, vec3 *olo,
                       vec3 *ohi)
{
    bool diag = true;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            if (i != j && m[i][j] != 0)
                diag = false;
    if (diag) {
        for (int k = 0; k < 3; k++) {
            double s = m[k][k];
            if (s == 0 || !isfinite(s))
                return false;
            double a = s * axis(lo, k) + m[k][3], b = s * axis(hi, k) + m[k][3];
            set_axis(olo, k, fmin(a, b));
            set_axis(ohi, k, fmax(a, b));
        }
        return true;
    }
    if (!(isfinite(lo.x) && isfinite(lo.y) && isfinite(lo.z) &&
          isfinite(hi.x) && isfinite(hi.y) && isfinite(hi.z)))
        return false;
    for (int c = 0; c < 8; c++) {
        vec3 p = v3(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y,
                    c & 4 ? hi.z : lo.z);
        vec3 q = v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
                    m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
                    m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
        *olo = c ? v3_min(*olo, q) : q;
        *ohi = c ? v3_max(*ohi, q) : q;
    }
    return true;
}

/*
** Half-space n·x < d: along each axis k with n_k != 0,
** n_k x_k < d - min over the box of the other terms.
*/
static bool narrow_half_space(vec3 n, double d, vec3 *lo, vec3 *hi)
{
    double mn[3], mx[3];
    for (int j = 0; j < 3; j++)
        lin_range(axis(n, j), axis(*lo, j), axis(*hi, j), &mn[j], &mx[j]);
    for (int k = 0; k < 3; k++) {
        double nk = axis(n, k);
        if (nk == 0)
            continue;
        double rest = 0;
        for (int j = 0; j < 3; j++)
            if (j != k)
                rest += mn[j];
        double lim = (d - rest) / nk;
        if (isnan(lim))
            continue; /* an infinite side left no bound */
        if (nk > 0)
            set_axis(hi, k, fmin(axis(*hi, k), lim));
        else
            set_axis(lo, k, fmax(axis(*lo, k), lim));
    }
    return box_ok(*lo, *hi);
}

static bool narrow_plane(const iris_object *o, vec3 *lo, vec3 *hi)
{
    vec3 n = o->u.plane.normal;
    double d = o->u.plane.distance;
    double n2 = v3_dot(n, n);
    if (!(n2 > 0))
        return true;
    /* inside is n̂·x < d with the unit normal, as geom_inside has it */
    double len = sqrt(n2);
    n = v3_scale(n, 1.0 / len);
    if (o->has_transform) {
        /* world: (M^-T n)·w < d + (M^-T n)·t, from n·M^-1(w - t) < d */
        vec3 p0 = v3_scale(n, d);
        vec3 p0w = xf_point(&o->transform, p0);
        n = xf_normal(&o->transform, n);
        d = v3_dot(n, p0w);
    }
    if (!(isfinite(n.x) && isfinite(n.y) && isfinite(n.z) && isfinite(d)))
        return true;
    return narrow_half_space(n, d, lo, hi);
}

/*
** Quadric A x² + B y² + C z² + G x + H y + I z + J < 0 without cross
** terms, in object space: with the squares completed,
** sum a_k (x_k - c_k)² + sum g_k x_k (a_k = 0) + J' < 0, so along axis k
** a_k (x_k - c_k)² (or g_k x_k) < -J' - min over the box of the others.
*/
static bool narrow_quadric_local(const double *q, vec3 *lo, vec3 *hi)
{
    double a[3] = { q[0], q[1], q[2] }, g[3] = { q[6], q[7], q[8] };
    double c[3] = { 0, 0, 0 }, jj = q[9];
    for (int k = 0; k < 3; k++)
        if (a[k] != 0) {
            c[k] = -g[k] / (2 * a[k]);
            jj -= a[k] * c[k] * c[k];
        }
    double tmin[3];
    for (int j = 0; j < 3; j++) {
        double l = axis(*lo, j), h = axis(*hi, j), mn, mx;
        if (a[j] != 0) {
            sq_range(c[j], l, h, &mn, &mx);
            tmin[j] = a[j] > 0 ? a[j] * mn : a[j] * mx;
        } else {
            lin_range(g[j], l, h, &mn, &mx);
            tmin[j] = mn;
        }
    }
    for (int k = 0; k < 3; k++) {
        double rest = jj;
        for (int j = 0; j < 3; j++)
            if (j != k)
                rest += tmin[j];
        double rhs = -rest; /* term_k < rhs */
        if (isnan(rhs) || rhs == INFINITY)
            continue;
        if (a[k] > 0) {
            if (rhs < 0)
                return false; /* no point of the box is inside */
            double r = sqrt(rhs / a[k]);
            set_axis(lo, k, fmax(axis(*lo, k), c[k] - r));
            set_axis(hi, k, fmin(axis(*hi, k), c[k] + r));
        } else if (a[k] == 0 && g[k] != 0) {
            double lim = rhs / g[k];
            if (g[k] > 0)
                set_axis(hi, k, fmin(axis(*hi, k), lim));
            else
                set_axis(lo, k, fmax(axis(*lo, k), lim));
        }
    }
    return box_ok(*lo, *hi);
}

static bool narrow_quadric(const iris_object *o, vec3 *lo, vec3 *hi)
{
    const double *q = o->u.poly.coeffs;
    if (!q || o->u.poly.order != 2 || o->u.poly.n_coeffs != 10)
        return true;
    if (q[3] != 0 || q[4] != 0 || q[5] != 0)
        return true; /* cross terms: left unbounded */
    for (int i = 0; i < 10; i++)
        if (!isfinite(q[i]))
            return true;
    if (!o->has_transform)
        return narrow_quadric_local(q, lo, hi);
    vec3 llo, lhi, wlo, whi;
    if (!box_affine(o->transform.inv, *lo, *hi, &llo, &lhi))
        return true;
    if (!narrow_quadric_local(q, &llo, &lhi))
        return false;
    if (!box_affine(o->transform.m, llo, lhi, &wlo, &whi))
        return true;
    *lo = v3_max(*lo, wlo);
    *hi = v3_min(*hi, whi);
    return box_ok(*lo, *hi);
}

bool csgbox_narrow(const iris_object *o, vec3 *lo, vec3 *hi)
{
    switch (o->kind) {
    case IRIS_OBJ_PLANE:
        return narrow_plane(o, lo, hi);
    case IRIS_OBJ_QUADRIC:
        return narrow_quadric(o, lo, hi);
    default:
        return true;
    }
}
