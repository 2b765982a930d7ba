/* SPDX-License-Identifier: MIT */
/*
** parse_placeholder.c: TEMPORARY entry points so that the build links
** while povparse is written. The povparse work replaces this file.
*/
#include "config.h"

#include <stdlib.h>

#include "iris/parse.h"

void iris_diag_list_init(iris_diag_list *list) { list->n = list->cap = 0; list->items = NULL; list->n_errors = list->n_warnings = 0; }
void iris_diag_list_fini(iris_diag_list *list) { free(list->items); list->items = NULL; }
void iris_diag_format(const iris_diag *d, FILE *out) { fprintf(out, "%s:%u:%u: %s\n", d->file, d->line, d->col, d->message); }
enum iris_status iris_parse_file(const char *path, const iris_parse_options *opts, iris_scene **out, iris_diag_list *diags)
{ (void)path; (void)opts; (void)diags; *out = NULL; return IRIS_EUNSUPPORTED; }
void iris_scene_destroy(iris_scene *scene) { (void)scene; }
void iris_scene_dump(const iris_scene *scene, FILE *out) { (void)scene; (void)out; }
