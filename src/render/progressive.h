/* SPDX-License-Identifier: MIT */
/*
** progressive.h: progressive photon mapping (issue 6): independent photon
** passes with a shrinking estimate radius, each followed by an eye pass
** with new jitter, averaged into a running image.
**
** Depends on: photon (the map of each pass), render (eye pass, tracer).
** Used by: render.c when the options ask for more than one pass, a time
** limit or a resumed accumulation.
*/
#ifndef IRIS_RENDER_PROGRESSIVE_H
#define IRIS_RENDER_PROGRESSIVE_H

#include <stdbool.h>
#include <stdint.h>

#include "iris/render.h"
#include "render/trace.h"

struct accel;
struct mat_ctx;
struct photon_map;

/* Knaus and Zwicker's alpha: the fraction of photons a pass keeps. */
#define PROGRESSIVE_ALPHA (2.0 / 3.0)

/* True when 'opts' asks for progressive rendering rather than one render
** (--passes > 1, --time-limit or --resume). */
bool progressive_wanted(const iris_render_options *opts);

/*
** The estimate radius of pass 'pass' (0-based) relative to the first's:
** r_i/r_1 = sqrt(prod_{k=1}^{i-1} (k + alpha)/(k + 1)) with i = pass + 1
** (Knaus and Zwicker 2011, eq. 20). 1 for pass 0.
*/
double progressive_radius_scale(int pass);

/*
** Runs the passes. 'tr' is the tracer with pass 0's photon hooks already
** set by the caller (render.c) and *map pass 0's map (may be NULL); the
** driver replaces it pass by pass, freeing each map before the next is
** built, and leaves the last in *map for the caller to free. 't_start' is
** par_now() at the start of iris_render() (the time limit and the pass
** callback count from it). *photon_s gets the seconds spent building
** maps after the first. 'out' receives the average of the passes done
** (on IRIS_EINTR too). Returns IRIS_OK, IRIS_ENOMEM, IRIS_EINVAL (an empty
** window), IRIS_EIO (a checkpoint that cannot be read or written, or does
** not fit this render; message in 'err') or IRIS_EINTR.
**
** 'pass0' is the caller's status of pass 0's map. Under MPI that map is
** rank 0's alone, and when it failed rank 0 still joins the other ranks'
** collectives to stop them (no rank waits for ever); progressive_run
** then returns 'pass0' with 'err' as the caller left it. Otherwise
** IRIS_OK; with one rank the caller does not call it on a failure.
** Rank 0 returns another rank's failure as its own status (a message in
** 'err').
*/
enum iris_status progressive_run(struct tracer *tr, const struct accel *acc,
                                 const struct mat_ctx *mat, int threads,
                                 const iris_render_options *opts,
                                 double t_start, enum iris_status pass0,
                                 struct photon_map **map,
                                 iris_image *out, iris_render_stats *stats,
                                 double *photon_s, char *err, size_t errlen);

#endif
