/* SPDX-License-Identifier: MIT */
/*
** thread.c: a parallel for-loop over pthreads (see thread.h).
*/
#include "config.h"

#include "util/thread.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
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

/* ---- the pool ----
** A progressive render calls par_for() about ten times a pass (shooting,
** the kd-tree's levels, the radius samples, the eye pass), each of them
** a few milliseconds of work on a small image. A thread created per call
** cost a clone, a fresh stack's page faults and its wake-up each time,
** and the items of a short call started late on it. The workers are
** therefore created once and wait on a condition variable between calls
** (they sleep, never spin: a spinning worker would take the CPU from the
** machine's other work and count as CPU time). Worker k (from 0) serves
** thread index k + 1 of every call that wants more than k + 1 threads;
** one that has not woken when the caller finds no item left is left out
** of the call, which then does not wait for a descheduled worker.
** One call at a time uses the pool ('owner'); a call made meanwhile (an
** item that calls par_for(), or another thread's call) creates and joins
** threads of its own as before, so nesting cannot deadlock. */
struct pool_worker {
    pthread_t tid;
    uint64_t gen0;             /* pool.gen when it was created: the calls
                                  up to it are not its to serve */
    bool started;              /* it took part in this call */
    bool skipped;              /* the call ended before it woke */
    struct par_worker w;       /* this call's state (under the lock) */
};

static struct {
    pthread_mutex_t owner;     /* held by the call using the pool */
    pthread_mutex_t mu;        /* guards everything below */
    pthread_cond_t work_cv;    /* a new call (gen) or quit */
    pthread_cond_t done_cv;    /* running reached 0 */
    struct pool_worker **ws;
    int n, cap;                /* workers started; slots in ws */
    uint64_t gen;              /* calls so far */
    int want;                  /* workers taking part in call 'gen' */
    int running;               /* of those, still in their item loop */
    bool quit;
    bool hooks;                /* atexit and atfork registered */
} pool = { PTHREAD_MUTEX_INITIALIZER, PTHREAD_MUTEX_INITIALIZER,
           PTHREAD_COND_INITIALIZER, PTHREAD_COND_INITIALIZER,
           NULL, 0, 0, 0, 0, 0, false, false };

/* Set in pool workers: their own par_for() calls never wait for the pool
** (which is busy with the call they serve). */
static _Thread_local bool in_pool_worker;

static void *pool_main(void *arg)
{
    int k = (int)(intptr_t)arg;
    in_pool_worker = true;
    pthread_mutex_lock(&pool.mu);
    /* not pool.gen now: the call that created it may have begun */
    uint64_t seen = pool.ws[k]->gen0;
    for (;;) {
        while (!pool.quit && pool.gen == seen)
            pthread_cond_wait(&pool.work_cv, &pool.mu);
        if (pool.quit)
            break;
        seen = pool.gen;
        if (k >= pool.want || pool.ws[k]->skipped)
            continue; /* a call with fewer threads, or one already done */
        pool.ws[k]->started = true;
        struct par_worker *w = &pool.ws[k]->w;
        pthread_mutex_unlock(&pool.mu);
        run_items(w);
        pthread_mutex_lock(&pool.mu);
        if (--pool.running == 0)
            pthread_cond_signal(&pool.done_cv);
    }
    pthread_mutex_unlock(&pool.mu);
    return NULL;
}

/* At exit the workers end and are joined (sanitizers and valgrind then see
** no thread alive). Not while a call is using the pool (exit() from
** another thread): then they are left to the process's end. */
static void pool_shutdown(void)
{
    if (pthread_mutex_trylock(&pool.owner) != 0)
        return;
    pthread_mutex_lock(&pool.mu);
    pool.quit = true;
    pthread_cond_broadcast(&pool.work_cv);
    pthread_mutex_unlock(&pool.mu);
    for (int k = 0; k < pool.n; k++) {
        pthread_join(pool.ws[k]->tid, NULL);
        iris_free(pool.ws[k]);
    }
    iris_free(pool.ws);
    pool.ws = NULL;
    pool.n = pool.cap = 0;
    pthread_mutex_unlock(&pool.owner);
}

/* A forked child has only the thread that forked: it starts without
** workers (their slots leak in the child, which has not got the threads
** to free them with). */
static void pool_after_fork(void)
{
    pthread_mutex_init(&pool.owner, NULL);
    pthread_mutex_init(&pool.mu, NULL);
    pthread_cond_init(&pool.work_cv, NULL);
    pthread_cond_init(&pool.done_cv, NULL);
    pool.ws = NULL;
    pool.n = pool.cap = 0;
    pool.want = pool.running = 0;
    pool.quit = false;
}

/* Starts workers up to 'want' (the owner holds the pool); returns how many
** there are, fewer when a thread or memory could not be had. */
static int pool_grow(int want)
{
    if (!pool.hooks) {
        pool.hooks = true;
        atexit(pool_shutdown);
        pthread_atfork(NULL, NULL, pool_after_fork);
    }
    if (want > pool.cap) {
        struct pool_worker **ws = iris_realloc(pool.ws,
                                               (size_t)want * sizeof *ws);
        if (!ws)
            return pool.n;
        pthread_mutex_lock(&pool.mu);
        pool.ws = ws;
        pool.cap = want;
        pthread_mutex_unlock(&pool.mu);
    }
    while (pool.n < want) {
        struct pool_worker *pw = iris_calloc(1, sizeof *pw);
        if (!pw)
            break;
        pw->gen0 = pool.gen;
        pthread_mutex_lock(&pool.mu);
        pool.ws[pool.n] = pw;
        pthread_mutex_unlock(&pool.mu);
        if (pthread_create(&pw->tid, NULL, pool_main,
                           (void *)(intptr_t)pool.n) != 0) {
            iris_free(pw);
            break;
        }
        pool.n++;
    }
    return pool.n;
}

/* The call on the pool; false when the pool is taken (the caller then
** starts threads of its own). */
static bool pool_run(struct par_job *job, int n_threads, double *cpu_s,
                     int *rc)
{
    if (in_pool_worker || pthread_mutex_trylock(&pool.owner) != 0)
        return false;
    int helpers = pool_grow(n_threads - 1);
    if (helpers > n_threads - 1)
        helpers = n_threads - 1;
    *rc = helpers == 0 ? -1 : 0; /* everything on this thread */
    pthread_mutex_lock(&pool.mu);
    for (int k = 0; k < helpers; k++) {
        pool.ws[k]->w = (struct par_worker){ job, k + 1, cpu_s != NULL,
                                             0.0 };
        pool.ws[k]->started = pool.ws[k]->skipped = false;
    }
    pool.want = helpers;
    pool.running = helpers;
    pool.gen++;
    if (helpers > 0)
        pthread_cond_broadcast(&pool.work_cv);
    pthread_mutex_unlock(&pool.mu);
    struct par_worker self = { job, 0, cpu_s != NULL, 0.0 };
    run_items(&self);
    pthread_mutex_lock(&pool.mu);
    /* Every item is taken: a worker that has not woken yet (a busy
    ** machine can keep it waiting for milliseconds) has nothing to do,
    ** and the call does not wait for it to wake. */
    for (int k = 0; k < helpers; k++)
        if (!pool.ws[k]->started) {
            pool.ws[k]->skipped = true;
            pool.running--;
        }
    while (pool.running > 0)
        pthread_cond_wait(&pool.done_cv, &pool.mu);
    if (cpu_s) {
        *cpu_s += self.cpu_s;
        for (int k = 0; k < helpers; k++)
            *cpu_s += pool.ws[k]->w.cpu_s;
    }
    pthread_mutex_unlock(&pool.mu);
    pthread_mutex_unlock(&pool.owner);
    return true;
}

static void *worker_main(void *arg)
{
    run_items(arg);
    return NULL;
}

/* Threads of the call's own, created and joined here (the pool is
** busy). */
static int spawn_run(struct par_job *job, int n_threads, double *cpu_s)
{
    pthread_t *tids = iris_calloc((size_t)n_threads, sizeof *tids);
    struct par_worker *ws = iris_calloc((size_t)n_threads, sizeof *ws);
    int started = 0, rc = 0;
    if (!tids || !ws)
        rc = -1;
    for (int t = 1; !rc && t < n_threads; t++) {
        ws[t].job = job;
        ws[t].thread = t;
        ws[t].timed = cpu_s != NULL;
        if (pthread_create(&tids[t], NULL, worker_main, &ws[t]) != 0) {
            rc = -1;
            break;
        }
        started = t;
    }
    struct par_worker self = { job, 0, cpu_s != NULL, 0.0 };
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
    if (n_threads == 1) {
        struct par_worker self = { &job, 0, cpu_s != NULL, 0.0 };
        run_items(&self);
        if (cpu_s)
            *cpu_s += self.cpu_s;
        return 0;
    }
    int rc = 0;
    if (pool_run(&job, n_threads, cpu_s, &rc))
        return rc;
    return spawn_run(&job, n_threads, cpu_s);
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
