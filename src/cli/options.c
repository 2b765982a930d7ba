/* SPDX-License-Identifier: MIT */
/*
** options.c: parsing the iris command line (see options.h).
*/
#include "config.h"

#include "cli/options.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* Parses a whole decimal integer in [lo, hi]; false on anything else. */
static bool parse_int(const char *s, long lo, long hi, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (errno || end == s || *end || v < lo || v > hi)
        return false;
    *out = v;
    return true;
}

/* Parses a whole finite number in [lo, hi]. */
static bool parse_num(const char *s, double lo, double hi, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || *end || !(v >= lo && v <= hi))
        return false;
    *out = v;
    return true;
}

/* A size in bytes: a positive number with an optional k, M, G or T
** (powers of 1000, as the memory error messages print them). */
static bool parse_size(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (errno || end == s || !(v > 0.0))
        return false;
    static const char units[] = "kMGT";
    const char *u = *end ? strchr(units, *end) : NULL;
    if (*end && (!u || end[1]))
        return false;
    for (const char *k = units; u && k <= u; k++)
        v *= 1000.0;
    if (!(v >= 1.0 && v <= 1e18))
        return false;
    *out = v;
    return true;
}

IRIS_PRINTF(3, 4)
static int fail(char *err, size_t errlen, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, errlen, fmt, ap);
    va_end(ap);
    return -1;
}

/* Does switch body 'body' start with the letters 'name' (any case)? */
static bool has_prefix(const char *body, const char *name)
{
    return strncasecmp(body, name, strlen(name)) == 0;
}

/* One POV-Ray switch: 'sign' is '+' or '-', 'body' what follows. */
static int pov_switch(struct cli_options *o, char sign, const char *arg,
                      const char *body, char *err, size_t errlen)
{
    long n;
    double d;
    bool on = sign == '+';
    if (has_prefix(body, "WT")) {
        if (!parse_int(body + 2, 1, 1024, &n))
            return fail(err, errlen, "%s: expected a thread count 1..1024", arg);
        o->render.threads = (int)n;
    } else if (has_prefix(body, "AM")) {
        if (!parse_int(body + 2, 0, 3, &n))
            return fail(err, errlen, "%s: antialiasing method must be 0, 1, 2 or 3", arg);
        o->render.aa = (enum iris_aa_method)n;
    } else if (has_prefix(body, "AG")) {
        if (!parse_num(body + 2, 0.01, 100, &d))
            return fail(err, errlen, "%s: expected an antialiasing gamma", arg);
        o->render.aa_gamma = d;
    } else if (toupper((unsigned char)body[0]) == 'A' && !isalpha((unsigned char)body[1])) {
        if (!on) {
            o->render.aa = IRIS_AA_NONE;
        } else {
            if (o->render.aa == IRIS_AA_NONE)
                o->render.aa = IRIS_AA_POV1;
            if (body[1]) {
                if (!parse_num(body + 1, 0, 3, &d))
                    return fail(err, errlen, "%s: expected an antialiasing threshold 0..3", arg);
                o->render.aa_threshold = d;
            }
        }
    } else if (toupper((unsigned char)body[0]) == 'I' && body[1]) {
        o->scene = body + 1;
    } else if (toupper((unsigned char)body[0]) == 'O' && body[1]) {
        o->output = body + 1;
    } else if (toupper((unsigned char)body[0]) == 'W' && isdigit((unsigned char)body[1])) {
        if (!parse_int(body + 1, 1, 65536, &n))
            return fail(err, errlen, "%s: width must be 1..65536", arg);
        o->render.width = (int)n;
    } else if (toupper((unsigned char)body[0]) == 'H' && isdigit((unsigned char)body[1])) {
        if (!parse_int(body + 1, 1, 65536, &n))
            return fail(err, errlen, "%s: height must be 1..65536", arg);
        o->render.height = (int)n;
    } else if (toupper((unsigned char)body[0]) == 'R' && isdigit((unsigned char)body[1])) {
        if (!parse_int(body + 1, 1, 9, &n))
            return fail(err, errlen, "%s: antialiasing depth must be 1..9", arg);
        o->render.aa_depth = (int)n;
    } else if (toupper((unsigned char)body[0]) == 'J' && !isalpha((unsigned char)body[1])) {
        o->render.jitter = on;
        if (on && body[1]) {
            if (!parse_num(body + 1, 0, 10, &d))
                return fail(err, errlen, "%s: expected a jitter amount", arg);
            o->render.jitter_amount = d;
        }
    } else if (toupper((unsigned char)body[0]) == 'Q' && isdigit((unsigned char)body[1])) {
        if (!parse_int(body + 1, 0, 11, &n))
            return fail(err, errlen, "%s: quality must be 0..11", arg);
        o->render.quality = n > 9 ? 9 : (int)n; /* POV-Ray clips 10, 11 to 9 */
    } else if (toupper((unsigned char)body[0]) == 'L' && body[1]) {
        if (o->n_include_paths >= CLI_MAX_PATHS)
            return fail(err, errlen, "%s: too many include paths", arg);
        o->include_paths[o->n_include_paths++] = body + 1;
    } else if (toupper((unsigned char)body[0]) == 'K' && body[1] && !isalpha((unsigned char)body[1])) {
        if (!parse_num(body + 1, -1e30, 1e30, &d))
            return fail(err, errlen, "%s: expected a clock value", arg);
        o->clock = d;
    } else if (toupper((unsigned char)body[0]) == 'F') {
        char t = (char)toupper((unsigned char)body[1]);
        if (t == 'N') {
            o->output_type = 'N';
            if (body[2] && (!parse_int(body + 2, 5, 16, &n) || (n != 8 && n != 16)))
                return fail(err, errlen, "%s: PNG bit depth must be 8 or 16", arg);
            o->output_bits = body[2] ? (int)n : 8;
        } else if (t == 'E' && !body[2]) {
            o->output_type = 'E';
        } else {
            return fail(err, errlen, "%s: output type must be +FN (PNG) or +FE (OpenEXR); "
                        "or name the file with its extension", arg);
        }
    } else if (strcasecmp(body, "UA") == 0) {
        /* output alpha: a transmitting background is transparent */
        o->render.alpha = on;
    } else if (has_prefix(body, "SR") || has_prefix(body, "ER") ||
               has_prefix(body, "SC") || has_prefix(body, "EC")) {
        /* a row or column number, or a fraction of the image (+SR0.5):
        ** resolve_window() below, once +W and +H are known */
        if (!parse_num(body + 2, 0.0, 65536.0, &d))
            return fail(err, errlen, "%s: expected a row or column number, "
                        "or a fraction of the image in [0, 1]", arg);
        int k = has_prefix(body, "SR") ? 0 : has_prefix(body, "ER") ? 1
              : has_prefix(body, "SC") ? 2 : 3;
        o->window_arg[k] = arg;
        o->window[k] = d;
    } else if (strcasecmp(body, "D") == 0 || strcasecmp(body, "V") == 0 ||
               strcasecmp(body, "P") == 0 || strcasecmp(body, "X") == 0 ||
               has_prefix(body, "D0") || strcasecmp(body, "GA") == 0) {
        /* Display, verbose, pause, abort: no preview window here. */
        if (toupper((unsigned char)body[0]) == 'V')
            o->verbose = on;
    } else {
        return fail(err, errlen, "unknown option '%s' (see iris --help)", arg);
    }
    return 0;
}

/* Long options that take a value, as --name=value or --name value. */
static const char *long_value(int argc, char **argv, int *i, const char *name,
                              bool *matched)
{
    size_t len = strlen(name);
    const char *a = argv[*i] + 2;
    *matched = false;
    if (strncmp(a, name, len) != 0)
        return NULL;
    if (a[len] == '=') {
        *matched = true;
        return a + len + 1;
    }
    if (a[len] == 0) {
        *matched = true;
        if (*i + 1 < argc)
            return argv[++*i];
    }
    return NULL;
}

static int long_option(int argc, char **argv, int *i, struct cli_options *o,
                       char *err, size_t errlen)
{
    const char *a = argv[*i];
    const char *v;
    bool m;
    long n;
    double d;
    if (!strcmp(a, "--help")) { o->action = CLI_HELP; return 0; }
    if (!strcmp(a, "--version")) { o->action = CLI_VERSION; return 0; }
    if (!strcmp(a, "--quiet")) { o->quiet = true; return 0; }
    if (!strcmp(a, "--verbose")) { o->verbose = true; return 0; }
    if (!strcmp(a, "--parse-only")) { o->action = CLI_PARSE_ONLY; return 0; }
    if (!strcmp(a, "--plan")) { o->action = CLI_PLAN; return 0; }
    if (!strcmp(a, "--unrestricted-io")) { o->allow_unrestricted_io = true; return 0; }
    if (!strcmp(a, "--allow-writes")) { o->allow_writes = true; return 0; }
    if (!strcmp(a, "--no-photons")) { o->render.use_photons = false; return 0; }

    v = long_value(argc, argv, i, "output", &m);
    if (m) {
        if (!v || !*v) return fail(err, errlen, "%s needs a file name", a);
        o->output = v;
        return 0;
    }
    v = long_value(argc, argv, i, "max-loop-iterations", &m);
    if (m) {
        if (!v || !parse_int(v, 1, 1000000000000000L, &n))
            return fail(err, errlen, "%s: a positive number of iterations", a);
        o->max_loop_iterations = n;
        return 0;
    }
    v = long_value(argc, argv, i, "stats", &m);
    if (m) {
        if (!v || !*v) return fail(err, errlen, "%s needs a file name", a);
        o->stats_file = v;
        return 0;
    }
    v = long_value(argc, argv, i, "width", &m);
    if (m) {
        if (!v || !parse_int(v, 1, 65536, &n)) return fail(err, errlen, "%s: width must be 1..65536", a);
        o->render.width = (int)n;
        return 0;
    }
    v = long_value(argc, argv, i, "height", &m);
    if (m) {
        if (!v || !parse_int(v, 1, 65536, &n)) return fail(err, errlen, "%s: height must be 1..65536", a);
        o->render.height = (int)n;
        return 0;
    }
    v = long_value(argc, argv, i, "threads", &m);
    if (m) {
        if (!v || !parse_int(v, 1, 1024, &n)) return fail(err, errlen, "%s: threads must be 1..1024", a);
        o->render.threads = (int)n;
        return 0;
    }
    v = long_value(argc, argv, i, "seed", &m);
    if (m) {
        char *end;
        errno = 0;
        unsigned long long s = v ? strtoull(v, &end, 10) : 0;
        if (!v || errno || end == v || *end || v[0] == '-')
            return fail(err, errlen, "%s: the seed must be a non-negative integer", a);
        o->render.seed = (uint64_t)s;
        return 0;
    }
    v = long_value(argc, argv, i, "passes", &m);
    if (m) {
        if (!v || !parse_int(v, 1, 1000000000L, &n)) return fail(err, errlen, "%s: passes must be a positive integer", a);
        o->render.passes = (int)n;
        return 0;
    }
    v = long_value(argc, argv, i, "time-limit", &m);
    if (m) {
        if (!v || !parse_num(v, 0.0, 1e9, &d) || d <= 0) return fail(err, errlen, "%s: expected a time in seconds", a);
        o->render.time_limit = d;
        return 0;
    }
    {
        /* progressive mode: files */
        static const char *const names[4] = { "checkpoint", "resume",
                                              "reference", "error-log" };
        for (int k = 0; k < 4; k++) {
            v = long_value(argc, argv, i, names[k], &m);
            if (!m)
                continue;
            if (!v || !*v)
                return fail(err, errlen, "%s needs a file name", a);
            const char **slot = k == 0 ? &o->render.checkpoint
                              : k == 1 ? &o->render.resume
                              : k == 2 ? &o->reference
                                       : &o->error_log;
            *slot = v;
            return 0;
        }
    }
    v = long_value(argc, argv, i, "node-memory", &m);
    if (m) {
        if (!v || !parse_size(v, &d))
            return fail(err, errlen, "%s: expected a size in bytes, with "
                        "k, M, G or T (powers of 1000), e.g. 8G", a);
        o->node_memory = d;
        return 0;
    }
    v = long_value(argc, argv, i, "spectral-samples", &m);
    if (m) {
        if (!v || !parse_int(v, 2, 10000, &n)) return fail(err, errlen, "%s: expected 2..10000 wavelengths", a);
        o->render.spectral_samples_min = (int)n;
        return 0;
    }
    return fail(err, errlen, "unknown option '%s' (see iris --help)", a);
}

/*
** The render window as POV-Ray 3.7 computes it (View::StartRender in
** source/backend/scene/view.cpp, and the same in renderfrontend.cpp): a
** start in [0, 1) is a fraction, its first pixel (int)(size * v) counted
** from 0; an end in [0, 1] is a fraction, its last pixel
** (int)(size * v) - 1; any other value is the pixel (int)v counted from
** 1 (+SR2.7 is row 2). So +ER1 is the last row, not the first. POV-Ray
** keeps the value as a float (POVMSFloat): +SR0.7 of 10 rows starts at
** row 7, (int)(10 * 0.7f) = 6, where double arithmetic would give 7.
** Writes iris's 1-based render.start_row ... (0: the image's edge).
*/
static int resolve_window(struct cli_options *o, char *err, size_t errlen)
{
    iris_render_options *r = &o->render;
    int *slot[4] = { &r->start_row, &r->end_row, &r->start_col, &r->end_col };
    for (int k = 0; k < 4; k++) {
        if (!o->window_arg[k])
            continue;
        bool start = k == 0 || k == 2;
        int size = k < 2 ? r->height : r->width;
        double v = (float)o->window[k];
        if (start)
            *slot[k] = v < 1.0 ? (int)(size * v) + 1 : (int)v;
        else
            *slot[k] = v <= 1.0 ? (int)(size * v) : (int)v;
        /* +ER0.1 of 8 rows ends before the first row (POV-Ray: "Invalid
        ** end column or row"); 0 would mean "to the edge" here */
        if (*slot[k] < 1)
            return fail(err, errlen, "%s: the window ends before the "
                        "first %s", o->window_arg[k], k < 2 ? "row" : "column");
    }
    return 0;
}

/*
** Options that contradict each other or the image size, said before the
** parse rather than ignored or found after a render of hours.
*/
static int check_combination(const struct cli_options *o, char *err,
                             size_t errlen)
{
    const iris_render_options *r = &o->render;
    /* progressive_wanted(): only a progressive render writes one */
    if (r->checkpoint && r->passes <= 1 && !(r->time_limit > 0.0) &&
        !r->resume)
        return fail(err, errlen, "--checkpoint=%s: only a progressive render "
                    "writes a checkpoint: add --passes=N (N >= 2), "
                    "--time-limit=S or --resume=FILE", r->checkpoint);
    /* +SR/+SC past the image leave nothing to render (eyepass.c would
    ** render the last row); +ER/+EC past it are errors too, as in POV-Ray
    ** 3.7 ("Invalid start/end column or row"; eyepass.c would clip).
    ** Messages give the row or column the switch resolved to. */
    static const char *const sw[4] = { "+SR", "+ER", "+SC", "+EC" };
    const int val[4] = { r->start_row, r->end_row, r->start_col, r->end_col };
    for (int k = 0; k < 4; k++) {
        int size = k < 2 ? r->height : r->width;
        if (val[k] > size)
            return fail(err, errlen, "%s%d: the image has %d %s (+%c%d)",
                        sw[k], val[k], size, k < 2 ? "rows" : "columns",
                        k < 2 ? 'H' : 'W', size);
    }
    if (r->end_row > 0 && r->start_row > r->end_row)
        return fail(err, errlen, "+SR%d +ER%d: the start row is below the "
                    "end row", r->start_row, r->end_row);
    if (r->end_col > 0 && r->start_col > r->end_col)
        return fail(err, errlen, "+SC%d +EC%d: the start column is right of "
                    "the end column", r->start_col, r->end_col);
    return 0;
}

int cli_parse(int argc, char **argv, struct cli_options *o, char *err,
              size_t errlen)
{
    memset(o, 0, sizeof *o);
    iris_render_defaults(&o->render);
    /* Debian's povray.ini renders 800x600; users expect the same size. */
    o->render.width = 800;
    o->render.height = 600;
    o->render.aa = IRIS_AA_NONE;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (a[0] == '-' && a[1] == '-' && a[2]) {
            if (long_option(argc, argv, &i, o, err, errlen))
                return -1;
        } else if (!strcmp(a, "-o")) {
            if (i + 1 >= argc || !argv[i + 1][0])
                return fail(err, errlen, "%s needs a file name", a);
            o->output = argv[++i];
        } else if (!strcmp(a, "-q")) {
            o->quiet = true;
        } else if (!strncasecmp(a, "Declare=", 8)) {
            const char *nv = a + 8, *eq = strchr(nv, '=');
            if (!eq || eq == nv || !eq[1])
                return fail(err, errlen, "%s: expected Declare=Name=Value", a);
            if (o->n_declares >= CLI_MAX_DECLARES)
                return fail(err, errlen, "%s: too many declarations", a);
            /* Split in place: argv strings are writable (C11 5.1.2.2.1). */
            ((char *)eq)[0] = 0;
            o->declares[o->n_declares].name = nv;
            o->declares[o->n_declares].value = eq + 1;
            o->n_declares++;
        } else if ((a[0] == '+' || a[0] == '-') && a[1]) {
            if (pov_switch(o, a[0], a, a + 1, err, errlen))
                return -1;
        } else if (a[0] == '-' && !a[1]) {
            return fail(err, errlen, "%s: reading a scene from standard input is not supported", a);
        } else {
            if (o->scene)
                return fail(err, errlen, "more than one scene given ('%s')", a);
            o->scene = a;
        }
    }
    if (o->action == CLI_RENDER || o->action == CLI_PARSE_ONLY || o->action == CLI_PLAN) {
        if (!o->scene)
            return fail(err, errlen, "%s", "no scene given (usage: iris [options] scene.pov)");
        if (resolve_window(o, err, errlen))
            return -1;
        return check_combination(o, err, errlen);
    }
    return 0;
}

char *cli_output_name(const struct cli_options *o)
{
    const char *ext = o->output_type == 'E' ? ".exr" : ".png";
    const char *src = o->output;
    char *name;
    if (src) {
        const char *slash = strrchr(src, '/');
        const char *dot = strrchr(slash ? slash : src, '.');
        size_t n = strlen(src) + 8;
        name = malloc(n);
        if (name)
            snprintf(name, n, "%s%s", src, dot && dot[1] ? "" : ext);
        return name;
    }
    /* The scene's base name without .pov, in the current directory. */
    const char *base = strrchr(o->scene, '/');
    base = base ? base + 1 : o->scene;
    const char *dot = strrchr(base, '.');
    size_t len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
    name = malloc(len + 8);
    if (name)
        snprintf(name, len + 8, "%.*s%s", (int)len, base, ext);
    return name;
}

void cli_usage(FILE *out)
{
    fputs(
"Usage: iris [options] scene.pov\n"
"       iris +Iscene.pov [+Oimage.png] [+W800 +H600] [+A0.3] ...\n"
"\n"
"Renders a POV-Ray 3.7 scene with spectral photon mapping.\n"
"\n"
"POV-Ray switches (case-insensitive):\n"
"  +Ifile          scene file          +Ofile       output image\n"
"  +Wn +Hn         image size (800x600) +Qn          quality 0..9 (9)\n"
"  +A[thr] -A      antialiasing on (threshold 0.3) / off (default)\n"
"  +AMn            method: 1 POV-Ray, 2 adaptive, 3 stratified\n"
"  +Rn             antialiasing depth (3)   +J[amt] -J   jitter on/off\n"
"  +Lpath          include directory        +WTn         threads\n"
"  +FN[16] +FE     PNG (8/16-bit) or OpenEXR when the name has no extension\n"
"  +UA -UA         alpha channel: a transmitting background is transparent\n"
"  +Kclock         clock value              +D -D +V -V  accepted\n"
"  Declare=Name=Value  declare an identifier before parsing\n"
"\n"
"Options:\n"
"  -o, --output=FILE   output image (png, exr, tif, hdr, jpg, pfm)\n"
"      --width=N       --height=N    image size\n"
"      --threads=N     worker threads (the image does not depend on it)\n"
"      --seed=N        seed of every random stream (0)\n"
"      --passes=N      progressive photon passes\n"
"      --time-limit=S  progressive rendering: stop after S seconds\n"
"      --checkpoint=F  save the progressive accumulation in F\n"
"      --resume=F      continue the accumulation saved in F\n"
"      --reference=IMG error against IMG after each pass (rmse, bias)\n"
"      --error-log=F   append time_s,passes,photons,rmse,rel_rmse,bias\n"
"                      to the CSV file F after each pass\n""      --node-memory=SIZE  memory all MPI ranks on one machine may use\n"
"                      together (e.g. 8G); a photon pass that would not\n"
"                      fit its share stops with an error\n"
"      --spectral-samples=N  minimum wavelengths per dispersive ray\n"
"      --no-photons    render without photons\n"
"  -q, --quiet         no progress output\n"
"      --verbose       more detail, including the render plan\n"
"      --parse-only    parse and report diagnostics, render nothing\n"
"      --plan          print the render plan, render nothing\n"
"      --stats=FILE    write timings and counters as JSON\n"
"      --unrestricted-io  let the scene read files anywhere\n"
"      --allow-writes  let #fopen ... write create files in the scene's\n"
"                      directory (refused by default)\n"
"      --max-loop-iterations=N  stop a #while or #for loop after N\n"
"                      iterations with an error (1000000)\n"
"      --version       print the version     --help   this text\n"
"\n"
"Exit status: 0 success, 1 render or I/O failure, 2 bad usage or scene\n"
"error, 130 interrupted (the image so far is written).\n", out);
}
