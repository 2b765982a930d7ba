/* SPDX-License-Identifier: MIT */
/*
** compare.c: iris-compare, POV-Ray and iris side by side.
**
**   iris-compare scene.pov [+W +H +A... POV-Ray switches] [-o FILE]
**
** Renders the scene with POV-Ray (+Q9, so photons are on) and with iris at
** the same size, antialiasing and include paths, then writes one image:
** POV-Ray | iris | a heat map of the difference, with the heat map's scale
** drawn beneath it. Prints PSNR (on sRGB-encoded values, as an 8-bit viewer
** sees them), RMSE (linear), and both wall times with their ratio.
** Switches it does not know are passed to both renderers.
*/
#include "config.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "iris/image.h"

extern char **environ;

#define MAX_ARGS 128

struct compare_args {
    const char *scene, *output, *povray, *iris;
    int n_common;
    const char *common[MAX_ARGS];   /* passed to both renderers */
    int n_iris;
    const char *iris_only[MAX_ARGS];
    double max_diff;                /* heat map scale; 0 = 0.1 */
};

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Runs argv with stdout and stderr to 'log'; returns the exit status. */
static int run(char *const argv[], const char *log, double *seconds)
{
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    pid_t pid;
    double t0 = now();
    int rc = posix_spawnp(&pid, argv[0], &fa, NULL, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    if (rc != 0) {
        fprintf(stderr, "iris-compare: cannot run %s: %s\n", argv[0], strerror(rc));
        return 127;
    }
    int status;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
        ;
    *seconds = now() - t0;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

static double clip_enc(double v)
{
    v = iris_srgb_encode(v);
    return v < 0 ? 0 : v > 1 ? 1 : v;
}

/* A perceptually ordered ramp: black, blue, magenta, orange, yellow. */
static void heat(double t, float rgb[3])
{
    static const float stops[5][3] = {
        { 0, 0, 0 }, { 0.05f, 0.1f, 0.6f }, { 0.6f, 0.1f, 0.6f },
        { 1.0f, 0.5f, 0.05f }, { 1.0f, 1.0f, 0.6f } };
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    double x = t * 4;
    int i = x >= 4 ? 3 : (int)x;
    double f = x - i;
    for (int c = 0; c < 3; c++) {
        double e = stops[i][c] + (stops[i + 1][c] - stops[i][c]) * f;
        rgb[c] = (float)iris_srgb_decode(e); /* the file is sRGB-encoded */
    }
}

static int usage(void)
{
    fputs("usage: iris-compare scene.pov [+Wn +Hn +A... +Lpath Declare=N=V] "
          "[-o compare.png] [--povray PATH] [--iris PATH] [--max-diff D] "
          "[--iris-arg ARG]...\n", stderr);
    return 2;
}

static int parse_args(int argc, char **argv, struct compare_args *a)
{
    memset(a, 0, sizeof *a);
    a->povray = "povray";
    a->iris = "iris";
    a->output = NULL;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "-o") && i + 1 < argc) {
            a->output = argv[++i];
        } else if (!strcmp(s, "--povray") && i + 1 < argc) {
            a->povray = argv[++i];
        } else if (!strcmp(s, "--iris") && i + 1 < argc) {
            a->iris = argv[++i];
        } else if (!strcmp(s, "--iris-arg") && i + 1 < argc) {
            if (a->n_iris >= MAX_ARGS)
                return -1;
            a->iris_only[a->n_iris++] = argv[++i];
        } else if (!strcmp(s, "--max-diff") && i + 1 < argc) {
            a->max_diff = atof(argv[++i]);
        } else if (!strcmp(s, "--help")) {
            return -1;
        } else if (s[0] == '+' || s[0] == '-' || !strncmp(s, "Declare=", 8)) {
            if (s[1] == 'O' || s[1] == 'o' || (s[1] == 'I' || s[1] == 'i'))
                return -1; /* the tool names the files itself */
            if (a->n_common >= MAX_ARGS)
                return -1;
            a->common[a->n_common++] = s;
        } else if (!a->scene) {
            a->scene = s;
        } else {
            return -1;
        }
    }
    return a->scene ? 0 : -1;
}

int main(int argc, char **argv)
{
    struct compare_args a;
    if (parse_args(argc, argv, &a) != 0)
        return usage();

    char dir[] = "/tmp/iris-compare-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("iris-compare: mkdtemp");
        return 1;
    }
    char pov_out[256], iris_out[256], pov_log[256], iris_log[256], in_arg[4096];
    snprintf(pov_out, sizeof pov_out, "+O%s/povray.png", dir);
    snprintf(iris_out, sizeof iris_out, "%s/iris.exr", dir);
    snprintf(pov_log, sizeof pov_log, "%s/povray.log", dir);
    snprintf(iris_log, sizeof iris_log, "%s/iris.log", dir);
    snprintf(in_arg, sizeof in_arg, "+I%s", a.scene);

    /* POV-Ray: headless, quality 9 (photons), 16-bit PNG for precision */
    const char *pv[MAX_ARGS + 16];
    int n = 0;
    pv[n++] = a.povray; pv[n++] = in_arg; pv[n++] = pov_out;
    pv[n++] = "-D"; pv[n++] = "-V"; pv[n++] = "+Q9"; pv[n++] = "+FN16";
    pv[n++] = "-GA"; /* no console messages but errors */
    for (int i = 0; i < a.n_common; i++)
        pv[n++] = a.common[i];
    pv[n] = NULL;
    const char *iv[2 * MAX_ARGS + 16];
    int m = 0;
    iv[m++] = a.iris; iv[m++] = a.scene; iv[m++] = "-q";
    iv[m++] = "-o"; iv[m++] = iris_out;
    for (int i = 0; i < a.n_common; i++)
        iv[m++] = a.common[i];
    for (int i = 0; i < a.n_iris; i++)
        iv[m++] = a.iris_only[i];
    iv[m] = NULL;

    double t_pov = 0, t_iris = 0;
    int rp = run((char *const *)pv, pov_log, &t_pov);
    int ri = run((char *const *)iv, iris_log, &t_iris);
    if (rp != 0)
        fprintf(stderr, "iris-compare: POV-Ray failed (exit %d); its log is %s\n", rp, pov_log);
    if (ri != 0)
        fprintf(stderr, "iris-compare: iris failed (exit %d); its log is %s\n", ri, iris_log);
    if (rp != 0 || ri != 0)
        return 1;

    iris_image p, q, out;
    char err[512];
    if (iris_image_read(&p, pov_out + 2, err, sizeof err) != IRIS_OK ||
        iris_image_read(&q, iris_out, err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "iris-compare: %s\n", err);
        return 1;
    }
    if (p.width != q.width || p.height != q.height) {
        fprintf(stderr, "iris-compare: the images differ in size\n");
        return 1;
    }
    int w = p.width, h = p.height, bar = h / 12 + 4;
    if (iris_image_init(&out, 3 * w, h + bar) != IRIS_OK) {
        fprintf(stderr, "iris-compare: out of memory\n");
        return 1;
    }

    /* Metrics: PSNR on encoded values, RMSE and peak on linear ones. */
    double se_enc = 0, se_lin = 0, peak = 0;
    size_t np = (size_t)w * h;
    float *diff = calloc(np, sizeof *diff);
    if (!diff)
        return 1;
    for (size_t i = 0; i < np; i++) {
        double dl = 0;
        for (int c = 0; c < 3; c++) {
            double x = p.pixels[i * 4 + c], y = q.pixels[i * 4 + c];
            double de = clip_enc(x) - clip_enc(y);
            se_enc += de * de;
            se_lin += (x - y) * (x - y);
            dl += fabs(clip_enc(x) - clip_enc(y)) / 3.0;
        }
        diff[i] = (float)dl;
        if (dl > peak)
            peak = dl;
    }
    double mse = se_enc / (3.0 * np);
    double psnr = mse > 0 ? 10 * log10(1 / mse) : INFINITY;
    double rmse = sqrt(se_lin / (3.0 * np));
    /* A fixed scale keeps heat maps comparable between scenes; 0.1 in
    ** sRGB units is 25 steps of an 8-bit file. */
    double scale = a.max_diff > 0 ? a.max_diff : 0.1;

    /* Panels: POV-Ray | iris | heat map, with the scale bar below it */
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            size_t s = ((size_t)y * w + x) * 4;
            float *o0 = out.pixels + ((size_t)y * 3 * w + x) * 4;
            float *o1 = o0 + (size_t)w * 4, *o2 = o1 + (size_t)w * 4;
            for (int c = 0; c < 3; c++) {
                o0[c] = p.pixels[s + c];
                o1[c] = q.pixels[s + c];
            }
            heat(diff[(size_t)y * w + x] / scale, o2);
        }
    for (int y = h + 2; y < h + bar - 2; y++)
        for (int x = 2 * w + 2; x < 3 * w - 2; x++)
            heat((double)(x - 2 * w - 2) / (w - 5), out.pixels + ((size_t)y * 3 * w + x) * 4);

    const char *dest = a.output ? a.output : "compare.png";
    if (iris_image_write(&out, dest, 8, IRIS_ENC_SRGB, err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "iris-compare: %s\n", err);
        return 1;
    }
    printf("scene:   %s (%dx%d)\n", a.scene, w, h);
    printf("image:   %s  (POV-Ray | iris | |difference|, scale 0..%.3g sRGB below)\n", dest, scale);
    printf("peak:    %.4f (largest per-pixel mean |difference|, sRGB)\n", peak);
    printf("PSNR:    %.2f dB\n", psnr);
    printf("RMSE:    %.6f (linear)\n", rmse);
    printf("time:    POV-Ray %.3f s, iris %.3f s, ratio iris/POV-Ray %.3f\n",
           t_pov, t_iris, t_pov > 0 ? t_iris / t_pov : 0.0);
    free(diff);
    iris_image_fini(&p);
    iris_image_fini(&q);
    iris_image_fini(&out);
    unlink(pov_out + 2);
    unlink(iris_out);
    unlink(pov_log);
    unlink(iris_log);
    rmdir(dir);
    return 0;
}
