/* SPDX-License-Identifier: MIT */
/*
** parse.h: the POV-Ray SDL front end (libpovparse).
**
** iris_parse_file() reads a .pov file with its #includes and returns the
** plain-data scene of scene.h. Errors and warnings are returned as values
** (struct iris_diag), never printed; iris_diag_format() renders one in the
** compiler style "file:line:col: error: message", with the source line and
** a caret under the offending token.
*/
#ifndef IRIS_PARSE_H
#define IRIS_PARSE_H

#include <stddef.h>
#include <stdio.h>

#include "iris/common.h"
#include "iris/scene.h"

#ifdef __cplusplus
extern "C" {
#endif

enum iris_severity { IRIS_SEV_NOTE = 0, IRIS_SEV_WARNING, IRIS_SEV_ERROR };

/* One diagnostic. 'chain' lists the #include and macro calls that led to
** it, innermost first, already formatted ("in macro 'M' called at f:3:1"). */
typedef struct iris_diag {
    enum iris_severity sev;
    char file[512];            /* path as opened */
    unsigned line, col;        /* 1-based; 0 = no position */
    char message[512];
    char source_line[256];     /* the line's text, tabs expanded */
    unsigned caret_len;        /* width of the ~~~ under the token, >= 1 */
    int n_chain;
    char chain[8][256];
} iris_diag;

/* A growing list of diagnostics, owned by the caller. */
typedef struct iris_diag_list {
    int n, cap;
    iris_diag *items;
    int n_errors, n_warnings;  /* counted; warnings past the first 1000 are not kept */
} iris_diag_list;

void iris_diag_list_init(iris_diag_list *list);
void iris_diag_list_fini(iris_diag_list *list);

/* Writes 'd' to 'out' in the compiler style, with the caret line. */
void iris_diag_format(const iris_diag *d, FILE *out);

/* File access policy (issue 7: reads stay inside the allowed tree). */
enum iris_io_policy { IRIS_IO_RESTRICTED = 0, IRIS_IO_UNRESTRICTED };

/* One Declare=Name=Value from the command line. */
typedef struct iris_declare {
    const char *name;
    const char *value;         /* parsed as an SDL expression */
} iris_declare;

/*
** Geometry the parser cannot compute alone: trace(), inside(), and
** min_extent/max_extent of objects it cannot bound itself (text, meshes,
** isosurfaces, ...). A program that links the renderer supplies these
** (the iris CLI answers them with src/accel on a world holding only that
** object); without them trace() and inside() are located errors and
** such extents are POV-Ray's infinite box, +-1e10.
**
** Every call gets the scene parsed so far ('scene': its settings; its
** object list is still growing) and one object as the renderer would
** see it: world space, transforms folded in, textures resolved. The
** object lives in the scene's arena until the parse ends, and the
** parser passes the same pointer for the same declared object, so a
** callback may cache what it builds by that pointer (and free the cache
** when the parse returns). Any member may be NULL.
*/
typedef struct iris_geometry_queries {
    void *user;
    /* World bounding box of 'obj'; false when it is unbounded. */
    bool (*bounds)(void *user, const iris_scene *scene,
                   const iris_object *obj, iris_vec3 *lo, iris_vec3 *hi);
    /* The nearest hit of the ray origin + t*dir, t > 0 ('dir' has unit
    ** length) with 'obj': the point and the unit normal pointing out of
    ** the object (POV-Ray's: flipped for inverse). False on a miss. */
    bool (*trace)(void *user, const iris_scene *scene,
                  const iris_object *obj, iris_vec3 origin, iris_vec3 dir,
                  iris_vec3 *point, iris_vec3 *normal);
    /* Whether 'point' is inside the solid 'obj' (POV-Ray's Inside()). */
    bool (*inside)(void *user, const iris_scene *scene,
                   const iris_object *obj, iris_vec3 point);
} iris_geometry_queries;

/* Options of one parse. Zeroed options give POV-Ray's behaviour. */
typedef struct iris_parse_options {
    int n_include_paths;       /* +L paths, searched after the scene's dir */
    const char *const *include_paths;
    bool no_system_includes;   /* do not add POV-Ray's installed includes */
    int n_declares;
    const iris_declare *declares;
    double clock;              /* +K, default 0 */
    int frame_number;          /* default 0 */
    int image_width, image_height; /* for image_width/image_height */
    long max_while_iterations; /* per #while/#for loop; 0 = default
                                  (1 000 000: an endless loop stops in
                                  about a second) */
    int max_include_depth;     /* 0 = default (64) */
    int max_macro_depth;       /* 0 = default (256) */
    size_t max_memory;         /* 0 = default (2 GiB, at most a third of
                                  the address-space limit, RLIMIT_AS) */
    enum iris_io_policy read_policy;
    bool allow_writes;         /* #fopen write inside the scene dir */
    bool quiet_debug;          /* drop #debug output */
    FILE *debug_stream;        /* #debug/#warning text; NULL = stderr */
    const iris_geometry_queries *geometry; /* NULL: trace()/inside() fail */
    volatile int *interrupt;   /* when set non-zero (SIGINT), the parse
                                  stops soon with IRIS_EINTR */
} iris_parse_options;

/*
** Parses 'path' into '*out'. Returns IRIS_OK, IRIS_EPARSE (with at least
** one error in 'diags'), IRIS_EIO, IRIS_ENOMEM (located in 'diags') or
** IRIS_EINTR (opts->interrupt was set). On failure '*out' is NULL.
** 'diags' also receives warnings (unsupported features, POV-Ray's
** "possible parse errors"), once per keyword and location.
*/
enum iris_status iris_parse_file(const char *path,
                                 const iris_parse_options *opts,
                                 iris_scene **out, iris_diag_list *diags);

/* Parses SDL held in memory; 'name' is used in diagnostics. */
enum iris_status iris_parse_string(const char *name, const char *text,
                                   size_t len,
                                   const iris_parse_options *opts,
                                   iris_scene **out, iris_diag_list *diags);

/* Writes a readable dump of 'scene' (used by the parse tests). */
void iris_scene_dump(const iris_scene *scene, FILE *out);

#ifdef __cplusplus
}
#endif

#endif
