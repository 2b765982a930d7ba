/* SPDX-License-Identifier: MIT */
/*
** pp_test.h: a test hook into povparse (not part of the public API).
**
** pp_test_value() parses 'sdl' and reports the value the symbol 'name'
** holds at the end of the parse, so unit tests can check what expressions,
** directives and macros computed without going through a scene.
*/
#ifndef IRIS_POVPARSE_PP_TEST_H
#define IRIS_POVPARSE_PP_TEST_H

#include "iris/parse.h"

typedef struct pp_test_result {
    int kind;          /* 0 undefined, 1 float, 2 vector, 3 colour,
                          4 string, ... (pp.h enum pp_vkind) */
    int dim;           /* components, or array dimensions */
    double v[5];
    long n;            /* array elements */
    char str[256];
} pp_test_result;

enum iris_status pp_test_value(const char *sdl, const char *name,
                               const iris_parse_options *opts,
                               pp_test_result *res, iris_diag_list *diags);

#endif
