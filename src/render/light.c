/* SPDX-License-Identifier: MIT */
/*
** light.c: light geometry and attenuation (see light.h), following
** POV-Ray 3.7's point.cpp (Attenuate_Light, cubic_spline) and trace.cpp
** (ComputeOneWhiteLightRay, TraceAreaLightSubsetShadowRay's offsets).
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "render/light.h"
#include "render/query.h"
#include "spectrum/spectrum.h"

#define LIGHT_EPSILON 1e-10

void light_prepare(const iris_light *l, struct rlight *out)
{
    memset(out, 0, sizeof *out);
    out->src = l;
    spec_light_rgb(l, out->colour);
    out->centre = l->location;
    out->points_at = l->point_at;
    vec3 d = v3_sub(l->point_at, l->location);
    out->dir = v3_len(d) > 0 ? v3_norm(d) : v3(0, 0, 1);
    out->spot = l->kind == IRIS_LIGHT_SPOT;
    out->cylinder = l->kind == IRIS_LIGHT_CYLINDER;
    out->parallel = l->parallel || out->cylinder;
    out->tightness = l->tightness;
    if (out->spot) {
        out->cos_radius = cos(l->radius * M_PI / 180.0);
        out->cos_falloff = cos(l->falloff * M_PI / 180.0);
    } else if (out->cylinder) {
        out->radius = l->radius;
        out->falloff = l->falloff;
    }
    out->area = l->area && l->size1 > 0 && l->size2 > 0;
    out->axis1 = l->axis1;
    out->axis2 = l->axis2;
    out->size1 = l->size1 > 0 ? l->size1 : 1;
    out->size2 = l->size2 > 0 ? l->size2 : 1;
    out->fill = l->shadowless;
    out->attenuates = out->spot || out->cylinder || l->fade_power > 0.0;
}

double light_smoothstep(double low, double high, double pos)
{
    if (pos < low)
        return 0.0;
    if (pos >= high)
        return 1.0;
    pos = (pos - low) / (high - low);
    return (3 - 2 * pos) * pos * pos;
}

double light_attenuation_full(const struct rlight *l, vec3 p, vec3 L,
                              double depth)
{
    double att = 1.0;
    if (l->spot) {
        double c = v3_dot(L, l->dir);
        if (depth > 0.0)
            c = -c;
        if (!(c > 0.0))
            return 0.0;
        att = pow(c, l->tightness);
        if (l->cos_radius > 0.0 && c < l->cos_radius)
            att *= light_smoothstep(l->cos_falloff, l->cos_radius, c);
    } else if (l->cylinder) {
        vec3 v1 = v3_sub(p, l->centre);
        double k = v3_dot(v1, l->dir);
        if (!(k > 0.0))
            return 0.0;
        double len = v3_len(v3_madd(v1, l->dir, -k));
        if (!(len < l->falloff))
            return 0.0;
        double dist = 1.0 - len / l->falloff;
        att = pow(dist, l->tightness);
        if (l->radius > 0.0 && len > l->radius)
            att *= light_smoothstep(0.0, 1.0 - l->radius / l->falloff, dist);
    }
    const iris_light *s = l->src;
    if (att > 0.0 && s->fade_power > 0.0 &&
        fabs(s->fade_distance) > LIGHT_EPSILON)
        att *= 2.0 / (1.0 + pow(depth / s->fade_distance, s->fade_power));
    return isfinite(att) ? att : 0.0;
}

bool light_through_object(const struct rlight *l, vec3 p, double tmin,
                          vec3 L, double *depth)
{
    ray r = { p, L };
    struct hit h;
    if (!l->through->intersect(l->through->impl, &r, tmin, *depth, 0, &h) ||
        !(h.t < *depth))
        return false;
    *depth = h.t;
    return true;
}
