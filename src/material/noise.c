/* SPDX-License-Identifier: MIT */
/*
** noise.c: POV-Ray 3.7's noise functions (see noise.h).
**
** DESIGN. POV-Ray's lattice noise hashes the integer cell of a point into
** a 4096-entry permutation (shuffled by a fixed LCG with seed 0) and reads
** four coefficients per lattice corner from a 267-entry table of random
** numbers, whose odd slots hold half of each value. The sum of the eight
** trilinear corner terms, smoothed by the cubic s-curve, is the noise;
** generator 2 stretches its observed range [-1.05242, 0.988997] to [0, 1],
** generator 1 adds 0.5 and clamps. Generator 3 is Perlin's gradient noise
** over 2048 random unit gradients drawn by the same LCG from seed 1. All
** tables are rebuilt from those seeds at start-up; only the 267 random
** coefficients are data, listed below as POV-Ray ships them
** (source/backend/texture/texture.cpp, RTable, v3.7.0.10).
*/
#include "config.h"

#include <math.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif

#include "material/noise.h"

/* POV-Ray's integer-lattice offset: cells are counted from -10000 so
** that negative coordinates hash like positive ones. */
#define LATTICE_MIN (-10000)
#define NOISE_EPSILON 1e-10

/* The random coefficients of the lattice noise (see the file comment). */
static const double rtable_values[267] = {
    -1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593,
    0.432334, 0.103685, 0.590539, 0.0286412, 0.46981, -0.84622,
    -0.0734112, -0.304097, -0.40206, -0.210132, -0.919127, 0.652033,
    -0.83151, -0.183948, -0.671107, 0.852476, 0.043595, -0.404532,
    0.75494, -0.335653, 0.618433, 0.605707, 0.708583, -0.477195,
    0.899474, 0.490623, 0.221729, -0.400381, -0.853727, -0.932586,
    0.659113, 0.961303, 0.325948, -0.750851, 0.842466, 0.734401,
    -0.649866, 0.394491, -0.466056, -0.434073, 0.109026, 0.0847028,
    -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408,
    -0.90396, -0.686549, -0.785214, 0.488548, 0.0246433, 0.142473,
    -0.602136, 0.375845, -0.00779736, 0.498955, -0.268147, 0.856382,
    -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896,
    0.672206, -0.233783, 0.94815, 0.895262, 0.343252, -0.173388,
    -0.767971, -0.314748, 0.824308, -0.342092, 0.721431, -0.24004,
    -0.63653, 0.553277, 0.376272, 0.158984, -0.452659, 0.396323,
    -0.420676, -0.454154, 0.122179, 0.295857, 0.0664225, -0.202075,
    -0.724788, 0.453513, 0.224567, -0.908812, 0.176349, -0.320516,
    -0.697139, 0.742702, -0.900786, 0.471489, -0.133532, 0.119127,
    -0.889769, -0.23183, -0.669673, -0.046891, -0.803433, -0.966735,
    0.475578, -0.652644, 0.0112459, -0.730007, 0.128283, 0.145647,
    -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908,
    0.480797, 0.535668, -0.250172, -0.83093, -0.653773, -0.443809,
    0.119982, -0.897642, 0.89453, 0.165789, 0.633875, -0.886839,
    0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659,
    -0.814267, -0.919432, 0.280262, -0.66302, -0.558099, -0.537469,
    -0.598779, 0.929656, -0.170794, -0.537163, 0.312581, 0.959442,
    0.722652, 0.499931, 0.175616, -0.534874, -0.685115, 0.444999,
    0.17171, 0.108202, -0.768704, -0.463828, 0.254231, 0.546014,
    0.869474, 0.875212, -0.944427, 0.130724, -0.110185, 0.312184,
    -0.33138, -0.629206, 0.0606546, 0.722866, -0.0979477, 0.821561,
    0.0931258, -0.972808, 0.0318151, -0.867033, -0.387228, 0.280995,
    -0.218189, -0.539178, -0.427359, -0.602075, 0.311971, 0.277974,
    0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132,
    0.581079, 0.209461, -0.317433, -0.284993, 0.181323, 0.341634,
    0.804959, -0.229572, -0.758907, -0.336721, 0.605463, -0.991272,
    -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569,
    0.62356, -0.573938, 0.278309, -0.971313, 0.839994, -0.830686,
    0.439078, 0.66128, 0.694514, 0.0565042, 0.54342, -0.438804,
    -0.0228428, -0.687068, 0.857267, 0.301991, -0.494255, -0.941039,
    0.775509, 0.410575, -0.362081, -0.671534, -0.348379, 0.932433,
    0.886442, 0.868681, -0.225666, -0.062211, -0.0976425, -0.641444,
    -0.848112, 0.724697, 0.473503, 0.998749, 0.174701, 0.559625,
    -0.029099, -0.337392, -0.958129, -0.659785, 0.236042, -0.246937,
    0.659449, -0.027512, 0.821897, -0.226215, 0.0181735, 0.500481,
    -0.420127, -0.427878, 0.566186,
};

/* POV-Ray lays the coefficients out as rtable[2k] = value k and
** rtable[2k+1] = half of it, and a lattice corner with hash b reads
** mp = &rtable[2b]: the constant and the x, y, z slopes of the x component
** at mp[1], mp[2], mp[4], mp[6], of the y component at mp[9..14] and of the
** z component at mp[17..22]. The same twelve numbers are regrouped here,
** one block per hash value, so that the x and y components of a corner
** sit side by side (one 16-byte load each for a two-lane product) and the
** hot paths skip the index arithmetic. The numbers, and the order of the
** operations on them, are POV-Ray's, so the noise is bit for bit the same. */
struct corner_block {
    _Alignas(16) double xy[4][2]; /* {x, y} components: const, slopes x y z */
    double z[4];                  /* z component: const, slopes x y z */
};
static struct corner_block corner_blocks[256];
/* The byte offset in corner_blocks of the block of hash entry i, whose
** number is hash_table[i] & 0xFF as POV-Ray masks it (an offset, not an
** index: this saves the multiplication by the block size per corner). */
static unsigned short block_of[8192];
static unsigned short hash_table[8192];

#define GRAD_ENTRIES 2048
static int grad_perm[2 * (GRAD_ENTRIES + 1)];
static vec3 grad_vec[2 * (GRAD_ENTRIES + 1)];

#define WAVE_TABLE 256
static vec3 wave_sources[WAVE_TABLE];
static double wave_freqs[WAVE_TABLE];

static pthread_once_t noise_once = PTHREAD_ONCE_INIT;

/* MT19937: POV-Ray's PatternRands table comes from its default stream.
** Built with the noise tables (at mat_ctx_create, before rendering, as
** POV-Ray builds it at start-up) rather than at its first use, which
** would fall inside the render. */
#define MT_N 624
#define RAND_TABLE 32768

static double rand_table[RAND_TABLE];

/* Fills rand_table with the first 32768 outputs of MT19937 seeded with
** 5489 (the standard default), each divided by 2^32 as Boost's
** uniform_real<double>(0, 1) does for a 32-bit engine. */
static void build_rand_table(void)
{
    uint32_t mt[MT_N];
    mt[0] = 5489u;
    for (int i = 1; i < MT_N; i++)
        mt[i] = 1812433253u * (mt[i - 1] ^ (mt[i - 1] >> 30)) + (uint32_t)i;
    int idx = MT_N;
    for (int k = 0; k < RAND_TABLE; k++) {
        if (idx >= MT_N) {
            for (int i = 0; i < MT_N; i++) {
                uint32_t y = (mt[i] & 0x80000000u) |
                             (mt[(i + 1) % MT_N] & 0x7fffffffu);
                mt[i] = mt[(i + 397) % MT_N] ^ (y >> 1) ^
                        ((y & 1u) ? 0x9908b0dfu : 0u);
            }
            idx = 0;
        }
        uint32_t y = mt[idx++];
        y ^= y >> 11;
        y ^= (y << 7) & 0x9d2c5680u;
        y ^= (y << 15) & 0xefc60000u;
        y ^= y >> 18;
        rand_table[k] = (double)y / 4294967296.0;
    }
}


/* POV-Ray's table generator: next = next*1812433253 + 12345 in 32 bits,
** and 15 bits taken from bit 16 up. */
static int lcg15(uint32_t *state)
{
    *state = *state * 1812433253u + 12345u;
    return (int)((*state >> 16) & 0x7FFF);
}

static void build_hash_table(void)
{
    uint32_t st = 0;
    for (int i = 0; i < 4096; i++)
        hash_table[i] = (unsigned short)i;
    for (int i = 4095; i >= 0; i--) {
        int j = lcg15(&st) % 4096;
        unsigned short tmp = hash_table[i];
        hash_table[i] = hash_table[j];
        hash_table[j] = tmp;
    }
    for (int i = 0; i < 4096; i++)
        hash_table[4096 + i] = hash_table[i];
}

static void build_gradients(void)
{
    uint32_t st = 1;
    for (int i = 0; i < GRAD_ENTRIES; i++) {
        double v[3], s;
        do {
            for (int j = 0; j < 3; j++)
                v[j] = (double)((lcg15(&st) % (GRAD_ENTRIES << 1)) -
                                GRAD_ENTRIES) / (double)GRAD_ENTRIES;
            s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        } while (s > 1.0 || s < 1.0e-5);
        s = 1.0 / sqrt(s);
        grad_vec[i] = v3(v[0] * s, v[1] * s, v[2] * s);
    }
    for (int i = 0; i < GRAD_ENTRIES; i++)
        grad_perm[i] = i;
    /* POV-Ray steps by two here; reproduced because it fixes the table. */
    for (int i = GRAD_ENTRIES; i > 0; i -= 2) {
        int k = grad_perm[i];
        int j = lcg15(&st) % GRAD_ENTRIES;
        grad_perm[i] = grad_perm[j];
        grad_perm[j] = k;
    }
    for (int i = 0; i < GRAD_ENTRIES + 2; i++) {
        grad_perm[GRAD_ENTRIES + i] = grad_perm[i];
        grad_vec[GRAD_ENTRIES + i] = grad_vec[i];
    }
}

static inline vec3 dnoise(vec3 p);

static void build_waves(void)
{
    uint32_t st = (uint32_t)-560851967;
    for (int i = 0; i < WAVE_TABLE; i++) {
        wave_sources[i] = v3_norm(dnoise(v3((double)i, 0, 0)));
        wave_freqs[i] = (double)lcg15(&st) * 0.000030518509476 + 0.01;
    }
}

static void build_corner_blocks(void)
{
    double rtable[267 * 2];
    for (int i = 0; i < 267; i++) {
        rtable[2 * i] = rtable_values[i];
        rtable[2 * i + 1] = rtable_values[i] * 0.5;
    }
    static const int slot[4] = {1, 2, 4, 6};
    for (int b = 0; b < 256; b++) {
        const double *mp = &rtable[2 * b];
        for (int k = 0; k < 4; k++) {
            corner_blocks[b].xy[k][0] = mp[slot[k]];
            corner_blocks[b].xy[k][1] = mp[slot[k] + 8];
            corner_blocks[b].z[k] = mp[slot[k] + 16];
        }
    }
    for (int i = 0; i < 8192; i++)
        block_of[i] = (unsigned short)((hash_table[i] & 0xFF) *
                                       sizeof(struct corner_block));
}

static void build_tables(void)
{
    build_hash_table();
    build_corner_blocks(); /* needs the hash table */
    build_gradients();
}

/* Set once the tables are built, so that the hot paths skip
** pthread_once's call after the first time. */
static atomic_bool noise_ready;

static void init_once(void)
{
    build_tables();
    build_waves(); /* needs the tables above */
    build_rand_table();
    atomic_store_explicit(&noise_ready, true, memory_order_release);
}

void noise_init(void)
{
    if (!atomic_load_explicit(&noise_ready, memory_order_acquire))
        pthread_once(&noise_once, init_once);
}

/* Two doubles in the lanes of an SSE2 register where there is one: the
** x and y components of dnoise()'s sum. Each lane does exactly the scalar
** operations in the scalar order (IEEE double in both), so the lanes give
** the scalar bits. */
#ifdef __SSE2__
typedef __m128d pair;
static inline pair pair_zero(void) { return _mm_setzero_pd(); }
static inline pair pair_dup(double a) { return _mm_set1_pd(a); }
static inline pair pair_load(const double *p) { return _mm_load_pd(p); }
static inline pair pair_add(pair a, pair b) { return _mm_add_pd(a, b); }
static inline pair pair_mul(pair a, pair b) { return _mm_mul_pd(a, b); }
static inline double pair_lo(pair a) { return _mm_cvtsd_f64(a); }
static inline double pair_hi(pair a)
{
    return _mm_cvtsd_f64(_mm_unpackhi_pd(a, a));
}
#else
typedef struct { double lo, hi; } pair;
static inline pair pair_zero(void) { return (pair){0, 0}; }
static inline pair pair_dup(double a) { return (pair){a, a}; }
static inline pair pair_load(const double *p) { return (pair){p[0], p[1]}; }
static inline pair pair_add(pair a, pair b)
{
    return (pair){a.lo + b.lo, a.hi + b.hi};
}
static inline pair pair_mul(pair a, pair b)
{
    return (pair){a.lo * b.lo, a.hi * b.hi};
}
static inline double pair_lo(pair a) { return a.lo; }
static inline double pair_hi(pair a) { return a.hi; }
#endif

static double scurve(double a)
{
    return a * a * (3.0 - 2.0 * a);
}

/* The lattice cell of one coordinate: integer part (floored, with POV-Ray's
** epsilon for negatives), its hash index and the fraction. */
static void lattice(double x, unsigned *index, double *frac)
{
    int cell = x >= 0 ? (int)x : (int)(x - (1 - NOISE_EPSILON));
    *index = (unsigned)(cell - LATTICE_MIN) & 0xFFF;
    *frac = x - cell;
}

/* What both lattice noises need of a point: the hash indices of its cell,
** the offsets from the cell's low (f) and high (g) corners, and the
** s-curve weights (s along, t = 1 - s) with the four xy products. */
static unsigned hash2d(unsigned a, unsigned b)
{
    return hash_table[hash_table[a] ^ b];
}

/* (Indices unsigned: no sign extension before each table read.) */
struct cell {
    unsigned ix, iy, iz;
    unsigned h00, h10, h01, h11; /* the hashes of the four (x, y) columns */
    double fx, fy, fz, gx, gy, gz;
    double sz, tz, txty, sxty, txsy, sxsy;
};

static inline void cell_setup(vec3 p, struct cell *c)
{
    lattice(p.x, &c->ix, &c->fx);
    lattice(p.y, &c->iy, &c->fy);
    lattice(p.z, &c->iz, &c->fz);
    c->gx = c->fx - 1;
    c->gy = c->fy - 1;
    c->gz = c->fz - 1;
    double sx = scurve(c->fx), sy = scurve(c->fy);
    c->sz = scurve(c->fz);
    double tx = 1 - sx, ty = 1 - sy;
    c->tz = 1 - c->sz;
    c->txty = tx * ty;
    c->sxty = sx * ty;
    c->txsy = tx * sy;
    c->sxsy = sx * sy;
    c->h00 = hash2d(c->ix, c->iy);
    c->h10 = hash2d(c->ix + 1, c->iy);
    c->h01 = hash2d(c->ix, c->iy + 1);
    c->h11 = hash2d(c->ix + 1, c->iy + 1);
}

/* The coefficients for lattice hash 'h' at z index 'iz'. */
static inline const struct corner_block *coeffs(unsigned h, unsigned iz)
{
    return (const struct corner_block *)((const char *)corner_blocks +
                                         block_of[h ^ iz]);
}

/* One corner's term of the scalar noise (the x component's numbers):
** weight times the linear function of the offsets. */
static inline double corner(const struct corner_block *b, double s, double x,
                            double y, double z)
{
    return s * (b->xy[0][0] + b->xy[1][0] * x + b->xy[2][0] * y +
                b->xy[3][0] * z);
}

/* Clips 'p' coordinates that would overflow the lattice arithmetic. */
static inline vec3 safe_point(vec3 p)
{
    const double lim = 1e9;
    if (!(fabs(p.x) < lim)) p.x = isnan(p.x) ? 0 : copysign(lim, p.x);
    if (!(fabs(p.y) < lim)) p.y = isnan(p.y) ? 0 : copysign(lim, p.y);
    if (!(fabs(p.z) < lim)) p.z = isnan(p.z) ? 0 : copysign(lim, p.z);
    return p;
}

static double gradient_noise(vec3 p);

#ifdef __SSE2__
/* corner() for two corners a (low lane) and b (high lane) that share the
** y and z offsets; w holds their weights, x their x offsets. Each lane
** does corner()'s operations in corner()'s order, so gives its bits. */
static inline __m128d corner_pair(const struct corner_block *a,
                                  const struct corner_block *b, __m128d w,
                                  __m128d x, double y, double z)
{
    __m128d k0 = _mm_loadh_pd(_mm_load_sd(&a->xy[0][0]), &b->xy[0][0]);
    __m128d k1 = _mm_loadh_pd(_mm_load_sd(&a->xy[1][0]), &b->xy[1][0]);
    __m128d k2 = _mm_loadh_pd(_mm_load_sd(&a->xy[2][0]), &b->xy[2][0]);
    __m128d k3 = _mm_loadh_pd(_mm_load_sd(&a->xy[3][0]), &b->xy[3][0]);
    __m128d t = _mm_add_pd(k0, _mm_mul_pd(k1, x));
    t = _mm_add_pd(t, _mm_mul_pd(k2, _mm_set1_pd(y)));
    t = _mm_add_pd(t, _mm_mul_pd(k3, _mm_set1_pd(z)));
    return _mm_mul_pd(w, t);
}
#endif

/* fmin(fmax(v, 0), 1) without the two library calls (GCC cannot inline
** them without -ffinite-math-only). Same result for every v the noise can
** produce: NaN gives 0 like fmax, and -0 cannot occur (x + c == 0 is +0 in
** round-to-nearest), so the sign of a zero never differs. */
static inline double clamp01(double v)
{
    return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

double noise_value(vec3 p, int generator)
{
    noise_init();
    p = safe_point(p);
    if (generator == 3) {
        /* POV-Ray's bias correction for the gradient noise. */
        double v = 0.5 * (1.59 * gradient_noise(p) + 0.985);
        return clamp01(v);
    }
    struct cell c;
    cell_setup(p, &c);
    const unsigned iz = c.iz;
    const double fx = c.fx, fy = c.fy, fz = c.fz, gx = c.gx, gy = c.gy,
                 gz = c.gz;
    const double sz = c.sz, tz = c.tz, txty = c.txty, sxty = c.sxty,
                 txsy = c.txsy, sxsy = c.sxsy;
    const unsigned h00 = c.h00, h10 = c.h10, h01 = c.h01, h11 = c.h11;
    double sum;
#ifdef __SSE2__
    /* Corners two at a time (each pair differs only in x), the terms
    ** then summed one by one in POV-Ray's order. */
    __m128d px = _mm_set_pd(gx, fx);
    __m128d wy0 = _mm_set_pd(sxty, txty), wy1 = _mm_set_pd(sxsy, txsy);
    __m128d wtz = _mm_set1_pd(tz), wsz = _mm_set1_pd(sz);
    __m128d t0 = corner_pair(coeffs(h00, iz), coeffs(h10, iz),
                             _mm_mul_pd(wy0, wtz), px, fy, fz);
    __m128d t1 = corner_pair(coeffs(h01, iz), coeffs(h11, iz),
                             _mm_mul_pd(wy1, wtz), px, gy, fz);
    __m128d t2 = corner_pair(coeffs(h00, iz + 1), coeffs(h10, iz + 1),
                             _mm_mul_pd(wy0, wsz), px, fy, gz);
    __m128d t3 = corner_pair(coeffs(h01, iz + 1), coeffs(h11, iz + 1),
                             _mm_mul_pd(wy1, wsz), px, gy, gz);
    sum = pair_lo(t0);
    sum += pair_hi(t0);
    sum += pair_lo(t1);
    sum += pair_hi(t1);
    sum += pair_lo(t2);
    sum += pair_hi(t2);
    sum += pair_lo(t3);
    sum += pair_hi(t3);
#else
    sum = corner(coeffs(h00, iz), txty * tz, fx, fy, fz);
    sum += corner(coeffs(h10, iz), sxty * tz, gx, fy, fz);
    sum += corner(coeffs(h01, iz), txsy * tz, fx, gy, fz);
    sum += corner(coeffs(h11, iz), sxsy * tz, gx, gy, fz);
    sum += corner(coeffs(h00, iz + 1), txty * sz, fx, fy, gz);
    sum += corner(coeffs(h10, iz + 1), sxty * sz, gx, fy, gz);
    sum += corner(coeffs(h01, iz + 1), txsy * sz, fx, gy, gz);
    sum += corner(coeffs(h11, iz + 1), sxsy * sz, gx, gy, gz);
#endif
    if (generator == 2) {
        /* Stretch the measured range [-1.05242, 0.988997] to [0, 1]. */
        sum = (sum + 1.05242) * 0.48985582;
    } else {
        sum += 0.5;
    }
    return clamp01(sum);
}


/* Adds the three components of one corner. The offsets come duplicated
** (px, py, pz) and as scalars for the z component. */
/* inline: eight calls per dnoise(), the inner loop of turbulence */
static inline void dcorner(pair *rxy, double *rz, const struct corner_block *b,
                           double s, pair px, pair py, pair pz, double x,
                           double y, double z)
{
    pair t = pair_add(pair_load(b->xy[0]), pair_mul(pair_load(b->xy[1]), px));
    t = pair_add(t, pair_mul(pair_load(b->xy[2]), py));
    t = pair_add(t, pair_mul(pair_load(b->xy[3]), pz));
    *rxy = pair_add(*rxy, pair_mul(pair_dup(s), t));
    *rz += s * (b->z[0] + b->z[1] * x + b->z[2] * y + b->z[3] * z);
}


/* The vector noise proper; the tables must be built. Inline for the
** octave loop of noise_dturbulence(). */
static inline vec3 dnoise(vec3 p)
{
    p = safe_point(p);
    struct cell c;
    cell_setup(p, &c);
    const unsigned iz = c.iz;
    const double fx = c.fx, fy = c.fy, fz = c.fz, gx = c.gx, gy = c.gy,
                 gz = c.gz;
    const double sz = c.sz, tz = c.tz, txty = c.txty, sxty = c.sxty,
                 txsy = c.txsy, sxsy = c.sxsy;
    const unsigned h00 = c.h00, h10 = c.h10, h01 = c.h01, h11 = c.h11;
    pair pfx = pair_dup(fx), pgx = pair_dup(gx), pfy = pair_dup(fy);
    pair pgy = pair_dup(gy), pfz = pair_dup(fz), pgz = pair_dup(gz);
    /* Sums start from zero as POV-Ray's do (0 + -0 is +0). */
    pair rxy = pair_zero();
    double rz = 0;
    dcorner(&rxy, &rz, coeffs(h00, iz), txty * tz, pfx, pfy, pfz, fx, fy, fz);
    dcorner(&rxy, &rz, coeffs(h10, iz), sxty * tz, pgx, pfy, pfz, gx, fy, fz);
    dcorner(&rxy, &rz, coeffs(h11, iz), sxsy * tz, pgx, pgy, pfz, gx, gy, fz);
    dcorner(&rxy, &rz, coeffs(h01, iz), txsy * tz, pfx, pgy, pfz, fx, gy, fz);
    dcorner(&rxy, &rz, coeffs(h01, iz + 1), txsy * sz, pfx, pgy, pgz, fx, gy,
            gz);
    dcorner(&rxy, &rz, coeffs(h11, iz + 1), sxsy * sz, pgx, pgy, pgz, gx, gy,
            gz);
    dcorner(&rxy, &rz, coeffs(h10, iz + 1), sxty * sz, pgx, pfy, pgz, gx, fy,
            gz);
    dcorner(&rxy, &rz, coeffs(h00, iz + 1), txty * sz, pfx, pfy, pgz, fx, fy,
            gz);
    return v3(pair_lo(rxy), pair_hi(rxy), rz);
}

/* Splits one coordinate for the gradient noise. */
static void grad_setup(double x, int *b0, int *b1, double *r0, double *r1)
{
    const double rollover = 10000000.023157213;
    double t = x + rollover;
    int it = (int)floor(t);
    *b0 = it & (GRAD_ENTRIES - 1);
    *b1 = (*b0 + 1) & (GRAD_ENTRIES - 1);
    *r0 = t - it;
    *r1 = *r0 - 1.0;
}

static double lerp(double t, double a, double b)
{
    return a + t * (b - a);
}

static double gdot(int i, double x, double y, double z)
{
    return grad_vec[i].x * x + grad_vec[i].y * y + grad_vec[i].z * z;
}

static double gradient_noise(vec3 p)
{
    int bx0, bx1, by0, by1, bz0, bz1;
    double rx0, rx1, ry0, ry1, rz0, rz1;
    grad_setup(p.x, &bx0, &bx1, &rx0, &rx1);
    grad_setup(p.y, &by0, &by1, &ry0, &ry1);
    grad_setup(p.z, &bz0, &bz1, &rz0, &rz1);
    int i = grad_perm[bx0], j = grad_perm[bx1];
    int b00 = grad_perm[i + by0], b10 = grad_perm[j + by0];
    int b01 = grad_perm[i + by1], b11 = grad_perm[j + by1];
    double sx = scurve(rx0), sy = scurve(ry0), sz = scurve(rz0);
    double a = lerp(sx, gdot(b00 + bz0, rx0, ry0, rz0),
                    gdot(b10 + bz0, rx1, ry0, rz0));
    double b = lerp(sx, gdot(b01 + bz0, rx0, ry1, rz0),
                    gdot(b11 + bz0, rx1, ry1, rz0));
    double c = lerp(sy, a, b);
    a = lerp(sx, gdot(b00 + bz1, rx0, ry0, rz1),
             gdot(b10 + bz1, rx1, ry0, rz1));
    b = lerp(sx, gdot(b01 + bz1, rx0, ry1, rz1),
             gdot(b11 + bz1, rx1, ry1, rz1));
    double d = lerp(sy, a, b);
    return lerp(sz, c, d);
}

vec3 noise_vector(vec3 p)
{
    noise_init();
    return dnoise(p);
}

double noise_turbulence(vec3 p, const struct noise_turb *t, int generator)
{
    /* Generators 2 and 3 are re-centred octave by octave, as POV-Ray does. */
    double value = generator > 1
        ? clamp01(2.0 * noise_value(p, generator) - 0.5)
        : noise_value(p, generator);
    double l = t->lambda, o = t->omega;
    for (int i = 2; i <= t->octaves; i++) {
        double n = noise_value(v3_scale(p, l), generator);
        value += o * (generator > 1 ? 2.0 * n - 0.5 : n);
        if (i < t->octaves) {
            l *= t->lambda;
            o *= t->omega;
        }
    }
    return value;
}

vec3 noise_dturbulence(vec3 p, const struct noise_turb *t)
{
    noise_init();
    vec3 r = dnoise(p);
    double l = t->lambda, o = t->omega;
    for (int i = 2; i <= t->octaves; i++) {
        r = v3_madd(r, dnoise(v3_scale(p, l)), o);
        if (i < t->octaves) {
            l *= t->lambda;
            o *= t->omega;
        }
    }
    return r;
}

double noise_pattern_rand(unsigned long i)
{
    noise_init();
    return rand_table[i % RAND_TABLE];
}

vec3 noise_pattern_rand3(unsigned long i)
{
    noise_init();
    return v3(rand_table[i % RAND_TABLE], rand_table[(i + 1) % RAND_TABLE],
              rand_table[(i + 2) % RAND_TABLE]);
}

int noise_hash_entry(int i)
{
    noise_init();
    return hash_table[i & 0x1fff];
}

double noise_coefficient(int i)
{
    return i >= 0 && i < 267 ? rtable_values[i] : 0.0;
}

int noise_hash3d(int a, int b, int c)
{
    noise_init();
    return hash_table[hash_table[hash_table[a & 0xFFF] ^ (b & 0xFFF)] ^
                      (c & 0xFFF)];
}

void noise_wave_source(int i, vec3 *source, double *frequency)
{
    noise_init();
    if (i >= 0 && i < WAVE_TABLE) {
        *source = wave_sources[i];
        *frequency = wave_freqs[i];
        return;
    }
    /* Past the table: replay the generator (rare: number_of_waves > 256). */
    uint32_t st = (uint32_t)-560851967;
    int r = 0;
    for (int k = 0; k <= i; k++)
        r = lcg15(&st);
    *source = v3_norm(noise_vector(v3((double)i, 0, 0)));
    *frequency = (double)r * 0.000030518509476 + 0.01;
}

double noise_cycloidal(double v)
{
    /* sin(2 pi v), written as POV-Ray writes it so that rounding agrees. */
    const double two_pi = 6.283185307179586;
    if (v >= 0.0)
        return sin((double)((v - floor(v)) * 50000.0) / 50000.0 * two_pi);
    return -sin((double)((-(v + floor(-v))) * 50000.0) / 50000.0 * two_pi);
}

double noise_triangle_wave(double v)
{
    double off = v >= 0.0 ? v - floor(v) : v + 1.0 + floor(fabs(v));
    return off >= 0.5 ? 2.0 * (1.0 - off) : 2.0 * off;
}
