/* SPDX-License-Identifier: MIT */
/*
** jitter.h: POV-Ray's position-keyed antialiasing jitter.
**
** Depends on: material (the noise hash table). Used by: eyepass.c.
*/
#ifndef IRIS_RENDER_JITTER_H
#define IRIS_RENDER_JITTER_H

#include <stdatomic.h>

/* jitter.c's data: POV-Ray's 256 offsets and a copy of the noise hash
** table's first 4096 entries, made once by jitter_hash_init() (it sets
** jitter_hash_ready). Here so that jitter2d() is inline: it runs once
** per antialiasing subsample, and its call was a tenth of its cost. */
extern const float jitter_table[256];
extern int jitter_hash[4096];
extern atomic_bool jitter_hash_ready;
void jitter_hash_init(void);

static inline int jitter_lookup(int a, int b)
{
    return jitter_hash[(jitter_hash[a & 0xfff] ^ b) & 0xfff] & 0xff;
}

/* The jitter of the subsample at image position (x, y), each component
** in [-0.5, 0.5): a pure function of the position, as POV-Ray's. */
static inline void jitter2d(double x, double y, double *jx, double *jy)
{
    if (!atomic_load_explicit(&jitter_hash_ready, memory_order_acquire))
        jitter_hash_init();
    *jx = jitter_table[jitter_lookup((int)(x * 1021.0), (int)(y * 1019.0))];
    *jy = jitter_table[jitter_lookup((int)(x * 1019.0), (int)(y * 1021.0))];
}

#endif
