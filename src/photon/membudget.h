/* SPDX-License-Identifier: MIT */
/*
** membudget.h: how much memory the photon pass may use, and how much it
** will (issue 8: "a clear error before a run would exceed the memory
** available").
**
** A photon pass that outgrows memory is killed by the kernel (or fails an
** allocation deep in the build) with no word about the scene line that
** asked for it. shoot.c therefore compares, before it allocates, the
** pass's peak estimated from its photon count with the least of the
** limits the process runs under, and refuses with a located error.
**
** Depends on: nothing but libc and /proc. Used by: shoot.c.
*/
#ifndef IRIS_PHOTON_MEMBUDGET_H
#define IRIS_PHOTON_MEMBUDGET_H

#include <stdbool.h>
#include <stdint.h>

/*
** Peak bytes of a photon pass per caustic photon emitted. Measured on
** bench/caustic_ball.pov (bench/memory.sh, docs/photons.md "Memory"):
** 30 bytes per photon emitted, 33 per photon stored, from 1e6 to 1e7
** photons (45 and 49 before the in-place build). The budget still allows
** 64: a batch that stores more photons than it shoots (mirrors, several
** caustic deposits) falls back to concatenating its batches, where a
** stored photon is a 32-byte raw record twice (pstore.c), and a scene can
** store about as many photons as it emits.
*/
#define MEMBUDGET_PHOTON_BYTES 64.0

/* Deposits per global photon the budget allows (diffuse bounces continue
** by Russian roulette on the albedo: 1/(1 - a) stores, 4 at a = 0.75). */
#define MEMBUDGET_GLOBAL_DEPOSITS 4.0

/* The tightest limit on what this process may still allocate. */
struct membudget {
    double bytes;              /* INFINITY when no limit is known */
    const char *what;          /* which limit: "MemAvailable", "ulimit -v",
                                  "ulimit -d", "the cgroup's memory.max",
                                  "--node-memory", the node-wide ones with
                                  " shared by R ranks" */
};

/* Reads the limits: MemAvailable (/proc/meminfo; sysconf's available
** pages without it), RLIMIT_AS less the address space in use (VmSize),
** RLIMIT_DATA less the data in use (VmData), the cgroup's memory.max
** less memory.current (v2; v1's limit_in_bytes) and the node limit set
** by membudget_set_node_limit() less this process's resident set.
**
** The ulimits are this process's own; the others belong to the node (the
** machine, or the cgroup its ranks run in), which the MPI ranks on it
** share: each rank's photon passes run at the same time as the others',
** so each may use 1/R of those, R = membudget_set_node_ranks()'s. */
void membudget_available(struct membudget *b);

/* The number of processes (MPI ranks) sharing this node's memory, 1 by
** default (render/mpi_passes.c sets it from MPI_COMM_TYPE_SHARED). */
void membudget_set_node_ranks(int ranks);

/* A limit in bytes on what all of this node's ranks together may use
** (iris --node-memory), <= 0 for none. It counts like the cgroup's:
** each rank gets 1/R of it, less what the rank already holds. */
void membudget_set_node_limit(double bytes);

/* The estimated peak in bytes of a photon pass that emits 'caustic'
** caustic photons and 'global' global ones (0 when there is no global
** map). */
double membudget_photon_peak(double caustic, double global);

/* Formats 'bytes' as "1.23 GB" / "456 MB" into buf (for messages). */
const char *membudget_format(double bytes, char *buf, int len);

#endif
