/* SPDX-License-Identifier: MIT */
/*
** fractal_pattern.h: POV-Ray's magnet fractal patterns.
*/
#ifndef IRIS_MATERIAL_FRACTAL_PATTERN_H
#define IRIS_MATERIAL_FRACTAL_PATTERN_H

#include <stdbool.h>

#include "iris/scene.h"

/*
** Iterates the magnet map of type 'type' (1 or 2) at the point (x, y): the
** mandel form when 'julia' is false (c = the point, z from 0), the julia
** form otherwise (c = 'cu' + 'cv' i, z from the point). Returns whether
** the orbit left (|z|² > 10000) or converged (|z - 1|² < 1e-4) within
** 'it_max' steps; '*k' is then the step (else it_max), '*a' + '*b' i the
** last z, '*mind2' the least |z|² seen, for the mandel/julia colourings.
*/
bool pat_magnet(int type, bool julia, double x, double y, double cu,
                double cv, int it_max, int *k, double *a, double *b,
                double *mind2);

#endif
