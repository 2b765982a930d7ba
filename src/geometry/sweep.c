/* SPDX-License-Identifier: MIT */
/*
** sweep.c: surfaces made from a 2-D profile: revolved about the y axis
** (lathe, sor) or extruded along an axis (prism along y, text along z).
**
** The profile is made of straight segments (profile.c), so every piece is
** a cone, cylinder, annulus or plane strip with a closed-form crossing.
** Normals use the spline tangents kept by profile.c, interpolated along
** the segment, so flattened curves still shade smoothly. Inside tests use
** the even-odd rule on the profile, as POV-Ray's Inside() for these
** shapes does. The curved segments of a lathe or sor are intersected
** exactly instead (curve_roots: POV-Ray's polynomial in the spline
** parameter, or in t for a sor, then a Newton polish), with the curve's
** own normal and an exact even-odd inside test; so are the walls and
** caps of a linear prism (wall_hits, a cubic per curve), while conic
** prisms and text stay flattened. A curve whose Bezier control points lie
** all on one side of the ray's line is skipped before its polynomial is
** set up (curve_side).
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/roots.h"

#include <math.h>

/* Outward 2-D normal of segment 'i' at parameter 's' in [0,1]. */
static iris_vec2 seg_normal(const struct geom_profile *p, int i, double s)
{
    iris_vec2 t = { p->ta[i].u + s * (p->tb[i].u - p->ta[i].u),
                    p->ta[i].v + s * (p->tb[i].v - p->ta[i].v) };
    if (t.u == 0 && t.v == 0) {
        t.u = p->b[i].u - p->a[i].u;
        t.v = p->b[i].v - p->a[i].v;
    }
    iris_vec2 n = { p->side[i] * t.v, -p->side[i] * t.u };
    return n;
}

/*
** The chord normal at curve parameter 'cs' of the curve whose chords
** are pieces i .. e-1: the piece holding 'cs' ('*jp') and the fraction
** along it ('*fp', in [0,1]). It orients an exact curve's normal; the
** piece and fraction give the texture's v.
*/
static iris_vec2 chord_normal_at(const struct geom_profile *p, int i, int e,
                                 double cs, int *jp, double *fp)
{
    int j = i;
    while (j + 1 < e && cs >= p->cs1[j])
        j++;
    double f = p->cs1[j] > p->cs0[j]
                   ? (cs - p->cs0[j]) / (p->cs1[j] - p->cs0[j]) : 0;
    f = fmax(0, fmin(1, f));
    *jp = j;
    *fp = f;
    return seg_normal(p, j, f);
}

/*
** Refines a crossing 't' of the unit-direction ray o + t d with curve 'c'
** at the curve's parameter '*cs' by Newton's method (lathe: two
** equations in t and s, sor: one in t), to full precision: the
** polynomial's roots (curve_roots) lose digits for nearly horizontal
** rays. On success '*t', '*cs' and the curve's 2-D normal '*n2'
** (unoriented) are set; on failure (a grazing ray, where Newton does not
** converge) they are kept. 'L' is the profile's size, for tolerances.
*/
static bool polish(const struct geom_curve *c, vec3 o, vec3 d, double L,
                   double *t, double *cs_io, iris_vec2 *n2)
{
    double tt = *t, cs = *cs_io;
    for (int k = 0; k < 16; k++) {
        double px = o.x + tt * d.x, pz = o.z + tt * d.z;
        double rho2 = px * px + pz * pz;
        double drho2 = 2 * (px * d.x + pz * d.z);
        double dt, ds = 0, nu, nv;
        if (c->kind == GEOM_CURVE_SOR) {
            /* r² = f(h), h = (y - y0)/dy: one equation in t */
            double h = (o.y + tt * d.y - c->y0) / c->dy;
            double f = ((c->c[0].u * h + c->c[1].u) * h + c->c[2].u) * h +
                       c->c[3].u;
            double fy = ((3 * c->c[0].u * h + 2 * c->c[1].u) * h +
                         c->c[2].u) / c->dy;
            double g = rho2 - f, dg = drho2 - fy * d.y;
            if (!(fabs(dg) > 1e-12 * (fabs(drho2) + fabs(fy * d.y))))
                return false;
            dt = g / dg;
            cs = h;
            /* gradient of r² - f(y) in (r, y): (2r, -f') */
            nu = 2 * sqrt(rho2);
            nv = -fy;
        } else {
            /* rho² = u(s)², y = v(s): two equations in t and s */
            const iris_vec2 *q = c->c;
            double u = ((q[0].u * cs + q[1].u) * cs + q[2].u) * cs + q[3].u;
            double v = ((q[0].v * cs + q[1].v) * cs + q[2].v) * cs + q[3].v;
            double du = (3 * q[0].u * cs + 2 * q[1].u) * cs + q[2].u;
            double dv = (3 * q[0].v * cs + 2 * q[1].v) * cs + q[2].v;
            double F1 = rho2 - u * u, F2 = o.y + tt * d.y - v;
            double J11 = drho2, J12 = -2 * u * du, J21 = d.y, J22 = -dv;
            double det = J11 * J22 - J12 * J21;
            if (!(fabs(det) >
                  1e-12 * (fabs(J11 * J22) + fabs(J12 * J21))))
                return false;
            dt = (F1 * J22 - F2 * J12) / det;
            ds = (J11 * F2 - J21 * F1) / det;
            nu = dv;
            nv = -du;
        }
        tt -= dt;
        cs -= ds;
        /* For a nearly horizontal ray the sextic's two roots of the
        ** front and back walls almost merge, and come out only to about
        ** 1e-4 L (measured at |d.y| = 1e-7, test_geom); a move past
        ** 1e-2 L would be Newton jumping to another root */
        if (!isfinite(tt) || !isfinite(cs) || fabs(tt - *t) > 1e-2 * L)
            return false;
        if (fabs(dt) <= 1e-13 * L && fabs(ds) <= 1e-13) {
            *t = tt;
            *cs_io = cs;
            n2->u = nu;
            n2->v = nv;
            return true;
        }
    }
    return false;
}

/* Product of ascending polynomials a (degree na) and b (degree nb). */
static void pmul(const double *a, int na, const double *b, int nb, double *r)
{
    for (int k = 0; k <= na + nb; k++)
        r[k] = 0;
    for (int i = 0; i <= na; i++)
        for (int j = 0; j <= nb; j++)
            r[i + j] += a[i] * b[j];
}

/* Real roots of c (degree 'deg', trailing zero terms dropped) in (lo, hi). */
static int proots(const double *c, int deg, double lo, double hi, double *out)
{
    while (deg > 0 && c[deg] == 0)
        deg--;
    if (deg == 0 || !(lo < hi))
        return 0;
    return roots_in_interval(c, deg, lo, hi, out);
}

/* proots() of a cubic: in closed form where roots.c finds that accurate
** (roots_cubic), as POV-Ray solves the sor's and prism's cubics; the
** bracketing solver took ~1900 instructions a sor segment, mostly
** Newton/bisection steps from the middle of wide brackets. */
static int proots3(const double *c, double lo, double hi, double *out)
{
    if (c[3] == 0)
        return proots(c, 3, lo, hi, out);
    return roots_cubic(c, lo, hi, out);
}

/*
** The crossings of the unit-direction ray o + t d with curve 'c', as
** POV-Ray finds them: a lathe segment (u(s), v(s)) meets the ray where
** (d.y o.x + (v(s) - o.y) d.x)² + (d.y o.z + (v(s) - o.y) d.z)² =
** d.y² u(s)², a polynomial of degree 6 in s (t = (v(s) - o.y) / d.y);
** a horizontal ray where v(s) = o.y and then on the circle of radius
** u(s); a sor segment where x² + z² = f(y), a cubic in t. Parameters run
** half-open over [0, 1) so that a crossing at a shared end counts once.
** Stores t and the parameter; returns the count (at most 6).
*/
static int curve_roots(const struct geom_curve *c, vec3 o, vec3 d,
                       double *ts, double *ss)
{
    const double lo = -1e-12, hi = 1 - 1e-12;
    double hd = d.x * d.x + d.z * d.z, od = o.x * d.x + o.z * d.z;
    double oo = o.x * o.x + o.z * o.z;
    int n = 0;
    if (c->kind == GEOM_CURVE_SOR) {
        /* h = a + b t; f(h) expanded in t; G(t) = rho²(t) - f(h(t)) */
        double a = (o.y - c->y0) / c->dy, b = d.y / c->dy;
        double F[4] = { c->c[3].u, c->c[2].u, c->c[1].u, c->c[0].u };
        double lin[2] = { a, b }, pw[4] = { 1, 0, 0, 0 }, G[4] = { oo, 2 * od,
                                                                 hd, 0 };
        int dp = 0;
        for (int k = 0; k < 4; k++) {
            for (int j = 0; j <= dp; j++)
                G[j] -= F[k] * pw[j];
            if (k < 3) {
                double r[4];
                pmul(pw, dp, lin, 1, r);
                dp++;
                for (int j = 0; j <= dp; j++)
                    pw[j] = r[j];
            }
        }
        double tlo, thi;
        if (b != 0) {
            tlo = fmin((lo - a) / b, (hi - a) / b);
            thi = fmax((lo - a) / b, (hi - a) / b);
        } else {
            /* A horizontal ray: a circle's crossings, wherever they are */
            if (!(a >= lo && a < hi))
                return 0;
            tlo = -INFINITY;
            thi = INFINITY;
        }
        double r[3];
        int m = proots3(G, tlo, thi, r);
        for (int k = 0; k < m; k++) {
            double h = a + b * r[k];
            if (h >= lo && h < hi) {
                ts[n] = r[k];
                ss[n++] = h;
            }
        }
        return n;
    }
    const iris_vec2 *q = c->c;
    double w[4] = { q[3].v - o.y, q[2].v, q[1].v, q[0].v };
    double U[4] = { q[3].u, q[2].u, q[1].u, q[0].u };
    double r[6];
    if (fabs(d.y) > 1e-9) {
        double A[4], B[4], A2[7], B2[7], U2[7], G[7];
        for (int k = 0; k < 4; k++) {
            A[k] = w[k] * d.x + (k == 0 ? d.y * o.x : 0);
            B[k] = w[k] * d.z + (k == 0 ? d.y * o.z : 0);
        }
        pmul(A, 3, A, 3, A2);
        pmul(B, 3, B, 3, B2);
        pmul(U, 3, U, 3, U2);
        for (int k = 0; k <= 6; k++)
            G[k] = A2[k] + B2[k] - d.y * d.y * U2[k];
        int m = proots(G, 6, lo, hi, r);
        for (int k = 0; k < m; k++) {
            ts[n] = roots_eval(w, 3, r[k]) / d.y;
            ss[n++] = r[k];
        }
        return n;
    }
    /* A horizontal ray: the height fixes s, the radius then t */
    int m = proots(w, 3, lo, hi, r);
    for (int k = 0; k < m && hd > 0; k++) {
        double u = roots_eval(U, 3, r[k]);
        double disc = od * od - hd * (oo - u * u);
        if (disc < 0)
            continue;
        double qq = -(od + copysign(sqrt(disc), od));
        if (qq == 0)
            continue;
        ts[n] = qq / hd;
        ss[n++] = r[k];
        ts[n] = (oo - u * u) / qq;
        ss[n++] = r[k];
    }
    return n;
}

/*
** The crossings of curve pieces i..e-1 of 'p' (one spline segment) with
** the ray o + t d, t in (lo, hi), pushed as geom_lathe_hits does: the
** exact curve, its normal oriented as the piece's chord normal.
*/
static void curve_hits(const struct geom_profile *p, int i, int e, vec3 o,
                       vec3 d, double sh, double dl, double lo, double hi,
                       double L, struct isect_list *out)
{
    const struct geom_curve *c = &p->curves[p->curve[i]];
    double ts[6], ss[6];
    int m = curve_roots(c, o, d, ts, ss);
    for (int k = 0; k < m; k++) {
        double t = ts[k], cs = ss[k];
        iris_vec2 ne = { 0, 0 };
        bool exact = polish(c, o, d, L, &t, &cs, &ne);
        if (!(t > lo && t < hi))
            continue;
        /* The piece the parameter falls in, for the orientation and v */
        int j;
        double f;
        iris_vec2 n2 = chord_normal_at(p, i, e, cs, &j, &f);
        if (exact && (ne.u != 0 || ne.v != 0)) {
            if (ne.u * n2.u + ne.v * n2.v < 0) {
                ne.u = -ne.u;
                ne.v = -ne.v;
            }
            n2 = ne;
        }
        vec3 q = v3_madd(o, d, t);
        double rho = sqrt(q.x * q.x + q.z * q.z);
        vec3 n = rho > 0 ? v3(n2.u * q.x / rho, n2.v, n2.u * q.z / rho)
                         : v3(0, n2.v != 0 ? n2.v : 1, 0);
        double u = atan2(q.z, q.x) / (2 * M_PI);
        isect_push(out, (t + sh) / dl, n, u < 0 ? u + 1 : u,
                   (j + f) / p->n_seg);
    }
}

void geom_lathe_hits(const struct geom_profile *p, vec3 ro, vec3 rd,
                     double t0, double t1, struct isect_list *out)
{
    /* Work from the closest approach to the origin along a unit direction
    ** (coefficients stay well scaled for far-away ray origins) */
    double dl = v3_len(rd);
    if (!(dl > 0))
        return;
    vec3 d = v3_scale(rd, 1.0 / dl);
    double sh = -v3_dot(ro, d);
    vec3 o = v3_madd(ro, d, sh);
    double lo = t0 * dl - sh, hi = t1 * dl - sh;

    /*
    ** Every crossing lies within the cylinder of the profile's largest
    ** radius R, where the ray spans heights [ylo, yhi]: a segment wholly
    ** above or below cannot be met. The cylinder is grown by 1e-7 of R
    ** (a crossing's radius is rounded by ~1e-16 of it; near a grazing
    ** ray the span's ends move fast with the radius) and the band padded
    ** by 1e-9 of the scale, so only segments that give no crossing are
    ** skipped.
    */
    double R = fmax(fabs(p->lo.u), fabs(p->hi.u)) * (1 + 1e-7);
    double L = R + p->hi.v - p->lo.v;
    /* Curves bulge past their chords by up to 5e-4 L (profile.c) */
    double bulge = p->n_curves > 0 ? 1e-2 * L : 0;
    R += bulge;
    double ylo = -INFINITY, yhi = INFINITY;
    double hd2 = d.x * d.x + d.z * d.z;
    if (hd2 > 0) {
        double tc = -(o.x * d.x + o.z * d.z) / hd2;
        double cx = o.x + tc * d.x, cz = o.z + tc * d.z;
        double h2 = (R * R - (cx * cx + cz * cz)) / hd2;
        if (h2 >= 0) {
            double h = sqrt(h2);
            double ya = o.y + (tc - h) * d.y, yb = o.y + (tc + h) * d.y;
            double pad = 1e-9 * (R + fabs(ya) + fabs(yb) + fabs(p->lo.v) +
                                 fabs(p->hi.v)) + 1e-300;
            ylo = fmin(ya, yb) - pad;
            yhi = fmax(ya, yb) + pad;
        }
        /* h2 < 0 by rounding alone is possible at a grazing ray: no band */
    }

    for (int i = 0; i < p->n_seg; i++) {
        if (p->curve && p->curve[i] >= 0) {
            /* Pieces i..e-1 stand for one curve: cross the curve */
            const struct geom_curve *c = &p->curves[p->curve[i]];
            int e = c->first + c->n;
            double vlo = c->vlo, vhi = c->vhi, umax = c->umax;
            /* The curve lies in the cylinder of radius umax + bulge
            ** over heights vlo..vhi (padded): a ray whose span of
            ** heights inside that cylinder misses them cannot meet it,
            ** and most rays are dismissed here without the sextic */
            double cyl = umax + bulge, clo = -INFINITY, chi = INFINITY;
            if (hd2 > 0) {
                double tc = -(o.x * d.x + o.z * d.z) / hd2;
                double cx = o.x + tc * d.x, cz = o.z + tc * d.z;
                double h2 = (cyl * cyl - (cx * cx + cz * cz)) / hd2;
                if (h2 < 0) {
                    i = e - 1;
                    continue;
                }
                double h = sqrt(h2);
                double ya = o.y + (tc - h) * d.y, yb = o.y + (tc + h) * d.y;
                clo = fmin(ya, yb) - bulge;
                chi = fmax(ya, yb) + bulge;
            }
            if (vhi + bulge >= clo && vlo - bulge <= chi &&
                vhi + bulge >= ylo && vlo - bulge <= yhi)
                curve_hits(p, i, e, o, d, sh, dl, lo, hi, L, out);
            i = e - 1;
            continue;
        }
        double r0 = p->a[i].u, y0 = p->a[i].v, r1 = p->b[i].u, y1 = p->b[i].v;
        if (fmax(y0, y1) < ylo || fmin(y0, y1) > yhi)
            continue;
        double ts[2];
        int nt = 0;
        if (y0 == y1) {
            /* An annulus in the plane y = y0 */
            if (d.y == 0)
                continue;
            double t = (y0 - o.y) / d.y;
            double x = o.x + t * d.x, z = o.z + t * d.z;
            double rho = sqrt(x * x + z * z);
            if (rho >= fmin(fabs(r0), fabs(r1)) &&
                rho <= fmax(fabs(r0), fabs(r1)))
                ts[nt++] = t;
        } else {
            /* x² + z² = (A0 + k·y)² between y0 and y1 */
            double k = (r1 - r0) / (y1 - y0), A0 = r0 - k * y0;
            double ry = A0 + k * o.y;
            double qa = d.x * d.x + d.z * d.z - k * k * d.y * d.y;
            double qb = 2 * (o.x * d.x + o.z * d.z - ry * k * d.y);
            double qc = o.x * o.x + o.z * o.z - ry * ry;
            if (fabs(qa) <= 1e-14 * (d.x * d.x + d.z * d.z + k * k * d.y * d.y)) {
                if (qb != 0)
                    ts[nt++] = -qc / qb;
            } else {
                double disc = qb * qb - 4 * qa * qc;
                if (disc >= 0) {
                    double q = -0.5 * (qb + copysign(sqrt(disc), qb));
                    ts[nt++] = q / qa;
                    if (q != 0)
                        ts[nt++] = qc / q;
                }
            }
            /* keep the nappe where the signed radius matches the profile */
            for (int j = 0; j < nt; j++) {
                double y = o.y + ts[j] * d.y;
                double r = A0 + k * y;
                double s = (y - y0) / (y1 - y0);
                /* Half-open, so a crossing at a shared end counts once */
                if (s < 0 || s >= 1 || (r0 >= 0 && r1 >= 0 && r < 0))
                    ts[j] = NAN;
            }
        }
        for (int j = 0; j < nt; j++) {
            double t = ts[j];
            if (!(t > lo && t < hi))
                continue;
            vec3 q = v3_madd(o, d, t);
            double rho = sqrt(q.x * q.x + q.z * q.z);
            double s = y0 == y1 ? (r1 != r0 ? (rho - r0) / (r1 - r0) : 0)
                                : (q.y - y0) / (y1 - y0);
            iris_vec2 n2 = seg_normal(p, i, fmax(0, fmin(1, s)));
            vec3 n = rho > 0 ? v3(n2.u * q.x / rho, n2.v, n2.u * q.z / rho)
                             : v3(0, n2.v != 0 ? n2.v : 1, 0);
            double u = atan2(q.z, q.x) / (2 * M_PI);
            isect_push(out, (t + sh) / dl, n, u < 0 ? u + 1 : u,
                       (i + s) / p->n_seg);
        }
    }
}

/*
** Whether lathe or prism curve 'c' (GEOM_CURVE_POLY) surely stays on one
** side of the line through (pu, pv) with normal (ku, kv) for parameters
** s in [-1e-12, 1]: the values of K(s) = (u(s) - pu) ku + (v(s) - pv) kv
** at the Bezier control points are its Bernstein coefficients, and K lies
** between the least and the greatest of them (convex hull). All four
** beyond a margin of 1e-9 of the magnitudes involved, which is far above
** the rounding of the solver's evaluation of K (~1e-15 of them) and above
** K's change over the 1e-12 the parameter range reaches below 0: a curve
** this rejects is one the cubic solver finds no root on, so skipping it
** changes no answer. Most curves of a prism are rejected so. Returns
** that side (+1: K > 0, -1: K < 0), or 0 when not proved.
*/
static int curve_side(const struct geom_curve *c, double pu, double pv,
                      double ku, double kv)
{
    double m = 1e-9 * (c->ext + fabs(pu) + fabs(pv)) * (fabs(ku) + fabs(kv));
    int pos = 0, neg = 0;
    for (int k = 0; k < 4; k++) {
        double b = (c->bz[k].u - pu) * ku + (c->bz[k].v - pv) * kv;
        pos += b > m;
        neg += b < -m;
    }
    return pos == 4 ? 1 : neg == 4 ? -1 : 0;
}

/*
** Whether the +u ray from (u, v) crosses curve 'c' an odd number of times
** (the even-odd rule on the exact curve, as for the chords in
** geom_profile_inside2d; heights half-open as curve_roots' parameters).
*/
static bool curve_parity(const struct geom_curve *c, double u, double v)
{
    const double lo = -1e-12, hi = 1 - 1e-12;
    if (c->kind == GEOM_CURVE_SOR) {
        double h = (v - c->y0) / c->dy;
        if (!(h >= lo && h < hi))
            return false;
        double f = ((c->c[0].u * h + c->c[1].u) * h + c->c[2].u) * h +
                   c->c[3].u;
        return f > 0 && sqrt(f) > u;
    }
    /* The curve away from the line v, or wholly left of u (a margin
    ** beyond rounding, curve_side): no crossing to the right */
    if (curve_side(c, 0, v, 0, 1) != 0 || curve_side(c, u, 0, 1, 0) < 0)
        return false;
    const iris_vec2 *q = c->c;
    double w[4] = { q[3].v - v, q[2].v, q[1].v, q[0].v };
    double U[4] = { q[3].u, q[2].u, q[1].u, q[0].u };
    double r[3];
    int m = proots3(w, lo, hi, r);
    bool parity = false;
    for (int k = 0; k < m; k++)
        parity ^= roots_eval(U, 3, r[k]) > u;
    return parity;
}

/* The even-odd rule on the exact curves and the straight segments. */
static bool exact_inside2d(const struct geom_profile *p, double u, double v)
{
    if (!p->curve || p->n_curves == 0)
        return geom_profile_inside2d(p, u, v);
    /* POV-Ray's Inside() tests the exact curves: so does this */
    bool parity = false;
    for (int i = 0; i < p->n_seg; i++) {
        if (p->curve[i] >= 0) {
            /* its pieces are i .. first + n - 1 (profile_finish) */
            const struct geom_curve *c = &p->curves[p->curve[i]];
            parity ^= curve_parity(c, u, v);
            i = c->first + c->n - 1;
            continue;
        }
        iris_vec2 a = p->a[i], b = p->b[i];
        if ((a.v > v) == (b.v > v))
            continue;
        parity ^= a.u + (v - a.v) * (b.u - a.u) / (b.v - a.v) > u;
    }
    return parity;
}

bool geom_lathe_inside(const struct geom_profile *p, vec3 q)
{
    return exact_inside2d(p, sqrt(q.x * q.x + q.z * q.z), q.y);
}

void geom_lathe_bounds(const struct geom_profile *p, vec3 *lo, vec3 *hi)
{
    double R = fmax(fabs(p->lo.u), fabs(p->hi.u));
    /* The curves bulge past their chords by up to 5e-4 of their size
    ** (profile.c): a margin of 1e-2 of the profile keeps them inside */
    double m = p->n_curves > 0 ? 1e-2 * (R + p->hi.v - p->lo.v) : 0;
    *lo = v3(-R - m, p->lo.v - m, -R - m);
    *hi = v3(R + m, p->hi.v + m, R + m);
}

/* 2-D coordinates (u, v) and height of 'q' for extrusion 'axis'. */
static void split(vec3 q, int axis, double *u, double *v, double *h)
{
    *u = q.x;
    *v = axis == 1 ? q.z : q.y;
    *h = axis == 1 ? q.y : q.z;
}

/* 3-D vector from 2-D (u, v) and height component 'h'. */
static vec3 join(double u, double v, double h, int axis)
{
    return axis == 1 ? v3(u, h, v) : v3(u, v, h);
}

bool geom_extrude_inside(const struct geom_profile *p, int axis, vec3 q)
{
    double u, v, h;
    split(q, axis, &u, &v, &h);
    /* POV-Ray's faces: Prism::Inside takes height1 <= y < height2 (the
    ** bottom inside, the top not), TrueType::Inside 0 <= z <= depth
    ** (both faces inside); they decide coplanar CSG faces and object
    ** patterns on them (tests/render/scenes/151) */
    bool text = axis == 2;
    if (!(h >= p->h1 && (text ? h <= p->h2 : h < p->h2)))
        return false;
    if (p->conic) {
        if (!(h > 0))
            return false;
        return geom_profile_inside2d(p, u / h, v / h);
    }
    return exact_inside2d(p, u, v);
}

void geom_extrude_bounds(const struct geom_profile *p, int axis, vec3 *lo,
                         vec3 *hi)
{
    double ulo = p->lo.u, uhi = p->hi.u, vlo = p->lo.v, vhi = p->hi.v;
    /* Curves bulge past their chords by up to 5e-4 of their size */
    double m = p->n_curves > 0 ? 1e-2 * (uhi - ulo + vhi - vlo) : 0;
    ulo -= m;
    vlo -= m;
    uhi += m;
    vhi += m;
    if (p->conic) {
        /* The outline scales with the height: extremes at h1 or h2 */
        double a[4] = { ulo * p->h1, ulo * p->h2, uhi * p->h1, uhi * p->h2 };
        double b[4] = { vlo * p->h1, vlo * p->h2, vhi * p->h1, vhi * p->h2 };
        ulo = fmin(fmin(a[0], a[1]), fmin(a[2], a[3]));
        uhi = fmax(fmax(a[0], a[1]), fmax(a[2], a[3]));
        vlo = fmin(fmin(b[0], b[1]), fmin(b[2], b[3]));
        vhi = fmax(fmax(b[0], b[1]), fmax(b[2], b[3]));
    }
    *lo = join(ulo, vlo, p->h1, axis);
    *hi = join(uhi, vhi, p->h2, axis);
}

/* The caps at h1 and h2. */
static void cap_hits(const struct geom_profile *p, int axis, vec3 ro,
                     vec3 rd, double t0, double t1, struct isect_list *out)
{
    double ou, ov, oh, du, dv, dh;
    split(ro, axis, &ou, &ov, &oh);
    split(rd, axis, &du, &dv, &dh);
    if (dh == 0)
        return;
    for (int k = 0; k < 2; k++) {
        double h = k ? p->h2 : p->h1;
        double t = (h - oh) / dh;
        if (!(t > t0 && t < t1))
            continue;
        double u = ou + t * du, v = ov + t * dv;
        if (p->conic) {
            if (!(h > 0))
                continue;
            u /= h;
            v /= h;
        }
        if (p->conic ? geom_profile_inside2d(p, u, v)
                     : exact_inside2d(p, u, v))
            isect_push(out, t, join(0, 0, k ? 1 : -1, axis), 0, 0);
    }
}

/*
** The crossings of a linear prism's wall over curve pieces i..e-1 (one
** spline segment) with the ray whose shadow on the profile's plane is
** (ou, ov) + t (du, dv), t in (ta, tb): where (u(s) - ou) dv = (v(s) -
** ov) du, a cubic in the spline parameter s, as POV-Ray solves it
** (prism.cpp). The normal is the curve's, oriented as the piece's chord.
*/
static void wall_hits(const struct geom_profile *p, int i, int e, int axis,
                      double ou, double ov, double du, double dv, double ta,
                      double tb, struct isect_list *out)
{
    double dd = du * du + dv * dv;
    if (!(dd > 0))
        return;
    const struct geom_curve *c = &p->curves[p->curve[i]];
    /* The ray's shadow is the line K = 0 below: a curve wholly to one
    ** side of it has no crossing (curve_side) */
    if (curve_side(c, ou, ov, dv, -du) != 0)
        return;
    const iris_vec2 *q = c->c;
    double U[4] = { q[3].u, q[2].u, q[1].u, q[0].u };
    double W[4] = { q[3].v, q[2].v, q[1].v, q[0].v };
    double K[4], r[3];
    for (int k = 0; k < 4; k++)
        K[k] = U[k] * dv - W[k] * du;
    K[0] -= ou * dv - ov * du;
    int m = proots3(K, -1e-12, 1 - 1e-12, r);
    for (int k = 0; k < m; k++) {
        double cs = r[k];
        double pu = roots_eval(U, 3, cs) - ou, pv = roots_eval(W, 3, cs) - ov;
        double t = (pu * du + pv * dv) / dd;
        if (!(t > ta && t < tb))
            continue;
        int j;
        double f;
        iris_vec2 n2 = chord_normal_at(p, i, e, cs, &j, &f);
        double tu = (3 * q[0].u * cs + 2 * q[1].u) * cs + q[2].u;
        double tv = (3 * q[0].v * cs + 2 * q[1].v) * cs + q[2].v;
        iris_vec2 ne = { tv, -tu };
        if (ne.u != 0 || ne.v != 0) {
            if (ne.u * n2.u + ne.v * n2.v < 0) {
                ne.u = -ne.u;
                ne.v = -ne.v;
            }
            n2 = ne;
        }
        isect_push(out, t, join(n2.u, n2.v, 0, axis), f, 0);
    }
}

/*
** The crossing of the ray whose shadow on the profile's plane is
** (ou, ov) + t (du, dv), t in (ta, tb), with the wall over straight
** segment 'i' of a linear extrusion.
*/
static void flat_wall_hit(const struct geom_profile *p, int i, int axis,
                          double ou, double ov, double du, double dv,
                          double ta, double tb, struct isect_list *out)
{
    iris_vec2 A = p->a[i], B = p->b[i];
    double eu = B.u - A.u, ev = B.v - A.v;
    double den = du * ev - dv * eu;
    if (den == 0)
        return;
    double t = -((ou - A.u) * ev - (ov - A.v) * eu) / den;
    double pu = ou + t * du - A.u, pv = ov + t * dv - A.v;
    double s = (pu * eu + pv * ev) / (eu * eu + ev * ev);
    /* Half-open, so a crossing at a shared corner counts once */
    if (!(t > ta && t < tb) || s < 0 || s >= 1)
        return;
    iris_vec2 n2 = seg_normal(p, i, s);
    isect_push(out, t, join(n2.u, n2.v, 0, axis), s, 0);
}

/*
** The walls of group 'g' of a linear extrusion of straight segments
** (text), run by run (geom.h): a crossing lies on its segment and on the
** ray's shadow between a and b (the span inside the group's box), so a
** run whose box, widened by run_pad, misses the shadow's box has none.
** The segments tested find what testing them all finds.
*/
static void flat_runs(const struct geom_profile *p, int g, int axis,
                      double ou, double ov, double du, double dv, double a,
                      double b, double ta, double tb, struct isect_list *out)
{
    double u0 = ou + a * du, u1 = ou + b * du;
    double v0 = ov + a * dv, v1 = ov + b * dv;
    double pad = p->run_pad;
    double ulo = (u0 < u1 ? u0 : u1) - pad, uhi = (u0 < u1 ? u1 : u0) + pad;
    double vlo = (v0 < v1 ? v0 : v1) - pad, vhi = (v0 < v1 ? v1 : v0) + pad;
    for (int k = p->group_run[g]; k < p->group_run[g + 1]; k++) {
        if (p->run_hi[k].u < ulo || p->run_lo[k].u > uhi ||
            p->run_hi[k].v < vlo || p->run_lo[k].v > vhi)
            continue;
        for (int i = p->run_first[k]; i < p->run_first[k + 1]; i++)
            flat_wall_hit(p, i, axis, ou, ov, du, dv, ta, tb, out);
    }
}

void geom_extrude_hits(const struct geom_profile *p, int axis, vec3 ro,
                       vec3 rd, double t0, double t1, struct isect_list *out)
{
    double ou, ov, oh, du, dv, dh;
    split(ro, axis, &ou, &ov, &oh);
    split(rd, axis, &du, &dv, &dh);

    /* The part of the ray between the two heights */
    double ta = t0, tb = t1;
    if (dh == 0) {
        if (!(oh > p->h1 && oh < p->h2))
            return;
    } else {
        double x = (p->h1 - oh) / dh, y = (p->h2 - oh) / dh;
        ta = fmax(ta, fmin(x, y));
        tb = fmin(tb, fmax(x, y));
        if (!(ta <= tb))
            return;
    }
    if (!p->open)
        cap_hits(p, axis, ro, rd, t0, t1, out);

    for (int g = 0; g < p->n_groups; g++) {
        int f = p->group_first[g], end = f + p->group_count[g];
        if (!p->conic) {
            /* Skip groups whose 2-D box the ray's shadow misses */
            double a = ta, b = tb;
            double m = p->n_curves > 0
                           ? 1e-2 * (p->hi.u - p->lo.u + p->hi.v - p->lo.v)
                           : 0;
            vec3 blo = v3(p->group_lo[g].u - m, p->group_lo[g].v - m, 0);
            vec3 bhi = v3(p->group_hi[g].u + m, p->group_hi[g].v + m, 0);
            if (!geom_clip_box(blo, bhi, v3(ou, ov, 0), v3(du, dv, 0), &a, &b))
                continue;
            if (p->n_runs && p->n_curves == 0 && isfinite(a) && isfinite(b)) {
                flat_runs(p, g, axis, ou, ov, du, dv, a, b, ta, tb, out);
                continue;
            }
        }
        for (int i = f; i < end; i++) {
            if (!p->conic && p->curve && p->curve[i] >= 0) {
                const struct geom_curve *c = &p->curves[p->curve[i]];
                int e = c->first + c->n;
                wall_hits(p, i, e, axis, ou, ov, du, dv, ta, tb, out);
                i = e - 1;
                continue;
            }
            if (!p->conic) {
                flat_wall_hit(p, i, axis, ou, ov, du, dv, ta, tb, out);
                continue;
            }
            iris_vec2 A = p->a[i], B = p->b[i];
            double eu = B.u - A.u, ev = B.v - A.v;
            /* The plane through the apex and the segment at h = 1 */
            vec3 a3 = join(A.u, A.v, 1, axis), b3 = join(B.u, B.v, 1, axis);
            vec3 N = v3_cross(a3, b3);
            double den = v3_dot(N, rd);
            if (den == 0)
                continue;
            double t = -v3_dot(N, ro) / den;
            double h = oh + t * dh;
            if (!(h > 0))
                continue;
            double pu = (ou + t * du) / h - A.u, pv = (ov + t * dv) / h - A.v;
            double s = (pu * eu + pv * ev) / (eu * eu + ev * ev);
            /* Half-open, so a crossing at a shared corner counts once */
            if (!(t > ta && t < tb) || s < 0 || s >= 1)
                continue;
            iris_vec2 n2 = seg_normal(p, i, s);
            vec3 n = join(n2.u, n2.v, 0, axis);
            /* Smooth tangent direction is lost on the cone: use the
            ** plane, turned to the outward side */
            n = v3_dot(N, n) < 0 ? v3_neg(N) : N;
            isect_push(out, t, n, s, 0);
        }
    }
}
