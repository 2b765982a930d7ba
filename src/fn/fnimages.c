/* SPDX-License-Identifier: MIT */
/*
** fnimages.c: pattern and pigment functions that read images.
**
** function { pigment { image_map { png "map.png" } } } is how scenes use
** an image as data: isosurface terrains (y - F(x, 0, z).gray), objects
** placed where a map is bright, pigments built from another pigment's
** channels. A render's textures read their images through the material
** context that src/render builds for the scene (mat_ctx_create), but a
** function is evaluated without one (while parsing, and inside
** isosurfaces and function patterns), so such functions were 0 everywhere.
** Here each pattern function that reads images, density files or objects
** gets a context of its own, built when the parser compiles it from a
** one-pigment scene that carries the real scene's gamma settings; the
** real scene frees it (iris_scene.cleanups).
*/
#include "config.h"

#include <string.h>

#include "fn/fnimages.h"
#include "iris/fn.h"
#include "iris/scene.h"
#include "material/material.h"
#include "util/mem.h"

/* The context and the one-pigment scene it was built from (the context
** keeps a pointer to the scene: both live as long as the function). */
struct fn_images {
    struct mat_ctx *ctx;
    iris_scene scene;
    iris_sky_sphere sky;
    iris_pigment *list[1];
    iris_pigment pig;          /* a pattern function: the pattern in a pigment */
    iris_map_entry grey[2];    /* ... whose colour map is value -> grey value */
};

/* Whether evaluating 'p' reads a file or an object (recursion bounded as
** material's own walk is). */
static bool reads_data(const iris_pattern *p)
{
    return p->image != NULL || (p->kind == IRIS_PAT_OBJECT && p->object);
}

static bool pigment_reads_data(const iris_pigment *p, int depth)
{
    if (!p || depth > 64)
        return false;
    if (reads_data(&p->pattern))
        return true;
    for (int i = 0; i < p->n_entries; i++)
        if (pigment_reads_data(p->entries[i].pigment, depth + 1))
            return true;
    return false;
}

bool iris_fn_load_images(iris_fn_insn *in, double assumed_gamma,
                         double version)
{
    if (in->op != IRIS_FN_PATTERN || in->images)
        return true;
    if (in->pigment ? !pigment_reads_data(in->pigment, 0)
                    : !in->pattern || !reads_data(in->pattern))
        return true;
    struct fn_images *fi = iris_calloc(1, sizeof *fi);
    if (!fi)
        return false;
    if (in->pigment) {
        fi->list[0] = (iris_pigment *)in->pigment;
    } else {
        /* A pigment whose colour map gives the pattern's value back as
        ** the red channel: [0 rgb 0] [1 rgb 1], linear in between. */
        fi->pig.pattern = *in->pattern;
        fi->grey[0].value = 0;
        fi->grey[1].value = 1;
        fi->grey[1].colour.r = fi->grey[1].colour.g = fi->grey[1].colour.b = 1;
        fi->pig.n_entries = 2;
        fi->pig.entries = fi->grey;
        fi->list[0] = &fi->pig;
    }
    fi->sky.n_pigments = 1;
    fi->sky.pigments = fi->list;
    iris_global_defaults(&fi->scene.settings);
    fi->scene.settings.assumed_gamma = assumed_gamma;
    fi->scene.version = version;
    fi->scene.sky_sphere = &fi->sky;
    if (mat_ctx_create(&fi->scene, NULL, &fi->ctx) != IRIS_OK) {
        iris_free(fi);
        return false;
    }
    in->images = fi;
    return true;
}

void iris_fn_free_images(void *images)
{
    struct fn_images *fi = images;
    if (!fi)
        return;
    mat_ctx_destroy(fi->ctx);
    iris_free(fi);
}

double fn_images_value(const iris_fn_insn *in, double x, double y, double z)
{
    const struct fn_images *fi = in->images;
    struct mat_point pt = { v3(x, y, z), v3(0, 1, 0), v3(0, 0, 1), { 0, 0 },
                            NULL, true };
    iris_colour c = { 0, 0, 0, 0, 0 };
    (void)mat_eval_pigment(fi->ctx, fi->list[0], &pt, &c);
    if (!in->pigment)
        return c.r;
    const double v[5] = { c.r, c.g, c.b, c.f, c.t };
    return fn_pigment_component(v, in->arg);
}
