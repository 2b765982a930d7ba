/* SPDX-License-Identifier: MIT */
/*
** report.c: the progress bar and the --stats file (see report.h).
*/
#include "config.h"

#include "cli/report.h"

#include <stdio.h>
#include <string.h>
#include <sys/resource.h>

#include "util/thread.h"

void progress_init(struct progress *p, bool enabled)
{
    memset(p, 0, sizeof *p);
    p->enabled = enabled;
    p->start = par_now();
}

void progress_update(void *user, const char *phase, double fraction)
{
    struct progress *p = user;
    if (!p->enabled)
        return;
    double now = par_now();
    bool new_phase = strncmp(p->phase, phase, sizeof p->phase - 1) != 0;
    if (new_phase) {
        snprintf(p->phase, sizeof p->phase, "%s", phase);
        p->start = now;
    } else if (now - p->last_draw < 0.1 && fraction < 1.0) {
        return; /* at most ten redraws a second */
    }
    p->last_draw = now;
    if (fraction < 0)
        fraction = 0;
    if (fraction > 1)
        fraction = 1;
    const int width = 30;
    int fill = (int)(fraction * width + 0.5);
    char bar[64];
    for (int i = 0; i < width; i++)
        bar[i] = i < fill ? '=' : ' ';
    bar[width] = 0;
    double spent = now - p->start;
    if (fraction > 0.01 && fraction < 1.0) {
        double left = spent * (1.0 - fraction) / fraction;
        fprintf(stderr, "\r%-10s [%s] %3.0f%%  %4.0fs left ", phase, bar,
                100 * fraction, left);
    } else {
        fprintf(stderr, "\r%-10s [%s] %3.0f%%            ", phase, bar,
                100 * fraction);
    }
    fflush(stderr);
}

void progress_done(struct progress *p)
{
    if (p->enabled && p->phase[0]) {
        fprintf(stderr, "\r%70s\r", "");
        fflush(stderr);
    }
}

uint64_t peak_rss_bytes(void)
{
    struct rusage ru;
    if (getrusage(RUSAGE_SELF, &ru) != 0)
        return 0;
    return (uint64_t)ru.ru_maxrss * 1024u; /* Linux reports kilobytes */
}

int stats_write(const char *path, const struct run_times *t,
                const iris_render_stats *rs)
{
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f,
            "{\"time_parse_s\": %.6f, \"time_build_s\": %.6f, "
            "\"time_photon_s\": %.6f, \"time_render_s\": %.6f, "
            "\"time_render_cpu_s\": %.6f, "
            "\"time_write_s\": %.6f, \"time_total_s\": %.6f, "
            "\"photons_emitted\": %llu, \"photons_stored\": %llu, "
            "\"photon_bytes\": %llu, \"rays_traced\": %llu, "
            "\"peak_rss_bytes\": %llu, \"threads\": %d, \"passes\": %d, "
            /* the eye pass's rays as POV-Ray's statistics count them */
            "\"rays\": %llu, \"rays_camera\": %llu, "
            "\"rays_reflected\": %llu, \"rays_refracted\": %llu, "
            "\"rays_transmitted\": %llu, \"shadow_tests\": %llu, "
            "\"shadow_hits\": %llu}\n",
            t->parse, rs->time_build_s, rs->time_photon_s, rs->time_render_s,
            rs->time_render_cpu_s, t->write, t->total,
            (unsigned long long)rs->photons_emitted,
            (unsigned long long)rs->photons_stored,
            (unsigned long long)rs->photon_bytes,
            (unsigned long long)rs->rays_traced,
            (unsigned long long)peak_rss_bytes(), rs->threads, rs->passes,
            (unsigned long long)rs->rays,
            (unsigned long long)rs->rays_camera,
            (unsigned long long)rs->rays_reflected,
            (unsigned long long)rs->rays_refracted,
            (unsigned long long)rs->rays_transmitted,
            (unsigned long long)rs->shadow_tests,
            (unsigned long long)rs->shadow_hits);
    return fclose(f) == 0 ? 0 : -1;
}
