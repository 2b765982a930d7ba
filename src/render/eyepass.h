/* SPDX-License-Identifier: MIT */
/*
** eyepass.h: tracing the image: tiles handed to threads, one camera ray
** per pixel or POV-Ray's antialiasing (+AM1, +AM2) or stratified
** supersampling, into linear RGBA with alpha 1.
**
** Depends on: util (threads), render (trace, camera). Used by: render.c
** and the unit tests (with a scene double behind the tracer).
*/
#ifndef IRIS_RENDER_EYEPASS_H
#define IRIS_RENDER_EYEPASS_H

#include "iris/render.h"
#include "render/trace.h"

/*
** Renders the window of 'opts' into 'out' with 'threads' threads. NaN and
** Inf samples become 0 and are counted in stats->nan_pixels; negative
** values are clamped to 0. Returns IRIS_OK, IRIS_ENOMEM, IRIS_EINVAL (an
** empty window) or IRIS_EINTR when *opts->interrupt was set.
*/
enum iris_status eyepass_run(const struct tracer *tr,
                             const iris_render_options *opts, int threads,
                             iris_image *out, iris_render_stats *stats);

#endif
