/* SPDX-License-Identifier: MIT */
/*
** geomq.h: the parser's geometry queries (trace(), inside(), extents of
** objects the parser cannot bound; include/iris/parse.h) answered with
** src/accel on a world that holds only the queried object.
*/
#ifndef IRIS_CLI_GEOMQ_H
#define IRIS_CLI_GEOMQ_H

#include "iris/parse.h"

struct geomq;

/* A query cache for one parse; NULL when out of memory. 'log' receives
** accel's warnings about objects it cannot build (may be NULL). */
struct geomq *geomq_new(FILE *log);

/* The callbacks to put in iris_parse_options.geometry ('q' as user). */
const iris_geometry_queries *geomq_callbacks(struct geomq *q);

/* Frees the cache and every structure built. NULL does nothing. */
void geomq_free(struct geomq *q);

#endif
