/* SPDX-License-Identifier: MIT */
/*
** fnimages.h: the value of a pattern function whose pattern or pigment
** reads images (fnimages.c; the loading is iris_fn_load_images, fn.h).
*/
#ifndef IRIS_FN_FNIMAGES_H
#define IRIS_FN_FNIMAGES_H

#include "iris/fn.h"

/* The value of PATTERN insn 'in' (in->images set) at (x, y, z): the
** pattern's value, or the pigment's component in->arg (5 = grey). */
double fn_images_value(const iris_fn_insn *in, double x, double y, double z);

#endif
