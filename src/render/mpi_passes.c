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
*/
#include "config.h"

#include "render/mpi_passes.h"

#ifdef HAVE_MPI
#include <limits.h>
#include <mpi.h>
#include <stdlib.h>

/* True when this module called MPI_Init (and so must finalize). */
static int mpi_owned;

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

void mpi_passes_init(int *argc, char ***argv)
{
    if (mpi_active() || !launched_by_mpi())
        return;
    if (MPI_Init(argc, argv) == MPI_SUCCESS)
        mpi_owned = 1;
}

void mpi_passes_finalize(void)
{
    if (mpi_owned && mpi_active())
        MPI_Finalize();
    mpi_owned = 0;
}

int mpi_passes_rank(void)
{
    int r = 0;
    if (mpi_active())
        MPI_Comm_rank(MPI_COMM_WORLD, &r);
    return r;
}

int mpi_passes_size(void)
{
    int s = 1;
    if (mpi_active())
        MPI_Comm_size(MPI_COMM_WORLD, &s);
    return s < 1 ? 1 : s;
}

void mpi_passes_bcast_int(int *v, int n)
{
    if (mpi_passes_size() > 1)
        MPI_Bcast(v, n, MPI_INT, 0, MPI_COMM_WORLD);
}

int mpi_passes_agree(int go_root, int failed_local, int *vals, int n)
{
    if (mpi_passes_size() <= 1)
        return go_root && !failed_local;
    /* one collective: the largest of "rank 0 says stop", "failed" and
    ** rank 0's values (>= 0; the others contribute 0) */
    enum { MAX_VALS = 4 };
    int root = mpi_passes_rank() == 0;
    int mine[2 + MAX_VALS] = { root ? !go_root : 0, !!failed_local };
    int all[2 + MAX_VALS] = { 0 };
    if (n > MAX_VALS)
        n = MAX_VALS;
    for (int i = 0; i < n; i++)
        mine[2 + i] = root ? vals[i] : 0;
    MPI_Allreduce(mine, all, 2 + n, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
    for (int i = 0; i < n; i++)
        vals[i] = all[2 + i];
    return !all[0] && !all[1];
}

void mpi_passes_gather(const double *mine, int n, double *all)
{
    if (mpi_passes_size() <= 1) {
        for (int i = 0; i < n; i++)
            all[i] = mine[i];
        return;
    }
    MPI_Gather(mine, n, MPI_DOUBLE, all, n, MPI_DOUBLE, 0, MPI_COMM_WORLD);
}

void mpi_passes_reduce(double *sum, size_t n, int *passes,
                       uint64_t *photons)
{
    if (mpi_passes_size() <= 1)
        return;
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
}

void mpi_passes_snapshot(const double *sum, double *total, size_t n,
                         int passes, uint64_t photons, int *tot_passes,
                         uint64_t *tot_photons)
{
    int root = mpi_passes_rank() == 0;
    if (mpi_passes_size() <= 1) {
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

int mpi_passes_rank(void) { return 0; }

int mpi_passes_size(void) { return 1; }

void mpi_passes_bcast_int(int *v, int n)
{
    (void)v;
    (void)n;
}

int mpi_passes_agree(int go_root, int failed_local, int *vals, int n)
{
    (void)vals; /* rank 0's values stay */
    (void)n;
    return go_root && !failed_local;
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
