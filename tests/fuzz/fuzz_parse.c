/* SPDX-License-Identifier: MIT */
/*
** fuzz_parse.c: a libFuzzer target for the scanner and parser: any bytes
** must give IRIS_OK or an error status, never a crash, a hang or growing
** memory. Limits are set low so that every input finishes quickly.
** Built by tests/fuzz/build.sh, not by make check.
*/
#include "config.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_common.h"
#include "iris/parse.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    iris_diag_list d;
    iris_scene *scene = NULL;
    enum iris_status st = fuzz_parse(data, size, &scene, &d);
    if (st == IRIS_OK) {
        FILE *null = fopen("/dev/null", "w");
        if (null) {
            iris_scene_dump(scene, null);
            fclose(null);
        }
    }
    for (int i = 0; i < d.n; i++) {
        FILE *null = fopen("/dev/null", "w");
        if (null) {
            iris_diag_format(&d.items[i], null);
            fclose(null);
        }
    }
    iris_scene_destroy(scene);
    iris_diag_list_fini(&d);
    return 0;
}
