/* SPDX-License-Identifier: MIT */
/*
** parsedump.c: parses a scene and prints its dump (or its diagnostics),
** the driver of the golden tests in tests/parse/cases.
**
** usage: parsedump [-w] [-q] [-t] [-U] [-W] [-s WxH] [-L dir] [-D name=value]
**                  [-n max_while] [-m MiB] file.pov
** Prints every diagnostic with iris_diag_format(), then the scene dump
** when the parse succeeded; exits 0 on success, 2 on a parse error.
** -w hides warnings; -q prints no dump; -U reads files anywhere
** (IRIS_IO_UNRESTRICTED); -W allows #fopen write in the scene's directory;
** -s sets image_width and image_height; -t prints the time iris_parse_file
** took on stderr ("parse time: S s"), like POV-Ray's own "Parse Time".
** trace(), inside() and object extents are answered as the iris command
** answers them (src/cli/geomq.c).
*/
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli/geomq.h"
#include "iris/parse.h"

int main(int argc, char **argv)
{
    iris_parse_options opt;
    memset(&opt, 0, sizeof opt);
    const char *paths[16];
    iris_declare decl[16];
    int np = 0, nd = 0;
    bool no_warn = false, dump = true, timing = false;
    int i;
    for (i = 1; i < argc - 1; i++) {
        if (!strcmp(argv[i], "-w")) {
            no_warn = true;
        } else if (!strcmp(argv[i], "-q")) {
            dump = false;
        } else if (!strcmp(argv[i], "-t")) {
            timing = true;
        } else if (!strcmp(argv[i], "-s")) {
            /* image_width x image_height, as +W +H give them */
            if (sscanf(argv[++i], "%dx%d", &opt.image_width,
                       &opt.image_height) != 2)
                return 64;
        } else if (!strcmp(argv[i], "-U")) {
            opt.read_policy = IRIS_IO_UNRESTRICTED;
        } else if (!strcmp(argv[i], "-W")) {
            opt.allow_writes = true;
        } else if (!strcmp(argv[i], "-L") && np < 16) {
            paths[np++] = argv[++i];
        } else if (!strcmp(argv[i], "-n")) {
            opt.max_while_iterations = atol(argv[++i]);
        } else if (!strcmp(argv[i], "-m")) {
            opt.max_memory = (size_t)atol(argv[++i]) << 20;
        } else if (!strcmp(argv[i], "-D") && nd < 16) {
            char *s = argv[++i];
            char *eq = strchr(s, '=');
            if (!eq)
                return 64;
            *eq = 0;
            decl[nd].name = s;
            decl[nd].value = eq + 1;
            nd++;
        } else {
            break;
        }
    }
    if (i != argc - 1) {
        fprintf(stderr, "usage: parsedump [-w] [-q] [-t] [-U] [-W] [-s WxH] [-L dir] [-D n=v] "
                "[-n max] [-m MiB] file.pov\n");
        return 64;
    }
    opt.include_paths = paths;
    opt.n_include_paths = np;
    opt.declares = decl;
    opt.n_declares = nd;
    opt.debug_stream = stdout;
    struct geomq *gq = geomq_new(NULL);
    opt.geometry = geomq_callbacks(gq);
    iris_diag_list diags;
    iris_diag_list_init(&diags);
    iris_scene *scene = NULL;
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    enum iris_status st = iris_parse_file(argv[argc - 1], &opt, &scene,
                                          &diags);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    geomq_free(gq);
    if (timing)
        fprintf(stderr, "parse time: %.6f s\n",
                (double)(t1.tv_sec - t0.tv_sec) +
                    1e-9 * (double)(t1.tv_nsec - t0.tv_nsec));
    for (int k = 0; k < diags.n; k++)
        if (!no_warn || diags.items[k].sev == IRIS_SEV_ERROR)
            iris_diag_format(&diags.items[k], stdout);
    iris_diag_list_fini(&diags);
    if (st != IRIS_OK)
        return 2;
    if (dump)
        iris_scene_dump(scene, stdout);
    iris_scene_destroy(scene);
    return 0;
}
