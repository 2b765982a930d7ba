/* SPDX-License-Identifier: MIT */
/*
** common.h: what every public header shares: version, status codes,
** attribute macros and the replaceable allocator.
*/
#ifndef IRIS_COMMON_H
#define IRIS_COMMON_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define IRIS_VERSION_MAJOR 0
#define IRIS_VERSION_MINOR 1
#define IRIS_VERSION_PATCH 0
#define IRIS_VERSION_STRING "0.1.0"

#if defined(__GNUC__)
#define IRIS_NODISCARD __attribute__((warn_unused_result))
#define IRIS_PRINTF(f, a) __attribute__((format(printf, f, a)))
#else
#define IRIS_NODISCARD
#define IRIS_PRINTF(f, a)
#endif

/* Status codes returned by every fallible public function. */
enum iris_status {
    IRIS_OK = 0,
    IRIS_ENOMEM = 1,    /* an allocation failed or a memory limit was hit */
    IRIS_EIO = 2,       /* a file could not be read or written */
    IRIS_EINVAL = 3,    /* an argument or scene value is invalid */
    IRIS_EPARSE = 4,    /* the scene text has an error (see diagnostics) */
    IRIS_EINTR = 5,     /* the work was interrupted (SIGINT, SIGTERM) */
    IRIS_EUNSUPPORTED = 6 /* a feature the scene needs is not implemented */
};

/* Returns a short English description of 'status'. */
const char *iris_status_str(enum iris_status status);

/* Returns the library version as "MAJOR.MINOR.PATCH". */
const char *iris_version(void);

/*
** Allocation hooks. Every allocation of the library goes through these, so
** a test can make the Nth allocation fail. Passing NULL restores malloc.
*/
typedef void *(*iris_malloc_fn)(size_t size);
typedef void *(*iris_realloc_fn)(void *ptr, size_t size);
typedef void (*iris_free_fn)(void *ptr);
void iris_replace_allocator(iris_malloc_fn m, iris_realloc_fn r, iris_free_fn f);

#ifdef __cplusplus
}
#endif

#endif
