/* SPDX-License-Identifier: MIT */
/*
** membudget.c: the memory limits of this process and the photon pass's
** estimated peak (see membudget.h).
**
** Each limit is what may still be allocated, not the limit itself: ulimit
** -v bounds the address space, of which the program, Embree's reserves
** and the thread stacks already hold hundreds of MB, so what is left is
** RLIMIT_AS - VmSize. Sources that cannot be read are skipped (not Linux,
** no cgroup): the check then errs towards running.
**
** MemAvailable, the cgroup and --node-memory are the node's: R MPI ranks
** on one node each read the same MemAvailable before any of them
** allocates, and each would take all of it. Each rank's share is 1/R
** (the ranks run their passes at the same time and pass sizes are
** equal).
*/
#include "config.h"

#include "photon/membudget.h"

#include <math.h>
#include <stdatomic.h>
#include <stdio.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

/* The ranks sharing the node and the --node-memory limit (0: none). Set
** once at start-up, read at each photon pass. */
static _Atomic int node_ranks = 1;
static _Atomic double node_limit = 0.0;

void membudget_set_node_ranks(int ranks)
{
    atomic_store(&node_ranks, ranks < 1 ? 1 : ranks);
}

void membudget_set_node_limit(double bytes)
{
    atomic_store(&node_limit, bytes > 0.0 && isfinite(bytes) ? bytes : 0.0);
}

/* The value in kB of the line "key: N kB" of a /proc file, or -1. */
static double proc_kb(const char *path, const char *key)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1.0;
    char line[256];
    size_t kl = strlen(key);
    double v = -1.0;
    while (fgets(line, sizeof line, f))
        if (strncmp(line, key, kl) == 0 && line[kl] == ':') {
            double x;
            if (sscanf(line + kl + 1, "%lf", &x) == 1)
                v = x;
            break;
        }
    fclose(f);
    return v;
}

/* A file holding one number ("max" or absent: -1). */
static double read_number(const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1.0;
    double v = -1.0;
    if (fscanf(f, "%lf", &v) != 1)
        v = -1.0;
    fclose(f);
    return v;
}

/* What the cgroup lets this process add, or -1 when unknown/unlimited. */
static double cgroup_left(void)
{
    char dir[576] = ""; /* "/sys/fs/cgroup" + a line */
    FILE *f = fopen("/proc/self/cgroup", "r");
    if (f) {
        char line[512];
        while (fgets(line, sizeof line, f))
            if (strncmp(line, "0::", 3) == 0) { /* cgroup v2 */
                line[strcspn(line, "\n")] = '\0';
                snprintf(dir, sizeof dir, "/sys/fs/cgroup%s", line + 3);
                break;
            }
        fclose(f);
    }
    char path[sizeof dir + 32];
    double max = -1.0, cur = -1.0;
    if (dir[0]) {
        snprintf(path, sizeof path, "%s/memory.max", dir);
        max = read_number(path);
        snprintf(path, sizeof path, "%s/memory.current", dir);
        cur = read_number(path);
    }
    if (max < 0.0) { /* v1, or a v2 namespace seen from inside */
        max = read_number("/sys/fs/cgroup/memory.max");
        cur = read_number("/sys/fs/cgroup/memory.current");
    }
    if (max < 0.0) {
        max = read_number("/sys/fs/cgroup/memory/memory.limit_in_bytes");
        cur = read_number("/sys/fs/cgroup/memory/memory.usage_in_bytes");
    }
    /* v1 says "no limit" with a number near 2^63 */
    if (max < 0.0 || max > 1e18)
        return -1.0;
    return fmax(0.0, max - fmax(cur, 0.0));
}

/* An rlimit's room left: the limit less 'in_use_kb', or -1 unlimited. */
static double rlimit_left(int resource, double in_use_kb)
{
    struct rlimit rl;
    if (getrlimit(resource, &rl) != 0 || rl.rlim_cur == RLIM_INFINITY)
        return -1.0;
    return fmax(0.0, (double)rl.rlim_cur - fmax(in_use_kb, 0.0) * 1024.0);
}

static void take(struct membudget *b, double bytes, const char *what)
{
    if (bytes >= 0.0 && bytes < b->bytes) {
        b->bytes = bytes;
        b->what = what;
    }
}

/* A node-wide limit's room: 'left' for the whole node (-1 unknown) split
** among 'ranks' ranks. */
static double node_share(double left, int ranks)
{
    return left < 0.0 ? -1.0 : left / ranks;
}

void membudget_available(struct membudget *b)
{
    b->bytes = INFINITY;
    b->what = "no limit known";
    const int r = atomic_load(&node_ranks);
    /* the names say when a node's limit is shared (a static string each:
    ** shoot.c keeps b->what) */
    const bool shared = r > 1;
    double avail = proc_kb("/proc/meminfo", "MemAvailable");
    if (avail >= 0.0) {
        take(b, node_share(avail * 1024.0, r),
             shared ? "MemAvailable shared by the node's MPI ranks"
                    : "MemAvailable");
    } else {
#if defined(_SC_AVPHYS_PAGES) && defined(_SC_PAGESIZE)
        long pages = sysconf(_SC_AVPHYS_PAGES), psz = sysconf(_SC_PAGESIZE);
        if (pages > 0 && psz > 0)
            take(b, node_share((double)pages * (double)psz, r),
                 shared ? "available memory shared by the node's MPI ranks"
                        : "the available memory");
#endif
    }
    take(b, rlimit_left(RLIMIT_AS, proc_kb("/proc/self/status", "VmSize")),
         "ulimit -v");
#ifdef RLIMIT_DATA
    take(b, rlimit_left(RLIMIT_DATA, proc_kb("/proc/self/status", "VmData")),
         "ulimit -d");
#endif
    take(b, node_share(cgroup_left(), r),
         shared ? "cgroup's memory.max shared by the node's MPI ranks"
                : "the cgroup's memory.max");
    /* --node-memory: this rank's share less what it holds already */
    double lim = atomic_load(&node_limit);
    if (lim > 0.0) {
        double rss = proc_kb("/proc/self/status", "VmRSS");
        take(b, fmax(0.0, lim / r - fmax(rss, 0.0) * 1024.0),
             shared ? "--node-memory shared by the node's MPI ranks"
                    : "--node-memory");
    }
}

double membudget_photon_peak(double caustic, double global)
{
    return MEMBUDGET_PHOTON_BYTES *
           (fmax(caustic, 0.0) + MEMBUDGET_GLOBAL_DEPOSITS * fmax(global, 0.0));
}

const char *membudget_format(double bytes, char *buf, int len)
{
    if (!isfinite(bytes))
        snprintf(buf, (size_t)len, "unlimited");
    else if (bytes >= 1e9)
        snprintf(buf, (size_t)len, "%.3g GB", bytes / 1e9);
    else
        snprintf(buf, (size_t)len, "%.3g MB", bytes / 1e6);
    return buf;
}
