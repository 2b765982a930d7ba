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
*/
void light_ray(const struct rlight *l, vec3 p, vec3 jitter, vec3 *L,
               double *depth);

/*
** POV-Ray's Attenuate_Light: spot/cylinder falloff and distance fade for
** a light ray leaving 'p' along unit 'L' with length 'depth'.
*/
double light_attenuation(const struct rlight *l, vec3 p, vec3 L,
                         double depth);

/* POV-Ray's cubic_spline(low, high, pos): 0 below, 1 above, 3t^2-2t^3. */
double light_smoothstep(double low, double high, double pos);

/*
** The offset of area-light grid sample (u, v) (fractional when jittered)
** from the light centre along 'a1', 'a2' (circular maps the square grid
** onto a disc, as POV-Ray does).
*/
vec3 light_area_offset(const struct rlight *l, vec3 a1, vec3 a2, double u,
                       double v);

/*
** POV-Ray's projected_through test (TracePointLightShadowRay): a light
** with a projected_through object reaches 'p' only if the ray from 'p'
** along 'L' meets that object (beyond 'tmin') before the light, at
** '*depth'. Returns false when it does not (the light is black there);
** else true, with '*depth' cut to the object's hit, since only objects
** between 'p' and the projecting object can cast shadows. A light
** without one returns true and leaves '*depth'.
*/
bool light_through(const struct rlight *l, vec3 p, double tmin, vec3 L,
                   double *depth);

#endif
