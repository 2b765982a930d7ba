/* SPDX-License-Identifier: MIT */
/*
** pstore.h: compact photon records in a balanced implicit kd-tree, and
** k-nearest-neighbour queries.
**
** Record layout (16 bytes, struct pstore_photon):
**
**   bits 0..59  of 'pos'   x, y, z quantised to 20 bits each over the
**                          bounding box of the stored photons
**   bits 60..61 of 'pos'   kd split axis of the node (0, 1, 2)
**   'power'                scalar photon power (float)
**   'lambda_q'             wavelength, 380 + 400·q/65535 nm (0.006 nm);
**                          PSTORE_WHITE (65535): a white photon, the same
**                          at every wavelength (raw lambda < 0)
**   'dir_q'                unit direction towards where the photon came
**                          from, octahedral map with 8 + 8 bits (~1 deg)
**
** 20-bit positions resolve 1e-6 of the box: far below any gather radius.
**
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

struct pstore {
    struct pstore_photon *ph;
    size_t n;
    double lo[3];              /* box corner */
    double step[3];            /* quantisation step per axis */
    size_t n_dropped;          /* far photons left out (pstore.c) */
};

/* A neighbour found by pstore_knn(). */
struct pstore_found {
    uint32_t index;
    float d2;
};

/*
** Builds the tree from 'n' raw photons ('raw' is reordered; it may be
** freed afterwards). Photons far outside the bulk of the others are left
** out (counted in n_dropped; see robust_box() in pstore.c). Returns IRIS_OK or IRIS_ENOMEM. n may be 0.
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
