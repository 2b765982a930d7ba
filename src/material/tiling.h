/* SPDX-License-Identifier: MIT */
/*
** tiling.h: the 'tiling N' pattern (POV-Ray 3.7's TilingPattern).
*/
#ifndef IRIS_MATERIAL_TILING_H
#define IRIS_MATERIAL_TILING_H
#include "math/vec3.h"

/*
** The value of 'tiling n' at p. Only x and z matter: every tiling fills
** the x-z plane. With one tile shape 0 is the tile's centre and 1 its
** edge; with k shapes (or k colours of one shape) tile j takes the band
** [j/k, (j+1)/k] and its edge is at the band's upper end. n is truncated
** as POV-Ray does; the parser refuses n outside [1, 28). All 27 are
** computed (25..27, the Penrose tilings, in penrose.c).
*/
double pattern_tiling(double n, vec3 p);
#endif
