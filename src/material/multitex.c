/* SPDX-License-Identifier: MIT */
/*
** multitex.c: the texture a hit shows, where one object carries several:
** a blob whose components have their own textures blends them by their
** fields, as POV-Ray's Blob::Determine_Textures does, and a mesh face
** with three textures blends them across the face (mat_face_weights,
** for the parser's IRIS_PAT_FACE_BLEND texture maps; Mesh::
** Determine_Textures).
**
** POV-Ray shades every texture of such a hit completely (lights,
** reflection, refraction) and mixes the colours by the weights
** (Trace::ComputeTextureColour's weighted texture list). That is what the
** weighted stacks of struct mat_eval already mean for a texture_map, so
** the blend is built here as stacks: each texture is evaluated by
** mat_eval_layers() and its stacks are scaled by the texture's weight.
** The tracer and the photon shooter need not know about it.
**
** The weight of a blob component at a point is |its field there|:
** strength·(1 - r²/R²)² where r < R (r: the distance to the centre, or to
** the axis segment of a cylinder, whose ends are hemispheres), 0 outside;
** POV-Ray takes the absolute value, so a negative component's texture
** counts too. A component without a texture contributes the blob's own.
** The weights are normalised to sum 1. Only when some component has a
** texture does POV-Ray blend (MULTITEXTURE_FLAG); a blend then ignores
** interior_texture, as POV-Ray's does.
*/
#include "config.h"

#include <math.h>

#include "material/mat_internal.h"
#include "math/transform.h"

/* The most textures of one hit that are shaded; POV-Ray shades them all,
** but a texture lighter than adc_bailout (1/255 by default) is skipped
** there too, and a point is rarely within more than a few components. */
#define MAX_TEXTURES MAT_MAX_STACKS

/* |field| of component 'bc' at blob-space point 'p'. */
static double component_weight(const iris_blob_component *bc, vec3 p)
{
    vec3 q = bc->has_transform ? xf_inv_point(&bc->transform, p) : p;
    double R = bc->radius;
    if (!(R > 0.0))
        return 0.0;
    vec3 c = bc->a;
    if (bc->kind == 1) {
        /* the nearest point of the axis segment: the side where the
        ** point projects inside it, a hemisphere beyond either end */
        vec3 ax = v3_sub(bc->b, bc->a);
        double l2 = v3_len2(ax);
        double h = l2 > 0.0 ? v3_dot(v3_sub(q, bc->a), ax) / l2 : 0.0;
        c = v3_madd(bc->a, ax, fmax(0.0, fmin(1.0, h)));
    }
    double r2 = v3_len2(v3_sub(q, c));
    if (!(r2 < R * R))
        return 0.0;
    double w = 1.0 - r2 / (R * R);
    double f = fabs(bc->strength * w * w);
    return isfinite(f) ? f : 0.0;
}

static bool blob_multitextured(const iris_object *o)
{
    for (int i = 0; i < o->u.blob.n_components; i++)
        if (o->u.blob.components[i].texture)
            return true;
    return false;
}

bool mat_texture_blended(const iris_object *o)
{
    return o && o->kind == IRIS_OBJ_BLOB && blob_multitextured(o);
}

/* Whether 'tex' is one the blob 'o' shows (its own, its interior texture
** or a component's): only those are replaced by the blend. */
static bool blob_texture(const iris_object *o, const iris_texture *tex)
{
    if (tex == o->texture || tex == o->interior_texture)
        return true;
    for (int i = 0; i < o->u.blob.n_components; i++)
        if (tex == o->u.blob.components[i].texture)
            return true;
    return false;
}

/*
** The weighted textures of blob 'o' at world point 'p': at most 'max',
** the heaviest, each texture once (components sharing one add up: the
** same texture at the same point shades the same). Returns the count;
** 0 when no component reaches the point.
*/
int mat_blob_textures(const iris_object *o, vec3 p,
                      const iris_texture **tex, double *w, int max)
{
    vec3 q = o->has_transform ? xf_inv_point(&o->transform, p) : p;
    int n = 0;
    for (int i = 0; i < o->u.blob.n_components; i++) {
        const iris_blob_component *bc = &o->u.blob.components[i];
        double wi = component_weight(bc, q);
        if (!(wi > 0.0))
            continue;
        const iris_texture *t = bc->texture ? bc->texture : o->texture;
        int k = 0;
        while (k < n && tex[k] != t)
            k++;
        if (k < n) {
            w[k] += wi;
            continue;
        }
        if (n < max) {
            tex[n] = t;
            w[n++] = wi;
            continue;
        }
        /* full: replace the lightest when this one weighs more */
        int lo = 0;
        for (k = 1; k < n; k++)
            if (w[k] < w[lo])
                lo = k;
        if (wi > w[lo]) {
            tex[lo] = t;
            w[lo] = wi;
        }
    }
    double sum = 0.0;
    for (int k = 0; k < n; k++)
        sum += w[k];
    if (!(sum > 0.0) || !isfinite(sum))
        return 0;
    for (int k = 0; k < n; k++)
        w[k] /= sum;
    return n;
}

/* Appends the stacks of 'ev', their weights times 'w', to 'out' as far
** as stacks and layers remain. */
static void append_stacks(struct mat_eval *out, const struct mat_eval *ev,
                          double w)
{
    for (int s = 0; s < ev->n_stacks; s++) {
        const struct mat_stack *src = &ev->stacks[s];
        if (out->n_stacks >= MAT_MAX_STACKS ||
            out->n_layers + src->n > MAT_MAX_LAYERS)
            return;
        struct mat_stack *dst = &out->stacks[out->n_stacks++];
        dst->weight = w * src->weight;
        dst->first = out->n_layers;
        dst->n = src->n;
        for (int k = 0; k < src->n; k++)
            out->layers[out->n_layers++] = ev->layers[src->first + k];
    }
}

/* The blend of a multi-textured blob's textures at 'pt'; false when the
** point is within no component (the caller shades the texture given). */
static bool eval_blob(const struct mat_ctx *ctx, const iris_object *o,
                      const struct mat_point *pt, struct mat_eval *out)
{
    const iris_texture *tex[MAX_TEXTURES];
    double w[MAX_TEXTURES];
    int n = mat_blob_textures(o, pt->p, tex, w, MAX_TEXTURES);
    if (n == 0)
        return false;
    /* heaviest first, so what does not fit is the lightest */
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            if (w[j] > w[i]) {
                double tw = w[i];
                const iris_texture *tt = tex[i];
                w[i] = w[j];
                tex[i] = tex[j];
                w[j] = tw;
                tex[j] = tt;
            }
    if (n == 1) {
        mat_eval_layers(ctx, tex[0], pt, out);
        return true;
    }
    struct mat_eval one;
    out->n_layers = out->n_stacks = 0;
    for (int i = 0; i < n; i++) {
        mat_eval_layers(ctx, tex[i], pt, &one);
        append_stacks(out, &one, w[i]);
    }
    /* what did not fit is dropped: the rest is renormalised */
    double sum = 0.0;
    for (int s = 0; s < out->n_stacks; s++)
        sum += out->stacks[s].weight;
    for (int s = 0; s < out->n_stacks && sum > 0.0; s++)
        out->stacks[s].weight /= sum;
    return out->n_stacks > 0;
}

void mat_eval_blob_texture(const struct mat_ctx *ctx,
                           const iris_texture *tex,
                           const struct mat_point *pt, struct mat_eval *out)
{
    const iris_object *o = pt->obj;
    if (mat_texture_blended(o) && blob_texture(o, tex) &&
        eval_blob(ctx, o, pt, out))
        return;
    mat_eval_layers(ctx, tex, pt, out);
}

/* POV-Ray's EPSILON (1e-10), which Calculate_Smooth_T compares squared
** determinants and differences with. */
#define SMOOTH_T_EPS 1.0e-10

/*
** How far 'p' lies from corner 'a' towards the opposite edge b-c, as
** POV-Ray's SmoothTriangle::Calculate_Smooth_T measures it: the line
** from 'a' through 'p' meets the line through b and c at q, and the
** result is (p - a) / (q - a) along one axis; 0 at 'a', 1 on the edge.
** p - a = r·(q - a) with q = b + s·(c - b) is solved by Cramer's rule
** in the first pair of axes (xy, xz, yz) whose determinant is not tiny,
** and the ratio is taken on the first axis where q - a is not tiny
** (0 when none is), as POV-Ray does, so that its weights come out on
** faces seen edge-on and on tiny faces too.
*/
static double smooth_t(vec3 p, vec3 a, vec3 b, vec3 c)
{
    /* r·(p - a) + s·(b - c) = b - a, solved for s */
    vec3 u = v3_sub(p, a), e = v3_sub(b, c), f = v3_sub(b, a);
    double dxy = u.x * e.y - u.y * e.x;
    double dxz = u.x * e.z - u.z * e.x;
    double dyz = u.y * e.z - u.z * e.y;
    double s;
    if (dxy * dxy >= SMOOTH_T_EPS)
        s = (u.x * f.y - u.y * f.x) / dxy;
    else if (dxz * dxz >= SMOOTH_T_EPS)
        s = (u.x * f.z - u.z * f.x) / dxz;
    else if (dyz * dyz >= SMOOTH_T_EPS)
        s = (u.y * f.z - u.z * f.y) / dyz;
    else
        return 0.0;
    vec3 q = v3_madd(b, v3_sub(c, b), s);
    vec3 qa = v3_sub(q, a);
    if (qa.x * qa.x >= SMOOTH_T_EPS)
        return u.x / qa.x;
    if (qa.y * qa.y >= SMOOTH_T_EPS)
        return u.y / qa.y;
    if (qa.z * qa.z >= SMOOTH_T_EPS)
        return u.z / qa.z;
    return 0.0;
}

double mat_face_weights(const struct mat_ctx *ctx, const iris_pattern *pat,
                        vec3 p, double w[3])
{
    /* the face's corners in the pattern's space: 'vector' and params */
    vec3 v[3] = { pat->vector,
                  v3(pat->params[0], pat->params[1], pat->params[2]),
                  v3(pat->params[3], pat->params[4], pat->params[5]) };
    vec3 q = pat_space(ctx, pat, p);
    double sum = 0.0;
    for (int k = 0; k < 3; k++) {
        w[k] = 1.0 - smooth_t(q, v[k], v[(k + 1) % 3], v[(k + 2) % 3]);
        sum += w[k];
    }
    /* normalised as POV-Ray does (off the face's plane the three need
    ** not sum to 1); a degenerate sum gives the first texture */
    if (!(fabs(sum) > 0.0) || !isfinite(sum)) {
        w[0] = 1.0;
        w[1] = w[2] = 0.0;
        return 1.0;
    }
    for (int k = 0; k < 3; k++)
        w[k] /= sum;
    return 1.0;
}
