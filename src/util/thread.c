/* SPDX-License-Identifier: MIT */
/*
** thread.c: a parallel for-loop over pthreads (see thread.h).
*/
#include "config.h"

#include "util/thread.h"

#include <pthread.h>
#include <stdatomic.h>
#include <time.h>
#include <unistd.h>

#include "util/mem.h"

struct par_job {
    par_fn fn;
    void *ctx;
    int64_t n_items;
    _Atomic int64_t next;
};

struct par_worker {
    struct par_job *job;
    int thread;
};

static void run_items(struct par_job *job, int thread)
{
    for (;;) {
        int64_t i = atomic_fetch_add(&job->next, 1);
        if (i >= job->n_items)
            break;
        job->fn(job->ctx, i, thread);
    }
}

static void *worker_main(void *arg)
{
    struct par_worker *w = arg;
    run_items(w->job, w->thread);
    return NULL;
}

int par_for(int n_threads, int64_t n_items, par_fn fn, void *ctx)
{
    struct par_job job = { fn, ctx, n_items, 0 };
    if (n_threads < 1)
        n_threads = 1;
    if (n_threads > n_items)
        n_threads = n_items > 0 ? (int)n_items : 1;
    pthread_t *tids = NULL;
    struct par_worker *ws = NULL;
    int started = 0, rc = 0;
    if (n_threads > 1) {
        tids = iris_calloc((size_t)n_threads, sizeof *tids);
        ws = iris_calloc((size_t)n_threads, sizeof *ws);
        if (!tids || !ws)
            rc = -1;
        for (int t = 1; !rc && t < n_threads; t++) {
            ws[t].job = &job;
            ws[t].thread = t;
            if (pthread_create(&tids[t], NULL, worker_main, &ws[t]) != 0) {
                rc = -1;
                break;
            }
            started = t;
        }
    }
    run_items(&job, 0);
    for (int t = 1; t <= started; t++)
        pthread_join(tids[t], NULL);
    iris_free(tids);
    iris_free(ws);
    return rc;
}

int par_cores(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n > 0 ? (int)n : 1;
}

double par_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}
