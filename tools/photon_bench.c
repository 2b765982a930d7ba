/* SPDX-License-Identifier: MIT */
/*
** photon_bench.c: measures the photon pass of a scene on its own, for
** bench/photons.sh: photons traced per second per thread, bytes per stored
** photon, and gather (estimate) queries per second.
**
** Usage: photon_bench [-t THREADS] [-q QUERIES] scene.pov
** Prints one line of key=value pairs. Textures are evaluated by the
** material module when IRIS_BENCH_MAT is set in the environment, else as
** solid pigments. Not installed; built by `make tools/photon_bench`.
*/
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "iris/parse.h"
#include "material/material.h"
#include "photon/pmap.h"
#include "util/rng.h"
#include "util/thread.h"

/* Times 'n' estimates at stored photon positions (where gathers matter),
** on one thread; returns queries per second. */
static double gather_rate(const struct photon_map *m, int n)
{
    if (!m || m->store.n == 0 || n <= 0)
        return 0.0;
    static iris_finish fin;
    fin.diffuse = 1;
    fin.brilliance = 1;
    rng r;
    rng_seed(&r, 1, 2, 3);
    double sink = 0.0, t0 = par_now();
    for (int i = 0; i < n; i++) {
        size_t j = (size_t)(rng_uniform(&r) * (double)m->store.n);
        vec3 p = pstore_position(&m->store, j);
        vec3 up = pstore_direction(&m->store, j);
        struct photon_shade_input in = { p, up, up, v3_neg(up), { 1, 1, 1 },
                                         1.0, &fin, NULL };
        double rgb[3];
        photon_map_shade(m, &in, rgb);
        sink += rgb[1];
    }
    double dt = par_now() - t0;
    if (sink < 0)
        printf("#");
    return dt > 0 ? n / dt : 0.0;
}

int main(int argc, char **argv)
{
    int threads = 1, queries = 100000;
    int i = 1;
    for (; i < argc - 1 && argv[i][0] == '-'; i += 2) {
        if (!strcmp(argv[i], "-t"))
            threads = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-q"))
            queries = atoi(argv[i + 1]);
    }
    if (i != argc - 1) {
        fprintf(stderr, "usage: photon_bench [-t N] [-q N] scene.pov\n");
        return 2;
    }
    iris_parse_options po;
    memset(&po, 0, sizeof po);
    iris_scene *scene = NULL;
    iris_diag_list diags;
    iris_diag_list_init(&diags);
    if (iris_parse_file(argv[i], &po, &scene, &diags) != IRIS_OK) {
        for (int k = 0; k < diags.n; k++)
            iris_diag_format(&diags.items[k], stderr);
        return 2;
    }
    iris_diag_list_fini(&diags);
    struct accel *a = NULL;
    char err[512];
    if (accel_build(scene, &a, stderr, err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "photon_bench: %s\n", err);
        return 1;
    }
    struct mat_ctx *mc = NULL;
    if (getenv("IRIS_BENCH_MAT") &&
        mat_ctx_create(scene, stderr, &mc) != IRIS_OK)
        return 1;
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = threads;
    o.seed = 1;
    o.mat = mc;
    struct photon_map *m = NULL;
    struct photon_stats st;
    if (photon_map_build(scene, a, &o, &m, &st) != IRIS_OK) {
        fprintf(stderr, "photon_bench: out of memory\n");
        return 1;
    }
    double per_thread = st.seconds_shoot > 0
                            ? st.shot / st.seconds_shoot / threads : 0.0;
    printf("threads=%d shot=%lld stored=%lld bytes_per_photon=%.2f "
           "shoot_s=%.3f build_s=%.3f photons_per_s_per_thread=%.0f "
           "gather_radius=%.4g gathers_per_s=%.0f\n",
           threads, (long long)st.shot, (long long)st.stored,
           st.stored ? (double)st.bytes / st.stored : 0.0, st.seconds_shoot,
           st.seconds_build, per_thread, st.gather_radius,
           gather_rate(m, queries));
    photon_map_destroy(m);
    mat_ctx_destroy(mc);
    accel_destroy(a);
    iris_scene_destroy(scene);
    return 0;
}
