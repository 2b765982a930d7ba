/* SPDX-License-Identifier: MIT */
/*
** main.c: the iris command: parse a scene, render it, write the image.
**
** This is the only place that joins the SDL front end (povparse) and the
** renderer; both are used through include/iris/ only. Exit status: 0
** success; 1 render or I/O failure; 2 bad usage or a scene error; 130
** interrupted, with the image so far written.
*/
#include "config.h"

#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/geomq.h"
#include "cli/options.h"
#include "cli/passlog.h"
#include "cli/report.h"
#include "iris/iris.h"
#include "photon/membudget.h"
#include "render/progressive.h"
#include "render/mpi_passes.h"
#include "util/thread.h"

enum { EXIT_RENDER = 1, EXIT_USAGE = 2, EXIT_INTERRUPTED = 130 };

/* Set by SIGINT/SIGTERM; the renderer polls it and stops soon. */
static volatile int interrupted;

static void on_signal(int sig)
{
    (void)sig;
    interrupted = 1;
}

static void install_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    /* a parent may have left them blocked (some job runners do) */
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_UNBLOCK, &set, NULL);
}

/* Prints every diagnostic; returns the number of errors. */
static int print_diags(const iris_diag_list *d, bool quiet)
{
    for (int i = 0; i < d->n; i++) {
        if (quiet && d->items[i].sev != IRIS_SEV_ERROR)
            continue;
        iris_diag_format(&d->items[i], stderr);
    }
    int kept = 0;
    for (int i = 0; i < d->n; i++)
        kept += d->items[i].sev == IRIS_SEV_WARNING;
    if (!quiet && d->n_warnings > kept)
        fprintf(stderr, "iris: %d more warnings not shown\n",
                d->n_warnings - kept);
    return d->n_errors;
}

/*
** 0 when the directory 'path' would be written into exists; else -1 with
** errno set. Checked before the parse, so that a render of hours does not
** end in "No such file or directory".
*/
static int output_dir_exists(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (!slash)
        return 0; /* the current directory */
    size_t n = slash == path ? 1 : (size_t)(slash - path);
    char *dir = malloc(n + 1);
    if (!dir)
        return 0; /* the write will say it */
    memcpy(dir, path, n);
    dir[n] = '\0';
    struct stat st;
    int rc = stat(dir, &st);
    if (rc == 0 && !S_ISDIR(st.st_mode)) {
        errno = ENOTDIR;
        rc = -1;
    }
    free(dir);
    return rc;
}

/*
** The image buffers a render of o's size holds at once, in bytes: the
** float RGBA image (16 bytes a pixel) and, when progressive, the pass
** image and the double sums (16 + 32), and rank 0's snapshot of the
** ranks' sums under MPI (32). What the scene needs besides (accel,
** photons) is not known before the parse and is checked where it is
** built (the photon pass's own memory check).
*/
static double image_bytes(const struct cli_options *o)
{
    double per_pixel = 16.0;
    if (progressive_wanted(&o->render))
        per_pixel += 48.0 + (mpi_passes_size() > 1 ? 32.0 : 0.0);
    return per_pixel * (double)o->render.width * (double)o->render.height;
}

/*
** True when the output the user gave names a directory: an existing one
** ('-o renders', '+O.'), or a name ending in '/'. cli_output_name() would
** add an extension to it and write 'renders.png' beside it or a hidden
** 'renders/.png' inside it, neither of which was asked for.
*/
static bool output_is_directory(const char *given)
{
    if (!given)
        return false;
    size_t n = strlen(given);
    struct stat st;
    return (n > 0 && given[n - 1] == '/') ||
           (stat(given, &st) == 0 && S_ISDIR(st.st_mode));
}

/*
** 0 when file 'path' (--stats, --checkpoint) can be created where it is
** named: its directory exists and the name is not a directory. Else -1
** with errno set. Checked before the parse: those files are written at
** the end, after the render, and a missing directory then cost the run
** (a failed checkpoint write also left the image unwritten).
*/
static int file_can_be_written(const char *path)
{
    struct stat st;
    if (stat(path, &st) == 0 && S_ISDIR(st.st_mode)) {
        errno = EISDIR;
        return -1;
    }
    return output_dir_exists(path);
}

/* True when 'a' and 'b' name the same existing file. */
static bool same_file(const char *a, const char *b)
{
    struct stat sa, sb;
    return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev &&
           sa.st_ino == sb.st_ino;
}

static int parse_scene(const struct cli_options *o, iris_scene **scene)
{
    iris_parse_options po;
    memset(&po, 0, sizeof po);
    po.n_include_paths = o->n_include_paths;
    po.include_paths = o->include_paths;
    po.n_declares = o->n_declares;
    po.declares = o->declares;
    po.clock = o->clock;
    po.image_width = o->render.width;
    po.image_height = o->render.height;
    po.read_policy = o->allow_unrestricted_io ? IRIS_IO_UNRESTRICTED : IRIS_IO_RESTRICTED;
    po.allow_writes = o->allow_writes;
    po.max_while_iterations = o->max_loop_iterations;
    po.interrupt = &interrupted; /* SIGINT stops the parse too */
    po.quiet_debug = o->quiet;
    /* trace(), inside(), extents: answered by src/accel (geomq.c); an
    ** object accel cannot build is warned about by the render itself */
    struct geomq *gq = geomq_new(NULL);
    po.geometry = geomq_callbacks(gq);
    iris_diag_list diags;
    iris_diag_list_init(&diags);
    enum iris_status st = iris_parse_file(o->scene, &po, scene, &diags);
    geomq_free(gq);
    print_diags(&diags, o->quiet);
    iris_diag_list_fini(&diags);
    if (st == IRIS_OK)
        return 0;
    if (st == IRIS_EIO) {
        fprintf(stderr, "iris: %s: cannot read the scene: %s\n", o->scene,
                errno ? strerror(errno) : iris_status_str(st));
        return EXIT_USAGE;
    }
    if (st == IRIS_EINTR)
        return EXIT_INTERRUPTED;
    if (st != IRIS_EPARSE)
        fprintf(stderr, "iris: %s: %s\n", o->scene, iris_status_str(st));
    return EXIT_USAGE;
}

/* The command, run on every MPI rank (or alone). */
static int iris_main(int argc, char **argv)
{
    double t0 = par_now();
    struct cli_options o;
    char err[512] = "";
    if (cli_parse(argc, argv, &o, err, sizeof err) != 0) {
        fprintf(stderr, "iris: %s\n", err);
        return EXIT_USAGE;
    }
    if (o.action == CLI_HELP) {
        cli_usage(stdout);
        return 0;
    }
    if (o.action == CLI_VERSION) {
        printf("iris %s\n", iris_version());
        return 0;
    }
    install_signals();
    if (o.node_memory > 0.0) /* shared by the node's MPI ranks */
        membudget_set_node_limit(o.node_memory);
    if (mpi_passes_rank() != 0) /* rank 0 alone writes the error log */
        o.error_log = NULL;

    /* the parser's read of a directory or a device said "No such file
    ** or directory" */
    struct stat scene_st;
    if (stat(o.scene, &scene_st) == 0 && !S_ISREG(scene_st.st_mode)) {
        fprintf(stderr, "iris: %s: cannot read the scene: %s\n", o.scene,
                S_ISDIR(scene_st.st_mode) ? "it is a directory"
                                          : "not a regular file");
        return EXIT_USAGE;
    }
    if (o.action == CLI_RENDER && output_is_directory(o.output)) {
        fprintf(stderr, "iris: %s: is a directory; name the image file "
                "(e.g. -o %s%sscene.png)\n", o.output, o.output,
                o.output[strlen(o.output) - 1] == '/' ? "" : "/");
        return EXIT_USAGE;
    }
    const char *early[2][2] = { { o.stats_file, "--stats" },
                                { o.render.checkpoint, "--checkpoint" } };
    for (int k = 0; k < 2; k++)
        if (early[k][0] && (o.action == CLI_RENDER || k == 0) &&
            mpi_passes_rank() == 0 && file_can_be_written(early[k][0]) != 0) {
            fprintf(stderr, "iris: %s=%s: cannot write there: %s\n",
                    early[k][1], early[k][0], strerror(errno));
            return EXIT_USAGE;
        }
    if (o.render.resume && access(o.render.resume, R_OK) != 0) {
        fprintf(stderr, "iris: --resume=%s: %s\n", o.render.resume,
                strerror(errno));
        return EXIT_USAGE;
    }

    char *out_name = cli_output_name(&o);
    if (!out_name) {
        fprintf(stderr, "iris: out of memory\n");
        return EXIT_RENDER;
    }
    if (same_file(out_name, o.scene)) {
        fprintf(stderr, "iris: %s: refusing to overwrite the scene file with the image\n", out_name);
        free(out_name);
        return EXIT_USAGE;
    }
    /* the files written besides the image: not the scene (--stats=s.pov
    ** replaced it with JSON), not the image, not each other */
    const char *written[3][2] = { { o.stats_file, "--stats" },
                                  { o.render.checkpoint, "--checkpoint" },
                                  { o.error_log, "--error-log" } };
    for (int k = 0; k < 3; k++) {
        const char *f = written[k][0], *clash = NULL;
        if (!f)
            continue;
        if (same_file(f, o.scene))
            clash = "the scene file";
        else if (!strcmp(f, out_name) || same_file(f, out_name))
            clash = "the image";
        for (int m = 0; m < k && !clash; m++)
            if (written[m][0] && (!strcmp(f, written[m][0]) ||
                                  same_file(f, written[m][0])))
                clash = written[m][1];
        if (clash) {
            fprintf(stderr, "iris: %s=%s: refusing to write over %s\n",
                    written[k][1], f, clash);
            free(out_name);
            return EXIT_USAGE;
        }
    }
    /* rank 0 alone writes (MPI) */
    if (o.action == CLI_RENDER && mpi_passes_rank() == 0 &&
        output_dir_exists(out_name) != 0) {
        fprintf(stderr, "iris: %s: cannot write the image there: %s\n",
                out_name, strerror(errno));
        free(out_name);
        return EXIT_RENDER;
    }

    /* A size beyond memory is said before anything is allocated (64K x
    ** 64K is 69 GB of floats), not by the allocator or the OOM killer in
    ** the middle of the render. Images under 64 MB are left to the
    ** checks of what the scene builds: with a limit already used up by
    ** the process itself (--node-memory 1M) the photon pass's located
    ** error says more than "the image needs 1 kB". */
    struct membudget mem;
    membudget_available(&mem);
    if (o.action == CLI_RENDER && image_bytes(&o) > 64e6 &&
        image_bytes(&o) > mem.bytes) {
        char need[32], have[32];
        fprintf(stderr, "iris: +W%d +H%d: the image needs %s, more than "
                "the %s %s leaves\n", o.render.width, o.render.height,
                membudget_format(image_bytes(&o), need, sizeof need),
                membudget_format(mem.bytes, have, sizeof have), mem.what);
        free(out_name);
        return EXIT_RENDER;
    }

    /* Progressive mode: error against a reference, images as it goes */
    struct passlog plog;
    if (passlog_open(&plog, &o.render, o.reference, o.error_log, o.verbose,
                     out_name, o.output_bits, err, sizeof err) != 0) {
        fprintf(stderr, "iris: %s\n", err);
        free(out_name);
        return EXIT_USAGE;
    }
    o.render.on_pass = passlog_on_pass;
    o.render.on_pass_user = &plog;
    /* MPI: every rank's time in work, agreements and the reduction
    ** (bench/scaling.sh); set on every rank, printed by rank 0 */
    const char *rt_env = getenv("IRIS_RANK_TIMES");
    if (rt_env && rt_env[0])
        o.render.rank_times = stderr;

    struct run_times times = { 0, 0, 0 };
    iris_scene *scene = NULL;
    int rc = parse_scene(&o, &scene);
    times.parse = par_now() - t0;
    if (rc) {
        passlog_close(&plog);
        free(out_name);
        return rc;
    }
    if (o.action == CLI_PARSE_ONLY) {
        if (o.verbose)
            iris_scene_dump(scene, stdout);
        passlog_close(&plog);
        free(out_name);
        iris_scene_destroy(scene);
        return 0;
    }

    struct progress prog;
    progress_init(&prog, !o.quiet && isatty(STDERR_FILENO));
    o.render.progress = progress_update;
    o.render.progress_user = &prog;
    o.render.interrupt = &interrupted;
    if (o.action == CLI_PLAN) {
        o.render.plan_out = stdout;
        o.render.plan_only = true;
    } else if (o.verbose) {
        o.render.plan_out = stderr;
    }

    iris_image img;
    iris_render_stats rs;
    memset(&rs, 0, sizeof rs);
    double t_render = par_now();
    enum iris_status st = iris_image_init(&img, o.render.width, o.render.height);
    if (st == IRIS_OK)
        st = iris_render(scene, &o.render, &img, &rs, err, sizeof err);
    progress_done(&prog);
    if (o.action == CLI_PLAN) {
        rc = st == IRIS_OK ? 0 : EXIT_RENDER;
        if (st != IRIS_OK)
            fprintf(stderr, "iris: %s: %s\n", o.scene, err[0] ? err : iris_status_str(st));
        goto done;
    }
    if (st != IRIS_OK && st != IRIS_EINTR) {
        fprintf(stderr, "iris: %s: %s\n", o.scene, err[0] ? err : iris_status_str(st));
        rc = st == IRIS_EPARSE || st == IRIS_EINVAL ? EXIT_USAGE : EXIT_RENDER;
        goto done;
    }
    if (interrupted)
        st = IRIS_EINTR;
    if (plog.calls == 0 && o.reference && st == IRIS_OK) {
        /* one ordinary render: log it as one pass */
        iris_pass_info info = { rs.passes > 0 ? rs.passes : 1,
                                par_now() - t_render, rs.photons_emitted,
                                1.0 };
        plog.out_name = NULL;
        passlog_on_pass(&plog, &img, &info);
    }

    if (mpi_passes_rank() != 0) /* MPI: rank 0 writes the reduced image */
        goto done;
    /* Write the image: all of it, or what was done before an interrupt. */
    double tw = par_now();
    enum iris_encoding enc = IRIS_ENC_SRGB;
    enum iris_status wst = iris_image_write_alpha(&img, out_name,
                                                  o.output_bits, enc,
                                                  o.render.alpha, err,
                                                  sizeof err);
    times.write = par_now() - tw;
    if (wst != IRIS_OK) {
        fprintf(stderr, "iris: %s\n", err);
        rc = EXIT_RENDER;
        goto done;
    }
    if (rs.nan_pixels)
        fprintf(stderr, "iris: warning: %llu non-finite values were replaced by 0\n",
                (unsigned long long)rs.nan_pixels);
    if (!o.quiet)
        fprintf(stderr, "iris: wrote %s (%dx%d) in %.2f s\n", out_name,
                img.width, img.height, par_now() - t0);
    rc = st == IRIS_EINTR ? EXIT_INTERRUPTED : 0;

done:
    times.total = par_now() - t0;
    if (o.stats_file && mpi_passes_rank() == 0 && stats_write(o.stats_file, &times, &rs) != 0) {
        fprintf(stderr, "iris: %s: cannot write the statistics: %s\n",
                o.stats_file, strerror(errno));
        if (rc == 0)
            rc = EXIT_RENDER;
    }
    passlog_close(&plog);
    iris_image_fini(&img);
    free(out_name);
    iris_scene_destroy(scene);
    return rc;
}

/*
** Under mpirun (issue 8) every rank runs the command and renders its share
** of the passes; only rank 0 writes files and speaks: the other ranks'
** stdout and stderr go to /dev/null, so diagnostics, progress and the plan
** appear once. Started without mpirun, this is one rank and changes
** nothing.
*/
int main(int argc, char **argv)
{
    mpi_passes_init(&argc, &argv);
    if (mpi_passes_rank() != 0) {
        if (!freopen("/dev/null", "w", stdout) ||
            !freopen("/dev/null", "w", stderr))
            return EXIT_RENDER;
    }
    int rc = iris_main(argc, argv);
    if (rc != 0) /* MPI: a rank that failed alone ends the job */
        mpi_passes_end_failed(rc);
    else
        mpi_passes_finalize();
    return rc;
}
