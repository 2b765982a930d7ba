/* SPDX-License-Identifier: MIT */
/*
** fuzz_common.h: what the libFuzzer targets share: the parse of one input
** with limits set low, so that every input finishes quickly (a fuzzer
** that waits on a 1e6-iteration #while finds nothing else).
*/
#ifndef IRIS_FUZZ_COMMON_H
#define IRIS_FUZZ_COMMON_H

#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "iris/parse.h"

/* Parses 'data' as a scene file "fuzz.pov"; 'd' is initialised here and
** the caller frees it and the scene. */
static inline enum iris_status fuzz_parse(const uint8_t *data, size_t size,
                                          iris_scene **scene,
                                          iris_diag_list *d)
{
    iris_parse_options o;
    memset(&o, 0, sizeof o);
    o.max_while_iterations = 20000;
    o.max_macro_depth = 64;
    o.max_include_depth = 8;
    o.max_memory = 64u << 20;
    o.quiet_debug = true;
    o.no_system_includes = true;
    iris_diag_list_init(d);
    *scene = NULL;
    return iris_parse_string("fuzz.pov", (const char *)data, size, &o, scene,
                             d);
}

#endif
