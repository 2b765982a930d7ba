/* SPDX-License-Identifier: MIT */
/*
** report.h: what the iris command tells its user: the progress bar on a
** terminal and the --stats JSON file.
*/
#ifndef IRIS_CLI_REPORT_H
#define IRIS_CLI_REPORT_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "iris/iris.h"

/* Progress shown on stderr when it is a terminal. */
struct progress {
    bool enabled;
    double start;
    double last_draw;
    char phase[32];
};

void progress_init(struct progress *p, bool enabled);
/* An iris_progress_fn: draws a bar, percentage and time left. */
void progress_update(void *user, const char *phase, double fraction);
/* Clears the line. */
void progress_done(struct progress *p);

/* Timings of the phases the command ran, in seconds. */
struct run_times {
    double parse, write, total;
};

/* Writes the flat --stats JSON object; returns 0 or -1 (errno set). */
int stats_write(const char *path, const struct run_times *t,
                const iris_render_stats *rs);

/* Peak resident set size of this process in bytes. */
uint64_t peak_rss_bytes(void);

#endif
