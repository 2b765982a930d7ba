/* SPDX-License-Identifier: MIT */
/*
** thread.c: a parallel for-loop over pthreads (see thread.h).
*/
#include "config.h"

#include "util/thread.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
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
    bool timed;
    double cpu_s;              /* the thread's CPU seconds in run_items */
};

/* This thread's CPU seconds so far (0 where the clock is missing: the
** difference is then 0, never garbage). */
static double thread_cpu_s(void)
{
    struct timespec ts;
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) != 0)
        return 0.0;
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void run_items(struct par_worker *w)
{
    struct par_job *job = w->job;
    double c0 = w->timed ? thread_cpu_s() : 0.0;
    for (;;) {
        int64_t i = atomic_fetch_add(&job->next, 1);
        if (i >= job->n_items)
            break;
        job->fn(job->ctx, i, w->thread);
    }
    if (w->timed)
        w->cpu_s = thread_cpu_s() - c0;
}

static void *worker_main(void *arg)
{
    run_items(arg);
    return NULL;
}

int par_for(int n_threads, int64_t n_items, par_fn fn, void *ctx)
{
    return par_for_timed(n_threads, n_items, fn, ctx, NULL);
}

int par_for_timed(int n_threads, int64_t n_items, par_fn fn, void *ctx,
                  double *cpu_s)
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
            ws[t].timed = cpu_s != NULL;
            if (pthread_create(&tids[t], NULL, worker_main, &ws[t]) != 0) {
                rc = -1;
                break;
            }
            started = t;
        }
    }
    struct par_worker self = { &job, 0, cpu_s != NULL, 0.0 };
    run_items(&self);
    for (int t = 1; t <= started; t++)
        pthread_join(tids[t], NULL);
    if (cpu_s) {
        *cpu_s += self.cpu_s;
        for (int t = 1; t <= started; t++)
            *cpu_s += ws[t].cpu_s;
    }
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
