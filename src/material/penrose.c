/* SPDX-License-Identifier: MIT */
/*
** penrose.c: the Penrose tilings 25..27 of the 'tiling' pattern, computed
** as POV-Ray 3.7's TilingPattern computes them (pattern.cpp).
**
** Each is self-similar: a tile of one generation is cut into smaller
** tiles of the next, phi times smaller. The point is folded by the
** five-fold symmetry into one wedge at the origin, scaled down to the
** generation whose first tile covers it, and then followed down through
** the subdivisions, each step picking the sub-tile the point is in and
** mapping it back onto its prototype, until the last generation says
** which tile it is and how far from its edge. The grout width factors
** (4.46, 5.55) are POV-Ray's, set by eye.
*/
#include "config.h"

#include <math.h>
#include <stdbool.h>

#include "material/penrose.h"

#define PHI 1.6180339887498948482
#define INV_PHI 0.6180339887498948482
#define SQR_PHI 2.6180339887498948482
#define INV_SQR_PHI 0.3819660112501051518
#define SIN18 0.3090169943749474241
#define SIN36 0.5877852522924731292
#define SIN54 0.8090169943749474241
#define SIN72 0.9510565162951535721
#define COS18 SIN72
#define COS36 SIN54
#define COS54 SIN36
#define COS72 SIN18
#define TAN18 0.3249196962329063262
#define TAN36 0.7265425280053608859
#define TAN54 1.3763819204711735382
#define TAN72 3.0776835371752534026
#define PENROSE_EPS 1e-6

static double max3(double a, double b, double c)
{
    return fmax(fmax(a, b), c);
}

/* Folds (x, z) at distance r from the origin into the wedge within 36
** degrees of +x, z >= 0, by the mirror in x and the turns by 72 and 144
** degrees. */
static void pentagon_fold(double *px, double *pz, double r)
{
    double x = *px, z = fabs(*pz);
    if (x < r * COS36) {
        double s = SIN72, c = COS72;
        if (x < -r * COS72) {       /* beyond 108 degrees: turn by 144 */
            s = SIN36;
            c = -COS36;
        }
        double rx = x * c + z * s;
        double rz = z * c - x * s;
        x = rx;
        z = fabs(rz);
    }
    *px = x;
    *pz = z;
}

/* P2 and P3 follow a half kite and a half dart through the deflations:
** kites (wide rhombs) take [0, 0.5), darts (narrow rhombs) (0.5, 1]. */

static double half_dart(double x, double z, int depth, bool rhombs);

static double half_kite(double x, double z, int depth, bool rhombs)
{
    z = fabs(z);
    if (depth > 0) {
        if (z < (x - INV_PHI) * -TAN36)     /* tan 144 */
            return half_dart(x * PHI, z * PHI, depth - 1, rhombs);
        x -= COS36;
        z -= SIN36;
        /* turn by 108 degrees: cos 108 = -cos 72, sin 108 = sin 72 */
        double rx = -x * COS72 - z * SIN72;
        double rz = -z * COS72 + x * SIN72;
        return half_kite(rx * PHI, rz * PHI, depth - 1, rhombs);
    }
    if (rhombs) {
        if (z < (x - INV_PHI) * TAN72) {
            double d1 = fabs(SIN72 * (x - INV_PHI) - COS72 * z) * 5.55;
            double d2 = fabs(SIN72 * (x - 1.0) + COS72 * z) * 5.55;
            return max3(1.0 - d1 / 2.0, 1.0 - d2 / 2.0, 0.5 + PENROSE_EPS);
        }
        double d1 = z * 5.55;
        double d2 = fabs(SIN72 * (x - INV_PHI) - COS72 * z) * 5.55;
        return fmin(max3(0.5 - d1 / 2.0, 0.5 - d2 / 2.0, 0.0),
                    0.5 - PENROSE_EPS);
    }
    double d1 = fabs(SIN36 * x - COS36 * z) * 4.46;
    double d2 = fabs(SIN72 * (x - 1.0) + COS72 * z) * 4.46;
    return fmin(max3(0.5 - d1 / 2.0, 0.5 - d2 / 2.0, 0.0), 0.5 - PENROSE_EPS);
}

static double half_dart(double x, double z, int depth, bool rhombs)
{
    z = fabs(z);
    if (depth > 0) {
        if (z < (x - INV_PHI) * -TAN72) {   /* tan 108 */
            double rx = x * COS36 + z * SIN36;
            double rz = z * COS36 - x * SIN36;
            return half_kite(rx * PHI, rz * PHI, depth - 1, rhombs);
        }
        x -= 1.0;
        /* turn by -144 degrees */
        double rx = -x * COS36 + z * SIN36;
        double rz = -z * COS36 - x * SIN36;
        return half_dart(rx * PHI, rz * PHI, depth - 1, rhombs);
    }
    if (rhombs) {
        double d1 = fabs(SIN36 * x - COS36 * z) * 5.55;
        double d2 = fabs(SIN36 * (x - 1.0) + COS36 * z) * 5.55;
        return fmin(max3(0.5 - d1 / 2.0, 0.5 - d2 / 2.0, 0.0),
                    0.5 - PENROSE_EPS);
    }
    double d1 = z * 4.46;
    double d2 = fabs(SIN36 * (x - 1.0) + COS36 * z) * 4.46;
    return max3(1.0 - d1 / 2.0, 1.0 - d2 / 2.0, 0.5 + PENROSE_EPS);
}

static double penrose_kd(double x, double z, bool rhombs)
{
    double r = sqrt(x * x + z * z);
    if (r <= 1e-10)
        return 1.0;
    pentagon_fold(&x, &z, r);
    if (rhombs) {
        x *= INV_PHI;
        z *= INV_PHI;
    }
    /* the generation whose first tiles reach this far (cos 18 = sin 72) */
    double dist = fabs(SIN72 * x + COS72 * z) / SIN72;
    int depth = dist > 1.0 ? (int)ceil(log(dist) / log(SQR_PHI)) : 0;
    double k = pow(INV_SQR_PHI, depth);
    x *= k;
    z *= k;
    if (depth % 2) {
        double rx = x * COS36 + z * SIN36;
        double rz = z * COS36 - x * SIN36;
        x = rx;
        z = fabs(rz);
    }
    return half_kite(x, z, 2 * depth, rhombs);
}

/* P1: pentagons (three kinds, by how they sit among the others), stars,
** boats and diamonds, each a sixth of [0, 1]. */
static double p1_pentagon2(double x, double z, int depth, bool in_quad);
static double p1_pentagon3(double x, double z, int depth, bool in_wedge);
static double p1_star(double x, double z, int depth);
static double p1_boat(double x, double z, int depth, bool in_wedge);
static double p1_diamond(double x, double z, int depth, bool side_a);

/* A pentagon's edge distance once folded into its wedge. */
static double p1_pentagon_dist(double x)
{
    return fabs(x - 0.5 / TAN36) * 5.55 * INV_PHI;
}

/* The last generation's value: 'd' into band [lo, lo + 1/6]. */
static double p1_band(double d, double lo)
{
    return fmin(fmax(lo + (1.0 - d) / 6.0, lo == 0.0 ? 0.0 : lo + PENROSE_EPS),
                lo + 1.0 / 6.0 - PENROSE_EPS);
}

static double p1_pentagon1(double x, double z, int depth)
{
    z = fabs(z);
    pentagon_fold(&x, &z, sqrt(x * x + z * z));
    if (depth <= 0)
        return p1_band(p1_pentagon_dist(x), 0.0);
    if (z < (x - 0.5 / TAN36) * TAN54 + 0.5)
        return p1_pentagon2((x - 0.5 / TAN36 - INV_PHI * 0.5 * COS72 / SIN36) *
                            PHI, z * PHI, depth - 1, false);
    double rx = x * COS36 + z * SIN36;
    double rz = z * COS36 - x * SIN36;
    return p1_star(rx * PHI, rz * PHI, depth - 1);
}

static double p1_pentagon2(double x, double z, int depth, bool in_quad)
{
    z = fabs(z);
    if (depth <= 0) {
        pentagon_fold(&x, &z, sqrt(x * x + z * z));
        return p1_band(p1_pentagon_dist(x), 1.0 / 6.0);
    }
    const double c = INV_SQR_PHI * 0.5 / SIN36;
    if (in_quad) {
        if (z < (x - c) * TAN54)
            return p1_pentagon1((x - 0.5 / SIN36) * PHI, z * PHI, depth - 1);
        if (z < (x - c) * -TAN18)           /* tan 162 */
            return p1_diamond(-x * PHI, z * PHI, depth - 1, true);
        /* turn by 108 degrees */
        double rx = -x * COS72 - z * SIN72 + INV_PHI * 0.5 / SIN36;
        double rz = -z * COS72 + x * SIN72;
        return p1_pentagon2(rx * PHI, rz * PHI, depth - 1, true);
    }
    if (z < (x + 0.5 / SIN36) * TAN18)
        return p1_diamond((x + 0.5 / SIN36 - c) * PHI, z * PHI, depth - 1,
                          false);
    double rx = -(x * COS36 + z * SIN36) - COS72 * 0.5 / SIN36;
    double rz = (z * COS36 - x * SIN36) - SIN72 * 0.5 / SIN36;
    return p1_pentagon3(rx * PHI, rz * PHI, depth - 1, false);
}

static double p1_pentagon3(double x, double z, int depth, bool in_wedge)
{
    z = fabs(z);
    if (depth <= 0) {
        pentagon_fold(&x, &z, sqrt(x * x + z * z));
        return p1_band(p1_pentagon_dist(x), 2.0 / 6.0);
    }
    const double c = INV_SQR_PHI * 0.5 * COS72 / SIN36;
    if (in_wedge && x > c)
        return p1_pentagon2(-(x - c - INV_PHI * 0.5 / TAN36) * PHI, z * PHI,
                            depth - 1, true);
    if (!in_wedge && x < -0.5 * COS72 / SIN36) {    /* cos 108 */
        /* turn by 144 degrees */
        double rx = -x * COS36 + z * SIN36 - 0.5 / SIN36;
        double rz = -z * COS36 - x * SIN36;
        return p1_pentagon2(rx * PHI, rz * PHI, depth - 1, false);
    }
    if (!in_wedge && z > (x - INV_SQR_PHI * 0.5 / SIN36) * -TAN54) {
        double rx = -(x * COS36 - z * SIN36) - COS72 * 0.5 / SIN36;
        double rz = (z * COS36 + x * SIN36) - SIN72 * 0.5 / SIN36;
        return p1_pentagon3(rx * PHI, rz * PHI, depth - 1, false);
    }
    return p1_boat(x * PHI, z * PHI, depth - 1, in_wedge);
}

/* The distance to a star's (or boat's) slanted edge, the line through
** (phi / (2 sin 36), 0) at 162 degrees. */
static double p1_spike_dist(double x, double z)
{
    return fabs(SIN18 * (x - PHI * 0.5 / SIN36) + COS18 * z) * 5.55 * INV_PHI;
}

static double p1_star(double x, double z, int depth)
{
    z = fabs(z);
    if (depth <= 0)
        return p1_band(p1_spike_dist(x, z), 3.0 / 6.0);
    if (x < INV_PHI * 0.5 / TAN36)
        return p1_pentagon1(x * PHI, z * PHI, depth - 1);
    return p1_pentagon3(-(x - INV_PHI / TAN36) * PHI, z * PHI, depth - 1,
                        true);
}

static double p1_boat(double x, double z, int depth, bool in_wedge)
{
    z = fabs(z);
    if (depth <= 0) {
        double d1 = fabs(x - INV_PHI * 0.5 * COS72 / SIN36) * 5.55 * INV_PHI;
        x = -x;
        pentagon_fold(&x, &z, sqrt(x * x + z * z));
        double d2 = p1_spike_dist(x, z);
        return fmin(max3(5.0 / 6.0 - d1 / 6.0, 5.0 / 6.0 - d2 / 6.0,
                         4.0 / 6.0 + PENROSE_EPS),
                    5.0 / 6.0 - PENROSE_EPS);
    }
    if (in_wedge && x > -PHI * 0.5 * COS72 / SIN36)  /* cos 108 */
        return p1_pentagon1(-x * PHI, z * PHI, depth - 1);
    double rx = x, rz = z;
    if (!in_wedge) {                /* turn by 72 degrees */
        rx = x * COS72 - z * SIN72;
        rz = z * COS72 + x * SIN72;
    }
    rx += 0.5 / SIN36;
    return p1_pentagon3(rx * PHI, rz * PHI, depth - 1, true);
}

static double p1_diamond(double x, double z, int depth, bool side_a)
{
    z = fabs(z);
    if (depth <= 0) {
        double d = fabs(SIN18 * (x + INV_PHI * 0.5 / SIN36) - COS18 * z) *
                   5.55 * INV_PHI;
        return p1_band(d, 5.0 / 6.0);
    }
    if (side_a)
        return p1_pentagon1(x * PHI, z * PHI, depth - 1);
    return p1_pentagon3(x * PHI, z * PHI, depth - 1, true);
}

double penrose_p1(double x, double z)
{
    double r = sqrt(x * x + z * z);
    if (r <= 1e-10)
        return 1.0;
    pentagon_fold(&x, &z, r);
    /* four subdivisions bring a pentagon back onto itself: scale by phi^4 */
    double dist = x * 2.0 * TAN36;
    int depth = dist > 1.0 ?
        (int)ceil(log(dist) / log(SQR_PHI * SQR_PHI)) : 0;
    double k = pow(INV_SQR_PHI * INV_SQR_PHI, depth);
    return p1_pentagon1(x * k, z * k, 4 * depth);
}

double penrose_p2(double x, double z)
{
    return penrose_kd(x, z, false);
}

double penrose_p3(double x, double z)
{
    return penrose_kd(x, z, true);
}
