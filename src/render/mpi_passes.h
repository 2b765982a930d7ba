/* SPDX-License-Identifier: MIT */
/*
** mpi_passes.h: the few MPI collectives progressive rendering needs
** (issue 8): which rank this is, rank 0's decisions broadcast to all, and
** the reduction of the per-rank pass sums onto rank 0.
**
** Without HAVE_MPI, or when MPI was not initialized (a library user, or
** iris not started by mpirun), every function behaves as a single rank:
** rank 0 of 1, broadcasts and reductions leave their arguments as they
** are. So callers need no #ifdef.
**
** Depends on: MPI (optional), photon/membudget.h. Used by:
** progressive.c, render.c, cli/main.c.
*/
#ifndef IRIS_RENDER_MPI_PASSES_H
#define IRIS_RENDER_MPI_PASSES_H

#include <stddef.h>
#include <stdint.h>

/* MPI_Init (when built with MPI and started by an MPI launcher); call
** once at the start of main. When the launcher's environment gives this
** rank, the world size and the ranks on this node, MPI_Init runs on a
** thread of its own and the first collective waits for it. Tells
** membudget.h how many ranks share this node's memory. */
void mpi_passes_init(int *argc, char ***argv);

/* MPI_Finalize when mpi_passes_init initialized MPI. */
void mpi_passes_finalize(void);

/*
** Ends this process's part in the run after the command failed with
** status 'rc' (not 0). When every rank knows the run is over (an
** agreement said stop, or the final reduction ran) this is
** mpi_passes_finalize(). Otherwise this rank left early on its own (a
** usage error on one rank, a directory only rank 0 writes to is missing)
** while the others will wait for it at their next collective, and
** MPI_Finalize would wait for them: MPI_Abort ends the whole job with
** 'rc'. Without MPI, or on one rank, it finalizes.
*/
void mpi_passes_end_failed(int rc);

/* This process's rank, 0 when not running under MPI. */
int mpi_passes_rank(void);

/* The number of ranks, 1 when not running under MPI. */
int mpi_passes_size(void);

/* Rank 0's values of v[0..n-1] copied to every rank. */
void mpi_passes_bcast_int(int *v, int n);

/*
** One decision, the same on every rank: true when rank 0's 'go_root' is
** true and no rank has 'failed_local' > 0 (a failure code, e.g. an
** iris_status; 0 when this rank is fine). *failed_any (when not NULL)
** gets the largest rank's code. vals[0..n-1] (n <= 4, values >= 0) are
** rank 0's on entry and, on return, rank 0's on every rank (more
** decisions in the same collective). 'each' (NULL: none) has a slot per
** rank: on entry this rank's value (>= 0) in each[rank], on return every
** rank's value in its slot (up to 256 ranks; with more, 'each' is left
** as it is).
*/
int mpi_passes_agree(int go_root, int failed_local, int *vals, int n,
                     int *each, int *failed_any);

/*
** After an agreement that reported a failure (every rank calls it, or
** none): the message 'err' of the lowest-numbered rank whose
** 'failed_local' is true goes to rank 0, because only rank 0 speaks
** (main.c sends the other ranks' stderr to /dev/null). Returns that
** rank's number on rank 0 (its 'err' then holds the message; when the
** rank is 0 itself nothing is copied), -1 when no rank failed; the other
** ranks get -1 and keep their 'err'.
*/
int mpi_passes_first_error(int failed_local, char *err, size_t errlen);

/* Rank 0 gets every rank's mine[0..n-1], rank r's at all[r·n] ('all'
** has room for size·n; ignored on the other ranks). */
void mpi_passes_gather(const double *mine, int n, double *all);

/*
** Sums 'sum[0..n-1]', *passes and *photons over all ranks onto rank 0
** (in place there; the other ranks' arguments are left as they are).
*/
void mpi_passes_reduce(double *sum, size_t n, int *passes,
                       uint64_t *photons);

/*
** The same sums onto rank 0 without touching the ranks' own: rank 0 gets
** them in 'total' (n doubles; NULL on the other ranks), *tot_passes and
** *tot_photons. A snapshot of the run so far (progressive.c).
*/
void mpi_passes_snapshot(const double *sum, double *total, size_t n,
                         int passes, uint64_t photons, int *tot_passes,
                         uint64_t *tot_photons);

#endif
