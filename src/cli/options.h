/* SPDX-License-Identifier: MIT */
/*
** options.h: the iris command line.
**
** POV-Ray's switches as POV-Ray users type them (+I +O +W +H +A +AM +R +J
** +Q +L +WT +FN +FE, +D/-D, +V/-V, Declare=Name=Value; case-insensitive,
** '+' and '-' alike for numeric switches) and GNU long options for what
** POV-Ray has no switch for. cli_parse() only fills a struct; it prints
** nothing and never exits, so it can be tested.
*/
#ifndef IRIS_CLI_OPTIONS_H
#define IRIS_CLI_OPTIONS_H

#include <stdbool.h>
#include <stddef.h>

#include "iris/iris.h"

#define CLI_MAX_PATHS 64
#define CLI_MAX_DECLARES 64

enum cli_action { CLI_RENDER = 0, CLI_HELP, CLI_VERSION, CLI_PARSE_ONLY,
                  CLI_PLAN };

struct cli_options {
    enum cli_action action;
    const char *scene;          /* +I or the plain argument */
    const char *output;         /* +O / --output; NULL = default name */
    char output_type;           /* 'N' png, 'E' exr, 0 = from the name */
    int output_bits;            /* +FN16: 16 */
    iris_render_options render; /* width, height, AA, threads, seed ... */
    bool quiet, verbose;
    const char *stats_file;
    int n_include_paths;
    const char *include_paths[CLI_MAX_PATHS];
    int n_declares;
    iris_declare declares[CLI_MAX_DECLARES];
    double clock;
    bool allow_unrestricted_io;
    bool allow_writes;          /* --allow-writes: #fopen write in the
                                   scene's directory (issue 7) */
    long max_loop_iterations;   /* --max-loop-iterations, 0 = default */
    /* progressive mode (--checkpoint and --resume are in 'render') */
    const char *reference;      /* --reference IMG */
    const char *error_log;      /* --error-log FILE.csv */
    double node_memory;         /* --node-memory: bytes all ranks on a
                                   node may use, 0 = no such limit */
    /* +SR +ER +SC +EC as typed (NULL: not given) and their values; a
    ** fraction needs the final +W/+H, so cli_parse() turns them into
    ** render.start_row ... only after the last switch */
    const char *window_arg[4];
    double window[4];
};

/*
** Fills 'o' from argv. Returns 0, or -1 with a message in 'err' (bad
** usage: the caller exits with status 2). The strings in 'o' point into
** argv.
*/
int cli_parse(int argc, char **argv, struct cli_options *o, char *err,
              size_t errlen);

/* Prints the --help text. */
void cli_usage(FILE *out);

/*
** The output file name: the given one, with an extension added from +F
** when it has none; by default the scene's base name with .png (.exr for
** +FE), in the current directory, as POV-Ray names it. Returns a
** malloc'ed string.
*/
char *cli_output_name(const struct cli_options *o);

#endif
