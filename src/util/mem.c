/* SPDX-License-Identifier: MIT */
/*
** mem.c: the replaceable allocator behind iris_malloc and friends.
*/
#include "config.h"

#include "util/mem.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "iris/common.h"

/* The hooks are set once, before any rendering starts (tests, embedding
** programs); they are read-only while threads run. */
static iris_malloc_fn hook_malloc = malloc;
static iris_realloc_fn hook_realloc = realloc;
static iris_free_fn hook_free = free;

void iris_replace_allocator(iris_malloc_fn m, iris_realloc_fn r, iris_free_fn f)
{
    hook_malloc = m ? m : malloc;
    hook_realloc = r ? r : realloc;
    hook_free = f ? f : free;
}

void *iris_malloc(size_t size)
{
    return hook_malloc(size ? size : 1);
}

void *iris_calloc(size_t n, size_t size)
{
    if (size && n > SIZE_MAX / size)
        return NULL;
    void *p = iris_malloc(n * size);
    if (p)
        memset(p, 0, n * size);
    return p;
}

void *iris_realloc(void *ptr, size_t size)
{
    return hook_realloc(ptr, size ? size : 1);
}

void iris_free(void *ptr)
{
    if (ptr)
        hook_free(ptr);
}

char *iris_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = iris_malloc(n);
    if (p)
        memcpy(p, s, n);
    return p;
}

const char *iris_status_str(enum iris_status status)
{
    switch (status) {
    case IRIS_OK: return "success";
    case IRIS_ENOMEM: return "out of memory";
    case IRIS_EIO: return "input/output error";
    case IRIS_EINVAL: return "invalid argument";
    case IRIS_EPARSE: return "scene error";
    case IRIS_EINTR: return "interrupted";
    case IRIS_EUNSUPPORTED: return "unsupported feature";
    }
    return "unknown status";
}

const char *iris_version(void)
{
    return IRIS_VERSION_STRING;
}
