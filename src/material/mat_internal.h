/* SPDX-License-Identifier: MIT */
/*
** mat_internal.h: what the files of src/material share and nobody else
** needs: the context's layout, pattern evaluation and the MT19937 table
** POV-Ray's cells and crackle draw from.
*/
#ifndef IRIS_MATERIAL_MAT_INTERNAL_H
#define IRIS_MATERIAL_MAT_INTERNAL_H

#include "image/df3.h"
#include "iris/image.h"
#include "material/material.h"
#include "material/objpattern.h"

/* One image loaded for an image_map, bump_map or image_pattern. */
struct mat_image {
    const iris_image_ref *ref;
    iris_image img;            /* width 0 when it could not be loaded */
    /* A material_map's texture numbers per texel (image/indices.h), row 0
    ** at the top; also read for per-index filter/transmit; else NULL. */
    int *index;
    int index_w, index_h;
    bool index_palette;        /* the numbers are palette indices */
    iris_df3 df3;              /* a density_file's voxels, or none (nx 0) */
};

struct mat_ctx {
    struct mat_ctx_head head;  /* first: material.h's inline helpers */
    const iris_scene *scene;
    int noise_generator;       /* the scene's default, 1..3 */
    int n_waves;               /* number_of_waves */
    bool quick_colour;         /* quality below 6 (mat_ctx_set_quick_colour) */
    int n_images;
    struct mat_image *images;
    struct objpat_set objpats; /* the objects of object patterns */
};

/* The textures of blob 'o' at world point 'p' and their weights (|field|
** of each component, normalised to sum 1): at most 'max', the heaviest.
** Returns the count, 0 where no component reaches 'p' (multitex.c). */
int mat_blob_textures(const iris_object *o, vec3 p,
                      const iris_texture **tex, double *w, int max);

/* The weights of the three textures of an IRIS_PAT_FACE_BLEND map at
** world point 'p', as POV-Ray weighs a mesh face's three textures:
** 1 - Calculate_Smooth_T from each corner, normalised to sum 1 (the
** barycentric coordinates on the face). Returns their sum, 1. */
double mat_face_weights(const struct mat_ctx *ctx, const iris_pattern *pat,
                        vec3 p, double w[3]);

/* Maps world point 'p' to the pattern's space: transform, then warps. */
vec3 pat_space(const struct mat_ctx *ctx, const iris_pattern *pat, vec3 p);

/* Evaluates the pattern function at pattern-space point 'q', then applies
** frequency, phase and the wave type, as POV-Ray's Evaluate_TPat. */
double pat_eval_at(const struct mat_ctx *ctx, const iris_pattern *pat,
                   vec3 q, const struct mat_point *pt);

/*
** Where the entries of a map (pigment_map, normal_map, texture_map and the
** list patterns' pigments) are evaluated. POV-Ray evaluates them at the
** map pattern's warped point; the parser already gives each entry the map
** pattern's transforms, so only the warps are missing: this returns 'p'
** moved by them, taken back to world space (T W T^-1 p), or 'p' itself
** when the pattern has no warp.
*/
vec3 pat_warp_world(const struct mat_ctx *ctx, const iris_pattern *pat,
                    vec3 p);

/* Where a pattern starts from: 'p', or under uv_mapping the surface's
** <u, v, 0> (POV-Ray's UV_MAP_PATTERN: no warps or transforms of the
** object reach it). */
vec3 pat_input(const iris_pattern *pat, vec3 p, const struct mat_point *pt);

/* pat_eval_at(pat_space(pat_input(p))). */
double pat_value(const struct mat_ctx *ctx, const iris_pattern *pat,
                 vec3 p, const struct mat_point *pt);

/* Whether the pattern's value is a map index (checker, hexagon, brick...)
** rather than a position in [0, 1]. */
bool pat_is_list(enum iris_pattern_kind kind);

/* The quilted pattern's displacement at pattern-space point 'p': the
** offset from the unit cell's centre scaled by the control0/control1
** cubic. The pattern value is its mean |component|; a quilted normal
** adds it to the normal (POV-Ray's quilted() in normal.cpp). */
vec3 pat_quilt_vector(const iris_pattern *pat, vec3 p);

/* The noise generator the pattern uses. */
int pat_noise_generator(const struct mat_ctx *ctx, const iris_pattern *pat);

/* POV-Ray's PatternRands(i): the i-th (mod 32768) of MT19937's default
** stream scaled to [0, 1). */
double pat_rand(unsigned long i);

/* The loaded image for 'ref', or NULL. */
const iris_image *mat_find_image(const struct mat_ctx *ctx,
                                 const iris_image_ref *ref);

/* Forgets every converted texel pigment.c remembers (its texel memo):
** called as a context's images are freed. */
void mat_texel_memo_forget(void);

/* Image map lookup (planar/spherical/cylindrical, once, interpolate) at
** pattern-space point 'q'. Returns false outside a 'once' image. */
bool mat_image_lookup(const struct mat_ctx *ctx, const iris_image_ref *ref,
                      vec3 q, iris_colour *out);

/* A material_map's texture number (before the modulo) at pattern-space
** point 'q': the texel's palette index or red byte, 0 outside a 'once'
** image or for an image that could not be read (POV-Ray's material_map). */
int mat_image_index(const struct mat_ctx *ctx, const iris_image_ref *ref,
                    vec3 q);

/* The density_file pattern at pattern-space point 'q' (POV-Ray's
** density_pattern; 0 for a file that could not be read). */
double mat_density_file(const struct mat_ctx *ctx, const iris_pattern *pat,
                        vec3 q);

/* POV-Ray's bump_map: the normal 'n' (in pattern space) replaced by the
** normal of the image's grey levels around pattern-space point 'q', scaled
** by 'amount' (bump_size). Returns false where the map gives no normal
** ('once' outside the image, a missing image). */
bool mat_image_bump(const struct mat_ctx *ctx, const iris_image_ref *ref,
                    vec3 q, double amount, vec3 n, vec3 *out);

#endif
