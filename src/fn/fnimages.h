/* SPDX-License-Identifier: MIT */
/*
** fnimages.h: the value of a pattern function whose pattern or pigment
** reads images (fnimages.c; the loading is iris_fn_load_images, fn.h).
*/
#ifndef IRIS_FN_FNIMAGES_H
#define IRIS_FN_FNIMAGES_H

#include "iris/fn.h"

/* Component k of pigment colour c (r, g, b, f, t) that a pigment
** function's member selects: 0..4 = .red ... .transmit, 5 = .gray with
** POV-Ray's Greyscale() weights, 6 = .hf, POV-Ray's MegaPOV height
** field value (red + green / 255) * 0.996093 (FNCode::compile_member). */
static inline double fn_pigment_component(const double c[5], int k)
{
    if (k == 5)
        return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
    if (k == 6)
        return (c[0] + c[1] / 255.0) * 0.996093;
    return k >= 0 && k < 5 ? c[k] : c[0];
}

/* The value of PATTERN insn 'in' (in->images set) at (x, y, z): the
** pattern's value, or the pigment's component in->arg
** (fn_pigment_component). */
double fn_images_value(const iris_fn_insn *in, double x, double y, double z);

#endif
