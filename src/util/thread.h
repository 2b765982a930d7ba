/* SPDX-License-Identifier: MIT */
/*
** thread.h: a parallel for-loop over pthreads.
**
** DESIGN. par_for() starts 'n_threads' workers (the caller's thread is one
** of them) that take work items 0..n_items-1 in order from one C11 atomic
** counter. Which thread runs an item is not deterministic, so callers key
** random numbers and output slots by item, never by thread; then results do
** not depend on the thread count. 'thread' is passed so that a worker can
** use per-thread scratch state. The call returns when every item is done.
** The workers other than the caller come from a pool made at the first
** call and kept, asleep, between calls (thread.c says why); a call made
** while the pool serves another (from an item, or from a second thread)
** starts threads of its own.
*/
#ifndef IRIS_UTIL_THREAD_H
#define IRIS_UTIL_THREAD_H

#include <stdint.h>

typedef void (*par_fn)(void *ctx, int64_t item, int thread);

/* Runs fn(ctx, i, thread) for i in [0, n_items); returns 0, or -1 when no
** other thread could be had (then everything ran on the caller's
** thread). */
int par_for(int n_threads, int64_t n_items, par_fn fn, void *ctx);

/* par_for() that also adds to *cpu_s (if not NULL) the CPU seconds the
** workers spent taking and running items, summed over the threads (each
** thread's CLOCK_THREAD_CPUTIME_ID, read as it enters and leaves its item
** loop): the work's cost whatever the machine's load, as POV-Ray's
** "using N thread(s) with S CPU-seconds total" is for its render tasks.
** Waking and waiting for the workers are not counted. */
int par_for_timed(int n_threads, int64_t n_items, par_fn fn, void *ctx,
                  double *cpu_s);

/* The number of online processors (at least 1). */
int par_cores(void);

/* Seconds from a monotonic clock. */
double par_now(void);

#endif
