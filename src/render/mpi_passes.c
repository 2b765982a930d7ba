/* SPDX-License-Identifier: MIT */
/*
** mpi_passes.c: MPI collectives for progressive passes (see
** mpi_passes.h).
**
** The sum buffer is reduced in chunks of at most INT_MAX/2 elements
** because MPI counts are int. MPI_SUM of doubles adds the ranks' partial
** sums in an order MPI chooses, so an image made with R ranks equals the
** one made with one rank up to double rounding of the summation order
** (about 1e-16 relative), far below the float of the written image.
**
** MPI_Init in the background. MPI_Init takes 0.1-0.3 s of wall time but
** ~0.035 s of CPU (measured: 2 ranks on localhost, Open MPI 4): it waits
** for the launcher's exchange of the ranks' addresses. Every rank would
** wait it out before its first pass, a fixed cost that does not shrink
** with the ranks. The launchers put this process's rank, the world size
** and the ranks on this node in the environment, which is all a rank
** needs until its first collective (after its first round of passes), so
** when they are there MPI_Init_thread(MPI_THREAD_SERIALIZED) runs on a
** thread of its own while the rank starts work, and every function below
** that talks to MPI first waits for that thread (mpi_ready()). SERIALIZED:
** the main thread then makes the MPI calls, one at a time. The standard
** asks that MPI_Finalize run on the thread that initialised MPI, so the
** init thread stays parked until mpi_passes_finalize() wakes it to
** finalize, then is joined.
*/
#include "config.h"

#include "render/mpi_passes.h"

#include "photon/membudget.h"

#ifdef HAVE_MPI
#include <limits.h>
#include <mpi.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

/* True when this module called MPI_Init (and so must finalize). */
static int mpi_owned;

/* True once every rank knows the run is over (mpi_passes_end_failed). */
static int ended_together;

/* The background MPI_Init: pending until joined; what the launcher's
** environment said (-1: not said). */
static pthread_t init_thread;
static int init_pending;     /* started, not yet waited for */
static int init_threaded;    /* the init thread exists until finalize */
static int init_done, finalize_asked; /* under init_lock */
static pthread_mutex_t init_lock = PTHREAD_MUTEX_INITIALIZER;
static pthread_cond_t init_cond = PTHREAD_COND_INITIALIZER;
static int init_status = MPI_SUCCESS;
static int env_rank = -1, env_size = -1, env_local = -1;

/* True when MPI is usable: initialized and not yet finalized. */
static int mpi_active(void)
{
    int init = 0, fini = 0;
    MPI_Initialized(&init);
    if (!init)
        return 0;
    MPI_Finalized(&fini);
    return !fini;
}

/*
** Whether a process manager (mpirun, mpiexec, srun) started us. Open
** MPI's singleton MPI_Init spawns an orted daemon, 0.4-0.6 s at every
** start, so a plain `iris scene.pov` must not call it: without these
** variables iris runs as rank 0 of 1 without MPI at all.
*/
static int launched_by_mpi(void)
{
    static const char *const vars[] = { "OMPI_COMM_WORLD_SIZE", "PMIX_RANK",
                                        "PMI_RANK", "PMI_SIZE" };
    for (size_t i = 0; i < sizeof vars / sizeof vars[0]; i++)
        if (getenv(vars[i]))
            return 1;
    return 0;
}

/* The first of the variables 'names' (NULL-terminated) holding an integer
** >= lo, or -1. Open MPI: OMPI_COMM_WORLD_*; MPICH's Hydra: PMI_RANK,
** PMI_SIZE, MPI_LOCALNRANKS. */
static int env_int(const char *const *names, int lo)
{
    for (; *names; names++) {
        const char *v = getenv(*names);
        char *end;
        long x = v ? strtol(v, &end, 10) : -1;
        if (v && end != v && *end == '\0' && x >= lo && x <= INT_MAX)
            return (int)x;
    }
    return -1;
}

/* The ranks on this node: MPI_COMM_TYPE_SHARED groups them. */
static int node_ranks_from_mpi(void)
{
    MPI_Comm node;
    int n = 1;
    if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0,
                            MPI_INFO_NULL, &node) == MPI_SUCCESS) {
        MPI_Comm_size(node, &n);
        MPI_Comm_free(&node);
    }
    return n < 1 ? 1 : n;
}

static void *init_main(void *unused)
{
    (void)unused;
    int provided = 0;
    /* MPI-2 allows NULL argc and argv */
    int status = MPI_Init_thread(NULL, NULL, MPI_THREAD_SERIALIZED,
                                 &provided);
    /* below SERIALIZED the main thread may not call MPI at all */
    if (status == MPI_SUCCESS && provided < MPI_THREAD_SERIALIZED)
        status = MPI_ERR_OTHER;
    pthread_mutex_lock(&init_lock);
    init_status = status;
    init_done = 1;
    pthread_cond_broadcast(&init_cond);
    while (!finalize_asked)
        pthread_cond_wait(&init_cond, &init_lock);
    pthread_mutex_unlock(&init_lock);
    if (status == MPI_SUCCESS)
        MPI_Finalize();
    return NULL;
}

static void wait_gently(MPI_Request *rq);

/*
** Joins the background MPI_Init. A rank that told the environment's rank
** and size to its callers cannot go on as one rank alone: if MPI_Init
** failed or disagrees with the environment, it stops here.
*/
static void mpi_ready(void)
{
    if (!init_pending)
        return;
    pthread_mutex_lock(&init_lock);
    while (!init_done)
        pthread_cond_wait(&init_cond, &init_lock);
    pthread_mutex_unlock(&init_lock);
    init_pending = 0;
    if (init_status != MPI_SUCCESS) {
        fprintf(stderr, "iris: MPI_Init failed under an MPI launcher\n");
        exit(EXIT_FAILURE);
    }
    mpi_owned = 1;
    int r = -1, s = -1;
    MPI_Comm_rank(MPI_COMM_WORLD, &r);
    MPI_Comm_size(MPI_COMM_WORLD, &s);
    if (r != env_rank || s != env_size) {
        fprintf(stderr, "iris: MPI says rank %d of %d, the launcher's "
                "environment %d of %d\n", r, s, env_rank, env_size);
        MPI_Abort(MPI_COMM_WORLD, EXIT_FAILURE);
    }
    /* The first collective comes here, at a rank's first agreement, and
    ** MPI_Comm_split_type's blocking one busy-polls while the others
    ** finish their first passes (perf, 2 ranks, rank 1 started 0.4 s late:
    ** rank 0 0.38-0.42 s of CPU, 0.33 s with this); a sleeping barrier
    ** first, so that it runs with all ranks there */
    MPI_Request rq;
    if (MPI_Ibarrier(MPI_COMM_WORLD, &rq) == MPI_SUCCESS)
        wait_gently(&rq);
    int local = node_ranks_from_mpi();
    if (local != env_local) /* MPI knows best; photon budgets from now on */
        membudget_set_node_ranks(local);
}

void mpi_passes_init(int *argc, char ***argv)
{
    if (init_pending || mpi_active() || !launched_by_mpi())
        return;
    static const char *const rank_vars[] = { "OMPI_COMM_WORLD_RANK",
                                             "PMI_RANK", "PMIX_RANK", NULL };
    static const char *const size_vars[] = { "OMPI_COMM_WORLD_SIZE",
                                             "PMI_SIZE", NULL };
    static const char *const local_vars[] = { "OMPI_COMM_WORLD_LOCAL_SIZE",
                                              "MPI_LOCALNRANKS", NULL };
    env_rank = env_int(rank_vars, 0);
    env_size = env_int(size_vars, 1);
    env_local = env_int(local_vars, 1);
    if (env_rank >= 0 && env_size > env_rank && env_local >= 1 &&
        env_local <= env_size &&
        pthread_create(&init_thread, NULL, init_main, NULL) == 0) {
        init_pending = init_threaded = 1;
        membudget_set_node_ranks(env_local);
        return;
    }
    env_rank = env_size = env_local = -1;
    if (MPI_Init(argc, argv) == MPI_SUCCESS) {
        mpi_owned = 1;
        membudget_set_node_ranks(node_ranks_from_mpi());
    }
}

void mpi_passes_finalize(void)
{
    mpi_ready();
    if (init_threaded) { /* the thread that initialised MPI finalizes it */
        pthread_mutex_lock(&init_lock);
        finalize_asked = 1;
        pthread_cond_broadcast(&init_cond);
        pthread_mutex_unlock(&init_lock);
        pthread_join(init_thread, NULL);
        init_threaded = 0;
    } else if (mpi_owned && mpi_active()) {
        MPI_Finalize();
    }
    mpi_owned = 0;
}

void mpi_passes_end_failed(int rc)
{
    if (!ended_together && mpi_passes_size() > 1) {
        mpi_ready();
        if (mpi_active())
            MPI_Abort(MPI_COMM_WORLD, rc);
    }
    mpi_passes_finalize();
}

int mpi_passes_rank(void)
{
    if (init_pending)
        return env_rank;
    int r = 0;
    if (mpi_active())
        MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int mpi_passes_size(void)
{
    if (init_pending)
        return env_size;
    int s = 1;
    if (mpi_active())
        MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s < 1 ? 1 : s;
}

/*
** Waits for a non-blocking collective without spinning. Open MPI's
** blocking collectives busy-poll: a rank that waits at an agreement for a
** slower one burns a core, and where ranks share cores with each other
** or with other work (oversubscription, a loaded node) that core is the
** slower rank's. Here the rank tests, sleeps 20 us, and doubles the sleep
** up to 1 ms: a wait costs at most ~1 ms more than a spin, and a
** collective of this module completes in few tests (an allreduce of a few
** ints, a barrier).
*/
static void wait_gently(MPI_Request *rq)
{
    int done = 0;
    long ns = 20000;
    MPI_Test(rq, &done, MPI_STATUS_IGNORE);
    while (!done) {
        struct timespec ts = { 0, ns };
        nanosleep(&ts, NULL);
        if (ns < 1000000)
            ns *= 2;
        MPI_Test(rq, &done, MPI_STATUS_IGNORE);
    }
}

/* The world's size for a collective, MPI_Init joined first. */
static int world_size(void)
{
    mpi_ready();
    return mpi_passes_size();
}

void mpi_passes_bcast_int(int *v, int n)
{
    if (world_size() > 1)
        MPI_Bcast(v, n, MPI_INT, 0, MPI_COMM_WORLD);
}

int mpi_passes_agree(int go_root, int failed_local, int *vals, int n,
                     int *each, int *failed_any)
{
    if (world_size() <= 1) {
        if (failed_any)
            *failed_any = failed_local > 0 ? failed_local : 0;
        return go_root && failed_local <= 0;
    }
    /* one collective: the largest of "rank 0 says stop", the failure
    ** codes and rank 0's values (>= 0; the others contribute 0) */
    enum { MAX_VALS = 4, MAX_EACH = 256 };
    const int rank = mpi_passes_rank(), size = mpi_passes_size();
    const int m = each && size <= MAX_EACH ? size : 0;
    int root = rank == 0;
    int mine[2 + MAX_VALS + MAX_EACH] = { root ? !go_root : 0,
                                          failed_local > 0 ? failed_local
                                                           : 0 };
    int all[2 + MAX_VALS + MAX_EACH] = { 0 };
    if (n > MAX_VALS)
        n = MAX_VALS;
    for (int i = 0; i < n; i++)
        mine[2 + i] = root ? vals[i] : 0;
    if (m > 0) /* each rank's own slot; the others contribute 0 */
        mine[2 + n + rank] = each[rank] > 0 ? each[rank] : 0;
    MPI_Request rq;
    MPI_Iallreduce(mine, all, 2 + n + m, MPI_INT, MPI_MAX, MPI_COMM_WORLD,
                   &rq);
    wait_gently(&rq);
    for (int i = 0; i < n; i++)
        vals[i] = all[2 + i];
    for (int r = 0; r < m; r++)
        each[r] = all[2 + n + r];
    if (failed_any)
        *failed_any = all[1];
    if (all[0] || all[1]) /* every rank stops here, at the same agreement */
        ended_together = 1;
    return !all[0] && !all[1];
}

int mpi_passes_first_error(int failed_local, char *err, size_t errlen)
{
    if (world_size() <= 1)
        return failed_local ? 0 : -1;
    /* which rank: the lowest that failed (one collective, sleeping) */
    const int rank = mpi_passes_rank();
    int mine = failed_local ? rank : INT_MAX, first = INT_MAX;
    MPI_Request rq;
    MPI_Iallreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD, &rq);
    wait_gently(&rq);
    if (first == INT_MAX)
        return -1;
    if (first == 0) /* rank 0's own message is in its own 'err' */
        return rank == 0 ? 0 : -1;
    /* a fixed-size message, so that rank 0 need not ask for its length */
    enum { MSG = 512 };
    char buf[MSG] = "";
    if (rank == first) {
        if (err && errlen)
            snprintf(buf, sizeof buf, "%s", err);
        MPI_Request sq;
        MPI_Isend(buf, MSG, MPI_CHAR, 0, 0x1e7, MPI_COMM_WORLD, &sq);
        wait_gently(&sq);
    } else if (rank == 0) {
        MPI_Request rr;
        MPI_Irecv(buf, MSG, MPI_CHAR, first, 0x1e7, MPI_COMM_WORLD, &rr);
        wait_gently(&rr);
        buf[MSG - 1] = '\0';
        if (err && errlen)
            snprintf(err, errlen, "%s", buf);
        return first;
    }
    return -1;
}

void mpi_passes_gather(const double *mine, int n, double *all)
{
    if (world_size() <= 1) {
        for (int i = 0; i < n; i++)
            all[i] = mine[i];
        return;
    }
    MPI_Gather(mine, n, MPI_DOUBLE, all, n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void mpi_passes_reduce(double *sum, size_t n, int *passes,
                       uint64_t *photons)
{
    if (world_size() <= 1)
        return;
    /* the ranks that finished first wait here without spinning; the
    ** reduction then runs with all ranks present */
    MPI_Request rq;
    MPI_Ibarrier(MPI_COMM_WORLD, &rq);
    wait_gently(&rq);
    int root = mpi_passes_rank() == 0;
    const size_t chunk = (size_t)(INT_MAX / 2);
    for (size_t off = 0; off < n; off += chunk) {
        int c = (int)(n - off < chunk ? n - off : chunk);
        if (root)
            MPI_Reduce(MPI_IN_PLACE, sum + off, c, MPI_DOUBLE, MPI_SUM, 0,
                       MPI_COMM_WORLD);
        else
            MPI_Reduce(sum + off, NULL, c, MPI_DOUBLE, MPI_SUM, 0,
                       MPI_COMM_WORLD);
    }
    if (root) {
        MPI_Reduce(MPI_IN_PLACE, passes, 1, MPI_INT, MPI_SUM, 0,
                   MPI_COMM_WORLD);
        MPI_Reduce(MPI_IN_PLACE, photons, 1, MPI_UINT64_T, MPI_SUM, 0,
                   MPI_COMM_WORLD);
    } else {
        MPI_Reduce(passes, NULL, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
        MPI_Reduce(photons, NULL, 1, MPI_UINT64_T, MPI_SUM, 0,
                   MPI_COMM_WORLD);
    }
    ended_together = 1;
}

void mpi_passes_snapshot(const double *sum, double *total, size_t n,
                         int passes, uint64_t photons, int *tot_passes,
                         uint64_t *tot_photons)
{
    int root = mpi_passes_rank() == 0;
    if (world_size() <= 1) {
        for (size_t i = 0; root && i < n; i++)
            total[i] = sum[i];
        *tot_passes = passes;
        *tot_photons = photons;
        return;
    }
    const size_t chunk = (size_t)(INT_MAX / 2);
    for (size_t off = 0; off < n; off += chunk) {
        int c = (int)(n - off < chunk ? n - off : chunk);
        MPI_Reduce(sum + off, root ? total + off : NULL, c, MPI_DOUBLE,
                   MPI_SUM, 0, MPI_COMM_WORLD);
    }
    MPI_Reduce(&passes, tot_passes, 1, MPI_INT, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(&photons, tot_photons, 1, MPI_UINT64_T, MPI_SUM, 0,
               MPI_COMM_WORLD);
}

#else /* !HAVE_MPI: one rank */

void mpi_passes_init(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
}

void mpi_passes_finalize(void) {}

void mpi_passes_end_failed(int rc) { (void)rc; }

int mpi_passes_rank(void) { return 0; }

int mpi_passes_size(void) { return 1; }

void mpi_passes_bcast_int(int *v, int n)
{
    (void)v;
    (void)n;
}

int mpi_passes_agree(int go_root, int failed_local, int *vals, int n,
                     int *each, int *failed_any)
{
    (void)vals; /* rank 0's values stay */
    (void)n;
    (void)each; /* one rank: its own value stays */
    if (failed_any)
        *failed_any = failed_local > 0 ? failed_local : 0;
    return go_root && failed_local <= 0;
}

int mpi_passes_first_error(int failed_local, char *err, size_t errlen)
{
    (void)err; /* one rank: its own message stays */
    (void)errlen;
    return failed_local ? 0 : -1;
}

void mpi_passes_gather(const double *mine, int n, double *all)
{
    for (int i = 0; i < n; i++)
        all[i] = mine[i];
}

void mpi_passes_snapshot(const double *sum, double *total, size_t n,
                         int passes, uint64_t photons, int *tot_passes,
                         uint64_t *tot_photons)
{
    for (size_t i = 0; i < n; i++)
        total[i] = sum[i];
    *tot_passes = passes;
    *tot_photons = photons;
}

void mpi_passes_reduce(double *sum, size_t n, int *passes,
                       uint64_t *photons)
{
    (void)sum;
    (void)n;
    (void)passes;
    (void)photons;
}

#endif
