/* SPDX-License-Identifier: MIT */
/*
** material.h: textures evaluated at a surface point, as POV-Ray 3.7 does.
**
** The tracer (src/render) and the photon shooter (src/photon) both need
** what a texture is at a hit: per layer the pigment (rgb, filter,
** transmit), the finish, and the normal after normal{} perturbation.
** mat_eval_texture() produces that. A texture_map blends whole textures,
** so the result is one or more "stacks" of layers with weights summing to
** 1; a plain layered texture gives a single stack. The helpers below
** compute what POV-Ray derives from a layer: transmittance (rgbTransm),
** opacity, Fresnel reflectivity and the layer's reflection colour.
**
** Patterns are evaluated in pattern space: the world point is mapped by
** pattern.transform.inv (when has_transform), then the warps{} are applied
** from the last in the array to the first, which is POV-Ray's order (a
** warp written later acts on the world side of the ones written earlier),
** and last the classic turbulence: the final array entry when it is a
** TURBULENCE warp, as the parser keeps it. Marble and wood use their
** classic turbulence themselves instead of warping by it; agate and the
** spirals read its parameters too.
**
** Depends on: util, math, image (image maps), geometry (object patterns).
** Used by: render, photon.
*/
#ifndef IRIS_MATERIAL_MATERIAL_H
#define IRIS_MATERIAL_MATERIAL_H

#include <math.h>
#include <stdbool.h>
#include <stdio.h>

#include "iris/common.h"
#include "iris/scene.h"
#include "math/vec3.h"

/* What a render shares for texture evaluation: loaded image maps and the
** scene-wide settings patterns need. Immutable once built; thread-safe. */
struct mat_ctx;

/*
** Builds the context for 'scene' (borrowed): loads every image an
** image_map or bump_map names. A missing image is reported on 'log' and
** evaluates as black, as a render must not fail for it.
*/
IRIS_NODISCARD enum iris_status mat_ctx_create(const iris_scene *scene,
                                               FILE *log,
                                               struct mat_ctx **out);
void mat_ctx_destroy(struct mat_ctx *ctx);

/* Below quality 6 POV-Ray replaces every pigment that has a quick_colour
** (one not all zero) by it. Call before the context is shared. */
void mat_ctx_set_quick_colour(struct mat_ctx *ctx, bool on);

/* A surface point as the texture sees it. */
struct mat_point {
    vec3 p;                    /* world point */
    vec3 n;                    /* unit normal facing the incoming ray */
    vec3 d;                    /* unit incoming ray direction */
    iris_vec2 uv;              /* surface uv, where the shape has one */
    const iris_object *obj;    /* the primitive hit, or NULL */
    bool skip_normals;         /* quality below 8: normal{} is ignored */
};

/* One texture layer at a point. */
struct mat_layer {
    iris_colour pigment;       /* rgb, filter, transmit */
    const iris_finish *finish; /* never NULL */
    vec3 n;                    /* perturbed unit normal; may tip away
                                  from the ray, as POV-Ray's may */
    bool valid;                /* false: no colour here (image_map once) */
};

#define MAT_MAX_LAYERS 32
#define MAT_MAX_STACKS 8

/* Layers first..first+n-1 shaded together (top layer first). */
struct mat_stack {
    double weight;
    int first, n;
};

struct mat_eval {
    int n_layers, n_stacks;
    struct mat_layer layers[MAT_MAX_LAYERS];
    struct mat_stack stacks[MAT_MAX_STACKS];
};

/* mat_eval_texture() for the one texture 'tex' (texture.c). */
void mat_eval_layers(const struct mat_ctx *ctx, const iris_texture *tex,
                     const struct mat_point *pt, struct mat_eval *out);

/* mat_eval_texture() on a blob (multitex.c): the blend of its components'
** textures where they have some, else mat_eval_layers(). */
void mat_eval_blob_texture(const struct mat_ctx *ctx,
                           const iris_texture *tex,
                           const struct mat_point *pt, struct mat_eval *out);

/*
** Evaluates 'tex' at 'pt' into stacks of layers. Blended texture_maps give
** up to MAT_MAX_STACKS stacks (past that, the heaviest neighbour wins).
** On a blob whose components have textures (pt->obj), the stacks are
** those of the component textures, weighted by their fields (multitex.c).
** Inline: only a blob can blend, and the call to learn that it is not
** one was 0.5 % of a simple scene's eye pass.
*/
static inline void mat_eval_texture(const struct mat_ctx *ctx,
                                    const iris_texture *tex,
                                    const struct mat_point *pt,
                                    struct mat_eval *out)
{
    if (pt->obj && pt->obj->kind == IRIS_OBJ_BLOB)
        mat_eval_blob_texture(ctx, tex, pt, out);
    else
        mat_eval_layers(ctx, tex, pt, out);
}

/* Whether the texture of a hit on primitive 'o' is a blend of several
** that mat_eval_texture() works out per point (a blob whose components
** have textures): the hit's own texture pointer then does not tell what
** the surface is (an opaque one may be blended with a clear one). */
bool mat_texture_blended(const iris_object *o);

/* Evaluates a pigment at world point 'p'. Returns false where it has no
** colour (image_map 'once' outside the image); *out is then clear. */
bool mat_eval_pigment(const struct mat_ctx *ctx, const iris_pigment *pig,
                      const struct mat_point *pt, iris_colour *out);

/* Returns the normal 'n' (unit, facing the ray) perturbed by 'nrm'. */
vec3 mat_perturb_normal(const struct mat_ctx *ctx, const iris_normal *nrm,
                        const struct mat_point *pt, vec3 n);

/* The first member of every struct mat_ctx (mat_internal.h): what the
** inline helpers below read, so that they need no call per hit (the
** three helpers were 1-2 % of a simple scene's eye pass as calls). */
struct mat_ctx_head {
    bool legacy_opacity;       /* #version < 3.7 */
};

/* rgbTransm: per channel rgb*filter + transmit (semantics §3.2). */
static inline void mat_rgb_transm(const iris_colour *c, double out[3])
{
    out[0] = c->r * c->f + c->t;
    out[1] = c->g * c->f + c->t;
    out[2] = c->b * c->f + c->t;
}

/* POV-Ray's opacity 1 - f - t, or the legacy 1 - (f max(rgb) + t) of
** scenes older than #version 3.7. 'ctx' may be NULL (3.7 rules). */
static inline double mat_opacity(const struct mat_ctx *ctx,
                                 const iris_colour *c)
{
    /* a pointer to a struct converts to one to its first member */
    const struct mat_ctx_head *h = (const struct mat_ctx_head *)ctx;
    if (h && h->legacy_opacity)
        return 1.0 - (c->f * fmax(c->r, fmax(c->g, c->b)) + c->t);
    return 1.0 - c->f - c->t;
}

/*
** fmax() and fmin() without libm's call (GCC calls them unless NaNs are
** ruled out; 5 calls per reflecting layer were 0.5 % of a glass scene's
** eye pass). The same values: the larger (smaller) operand, the second
** when they compare equal (glibc's maxsd/minsd, so +0 and -0 come out
** alike), and the other operand when one is a NaN.
*/
static inline double mat_fmax(double a, double b)
{
    return a > b || b != b ? a : b;
}
static inline double mat_fmin(double a, double b)
{
    return a < b || b != b ? a : b;
}

/* POV-Ray's greyscale: 0.297 r + 0.589 g + 0.114 b. */
static inline double mat_greyscale(const double c[3])
{
    return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
}

/*
** POV-Ray's Fresnel reflectance (ComputeReflectivity type 1) for the
** cosine 'cos_i' >= 0 of the incidence angle and the relative index
** n = n_t / n_i. Returns 1 past the critical angle; result in [0, 1].
*/
double mat_fresnel(double cos_i, double n);

/*
** The reflection colour of a layer (semantics §3.3 step 3): standard
** falloff or fresnel, then reflection metallic. 'cos_i' = -I.N_layer,
** 'n' = n_t/n_i for fresnel. '*weight' gets the factor POV-Ray multiplies
** the recursion weight by. Returns false when the layer does not reflect.
*/
bool mat_layer_reflectivity(const struct mat_layer *layer, double cos_i,
                            double n, double refl[3], double *weight);

/* The metallic-highlight factor of finish metallic M (semantics §3.3). */
void mat_metallic_tint(double metallic, double cos_angle,
                       const iris_colour *pigment, double out[3]);

/* The scene's default noise generator, for pattern evaluation. */
int mat_noise_generator(const struct mat_ctx *ctx);

/*
** For function { pattern { ... } } and function { pigment { ... } }
** (src/fn's IRIS_FN_PATTERN): the value in [0, 1] of 'pat' at world point
** (x, y, z), with its transform, warps and wave shaping, and the pigment's
** colour there as r, g, b, filter, transmit. No context is needed: the
** noise generator is the pattern's own or POV-Ray's default (2), and
** image maps read as black. Thread-safe; never NaN.
*/
double mat_pattern_at(const iris_pattern *pat, double x, double y, double z);
void mat_pigment_at(const iris_pigment *pig, double x, double y, double z,
                    double rgbft[5]);

#endif
