/* SPDX-License-Identifier: MIT */
/*
** pstore.h: compact photon records in a balanced implicit kd-tree, and
** k-nearest-neighbour queries.
**
** Record layout (16 bytes, struct pstore_photon):
**
**   bits 0..59  of 'pos'   x, y, z quantised to 20 bits each over the
**                          photon's cell (below)
**   bits 60..61 of 'pos'   kd split axis of the node (0, 1, 2)
**   'power'                scalar photon power (float)
**   'lambda_q'             wavelength, 380 + 400·q/65535 nm (0.006 nm);
**                          PSTORE_WHITE (65535): a white photon, the same
**                          at every wavelength (raw lambda < 0)
**   'dir_q'                unit direction towards where the photon came
**                          from, octahedral map with 8 + 8 bits (~1 deg)
**
** Levels and cells. 20 bits over the box of all the photons were too
** coarse: a glass box's photons also light the floor far away (grazing
** reflections), the box of all of them was 1e4 times wider than the
** caustic, and with 1e6 photons the caustic's photons merged onto 13 mm
** steps, fewer distinct points than the k nearest, so the cone filter gave
** ~0 between them (scenes/glass_box.pov: the caustic went black as the
** photon count grew). Two remedies, each for its own part of the problem:
** - Levels: the photons inside a box around their bulk (robust_box() in
**   pstore.c) are level 0, the rest are split the same way into levels
**   1, 2, ... (the last takes all that is left); each level is a
**   contiguous run of records with a tree of its own, and a search visits
**   them all. Nothing finite is dropped, and far photons no longer widen
**   the bulk's steps.
** - Cells: inside a level, a photon is quantised over its kd cell. Each
**   node of the top 'depth' levels of the tree (heap-numbered, root 1,
**   children 2k and 2k + 1) has a cell: the root's is the level's box, a
**   child's its parent's cut at the parent's median (as stored, widened
**   by one parent step so that every photon of the subtree is inside);
**   deeper photons use their depth-'depth' ancestor's cell. A focus of
**   millions of photons thus gets steps ~1/16 of its size over 2^20, not
**   of the level's box. The cells follow from the records and the level's
**   box (a loaded map recomputes them), 'depth' from the level's photon
**   count: cells of at least ~1024 photons, at most 8 levels deep.
** The tree is implicit and built in place: the photons of a segment
** [lo, hi) are partitioned around the median mid = (lo + hi)/2 along the
** axis of largest extent, which is stored in photon mid; [lo, mid) and
** [mid+1, hi) are the subtrees. No pointers, no padding.
**
**        [ left subtree | median | right subtree ]
**          lo ........ mid-1  mid  mid+1 ..... hi-1
*/
#ifndef IRIS_PHOTON_PSTORE_H
#define IRIS_PHOTON_PSTORE_H

#include <stddef.h>
#include <stdint.h>

#include "iris/common.h"
#include "math/vec3.h"

struct pstore_photon {
    uint64_t pos;
    float power;
    uint16_t lambda_q;
    uint16_t dir_q;
};

/* A photon as the shooter produces it, before packing (32 bytes). */
struct pstore_raw {
    float p[3];
    float power;
    float lambda;
    float dir[3];
};

/* A node's cell: its corner and its quantisation step per axis. */
struct pstore_cell {
    double lo[3], step[3];
};

/* A level (above): records [begin, begin + n), the box its root cell
** covers, its cells (cells[1 .. 2^(depth+1)) by heap number). */
struct pstore_level {
    size_t begin, n;
    double lo[3], step[3];
    int depth;
    struct pstore_cell *cells;
};

#define PSTORE_LEVELS 4

struct pstore {
    struct pstore_photon *ph;
    size_t n;
    double lo[3];              /* level 0's box corner */
    double step[3];            /* level 0's root steps */
    size_t n_dropped;          /* photons with a non-finite position */
    int n_levels;
    struct pstore_level level[PSTORE_LEVELS];
};

/* A neighbour found by pstore_knn(). */
struct pstore_found {
    uint32_t index;
    float d2;
};

/*
** Builds the tree from 'n' raw photons ('raw' is reordered; it may be
** freed afterwards). Photons with a non-finite position are left out
** (counted in n_dropped). Returns IRIS_OK or IRIS_ENOMEM. n may be 0.
*/
IRIS_NODISCARD enum iris_status pstore_build(struct pstore *s,
                                             struct pstore_raw *raw,
                                             size_t n);

/* The same, with 'threads' threads (the tree does not depend on it). */
IRIS_NODISCARD enum iris_status pstore_build_mt(struct pstore *s,
                                                struct pstore_raw *raw,
                                                size_t n, int threads);

/* The same, taking 'raw' (allocated with iris_malloc): the packed records
** are written over it and it is shrunk to them (33 bytes a photon at the
** peak instead of 49), or freed on failure. 'raw' must not be used
** afterwards. */
IRIS_NODISCARD enum iris_status pstore_build_in_place(struct pstore *s,
                                                      struct pstore_raw *raw,
                                                      size_t n, int threads);

void pstore_fini(struct pstore *s);

/*
** Computes every level's cells from the records and the levels' begin, n,
** lo and step (a loaded map's; the build does this itself). Returns
** IRIS_OK or IRIS_ENOMEM.
*/
IRIS_NODISCARD enum iris_status pstore_index_cells(struct pstore *s);

/* The bytes the store holds: its records and its levels' cells. */
size_t pstore_bytes(const struct pstore *s);

#define PSTORE_WHITE 65535u

/* Decodes photon 'i'. */
vec3 pstore_position(const struct pstore *s, size_t i);
double pstore_lambda(const struct pstore *s, size_t i);
vec3 pstore_direction(const struct pstore *s, size_t i);

/*
** The (at most) 'k' photons nearest to 'q' within squared distance
** 'max_d2', in no particular order. Returns how many were found; *r2 gets
** the squared distance of the farthest one found (0 when none). 'out' has
** room for k entries; k is at most PSTORE_MAX_K.
*/
#define PSTORE_MAX_K 4096
int pstore_knn(const struct pstore *s, vec3 q, int k, double max_d2,
               struct pstore_found *out, double *r2);

/* Octahedral encoding of a unit vector in 16 bits, and its decoding. */
uint16_t pstore_encode_dir(vec3 d);
vec3 pstore_decode_dir(uint16_t q);

#endif
