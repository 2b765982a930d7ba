/* SPDX-License-Identifier: MIT */
/*
** fuzz_plan.c: a libFuzzer target for parse -> render plan (issue 7): any
** bytes that parse must give a scene the planner can read: every object
** tree walked, every light counted, every interior's dispersion asked,
** under each quality level that changes what the plan contains. No pixel
** is rendered and no image file is loaded (the material context would
** open the files a fuzzed scene names), so every input finishes in
** milliseconds. Built by tests/fuzz/build.sh, not by make check.
*/
#include "config.h"

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "fuzz_common.h"
#include "iris/parse.h"
#include "iris/render.h"
#include "render/plan.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    iris_diag_list d;
    iris_scene *scene = NULL;
    enum iris_status st = fuzz_parse(data, size, &scene, &d);
    if (st == IRIS_OK && scene) {
        FILE *null = fopen("/dev/null", "w");
        /* quality 9 plans photons, 4 drops area lights, 0 everything */
        static const int qualities[] = { 9, 4, 0 };
        for (size_t i = 0; i < sizeof qualities / sizeof *qualities; i++) {
            iris_render_options ro;
            iris_render_defaults(&ro);
            ro.quality = qualities[i];
            ro.aa = (enum iris_aa_method)(i % 4);
            ro.spectral_samples_min = (int)i * 8;
            struct render_plan plan;
            plan_compute(scene, &ro, &plan);
            plan_print(&plan, null);
        }
        if (null)
            fclose(null);
    }
    iris_scene_destroy(scene);
    iris_diag_list_fini(&d);
    return 0;
}
