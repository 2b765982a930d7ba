/* SPDX-License-Identifier: MIT */
/*
** fuzz_render.c: a libFuzzer target for parse -> render (issue 7): any
** bytes that parse are rendered into a 4x3 image on one thread, and every
** pixel the renderer returns must be finite (the renderer replaces a
** non-finite sample by 0 and counts it; a non-finite value that gets past
** that is a defect, as is a crash, a hang or unbounded memory, which
** libFuzzer reports itself). 4x3 keeps an input at milliseconds: the
** fuzzer explores scenes, not pixels. Photons are off (their shooting is
** the photon tests' business and its cost would set the exec rate); the
** quality stays 9 so area lights, media and radiosity are traced. Image
** files a scene names are read as the iris command reads them (the
** parser's restricted read policy: the current directory only). Built by
** tests/fuzz/build.sh, not by make check.
*/
#include "config.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_common.h"
#include "iris/image.h"
#include "iris/parse.h"
#include "iris/render.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    iris_diag_list d;
    iris_scene *scene = NULL;
    enum iris_status st = fuzz_parse(data, size, &scene, &d);
    if (st == IRIS_OK && scene) {
        iris_render_options ro;
        iris_render_defaults(&ro);
        ro.width = 4;
        ro.height = 3;
        ro.threads = 1;
        ro.use_photons = false;
        iris_image img;
        iris_render_stats rs;
        memset(&rs, 0, sizeof rs);
        char err[512] = "";
        if (iris_image_init(&img, ro.width, ro.height) == IRIS_OK) {
            if (iris_render(scene, &ro, &img, &rs, err, sizeof err) ==
                IRIS_OK) {
                size_t n = (size_t)img.width * (size_t)img.height * 4;
                for (size_t i = 0; i < n; i++)
                    if (!isfinite(img.pixels[i])) {
                        fprintf(stderr, "fuzz_render: pixel value %zu is "
                                "%g\n", i, (double)img.pixels[i]);
                        abort();
                    }
            }
            iris_image_fini(&img);
        }
    }
    iris_scene_destroy(scene);
    iris_diag_list_fini(&d);
    return 0;
}
