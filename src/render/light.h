/* SPDX-License-Identifier: MIT */
/*
** light.h: light sources as POV-Ray's point.cpp and trace.cpp see them:
** the direction and distance from a point to a light, spot and cylinder
** attenuation, distance fade, and the area-light sample positions.
**
** Depends on: math, spectrum (a light's colour). Used by: render
** (trace.c), and tests.
*/
#ifndef IRIS_RENDER_LIGHT_H
#define IRIS_RENDER_LIGHT_H

#include <math.h>
#include <stdbool.h>

#include "iris/scene.h"
#include "math/vec3.h"

struct rquery;

/* A light prepared for shading: POV-Ray's derived quantities. */
struct rlight {
    const iris_light *src;
    double colour[3];          /* src's colour times its spectrum's RGB
                               ** (spec_light_rgb; = colour for D65) */
    vec3 centre;               /* location */
    vec3 points_at;
    vec3 dir;                  /* unit, location -> point_at */
    double cos_radius, cos_falloff; /* spot: cosines; cylinder: lengths */
    double radius, falloff;    /* cylinder radius and falloff lengths */
    double tightness;
    bool spot, cylinder, parallel, area, fill;
    /* spot, cylinder or fade_power > 0: light_attenuation() can give
    ** other than 1 (one flag read per shadow ray instead of three) */
    bool attenuates;
    /* colour is black (each channel below trace.c's epsilon): set by
    ** tracer_init(), which owns that test */
    bool black;
    vec3 axis1, axis2;
    int size1, size2;
    /* projected_through: a query on that object alone (render.c builds
    ** it), NULL for a light without one */
    const struct rquery *through;
};

/* Fills 'out' from 'l'. */
void light_prepare(const iris_light *l, struct rlight *out);

/*
** POV-Ray's ComputeOneWhiteLightRay: the unit direction '*L' from 'p'
** towards the light (centre moved by 'jitter') and the distance '*depth'
** along it, projected for parallel and cylinder lights.
** Inline, as light_area_offset(): called per shadow ray, and area lights
** call them per grid sample (the calls' vec3 arguments on the stack were
** 5-10 % of an area-light scene's render).
*/
static inline void light_ray(const struct rlight *l, vec3 p, vec3 jitter,
                             vec3 *L, double *depth)
{
    vec3 centre = v3_add(l->centre, jitter);
    if (l->cylinder) {
        vec3 d = v3_sub(centre, l->points_at);
        double len = v3_len(d);
        *depth = len > 0 ? v3_dot(v3_sub(centre, p), d) / len : 0;
        *L = len > 0 ? v3_scale(d, 1.0 / len) : v3(0, 1, 0);
    } else {
        vec3 d = v3_sub(centre, p);
        *depth = v3_len(d);
        *L = *depth > 0 ? v3_scale(d, 1.0 / *depth) : v3(0, 1, 0);
    }
    if (l->parallel) {
        if (l->area) {
            vec3 v1 = v3_norm(v3_sub(centre, l->points_at));
            *depth *= v3_dot(v1, *L);
            *L = v1;
        } else {
            *depth *= -v3_dot(l->dir, *L);
            *L = v3_neg(l->dir);
        }
    }
}

/*
** POV-Ray's Attenuate_Light: spot/cylinder falloff and distance fade for
** a light ray leaving 'p' along unit 'L' with length 'depth'.
*/
double light_attenuation_full(const struct rlight *l, vec3 p, vec3 L,
                              double depth);
static inline double light_attenuation(const struct rlight *l, vec3 p,
                                       vec3 L, double depth)
{
    /* inline: a point light without fade, the usual light, is 1 (what
    ** light_attenuation_full() returns for it) */
    if (!l->attenuates)
        return 1.0;
    return light_attenuation_full(l, p, L, depth);
}

/* POV-Ray's cubic_spline(low, high, pos): 0 below, 1 above, 3t^2-2t^3. */
double light_smoothstep(double low, double high, double pos);

/*
** The offset of area-light grid sample (u, v) (fractional when jittered)
** from the light centre along 'a1', 'a2' (circular maps the square grid
** onto a disc, as POV-Ray does).
*/
static inline vec3 light_area_offset(const struct rlight *l, vec3 a1,
                                     vec3 a2, double u, double v)
{
    if (l->src->circular) {
        double ju = (l->size1 > 1 ? u / (l->size1 - 1) : 0.5) - 0.5 + 0.001;
        double jv = (l->size2 > 1 ? v / (l->size2 - 1) : 0.5) - 0.5 + 0.001;
        double s = fmax(fabs(ju), fabs(jv)) / sqrt(ju * ju + jv * jv);
        return v3_add(v3_scale(a1, ju * s), v3_scale(a2, jv * s));
    }
    vec3 o = v3(0, 0, 0);
    if (l->size1 > 1)
        o = v3_madd(o, a1, u / (double)(l->size1 - 1) - 0.5);
    if (l->size2 > 1)
        o = v3_madd(o, a2, v / (double)(l->size2 - 1) - 0.5);
    return o;
}

/*
** POV-Ray's projected_through test (TracePointLightShadowRay): a light
** with a projected_through object reaches 'p' only if the ray from 'p'
** along 'L' meets that object (beyond 'tmin') before the light, at
** '*depth'. Returns false when it does not (the light is black there);
** else true, with '*depth' cut to the object's hit, since only objects
** between 'p' and the projecting object can cast shadows. A light
** without one returns true and leaves '*depth'.
*/
bool light_through_object(const struct rlight *l, vec3 p, double tmin,
                          vec3 L, double *depth);
static inline bool light_through(const struct rlight *l, vec3 p, double tmin,
                                 vec3 L, double *depth)
{
    /* inline: asked for every shadow ray, almost always of a light
    ** without projected_through */
    return !l->through || light_through_object(l, p, tmin, L, depth);
}

#endif
