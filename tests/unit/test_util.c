/* SPDX-License-Identifier: MIT */
/*
** test_util.c: arena, random streams, parallel loop and transforms.
*/
#include "config.h"

#include "testutil.h"

#include <pthread.h>
#include <stdint.h>
#include <string.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "math/transform.h"
#include "util/arena.h"
#include "util/rng.h"
#include "util/thread.h"

/* Allocations are 16-byte aligned, zeroed, and the limit is enforced. */
static void test_arena(void **state)
{
    (void)state;
    iris_arena *a = arena_create(1 << 20);
    assert_non_null(a);
    for (int i = 1; i < 200; i++) {
        unsigned char *p = arena_alloc(a, (size_t)i * 37);
        assert_non_null(p);
        assert_int_equal((uintptr_t)p % 16, 0);
        for (int k = 0; k < i * 37; k++)
            assert_int_equal(p[k], 0);
        memset(p, 0xab, (size_t)i * 37);
    }
    /* 199 allocations of up to 7.4 kB total ~740 kB: a 400 kB one fails */
    assert_null(arena_alloc(a, 400 * 1024));
    assert_non_null(arena_alloc(a, 1024));
    char *s = arena_strdup(a, "sphere");
    assert_string_equal(s, "sphere");
    assert_null(arena_array(a, SIZE_MAX / 8, 16));
    arena_destroy(a);
    arena_destroy(NULL);
}

/* Same key, same stream; different keys, different streams; the uniform
** mean and variance match U(0,1) (1/2 and 1/12) within 5 standard errors
** for 1e5 samples: se(mean) = 0.00091, se(var) ~ 0.00027. */
static void test_rng(void **state)
{
    (void)state;
    rng a, b, c;
    rng_seed(&a, 42, 1, 2);
    rng_seed(&b, 42, 1, 2);
    rng_seed(&c, 42, 1, 3);
    int same = 0;
    for (int i = 0; i < 100; i++) {
        uint32_t x = rng_u32(&a), y = rng_u32(&b), z = rng_u32(&c);
        assert_int_equal(x, y);
        same += x == z;
    }
    assert_true(same < 3);
    double sum = 0, sum2 = 0;
    const int n = 100000;
    for (int i = 0; i < n; i++) {
        double u = rng_uniform(&a);
        assert_true(u >= 0.0 && u < 1.0);
        sum += u;
        sum2 += u * u;
    }
    double mean = sum / n, var = sum2 / n - mean * mean;
    assert_near(mean, 0.5, 5 * 0.00091);
    assert_near(var, 1.0 / 12.0, 5 * 0.00027);
}

/* A lazily seeded stream (rng_lazy) draws exactly the numbers of
** rng_seed() with the key it was last given, whenever the first number
** is drawn: the eye pass re-keys one per sample and relies on it for
** images identical to eager seeding. Re-keying a stream part-way starts
** the new key's stream from its beginning; a key given and never drawn
** from costs nothing and changes nothing. */
static void test_rng_lazy(void **state)
{
    (void)state;
    rng_lazy l;
    rng e;
    rng_lazy_seed(&l, 7, 1, 99);
    rng_lazy_seed(&l, 7, 1, 100); /* never drawn from: replaced */
    rng_seed(&e, 7, 1, 100);
    for (int i = 0; i < 50; i++)
        assert_true(rng_uniform(rng_lazy_get(&l)) == rng_uniform(&e));
    /* re-keyed part-way, the first draw comes from the new stream */
    rng_lazy_seed(&l, 7, 3, 5);
    rng_seed(&e, 7, 3, 5);
    for (int i = 0; i < 50; i++)
        assert_int_equal(rng_u32(rng_lazy_get(&l)), rng_u32(&e));
    /* and differs from the stream it replaced (a different key) */
    rng_seed(&e, 7, 1, 100);
    rng_lazy_seed(&l, 7, 1, 101);
    int same = 0;
    for (int i = 0; i < 50; i++)
        same += rng_u32(rng_lazy_get(&l)) == rng_u32(&e);
    assert_true(same < 3);
}

struct sum_ctx {
    int64_t out[1000];
};

static void square_item(void *ctx, int64_t i, int thread)
{
    (void)thread;
    ((struct sum_ctx *)ctx)->out[i] = i * i;
}

/* Every item runs exactly once, whatever the thread count. */
static void test_par_for(void **state)
{
    (void)state;
    for (int t = 1; t <= 4; t++) {
        static struct sum_ctx ctx;
        memset(&ctx, 0xff, sizeof ctx);
        assert_int_equal(par_for(t, 1000, square_item, &ctx), 0);
        for (int i = 0; i < 1000; i++)
            assert_int_equal(ctx.out[i], (int64_t)i * i);
    }
}

/* Each item spins until its own thread's CPU clock has advanced 2 ms and
** records what it burned. */
#define BURN_ITEMS 24
struct burn_ctx {
    double burned[BURN_ITEMS];
};

static double thread_clock_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void burn_item(void *ctx, int64_t i, int thread)
{
    (void)thread;
    double t0 = thread_clock_s(), t;
    while ((t = thread_clock_s()) - t0 < 2e-3)
        ;
    ((struct burn_ctx *)ctx)->burned[i] = t - t0;
}

/* par_for_timed adds the threads' CPU time in their item loops: at least
** the CPU the items measured burning themselves (each on its own thread's
** clock), and not more than that plus 2 ms per thread for the loop's own
** work (an atomic add and a clock read per item: microseconds). Whatever
** the machine's load (thread CPU clocks do not count waiting), and with 2
** or 3 threads a process-wide clock would count every thread's items
** again and fail the upper bound. It adds to what *cpu_s held. */
static void test_par_for_timed(void **state)
{
    (void)state;
    for (int t = 1; t <= 3; t++) {
        struct burn_ctx ctx;
        memset(&ctx, 0, sizeof ctx);
        double cpu = 1.0;
        assert_int_equal(par_for_timed(t, BURN_ITEMS, burn_item, &ctx, &cpu),
                         0);
        double burned = 0.0;
        for (int i = 0; i < BURN_ITEMS; i++) {
            assert_true(ctx.burned[i] >= 2e-3);
            burned += ctx.burned[i];
        }
        assert_true(cpu - 1.0 >= burned);
        assert_true(cpu - 1.0 <= burned + 2e-3 * t);
    }
}

/* ---- the worker pool (thread.c) ---- */

#define POOL_ITEMS 32
struct tid_ctx {
    long tid[POOL_ITEMS];
};

/* Records the kernel's id of the thread running the item, after burning
** 0.5 ms of that thread's CPU so that a second thread, if there is one,
** takes items too. */
static void tid_item(void *ctx, int64_t i, int thread)
{
    (void)thread;
    double t0 = thread_clock_s();
    while (thread_clock_s() - t0 < 0.5e-3)
        ;
    ((struct tid_ctx *)ctx)->tid[i] = (long)syscall(SYS_gettid);
}

/* par_for() reuses its workers: over 40 calls with 2 threads at most 2
** distinct threads (the caller and one pooled worker) ran items. A thread
** created per call gets a new kernel id each time (ids are not reused
** until they wrap at pid_max), and would show up to 41. */
static void test_par_pool_reuse(void **state)
{
    (void)state;
    enum { CALLS = 40, MAX_SEEN = 2 * CALLS + 1 };
    long seen[MAX_SEEN];
    int n_seen = 0;
    for (int c = 0; c < CALLS; c++) {
        struct tid_ctx ctx;
        memset(&ctx, 0, sizeof ctx);
        assert_int_equal(par_for(2, POOL_ITEMS, tid_item, &ctx), 0);
        for (int i = 0; i < POOL_ITEMS; i++) {
            assert_true(ctx.tid[i] > 0); /* every item ran */
            int k = 0;
            while (k < n_seen && seen[k] != ctx.tid[i])
                k++;
            if (k == n_seen && n_seen < MAX_SEEN)
                seen[n_seen++] = ctx.tid[i];
        }
    }
    assert_true(n_seen <= 2);
}

struct nest_ctx {
    int64_t out[8][1000];
};

struct nest_inner {
    struct nest_ctx *c;
    int64_t row;
};

static void nest_inner_item(void *ctx, int64_t i, int thread)
{
    (void)thread;
    struct nest_inner *in = ctx;
    in->c->out[in->row][i] = in->row * 1000 + i;
}

/* An item that calls par_for() itself (the pool is busy with the outer
** call): the inner call runs on threads of its own, every item once. */
static void nest_outer_item(void *ctx, int64_t row, int thread)
{
    (void)thread;
    struct nest_inner in = { ctx, row };
    if (par_for(2, 1000, nest_inner_item, &in) != 0)
        in.c->out[row][0] = -1; /* (no cmocka assert off the main thread) */
}

static void test_par_nested(void **state)
{
    (void)state;
    static struct nest_ctx ctx;
    memset(&ctx, 0xff, sizeof ctx);
    assert_int_equal(par_for(2, 8, nest_outer_item, &ctx), 0);
    for (int r = 0; r < 8; r++)
        for (int i = 0; i < 1000; i++)
            assert_int_equal(ctx.out[r][i], (int64_t)r * 1000 + i);
}

/* Two threads calling par_for() at once (one gets the pool, the other
** threads of its own, call by call): both get every item right. */
static void *concurrent_caller(void *arg)
{
    int *bad = arg;
    for (int c = 0; c < 50; c++) {
        static _Thread_local struct sum_ctx ctx;
        memset(&ctx, 0xff, sizeof ctx);
        if (par_for(2 + c % 2, 1000, square_item, &ctx) != 0)
            (*bad)++;
        for (int i = 0; i < 1000; i++)
            if (ctx.out[i] != (int64_t)i * i)
                (*bad)++;
    }
    return NULL;
}

static void test_par_concurrent(void **state)
{
    (void)state;
    int bad[2] = { 0, 0 };
    pthread_t t;
    assert_int_equal(pthread_create(&t, NULL, concurrent_caller, &bad[1]),
                     0);
    concurrent_caller(&bad[0]);
    pthread_join(t, NULL);
    assert_int_equal(bad[0], 0);
    assert_int_equal(bad[1], 0);
}

/* A child forked after the pool has workers (which the child has not
** got) still runs par_for() to the end: without the fork handler it
** would wait for them forever (the alarm then kills it). */
static void test_par_fork(void **state)
{
    (void)state;
    static struct sum_ctx ctx;
    assert_int_equal(par_for(2, 1000, square_item, &ctx), 0);
    pid_t pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        alarm(20);
        memset(&ctx, 0xff, sizeof ctx);
        int ok = par_for(2, 1000, square_item, &ctx) == 0;
        for (int i = 0; i < 1000; i++)
            ok = ok && ctx.out[i] == (int64_t)i * i;
        _exit(ok ? 0 : 1);
    }
    int status = 0;
    assert_int_equal(waitpid(pid, &status, 0), pid);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
}

/* rotate <0,90,0> takes +x to -z in POV-Ray's left-handed frame (the
** documented "rotate y*90 turns x into -z"); a composed transform and its
** inverse undo each other; normals stay perpendicular under a
** non-uniform scale. */
static void test_transform(void **state)
{
    (void)state;
    xform r, s, t, c;
    xf_rotate(&r, v3(0, 90, 0));
    vec3 p = xf_point(&r, v3(1, 0, 0));
    assert_near(p.x, 0, 1e-12);
    assert_near(p.y, 0, 1e-12);
    assert_near(p.z, -1, 1e-12);
    xf_scale(&s, v3(2, 3, 0.5));
    xf_translate(&t, v3(1, 2, 3));
    xf_compose(&c, &s, &r);
    xf_compose(&c, &c, &t);
    /* scale then rotate then translate: (1,1,1) -> (2,3,.5) -> (.5,3,-2)
    ** -> (1.5,5,1) */
    vec3 q = xf_point(&c, v3(1, 1, 1));
    assert_near(q.x, 1.5, 1e-12);
    assert_near(q.y, 5, 1e-12);
    assert_near(q.z, 1, 1e-12);
    vec3 back = xf_inv_point(&c, q);
    assert_near(back.x, 1, 1e-12);
    assert_near(back.y, 1, 1e-12);
    assert_near(back.z, 1, 1e-12);
    /* plane x + y = 0 with normal (1,1,0); tangent (1,-1,0) */
    vec3 n = xf_normal(&s, v3(1, 1, 0)), tan = xf_dir(&s, v3(1, -1, 0));
    assert_near(v3_dot(n, tan), 0, 1e-12);
    /* scale 0 is replaced by 1, as POV-Ray does */
    xf_scale(&s, v3(0, 2, 2));
    assert_near(xf_point(&s, v3(3, 1, 1)).x, 3, 0);
    /* matrix: POV-Ray row-vector form, translation in the last row */
    double m[12] = { 1, 0, 0, 0, 1, 0, 0, 0, 1, 4, 5, 6 };
    assert_true(xf_matrix(&t, m));
    assert_near(xf_point(&t, v3(0, 0, 0)).y, 5, 0);
    double sing[12] = { 0 };
    assert_false(xf_matrix(&t, sing));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arena),
        cmocka_unit_test(test_rng),
        cmocka_unit_test(test_rng_lazy),
        cmocka_unit_test(test_par_for),
        cmocka_unit_test(test_par_for_timed),
        cmocka_unit_test(test_par_pool_reuse),
        cmocka_unit_test(test_par_nested),
        cmocka_unit_test(test_par_concurrent),
        cmocka_unit_test(test_par_fork),
        cmocka_unit_test(test_transform),
    };
    return cmocka_run_group_tests_name("util", tests, NULL, NULL);
}
