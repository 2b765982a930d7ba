/* SPDX-License-Identifier: MIT */
/*
** parse_util.h: what the parser's unit tests (test_parse.c,
** test_parse_parity.c and others) share: parse a scene from a string, failing the
** test on a parse error, and write a scratch file.
*/
#ifndef IRIS_TESTS_PARSE_UTIL_H
#define IRIS_TESTS_PARSE_UTIL_H

#include "testutil.h"

#include <stdio.h>
#include <string.h>

#include "iris/parse.h"

/* Parses 'sdl' (as "t.pov") with 'o' (NULL = defaults); prints the
** diagnostics and fails the test on a parse error. */
static inline iris_scene *pt_scene_with(const char *sdl,
                                        const iris_parse_options *o)
{
    iris_scene *sc = NULL;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = iris_parse_string("t.pov", sdl, strlen(sdl), o,
                                            &sc, &d);
    for (int i = 0; i < d.n && st != IRIS_OK; i++)
        iris_diag_format(&d.items[i], stderr);
    iris_diag_list_fini(&d);
    assert_int_equal(st, IRIS_OK);
    return sc;
}

/* Parses 'sdl' (as "t.pov"); returns the number of warnings, or -1 if it
** does not parse, and the first diagnostic's line and column. */
static inline int pt_parse_warnings(const char *sdl, unsigned *line,
                                    unsigned *col)
{
    iris_scene *sc = NULL;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = iris_parse_string("t.pov", sdl, strlen(sdl), NULL,
                                            &sc, &d);
    if (d.n > 0) {
        *line = d.items[0].line;
        *col = d.items[0].col;
    }
    int warnings = d.n_warnings;
    iris_diag_list_fini(&d);
    if (sc)
        iris_scene_destroy(sc);
    return st == IRIS_OK ? warnings : -1;
}

/* Writes 'text' to 'path'; fails the test if it cannot. */
static inline void pt_put_file(const char *path, const char *text)
{
    FILE *fp = fopen(path, "w");
    assert_non_null(fp);
    fputs(text, fp);
    fclose(fp);
}

#endif
