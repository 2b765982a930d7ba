/* SPDX-License-Identifier: MIT */
/*
** render_placeholder.c: TEMPORARY entry points so that the build links
** while the renderer is written. The render work replaces this file.
*/
#include "config.h"

#include <string.h>

#include "iris/render.h"

void iris_render_defaults(iris_render_options *o)
{
    memset(o, 0, sizeof *o);
    o->width = 160; o->height = 120; o->quality = 9; o->aa_threshold = 0.3;
    o->aa_depth = 3; o->jitter = true; o->jitter_amount = 1.0; o->aa_gamma = 2.5;
    o->use_photons = true;
}

enum iris_status iris_render(const iris_scene *scene, const iris_render_options *opts, iris_image *out, iris_render_stats *stats, char *err, size_t errlen)
{ (void)scene; (void)opts; (void)out; (void)stats; if (err && errlen) strncpy(err, "renderer not built yet", errlen - 1); return IRIS_EUNSUPPORTED; }
