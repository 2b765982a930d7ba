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
** 45 bytes per photon emitted, 49 per photon stored, from 1e6 to 1e8
** photons. The budget allows 64: while the batches are concatenated a
** stored photon is a 32-byte raw record twice (batch buffer and the
** concatenated array) before the 16-byte record and the kd axis byte
** replace one of them (pstore.c), and a scene can store about as many
** photons as it emits.
*/
#define MEMBUDGET_PHOTON_BYTES 64.0

/* Deposits per global photon the budget allows (diffuse bounces continue
** by Russian roulette on the albedo: 1/(1 - a) stores, 4 at a = 0.75). */
#define MEMBUDGET_GLOBAL_DEPOSITS 4.0

/* The tightest limit on what this process may still allocate. */
struct membudget {
    double bytes;              /* INFINITY when no limit is known */
    const char *what;          /* which limit: "MemAvailable", "ulimit -v",
                                  "ulimit -d", "the cgroup's memory.max" */
};

/* Reads the limits: MemAvailable (/proc/meminfo; sysconf's available
** pages without it), RLIMIT_AS less the address space in use (VmSize),
** RLIMIT_DATA less the data in use (VmData), and the cgroup's
** memory.max less memory.current (v2; v1's limit_in_bytes). */
void membudget_available(struct membudget *b);

/* The estimated peak in bytes of a photon pass that emits 'caustic'
** caustic photons and 'global' global ones (0 when there is no global
** map). */
double membudget_photon_peak(double caustic, double global);

/* Formats 'bytes' as "1.23 GB" / "456 MB" into buf (for messages). */
const char *membudget_format(double bytes, char *buf, int len);

#endif
