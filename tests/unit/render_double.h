/* SPDX-License-Identifier: MIT */
/*
** render_double.h: a scene double for the tracer's unit tests.
**
** Spheres and planes with exact ray intersection, answering through the
** same query table (src/render/query.h) that the real render fills from
** Embree, so the tracer is tested without the geometry module. Only the
** fields the tracer reads are set: t, p, n, shading_n, obj, top,
** texture, interior. Object transforms are ignored (tests place shapes
** directly).
*/
#ifndef IRIS_TESTS_RENDER_DOUBLE_H
#define IRIS_TESTS_RENDER_DOUBLE_H

#include "render/query.h"

struct dbl_scene {
    int n;
    iris_object **objs;
};

/* Fills 'q' to query 'd' (borrowed). */
void dbl_query(const struct dbl_scene *d, struct rquery *q);

struct tracer;
struct trace_ctx;

/* Traces one camera-like ray from 'o' along 'd' (normalised here),
** starting in the interiors that contain 'o', into 'rgb'. */
void dbl_shoot(const struct tracer *t, struct trace_ctx *c, vec3 o, vec3 d,
               double rgb[3]);

#endif
