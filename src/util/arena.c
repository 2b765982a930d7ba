/* SPDX-License-Identifier: MIT */
/*
** arena.c: a chain-of-blocks bump allocator (see arena.h).
*/
#include "config.h"

#include "util/arena.h"

#include <stdint.h>
#include <string.h>

#include "util/mem.h"

#define ARENA_ALIGN 16
#define ARENA_BLOCK (64 * 1024)

struct block {
    struct block *prev;
    size_t size, used;
    /* data follows, aligned */
};

struct iris_arena {
    struct block *head;
    size_t limit, total;
};

static size_t header_size(void)
{
    return (sizeof(struct block) + ARENA_ALIGN - 1) & ~(size_t)(ARENA_ALIGN - 1);
}

iris_arena *arena_create(size_t limit)
{
    iris_arena *a = iris_calloc(1, sizeof *a);
    if (a)
        a->limit = limit;
    return a;
}

void arena_destroy(iris_arena *a)
{
    if (!a)
        return;
    struct block *b = a->head;
    while (b) {
        struct block *prev = b->prev;
        iris_free(b);
        b = prev;
    }
    iris_free(a);
}

void *arena_alloc(iris_arena *a, size_t size)
{
    if (size > SIZE_MAX / 2)
        return NULL;
    size = (size + ARENA_ALIGN - 1) & ~(size_t)(ARENA_ALIGN - 1);
    if (size == 0)
        size = ARENA_ALIGN;
    if (a->limit && a->total + size > a->limit)
        return NULL;
    struct block *b = a->head;
    if (!b || b->size - b->used < size) {
        /* Start a new block; big requests get a block of their own. */
        size_t cap = size > ARENA_BLOCK / 4 ? size : ARENA_BLOCK;
        struct block *nb = iris_malloc(header_size() + cap);
        if (!nb)
            return NULL;
        nb->size = cap;
        nb->used = 0;
        if (b && size > ARENA_BLOCK / 4 && b->size - b->used >= ARENA_BLOCK / 8) {
            /* Keep filling the current block: slip the big one under it. */
            nb->prev = b->prev;
            b->prev = nb;
        } else {
            nb->prev = b;
            a->head = nb;
        }
        b = nb;
    }
    char *p = (char *)b + header_size() + b->used;
    b->used += size;
    a->total += size;
    memset(p, 0, size);
    return p;
}

void *arena_array(iris_arena *a, size_t n, size_t size)
{
    if (size && n > SIZE_MAX / 4 / size)
        return NULL;
    return arena_alloc(a, n * size);
}

char *arena_strndup(iris_arena *a, const char *s, size_t len)
{
    char *p = arena_alloc(a, len + 1);
    if (p) {
        memcpy(p, s, len);
        p[len] = 0;
    }
    return p;
}

char *arena_strdup(iris_arena *a, const char *s)
{
    return arena_strndup(a, s, strlen(s));
}

size_t arena_used(const iris_arena *a)
{
    return a->total;
}
