/* SPDX-License-Identifier: MIT */
/*
** tiling.c: the 'tiling N' pattern, computed as POV-Ray 3.7's
** TilingPattern computes it (J. Grimbert's tilings in pattern.cpp).
**
** Each tiling folds the x-z plane into one fundamental cell by its
** symmetries (period, mirrors, rotations), counts in 'band' which kind
** of tile the point fell in, and measures how far from the tile's centre
** it is: 0 at the centre, 1 on the edge. Several tile kinds share [0, 1]
** in equal bands so that a colour_map can give every kind its own
** colours and its own grout at the top of its band.
**
** Types 1..24 are here, the Penrose tilings 25..27 in penrose.c.
*/
#include "config.h"

#include <math.h>
#include <stdbool.h>

#include "material/penrose.h"
#include "material/tiling.h"

#define R3 1.7320508075688772935   /* sqrt(3): height of two triangles */
#define R3_2 0.8660254037844386468 /* sqrt(3)/2: one unit triangle's height */
#define R2 1.4142135623730950488
#define R2_2 0.7071067811865475244

/* v reduced to [0, period). */
static double wrap(double v, double period)
{
    return v - period * floor(v / period);
}

static double clamp01(double v)
{
    return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

/* 1: unit squares; the distance to the nearest edge, in the max norm.
** POV-Ray folds |x| (not x), so the cells either side of 0 mirror. */
static double square(double x, double z)
{
    x = fabs(x);
    z = fabs(z);
    x = 2.0 * fabs(x - floor(x) - 0.5);
    z = 2.0 * fabs(z - floor(z) - 0.5);
    return fmax(x, z);
}

/* 2: hexagons of unit side; the cell, 3 x sqrt(3), holds two. */
static double hexagon(double x, double z)
{
    x = wrap(x + 0.5, 3.0);
    z = wrap(z, R3);
    if (z > R3_2)
        z = R3 - z;                 /* mirror about the cell's middle row */
    if (x > 1.5) {                  /* the right half is the left, shifted */
        x -= 1.5;
        z = R3_2 - z;
    }
    if (R3 * x + z < R3_2) {        /* bottom-left corner: the next hexagon */
        x = 0.5 - x;
        z = R3_2 - z;
    }
    if (x > 1.0)
        x = 2.0 - x;
    /* distances to the two edges that bound this part of the hexagon */
    double to_flat = 1.0 - z / R3_2;
    double to_slant = 1.0 - (R3 * x + z - R3_2) / R3;
    return clamp01(fmax(to_flat, to_slant));
}

/* 3: equilateral triangles of unit side, pointing up (band 0) and down
** (band 1). */
static double triangle(double x, double z)
{
    int band = 0;
    x -= floor(x);
    z = wrap(z, R3);
    if (z > R3_2) {
        z = R3 - z;
        band = 1 - band;
    }
    if (x > 0.5)
        x = 1.0 - x;
    /* above the slope z = sqrt3 x: the neighbouring, flipped triangle
    ** (POV-Ray does not flip the band on the line x == 0 itself) */
    if (x != 0.0 && z / x > R3) {
        z = R3_2 - z;
        x = 0.5 - x;
        band = 1 - band;
    } else if (x == 0.0) {
        z = R3_2 - z;
        x = 0.5;
    }
    double to_base = 1.0 - z * 2.0 * R3;
    double to_side = 1.0 - (R3 * x - z) * R3;
    return band / 2.0 + 0.5 * fmax(to_base, to_side);
}

/* The lozenge (60-degree rhombus) distance once (x, z) is folded into the
** cell [0, 1) x [0, sqrt3/2); shared by lozenge and rhombus. */
static double lozenge_folded(double x, double z)
{
    if (2.0 * z > R3_2) {
        z = R3_2 - z;
        x = 1.5 - x;
    }
    if (x > 0.75)
        x -= 1.0;
    if (x != 0.0 && z / x > R3) {
        z = R3_2 - z;
        x = 0.5 - x;
    }
    double to_long = 1.0 - z * 4.0 * R3 / 3.0;
    double to_short = 1.0 - fabs(R3 * x - z) * R3 * 2.0 / 3.0;
    return fmax(to_long, to_short);
}

/* 4: lozenges all lying the same way. */
static double lozenge(double x, double z)
{
    x -= floor(x);
    z = wrap(z, R3);
    if (z > R3_2) {
        z -= R3_2;
        x += 0.5;
    }
    return lozenge_folded(x, z);
}

/* 5: lozenges in three orientations (the "tumbling blocks" cube
** illusion); band 0, 1, 2 per orientation. */
static double rhombus(double x, double z)
{
    int band = 0;
    x = wrap(x + 0.5, 3.0);
    z = wrap(z, R3);
    if (z > R3_2) {
        z = R3 - z;
        band = 2 - band;
    }
    if (x > 1.5) {
        x -= 1.5;
        z = R3_2 - z;
        band = 2 - band;
    }
    if (x < 0.5) {
        x = 1.0 - x;
        band = 2 - band;
    }
    x -= 0.5;
    /* steeper than 60 degrees: the upright lozenge; turn it by -60
    ** degrees onto the lying one */
    if (x == 0.0 || z / x > R3) {
        double rx = x / 2.0 + z * R3_2;
        double rz = z / 2.0 - x * R3_2;
        x = rx;
        z = rz;
        band = 1;
    }
    return clamp01(lozenge_folded(x, z) / 3.0 + band / 3.0);
}

/* 2x1 rectangles in two orientations (band 0: along x, band 1: along z)
** laid out in a 4x4 cell. For each unit square of the cell, 'off' gives
** the offset to its rectangle's reference corner and the orientation. */
static double dominoes(const signed char off[16][3], double x, double z)
{
    x = wrap(x, 4.0);
    z = wrap(z, 4.0);
    int cell = (int)x + 4 * (int)z;
    if (cell < 0 || cell > 15)
        cell = 0; /* only reached through rounding at the cell's edge */
    x -= off[cell][0];
    z -= off[cell][1];
    int along_z = off[cell][2];
    double dx, dz;
    if (along_z) {
        dx = 2.0 * fabs(x - 0.5);
        dz = 2.0 * (fmax(fabs(z), 0.5) - 0.5);
    } else {
        dx = 2.0 * (fmax(fabs(x), 0.5) - 0.5);
        dz = 2.0 * fabs(z - 0.5);
    }
    return fabs((fmax(dx, dz) + along_z) / 2.0);
}

/* 6: rectangles in a herringbone of single tiles. */
static double rectangle(double x, double z)
{
    static const signed char off[16][3] = {
        /* dx, dz, lying along z (1) or x (0) */
        {0, 1, 1}, {2, 0, 0}, {2, 0, 0}, {3, 0, 1},
        {0, 1, 1}, {1, 2, 1}, {3, 1, 0}, {3, 1, 0},
        {0, 2, 0}, {1, 2, 1}, {2, 3, 1}, {4, 2, 0},
        {1, 3, 0}, {1, 3, 0}, {2, 3, 1}, {3, 4, 1},
    };
    return dominoes(off, x, z);
}

/* 18: rectangles in pairs, each pair a 2x2 square, the pairs alternating
** in orientation (basket weave). */
static double rectangle_pair(double x, double z)
{
    static const signed char off[16][3] = {
        {0, 1, 1}, {1, 1, 1}, {3, 0, 0}, {3, 0, 0},
        {0, 1, 1}, {1, 1, 1}, {3, 1, 0}, {3, 1, 0},
        {1, 2, 0}, {1, 2, 0}, {2, 3, 1}, {3, 3, 1},
        {1, 3, 0}, {1, 3, 0}, {2, 3, 1}, {3, 3, 1},
    };
    return dominoes(off, x, z);
}

/* 15: 2x2 squares (band [0.5, 1]) with unit squares (band [0, 0.5])
** between them in a 5x5 cell; per unit square of the cell, the offset to
** its square's reference corner and whether it is a big one. */
static double square_double(double x, double z)
{
    static const signed char off[25][3] = {
        {0, 0, 0}, {2, 0, 1}, {2, 0, 1}, {4, 1, 1}, {4, 1, 1},
        {1, 2, 1}, {1, 2, 1}, {2, 1, 0}, {4, 1, 1}, {4, 1, 1},
        {1, 2, 1}, {1, 2, 1}, {3, 3, 1}, {3, 3, 1}, {4, 2, 0},
        {0, 4, 1}, {1, 3, 0}, {3, 3, 1}, {3, 3, 1}, {5, 4, 1},
        {0, 4, 1}, {2, 5, 1}, {2, 5, 1}, {3, 4, 0}, {5, 4, 1},
    };
    x = wrap(x, 5.0);
    z = wrap(z, 5.0);
    int cell = (int)x + 5 * (int)z;
    /* out of range only through rounding at the cell's edge; POV-Ray
    ** then takes the point as it is, in a big square */
    int big = 1;
    if (cell >= 0 && cell < 25) {
        x -= off[cell][0];
        z -= off[cell][1];
        big = off[cell][2];
    }
    double dx, dz;
    if (big) {
        dx = 2.0 * (fmax(fabs(x), 0.5) - 0.5);
        dz = 2.0 * (fmax(fabs(z), 0.5) - 0.5);
    } else {
        dx = 2.0 * fabs(x - 0.5);
        dz = 2.0 * fabs(z - 0.5);
    }
    /* POV-Ray lifts the big squares just above 0.5, so that the small
    ** squares' edge value stays theirs */
    return fabs(fmax(dx, dz) / 2.0 + (big ? 0.50000001 : 0.0));
}

/* 7: octagons (band 1) and the small squares between them (band 0), the
** octagon's side 1, the cell 1 + sqrt2 square. */
static double octa_square(double x, double z)
{
    const double cell = R2 + 1.0;
    x = fabs(wrap(x, cell) - (R2_2 + 0.5));
    z = fabs(wrap(z, cell) - (R2_2 + 0.5));
    if (z > x) {
        double t = x;
        x = z;
        z = t;
    }
    if (x + z < R2_2)
        return (x + z) / R2;        /* the square */
    double to_side = 1.0 - z;
    double to_diag = (R2 + R2_2 - (x + z)) / R2;
    /* POV-Ray keeps the octagon just above 0.5 so that it never shares a
    ** value with the square's edge */
    return fmax(0.500000000001, fmax(to_side, to_diag));
}

/* 8: rows of unit squares (band 2) between rows of triangles (bands 0,
** 1: up and down). */
static double square_triangle(double x, double z)
{
    int band = 0;
    x -= floor(x);
    z = wrap(z, 2.0 + R3);
    if (z > R3_2 + 1.0) {           /* the upper half is shifted by 1/2 */
        z -= R3_2 + 1.0;
        x += x > 0.5 ? -0.5 : 0.5;
    }
    if (x > 0.5)
        x = 1.0 - x;
    z -= 1.0;
    if (z > 0.0) {
        if (x == 0.0 || z / x > R3) {
            z = R3_2 - z;
            x = x == 0.0 ? 0.5 : 0.5 - x;
            band = 1 - band;
        }
        double to_base = 1.0 - 2.0 * z * R3;
        double to_side = 1.0 - (R3 * x - z) * R3;
        return (band + fmax(to_base, to_side)) / 3.0;
    }
    if (z < -0.5)
        z = -1.0 - z;
    if (x > 0.5)
        x = 1.0 - x;
    double dx = fmin(2.0 + 2.0 * R3 * fabs(x), 3.0);
    double dz = fmin(2.0 + 2.0 * R3 * fabs(z), 3.0);
    return (5.0000001 - fmin(dx, dz)) / 3.0;
}

/* 9: hexagons (band 2) with triangles (bands 0, 1) in the gaps: the
** trihexagonal tiling. */
static double hexa_triangle(double x, double z)
{
    int band = 0;
    x = wrap(x + 0.5, 2.0);
    z = wrap(z, 2.0 * R3);
    if (z > R3) {
        z -= R3;
        x += x < 1.0 ? 1.0 : -1.0;
    }
    if (z > R3_2) {
        z = R3 - z;
        band = 1 - band;
    }
    if (x > 1.0)
        x = 2.0 - x;
    if (R3 * x + z < R3_2) {
        double to_base = 1.0 - z * 2.0 * R3;
        double to_side = 1.0 + (R3 * x + z - R3_2) * R3;
        return (band + fmax(to_base, to_side)) / 3.0;
    }
    double d1 = 2.0 + 2.0 * z * R3;
    double d2 = 2.0 + 2.0 * (R3 * x + z - R3_2) * R3_2;
    return fmax(5.0 - fmin(d1, d2), 2.0000001) / 3.0;
}

/* 10: unit squares, every other row shifted by half a square (bricks). */
static double square_offset(double x, double z)
{
    z = wrap(z, 2.0);
    if (z > 1.0) {
        x += 0.5;
        z -= 1.0;
    }
    x -= floor(x);
    return fmax(2.0 * fabs(x - 0.5), 2.0 * fabs(z - 0.5));
}

/* 11 and 12: a unit square (band 0) ringed by four 2x1 rectangles
** turning around it (bands 1 and 2 by orientation), folded into the
** 3x3 cell [0, 3)^2. For each unit square of the cell, the offset to its
** tile's reference corner and the tile's band. */
static double pinwheel_cell(double x, double z)
{
    static const signed char off[9][3] = {
        {0, 1, 2}, {2, 0, 1}, {2, 0, 1},
        {0, 1, 2}, {1, 1, 0}, {2, 2, 2},
        {1, 2, 1}, {1, 2, 1}, {2, 2, 2},
    };
    int cell = (int)x + 3 * (int)z;
    int band = 2;
    if (cell >= 0 && cell < 9) {    /* else only at the cell's edge */
        x -= off[cell][0];
        z -= off[cell][1];
        band = off[cell][2];
    }
    double dx, dz;
    if (band == 1) {                /* lying along x */
        dx = 2.0 * (fmax(fabs(x), 0.5) - 0.5);
        dz = 2.0 * fabs(z - 0.5);
    } else if (band == 2) {         /* lying along z */
        dx = 2.0 * fabs(x - 0.5);
        dz = 2.0 * (fmax(fabs(z), 0.5) - 0.5);
    } else {
        dx = 2.0 * fabs(x - 0.5);
        dz = 2.0 * fabs(z - 0.5);
    }
    return (fmax(dx, dz) + band) / 3.0;
}

/* 11: the pinwheel repeated as it is. */
static double square_rectangle(double x, double z)
{
    return pinwheel_cell(wrap(x, 3.0), wrap(z, 3.0));
}

/* 12: the pinwheel mirrored in x and z every 3 units, so that it turns
** both ways. */
static double rectangle_square(double x, double z)
{
    return pinwheel_cell(fabs(wrap(x, 6.0) - 3.0), fabs(wrap(z, 6.0) - 3.0));
}

/* 13 and 14 fold the plane (scaled by sqrt2) into the quarter [0, 2]^2 of
** a 4x4 cell: a square at the corner (0, 0) and, around it, squares
** turned 45 degrees. The distances to the edges of each part; 'band_x'
** and 'band_z' say which band the tiles reached along x and along z
** take. */
static double square_internal_cell(double x, double z, double square_lo,
                                   double band_x, double band_z,
                                   double scale)
{
    int cell = (int)x + 2 * (int)z;
    double a = 0.0;
    switch (cell) {
    case 0:                         /* the upright square */
        return (square_lo + fmax(2.0 * fmax(x - 0.5, 0.0),
                                 2.0 * fmax(z - 0.5, 0.0))) / scale;
    case 1:
        a = fabs(1.5 - x) * 2.0;
        if (z > 0.5)
            a = fmax(a, 1.0 - R2 * fabs(x - z));
        return (a + band_x) / scale;
    case 2:
        a = fabs(1.5 - z) * 2.0;
        if (x > 0.5)
            a = fmax(a, 1.0 - R2 * fabs(x - z));
        return (a + band_z) / scale;
    case 3:
        if (x > z)
            return (fmax(fabs(1.5 - x) * 2.0, 1.0 - R2 * fabs(z - x)) +
                    band_x) / scale;
        return (fmax(fabs(1.5 - z) * 2.0, 1.0 - R2 * fabs(x - z)) + band_z) /
               scale;
    default:                        /* x or z exactly 2: POV-Ray gives 0 */
        return 0.0;
    }
}

/* 13: three bands: the upright squares (0), the turned ones met along z
** (1) and along x (2). */
static double square_internal(double x, double z)
{
    x = fabs(wrap(x * R2, 4.0) - 2.0);
    z = fabs(wrap(z * R2, 4.0) - 2.0);
    return square_internal_cell(x, z, 0.0, 2.0, 1.0, 3.0);
}

/* 14: the same with five bands: the turned squares also by which side of
** the cell's middle they lie (x: 0 or 1, z: 2 or 3), the upright square
** last (4). */
static double square_internal_5(double x, double z)
{
    x = wrap(x * R2, 4.0) - 2.0;
    z = wrap(z * R2, 4.0) - 2.0;
    double band_x = x < 0.0 ? 1.0 : 0.0;
    double band_z = z < 0.0 ? 2.0 : 3.0;
    return square_internal_cell(fabs(x), fabs(z), 4.000001, band_x, band_z,
                                5.0);
}

/* 16 and 17: hexagons ringed by squares, with triangles between the
** squares (the rhombitrihexagonal tiling). The plane folds into the cell
** [0, 1 + sqrt3/2]^2 whose top right corner is a hexagon's centre; the
** lower left part is turned by 60 degrees onto the square below it.
** 'mir_x', 'mir_z' and 'turned' record the folds, for type 17's colours. */
enum hst_part { HST_NONE, HST_HEXAGON, HST_SQUARE, HST_TRIANGLE };

static enum hst_part hexa_square_triangle_fold(double *px, double *pz,
                                               int *mir_x, int *mir_z,
                                               int *turned)
{
    const double w = 3.0 + R3, h = 2.0 * (1.0 + R3);
    const double half_w = R3_2 + 1.5, half_h = R3 + 1.0;
    const double corner = 1.0 + R3_2;
    double x = wrap(*px + 0.5, w), z = wrap(*pz, h);
    *mir_x = *mir_z = *turned = 0;
    if (x > half_w) {               /* the right half, shifted half a row */
        x -= half_w;
        z += z < half_h ? R3_2 + 0.5 : -(R3_2 + 0.5);
    }
    if (z > half_h)
        z -= half_h;
    if (z > 0.5 + R3_2) {
        z = half_h - z;
        *mir_z = 1 - *mir_z;
    }
    if (x > corner) {
        x = R3 + 2.0 - x;
        *mir_x = 1 - *mir_x;
    }
    if (R3 * x + z < R3_2 + 2.0 && x < 0.5 + R3_2) {
        /* turn by 60 degrees about the cell's middle */
        double cz = z - (0.5 + R3_2), cx = x - corner;
        x = cx / 2.0 - cz * R3_2 + corner;
        z = cz / 2.0 + cx * R3_2 + 0.5 + R3_2;
        *turned = 1 - *turned;
        if (z < 0.0)
            z = -z;
        if (x > corner) {
            x = R3 + 2.0 - x;
            *mir_x = 1 - *mir_x;
            *mir_z = 1 - *mir_z;
        }
    }
    *px = x;
    *pz = z;
    if (!(R3 * x + z < R3_2 + 2.0) && !(z < 0.5))
        return HST_HEXAGON;
    if (z < 0.5)
        return x > R3_2 + 0.5 ? HST_SQUARE : HST_TRIANGLE;
    return HST_NONE;
}

/* The distance measures of the three parts, from the folded point. */
static double hst_hexagon(double x, double z)
{
    z = fabs(z - 0.5);
    x = fabs(x - R3_2);
    return fmin(2.0 * z * R3, (R3 * x + z) * R3 - 1.5);
}

static double hst_square(double x, double z)
{
    x -= R3_2 + 0.5;
    z -= 0.5;
    return fmax(fmax(1.0 + z * 2.0 * R3, 0.0), fmax(1.0 - x * 2.0 * R3, 0.0));
}

static double hst_triangle(double x, double z)
{
    x = fabs(x - (R3_2 + 0.5));
    return fmax(2.0 - x * 2.0 * R3, (R3 * z + x) * R3 + 0.5);
}

/* 16: triangles [0, 1/3], squares [1/3, 2/3], hexagons [2/3, 1]. */
static double hexa_square_triangle(double x, double z)
{
    int mx, mz, turned;
    switch (hexa_square_triangle_fold(&x, &z, &mx, &mz, &turned)) {
    case HST_HEXAGON:
        return fmax(3.0 - hst_hexagon(x, z), 2.0000001) / 3.0;
    case HST_SQUARE: return hst_square(x, z) / 3.0;
    case HST_TRIANGLE: return hst_triangle(x, z) / 3.0;
    default: return 0.0;
    }
}

/* 17: the same tiles coloured by orientation as POV-Ray numbers them
** (sixths): the squares by how they were turned and mirrored, the two
** triangles by their mirror, the hexagons at the top. */
static double hexa_square_triangle_6(double x, double z)
{
    int mx, mz, turned;
    switch (hexa_square_triangle_fold(&x, &z, &mx, &mz, &turned)) {
    case HST_HEXAGON:
        return fmax(6.0 - hst_hexagon(x, z), 5.000001) / 6.0;
    case HST_SQUARE:
        return (hst_square(x, z) +
                turned * (1.000001 + (mx + mz) % 2)) / 6.0;
    case HST_TRIANGLE:
        return (hst_triangle(x, z) + ((turned + mx) % 2 ? 2.0 : 3.0)) / 6.0;
    default: return 0.0;
    }
}

/* 19 and 20: hexagons (band 2) each ringed by triangles (bands 0, 1),
** the rows sliding by half a unit every 3 sqrt3/2 so that the hexagons
** spiral to the right (19) or the left (20): the snub hexagonal tiling.
** The plane folds into a strip of unit triangles with one hexagon. */
static double hexa_tri(double x, double z, bool right)
{
    /* POV-Ray counts the row with integer arithmetic: truncated twice */
    double row = trunc(trunc(z / R3_2) / 3.0);
    if (z < 0.0)
        row -= 1.0;
    x += right ? row / 2.0 : -row / 2.0;
    z = wrap(z, 3.0 * R3_2);
    x = wrap(x + 7.0, 7.0);
    if (right) {
        if (x > 4.5 && z > R3) {
            x -= 4.5;
            z -= R3_2;
        }
        if (x > 5.0 && z < R3_2) {
            x -= 5.0;
            z += R3;
        }
        if (x > 2.5 && z < R3) {
            x -= 2.5;
            z += R3_2;
        }
    } else {
        if (x > 2.0 && z < R3_2) {
            x -= 2.0;
            z += R3;
        }
        if (x > 4.5 && z < R3) {
            x -= 4.5;
            z += R3_2;
        }
        if (x > 2.5 && z > R3) {
            x -= 2.5;
            z -= R3_2;
        }
    }
    int band = 0;
    int level = (int)(z / R3_2);    /* z is in [0, 3 sqrt3/2] here */
    if (level == 2) {
        level = 1;
        z = 2.0 * R3 - z;
        band = 1 - band;
    }
    if (!level || x > 2.0 || z + R3 * x < R3 || R3 * x - z > R3) {
        x -= floor(x);
        z = wrap(z, R3);
        if (z > R3_2) {
            z = R3 - z;
            band = 1 - band;
        }
        if (x > 0.5)
            x = 1.0 - x;
        if (x == 0.0 || z / x > R3) {
            z = R3_2 - z;
            x = x == 0.0 ? 0.5 : 0.5 - x;
            band = 1 - band;
        }
        double to_base = 1.0 - z * 2.0 * R3;
        double to_side = 1.0 - (R3 * x - z) * R3;
        return (band + fmax(to_base, to_side)) / 3.0;
    }
    z -= R3_2;
    if (x > 1.0)
        x = 2.0 - x;
    double d1 = 2.0 + 2.0 * z * R3;
    double d2 = 2.0 + 2.0 * (R3 * x + z - R3_2) * R3_2;
    return fmax(5.0 - fmin(d1, d2), 2.000001) / 3.0;
}

/* 21: squares and triangles, two triangles on each side of a square
** (the snub square tiling). The (1 + sqrt3) square cell folds by two
** mirrors into a quarter, which a turn by 90 degrees or a point mirror
** brings onto one half square and its triangle; 'gamma' numbers the
** triangle's orientation (sixths 0..4), the squares take the top bands
** by their mirror parity. */
static double square_tri(double x, double z)
{
    const double half = 0.5 + R3_2;
    int flip = 0, gamma = 0, beta = 0;
    x = wrap(x, 1.0 + R3);
    z = wrap(z, 1.0 + R3);
    if (z > half) {
        z = 1.0 + R3 - z;
        flip = 1 - flip;
    }
    if (x > half) {
        x = 1.0 + R3 - x;
        flip = 1 - flip;
        beta = 1;
    }
    int xflop = 2.0 * x + (R3 - 1.0) * 2.0 * z / (R3 + 1.0) > R3;
    int zflop = 2.0 * z * R3 + (R3 - 3.0) * 2.0 * x / (R3 + 1.0) > R3;
    double t;
    switch (xflop + 2 * zflop) {
    case 0:
        gamma = 2 * beta;
        break;
    case 1:                         /* turn clockwise */
        gamma = beta ? 1 + 2 * flip : 3 - 2 * flip;
        t = x;
        x = z;
        z = half - t;
        break;
    case 2:                         /* turn counter-clockwise */
        gamma = beta ? 3 - 2 * flip : 1 + 2 * flip;
        t = z;
        z = x;
        x = half - t;
        break;
    default:                        /* point mirror */
        gamma = beta ? 0 : 2;
        x = half - x;
        z = half - z;
        break;
    }
    if (x == 0.0)
        z = 0.0;
    double side = z * 2.0 * R3 - R3 + x * 2.0;
    if (side < 0.0) {               /* the triangle */
        double d = fmin(-1.5 / R3 * side, 2.0 * x * R3);
        return (gamma + 1.0 - d) / 6.0;
    }
    side = fmin(side * 1.5 / R3, 1.0);
    if (flip)
        return fmin(fmax((6.0 - side) / 6.0, 5.000001 / 6.0), 1.0);
    return fmax(fmin((5.0 - side) / 6.0, 5.0 / 6.0), 4.000001 / 6.0);
}

/* 22: dodecagons (band 2) with triangles (bands 0, 1) between them (the
** truncated hexagonal tiling). */
static double dodeca_tri(double x, double z)
{
    int toggle = 0;
    x = wrap(x, 2.0 + R3);
    z = wrap(z, 3.0 + 2.0 * R3);
    if (z > R3 + 1.5) {
        z -= R3 + 1.5;
        x += (x < 1.0 + R3_2 ? 1.0 : -1.0) * (1.0 + R3_2);
    }
    if (x > 1.0 + R3_2)
        x = 2.0 + R3 - x;
    if (z > 1.0 + R3_2) {
        z = 2.0 + R3 - z;
        toggle = 1 - toggle;
    }
    double d2 = x - R3_2 - 0.5 + z * R3;
    if (d2 < 0.0) {                 /* turn by 120 degrees */
        double tx = x, tz = z;
        x = (1.0 + R3) / 4.0 + 0.5 * tx - R3_2 * tz;
        z = (3.0 + R3) / 4.0 - R3_2 * tx - 0.5 * tz;
        d2 = -d2;
    }
    double d1 = z * 3.0;
    double d3 = (z - R3_2 - 0.5 + x * R3) * R3;
    double d4 = x * 3.0;
    d2 *= R3;
    if (d3 < 0.0)                   /* a triangle */
        return (fmax(d3, -1.0) + 1.0 + toggle) / 3.0;
    return (3.0000001 - fmin(fmin(fmin(d1, d2), fmin(d3, d4)), 1.0)) / 3.0;
}

/* 23 and 24: dodecagons, hexagons and squares (the truncated
** trihexagonal tiling). The cell (3 + sqrt3) x (3 + 3 sqrt3) folds by a
** half-cell shift, two mirrors and a turn by 120 degrees into one
** twelfth of a dodecagon and its neighbours. 23 has three bands:
** hexagons, squares, dodecagons; 24 five: hexagons, upright squares, the
** slanted squares in two by the parity of the mirrors, dodecagons. */
static double dodeca_hex(double x, double z, bool five)
{
    int mir = 0;
    x = wrap(x, 3.0 + R3);
    z = wrap(z, 3.0 + 3.0 * R3);
    if (z > 1.5 * R3 + 1.5) {
        z -= 1.5 * R3 + 1.5;
        x += (x < 1.5 + R3_2 ? 1.0 : -1.0) * (1.5 + R3_2);
    }
    if (x > 1.5 + R3_2) {
        x = 3.0 + R3 - x;
        mir ^= 1;
    }
    if (z > 1.0 + R3) {
        z = 2.0 + 2.0 * R3 - z;
        mir ^= 1;
    }
    if (x - R3_2 - 1.5 + z * R3 < 0.0) {
        double tx = x, tz = z;
        x = (3.0 + R3) / 4.0 + 0.5 * tx - R3_2 * tz;
        z = (3.0 + 3.0 * R3) / 4.0 - R3_2 * tx - 0.5 * tz;
    }
    double d2 = x - R3_2 - 2.5 + z * R3;
    double d1 = z * 2.0 - R3;
    double d3 = z - 1.5 * R3 - 0.5 + x * R3;
    double d4 = (x - 0.5) * 2.0;
    double v;
    if (d1 >= 0.0 && d2 >= 0.0 && d3 >= 0.0 && d4 >= 0.0) {
        /* the dodecagon, just above every other tile's values */
        v = (five ? 5.000001 : 3.000001) -
            fmin(fmin(fmin(d1, d2), fmin(d3, d4)), 1.0);
    } else {
        double d5 = 2.0 * z - 2.0 * R3 - 1.0;
        if (d5 >= 0.0) {            /* the upright square */
            v = 2.0 - fmin(d5, -d4);
        } else {
            double d6 = R3 * x - z - R3_2 + 0.5;
            double d7 = d6 - 2.0;
            if (d6 < 0.0 && d7 < 0.0)       /* the left hexagon */
                v = 1.0 - fmin(fmin(-d6, -d3), fmin(-d5, 1.0));
            else if (d6 >= 0.0 && d7 >= 0.0) /* the bottom hexagon */
                v = 1.0 - fmin(fmin(d7, -d1), 1.0);
            else                            /* a slanted square */
                v = (five ? mir + 3.0 : 2.0) - fmin(fmin(d6, -d2), -d7);
        }
    }
    return v / (five ? 5.0 : 3.0);
}

/* POV-Ray truncates the number and its parser accepts only 1..27; the
** parser here does the same, so 1 only guards a scene built through the
** API. */
static int tiling_type(double n)
{
    if (!(n >= 1.0 && n < 28.0))
        return 1;
    return (int)n;
}

double pattern_tiling(double n, vec3 p)
{
    double x = p.x, z = p.z;
    /* the folds cast coordinates to int: keep Inf and NaN away */
    if (!isfinite(x) || !isfinite(z))
        return 0.0;
    switch (tiling_type(n)) {
    case 2: return hexagon(x, z);
    case 3: return triangle(x, z);
    case 4: return lozenge(x, z);
    case 5: return rhombus(x, z);
    case 6: return rectangle(x, z);
    case 7: return octa_square(x, z);
    case 8: return square_triangle(x, z);
    case 9: return hexa_triangle(x, z);
    case 10: return square_offset(x, z);
    case 11: return square_rectangle(x, z);
    case 12: return rectangle_square(x, z);
    case 13: return square_internal(x, z);
    case 14: return square_internal_5(x, z);
    case 15: return square_double(x, z);
    case 16: return hexa_square_triangle(x, z);
    case 17: return hexa_square_triangle_6(x, z);
    case 18: return rectangle_pair(x, z);
    case 19: return hexa_tri(x, z, true);
    case 20: return hexa_tri(x, z, false);
    case 21: return square_tri(x, z);
    case 22: return dodeca_tri(x, z);
    case 23: return dodeca_hex(x, z, false);
    case 24: return dodeca_hex(x, z, true);
    case 25: return penrose_p1(x, z);
    case 26: return penrose_p2(x, z);
    case 27: return penrose_p3(x, z);
    default: return square(x, z);
    }
}
