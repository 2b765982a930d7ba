/* SPDX-License-Identifier: MIT */
/*
** rng.h: counter-based random numbers.
**
** Results must not depend on the thread count or the MPI rank count, so
** every random stream is keyed by what it is for: rng_seed(seed, a, b)
** with, for example, (pass, photon index) or (pass, pixel index). The
** generator is PCG32 (O'Neill 2014) started from a SplitMix64 hash of the
** key, which decorrelates neighbouring keys.
*/
#ifndef IRIS_UTIL_RNG_H
#define IRIS_UTIL_RNG_H

#include <stdint.h>

typedef struct rng {
    uint64_t state, inc;
} rng;

/* SplitMix64 finaliser: a good 64-bit mixing function. */
static inline uint64_t rng_mix64(uint64_t z)
{
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static inline uint32_t rng_u32(rng *r)
{
    uint64_t old = r->state;
    r->state = old * 6364136223846793005ULL + r->inc;
    uint32_t xorshifted = (uint32_t)(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = (uint32_t)(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((-rot) & 31));
}

/* Starts the stream for key (seed, a, b). */
static inline void rng_seed(rng *r, uint64_t seed, uint64_t a, uint64_t b)
{
    uint64_t h = rng_mix64(seed ^ rng_mix64(a ^ rng_mix64(b)));
    r->state = 0;
    r->inc = (rng_mix64(h + 1) << 1u) | 1u;
    rng_u32(r);
    r->state += h;
    rng_u32(r);
}

/* Uniform double in [0, 1). */
static inline double rng_uniform(rng *r)
{
    uint64_t hi = rng_u32(r), lo = rng_u32(r);
    return (double)(((hi << 21) ^ lo) & ((1ULL << 53) - 1)) * 0x1p-53;
}

/* Uniform float in [0, 1). */
static inline float rng_uniformf(rng *r)
{
    return (float)(rng_u32(r) >> 8) * 0x1p-24f;
}

/*
** A stream whose seeding waits for its first number. The eye pass keys a
** stream per camera sample, but most samples draw no random number at
** all (no jittered area light, crand, media or dispersion on their
** path), and rng_seed()'s four hashes were 2 % of a simple scene's
** render. The numbers drawn are those of rng_seed() with the same key.
*/
typedef struct rng_lazy {
    rng r;
    uint64_t seed, a, b;       /* the key of a stream not yet started */
    int pending;               /* 1: r is to be seeded from the key */
} rng_lazy;

static inline void rng_lazy_seed(rng_lazy *l, uint64_t seed, uint64_t a,
                                 uint64_t b)
{
    l->seed = seed;
    l->a = a;
    l->b = b;
    l->pending = 1;
}

/* The stream, seeded now if it was not yet. */
static inline rng *rng_lazy_get(rng_lazy *l)
{
    if (l->pending) {
        rng_seed(&l->r, l->seed, l->a, l->b);
        l->pending = 0;
    }
    return &l->r;
}

#endif
