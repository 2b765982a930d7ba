/* SPDX-License-Identifier: MIT */
/*
** photon_bench.c: measures the photon pass of a scene on its own, for
** bench/photons.sh: photons traced per second per thread, bytes per stored
** photon, and gather (estimate) queries per second.
**
** Usage: photon_bench [-t THREADS] [-q QUERIES] [-a 1] [-c 1] [-m 0]
**        [-s 0] [-w 0] scene.pov
** (-a 1: query accel, not the photon fast path of sphere-and-plane
** scenes, src/photon/fastpath.h; -c 1: evaluate every hit's texture, not
** the batch's cache of uniform textures, src/photon/trace.h; -m 0: no
** material context, see below; -s 0: one wavelength per photon, no
** sibling wavelengths, src/photon/trace.h; -w 0: the scalar tracer
** also where the wavefront tracer, src/photon/wavefront.h, applies)
** Prints one line of key=value pairs: shoot_s is the wall time of the
** shooting (emission, transport, concatenating the batches), build_s of
** the kd-tree build and the automatic radius; photons_per_s_per_thread is
** shot / shoot_s / threads (the build is not counted: it is reported on
** its own). cpu_shoot_s, cpu_build_s and photons_per_cpu_s are the same in
** CPU seconds of all threads, and gathers_per_cpu_s the gather rate per
** CPU second: on a shared machine the wall clock also counts the others'
** work. tex_cached counts the surface hits answered from the texture
** cache (src/photon/trace.h). map_fnv is a hash of the stored records
** (the same map, the same hash). wavefront is the photons the wavefront
** tracer emitted (0: the scalar tracer shot them all) and kernel its
** code (avx2 or generic). Textures are evaluated by the
** material module (a material context, as a render shoots its photons:
** what users get); -m 0 takes them as solid pigments without it, the
** way sessions 1-5 measured (cheaper per hit: not what a render pays).
** Not installed; built by `make tools/photon_bench`.
*/
#include "config.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "accel/accel.h"
#include "iris/parse.h"
#include "material/material.h"
#include "photon/pmap.h"
#include "photon/wavefront.h"
#include "util/rng.h"
#include "util/thread.h"

/* CPU seconds of the calling thread (a loaded machine stretches the wall
** clock, not this). */
static double thread_cpu(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Times 'n' estimates at stored photon positions (where gathers matter),
** on one thread; returns queries per second of wall time, *per_cpu_s per
** CPU second. */
static double gather_rate(const struct photon_map *m, int n, double *per_cpu_s)
{
    *per_cpu_s = 0.0;
    if (!m || m->store.n == 0 || n <= 0)
        return 0.0;
    static iris_finish fin;
    fin.diffuse = 1;
    fin.brilliance = 1;
    rng r;
    rng_seed(&r, 1, 2, 3);
    double sink = 0.0, t0 = par_now(), c0 = thread_cpu();
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
    double dt = par_now() - t0, dc = thread_cpu() - c0;
    if (sink < 0)
        printf("#");
    *per_cpu_s = dc > 0 ? n / dc : 0.0;
    return dt > 0 ? n / dt : 0.0;
}

/* FNV-1a over the stored records in tree order: two builds of the same
** map print the same value (checking that an optimisation left the map
** as it was). */
static unsigned long long map_hash(const struct photon_map *m)
{
    unsigned long long h = 1469598103934665603ULL;
    if (!m)
        return h;
    const unsigned char *b = (const unsigned char *)m->store.ph;
    for (size_t i = 0; i < m->store.n * sizeof *m->store.ph; i++)
        h = (h ^ b[i]) * 1099511628211ULL;
    return h;
}

int main(int argc, char **argv)
{
    int threads = 1, queries = 100000, accel_only = 0, no_cache = 0;
    int with_mat = 1, siblings = 1, wavefront = 1;
    int i = 1;
    for (; i < argc - 1 && argv[i][0] == '-'; i += 2) {
        if (!strcmp(argv[i], "-t"))
            threads = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-q"))
            queries = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-a"))
            accel_only = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-c"))
            no_cache = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-m"))
            with_mat = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-s"))
            siblings = atoi(argv[i + 1]);
        else if (!strcmp(argv[i], "-w"))
            wavefront = atoi(argv[i + 1]);
    }
    if (i != argc - 1) {
        fprintf(stderr,
                "usage: photon_bench [-t N] [-q N] [-a 1] [-c 1] [-m 0] [-s 0] "
                "[-w 0] scene.pov\n");
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
    if (with_mat && mat_ctx_create(scene, stderr, &mc) != IRIS_OK)
        return 1;
    struct photon_options o;
    memset(&o, 0, sizeof o);
    o.threads = threads;
    o.seed = 1;
    o.mat = mc;
    o.no_fastpath = accel_only != 0;
    o.no_tex_cache = no_cache != 0;
    o.no_siblings = siblings == 0;
    o.no_wavefront = wavefront == 0;
    struct photon_map *m = NULL;
    struct photon_stats st;
    if (photon_map_build(scene, a, &o, &m, &st) != IRIS_OK) {
        fprintf(stderr, "photon_bench: out of memory\n");
        return 1;
    }
    double per_thread = st.seconds_shoot > 0
                            ? st.shot / st.seconds_shoot / threads : 0.0;
    double g_cpu, g_wall = gather_rate(m, queries, &g_cpu);
    printf("threads=%d shot=%lld stored=%lld bytes_per_photon=%.2f "
           "shoot_s=%.3f build_s=%.3f photons_per_s_per_thread=%.0f "
           "cpu_shoot_s=%.3f cpu_build_s=%.3f photons_per_cpu_s=%.0f "
           "gather_radius=%.4g gathers_per_s=%.0f gathers_per_cpu_s=%.0f "
           "tex_cached=%lld mat=%d wavefront=%lld kernel=%s map_fnv=%016llx\n",
           threads, (long long)st.shot, (long long)st.stored,
           st.stored ? (double)st.bytes / st.stored : 0.0, st.seconds_shoot,
           st.seconds_build, per_thread, st.cpu_shoot, st.cpu_build,
           st.cpu_shoot > 0 ? st.shot / st.cpu_shoot : 0.0, st.gather_radius,
           g_wall, g_cpu, (long long)st.tex_cached, with_mat != 0,
           (long long)st.wavefront, wf_kernel_name(), map_hash(m));
    photon_map_destroy(m);
    mat_ctx_destroy(mc);
    accel_destroy(a);
    iris_scene_destroy(scene);
    return 0;
}
