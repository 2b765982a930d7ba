/* SPDX-License-Identifier: MIT */
/*
** penrose.h: the Penrose tilings of the 'tiling' pattern (25..27), as
** POV-Ray 3.7's TilingPattern computes them.
*/
#ifndef IRIS_MATERIAL_PENROSE_H
#define IRIS_MATERIAL_PENROSE_H

/* tiling 25: pentagons, stars, boats and diamonds (P1), a pentagon at the
** origin; six bands of sixths: the three pentagon kinds, stars, boats,
** diamonds. */
double penrose_p1(double x, double z);
/* tiling 26: kites [0, 0.5) and darts (0.5, 1] (P2), darts forming a star
** at the origin. */
double penrose_p2(double x, double z);
/* tiling 27: wide rhombs [0, 0.5) and narrow ones (0.5, 1] (P3). */
double penrose_p3(double x, double z);
#endif
