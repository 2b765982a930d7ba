/* SPDX-License-Identifier: MIT */
/*
** test_membudget.c: the photon memory budget shared by the MPI ranks of
** one node (src/photon/membudget.c, issue 8).
**
** The expectations are read here, independently, from /proc: a node-wide
** limit L (--node-memory) leaves each of R ranks L/R less its own
** resident set (VmRSS). The test reads VmRSS just before the call; the
** two reads differ by what the process touches in between (a few pages),
** so the tolerance is 1 MB. MemAvailable moves with the rest of the
** machine between the two reads: the check there is only an upper bound
** with 10% slack (a node-wide limit may not grow when split).
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <string.h>

#include "photon/membudget.h"

/* The kB of "key: N kB" in a /proc file, or -1. */
static double proc_kb(const char *path, const char *key)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1.0;
    char line[256];
    double v = -1.0;
    size_t kl = strlen(key);
    while (fgets(line, sizeof line, f))
        if (!strncmp(line, key, kl) && line[kl] == ':' &&
            sscanf(line + kl + 1, "%lf", &v) == 1)
            break;
    fclose(f);
    return v;
}

/* A node limit well below what the machine has, so that it is the
** tightest: half of MemAvailable, at most 1 GB (skipped without /proc). */
static double pick_limit(void)
{
    double avail = proc_kb("/proc/meminfo", "MemAvailable");
    if (avail <= 0.0)
        skip();
    return fmin(0.5 * avail * 1024.0, 1e9);
}

static void reset(void)
{
    membudget_set_node_ranks(1);
    membudget_set_node_limit(0.0);
}

/* One rank: the whole node limit less this process's resident set. */
static void test_node_limit_one_rank(void **state)
{
    (void)state;
    double lim = pick_limit();
    membudget_set_node_ranks(1);
    membudget_set_node_limit(lim);
    double rss = proc_kb("/proc/self/status", "VmRSS") * 1024.0;
    struct membudget b;
    membudget_available(&b);
    reset();
    assert_true(rss > 0.0);
    assert_near(b.bytes, lim - rss, 1e6);
    assert_string_equal(b.what, "--node-memory");
}

/* Four ranks on the node: a quarter each, less the rank's own RSS. */
static void test_node_limit_four_ranks(void **state)
{
    (void)state;
    double lim = pick_limit();
    membudget_set_node_ranks(4);
    membudget_set_node_limit(lim);
    double rss = proc_kb("/proc/self/status", "VmRSS") * 1024.0;
    struct membudget b;
    membudget_available(&b);
    reset();
    assert_near(b.bytes, lim / 4.0 - rss, 1e6);
    assert_string_equal(b.what,
                        "--node-memory shared by the node's MPI ranks");
}

/* Without --node-memory the machine's MemAvailable is split as well: the
** budget of 4 ranks is at most a quarter of it (10%: it moves). */
static void test_memavailable_split(void **state)
{
    (void)state;
    double avail = proc_kb("/proc/meminfo", "MemAvailable") * 1024.0;
    if (avail <= 0.0)
        skip();
    struct membudget one, four;
    membudget_available(&one);
    membudget_set_node_ranks(4);
    membudget_available(&four);
    reset();
    assert_true(four.bytes <= 1.1 * avail / 4.0);
    assert_true(four.bytes <= one.bytes);
    /* a ulimit (per process) could be tighter than a quarter; otherwise
    ** the message names the sharing */
    if (strncmp(four.what, "ulimit", 6) != 0)
        assert_non_null(strstr(four.what, "shared by the node's MPI ranks"));
}

/* Nonsense settings fall back to one rank, no limit. */
static void test_bad_settings(void **state)
{
    (void)state;
    struct membudget ref, b;
    membudget_set_node_ranks(0);
    membudget_set_node_limit(-5.0);
    membudget_available(&b);
    reset();
    membudget_available(&ref);
    assert_string_equal(b.what, ref.what);
    assert_true(strcmp(b.what, "--node-memory") != 0);
    assert_null(strstr(b.what, "shared"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_node_limit_one_rank),
        cmocka_unit_test(test_node_limit_four_ranks),
        cmocka_unit_test(test_memavailable_split),
        cmocka_unit_test(test_bad_settings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
