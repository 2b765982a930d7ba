/* SPDX-License-Identifier: MIT */
/*
** arena.h: a chain-of-blocks bump allocator.
**
** The scene and the parser's scratch space live in arenas: nodes are never
** freed one by one, and arena_destroy() frees the whole chain. An arena can
** carry a byte limit; past it arena_alloc() returns NULL, which the parser
** turns into a located "scene too large" error instead of exhausting the
** machine. Not thread-safe: one arena per owner.
*/
#ifndef IRIS_UTIL_ARENA_H
#define IRIS_UTIL_ARENA_H

#include <stddef.h>

typedef struct iris_arena iris_arena;

/* Creates an empty arena; 'limit' bytes at most in total (0 = none). */
iris_arena *arena_create(size_t limit);

/* Frees every block. NULL does nothing. */
void arena_destroy(iris_arena *a);

/* Returns 'size' bytes aligned to 16, zeroed; NULL past the limit or when
** memory runs out. */
void *arena_alloc(iris_arena *a, size_t size);

/* Returns an array of 'n' elements of 'size' bytes (overflow-checked). */
void *arena_array(iris_arena *a, size_t n, size_t size);

/* Copies 'len' bytes of 's' into the arena with a terminating NUL. */
char *arena_strndup(iris_arena *a, const char *s, size_t len);
char *arena_strdup(iris_arena *a, const char *s);

/* Bytes handed out so far (what the limit is checked against). */
size_t arena_used(const iris_arena *a);

#endif
