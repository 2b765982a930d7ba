/* SPDX-License-Identifier: MIT */
/*
** listpat.c: the square, triangular and cubic list patterns of POV-Ray
** 3.7 (square_pattern, triangular_pattern, cubic_pattern in its
** pattern.cpp), computed as POV-Ray computes them so that the same entry
** lands on the same cell. square and triangular ignore y: they pave the
** x-z plane. The value is an entry index; the caller picks the entry.
*/
#include "config.h"

#include <math.h>

#include "material/listpat.h"

#define R3 1.7320508075688772935   /* sqrt(3): two triangle heights */
#define R3_2 0.8660254037844386468 /* sqrt(3)/2: one triangle's height */

/* 1 if floor(v) is odd (also for negative v: floor(-0.5) = -1 is odd). */
static int odd_cell(double v)
{
    double h = floor(v) * 0.5;
    return h != floor(h);
}

double pattern_square(vec3 p)
{
    /* (even x, even z) 0, (even x, odd z) 1, (odd, odd) 2, (odd, even) 3:
    ** going round a lattice vertex meets all four */
    int ox = odd_cell(p.x), oz = odd_cell(p.z);
    if (ox)
        return oz ? 2.0 : 3.0;
    return oz ? 1.0 : 0.0;
}

double pattern_triangular(vec3 p)
{
    /* The lattice repeats every 3 along x and every sqrt(3) along z. */
    double x = p.x - 3.0 * floor(p.x / 3.0);
    double z = p.z - R3 * floor(p.z / R3);
    /* Which unit column of the period (0, 1, 2), and the x within it. */
    int col = (int)floor(x);
    x -= col;
    /* The upper half of the period mirrors the lower one. */
    int upper = z >= R3_2;
    if (upper)
        z = R3 - z;
    /* In the column's lower half: the triangle standing on the bottom
    ** edge (0) lies under both of its sides, whose slopes are +-sqrt(3)
    ** from the column's two lower corners; right of it is the piece of
    ** a downward triangle on the right (1), left of it the one on the
    ** left (3). A point on a column edge belongs to the right piece. */
    double t;
    double right = 1.0 - x;
    if (x != 0.0 && right != 0.0) {
        int under_left = z / x < R3;   /* below the side from (0, 0) */
        int under_right = z / right < R3; /* below the side from (1, 0) */
        if (under_left && under_right)
            t = 0.0;
        else if (under_right)
            t = 1.0;
        else if (under_left)
            t = 3.0;
        else
            t = 1.0; /* only exactly on the apex: a boundary */
    } else {
        t = 1.0;
    }
    /* Moving one column along x turns the six entries around a vertex
    ** by two: odd entries forward, even ones backward. */
    if ((int)t & 1)
        t = fmod(t + 2.0 * col, 6.0);
    else
        t = fmod(6.0 + t - 2.0 * col, 6.0);
    return upper ? 5.0 - t : t;
}

double pattern_cubic(vec3 p)
{
    /* The axis the point is farthest along, ties to the earlier one in
    ** the order +x, +y, +z, -x, -y, -z (POV-Ray tests them so). */
    double ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);
    if (p.x >= 0 && p.x >= ay && p.x >= az)
        return 0.0;
    if (p.y >= 0 && p.y >= ax && p.y >= az)
        return 1.0;
    if (p.z >= 0 && p.z >= ax && p.z >= ay)
        return 2.0;
    if (p.x < 0 && -p.x >= ay && -p.x >= az)
        return 3.0;
    if (p.y < 0 && -p.y >= ax && -p.y >= az)
        return 4.0;
    return 5.0;
}
