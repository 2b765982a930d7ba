/* SPDX-License-Identifier: MIT */
/*
** srgb8.c: recognising texel values decoded from 8-bit sRGB data (see
** srgb8.h), by the bits of the float.
**
** A value's exponent and the top 8 bits of its mantissa pick a bucket of
** relative width 2^-8 (0.39 %). Consecutive decoded values are at least
** 0.89 % apart (2.4 / (255 x + 14) relative, x the encoded value, in the
** power part of the curve; 10 % and more in the linear part below sample
** 11), so a bucket holds the values of at most one sample b, in both of
** its scalings: the bucket gives b, and one comparison per scaling
** decides. Buckets cover exponents from that of sample 1 (3.0e-4, 2^-12)
** to 1.0; 0 is sample 0.
*/
#include "config.h"

#include "image/srgb8.h"

#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <string.h>

#include "iris/image.h"

#define E0 115                       /* the biased exponent of 2^-12 */
#define N_BUCKETS ((127 - E0 + 1) * 256)

static float values[SRGB8_N];
static double encoded[SRGB8_N];
static short bucket_b[N_BUCKETS];    /* the sample of a bucket, or -1 */

static pthread_once_t tables_once = PTHREAD_ONCE_INIT;
/* Set after the tables are built: a plain load instead of pthread_once
** on every texel. */
static atomic_bool tables_ready;

static uint32_t float_bits(float v)
{
    uint32_t u;
    memcpy(&u, &v, sizeof u);
    return u;
}

/* The bucket of v > 0, or -1 outside the buckets' range. */
static int bucket_of(float v)
{
    uint32_t u = float_bits(v);
    int e = (int)(u >> 23);          /* v > 0: no sign bit */
    if (e < E0 || e > 127)
        return -1;
    return ((e - E0) << 8) | (int)((u >> 15) & 0xff);
}

static void build(void)
{
    for (int i = 0; i < N_BUCKETS; i++)
        bucket_b[i] = -1;
    for (int b = 0; b < 256; b++) {
        /* exactly as png.c scales and image_io.c decodes a sample */
        float mul = (float)b * (1.0f / 255.0f);
        float div = (float)b / 255.0f;
        values[b] = (float)iris_srgb_decode(mul);
        values[256 + b] = (float)iris_srgb_decode(div);
        for (int f = 0; f < 2; f++) {
            float v = values[f * 256 + b];
            encoded[f * 256 + b] = iris_srgb_encode(v);
            int k = v > 0 ? bucket_of(v) : -1;
            if (k >= 0)
                bucket_b[k] = (short)b;
        }
    }
    atomic_store_explicit(&tables_ready, true, memory_order_release);
}

static void ensure_tables(void)
{
    if (!atomic_load_explicit(&tables_ready, memory_order_acquire))
        pthread_once(&tables_once, build);
}

int srgb8_index(float v)
{
    ensure_tables();
    if (v == 0)
        return 0;
    if (!(v > 0))
        return -1;
    int k = bucket_of(v);
    int b = k >= 0 ? bucket_b[k] : -1;
    if (b < 0)
        return -1;
    if (v == values[b])
        return b;
    if (v == values[256 + b])
        return 256 + b;
    return -1;
}

float srgb8_value(int k)
{
    ensure_tables();
    return k >= 0 && k < SRGB8_N ? values[k] : 0.0f;
}

double srgb8_encode(float v)
{
    int k = srgb8_index(v);
    /* index 0 is v == 0, whose encoding is 0 as iris_srgb_encode's */
    return k >= 0 ? encoded[k] : iris_srgb_encode(v);
}
