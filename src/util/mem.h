/* SPDX-License-Identifier: MIT */
/*
** mem.h: the library's allocation entry points.
**
** Every allocation in libiris goes through iris_malloc/iris_realloc/
** iris_free so that tests can replace the allocator (common.h) and make the
** Nth allocation fail. xcalloc-style helpers check for size overflow.
*/
#ifndef IRIS_UTIL_MEM_H
#define IRIS_UTIL_MEM_H

#include <stddef.h>

void *iris_malloc(size_t size);
void *iris_calloc(size_t n, size_t size);   /* NULL on overflow */
void *iris_realloc(void *ptr, size_t size);
void iris_free(void *ptr);
char *iris_strdup(const char *s);

#endif
