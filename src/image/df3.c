/* SPDX-License-Identifier: MIT */
/*
** df3.c: .df3 density files and the density_file pattern (df3.h).
*/
#include "config.h"

#include "image/df3.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "util/mem.h"

/* The header's sizes and the byte count after it; -1 on a read error. */
static int header(FILE *f, int *nx, int *ny, int *nz, long *len)
{
    unsigned char h[6];
    if (fread(h, 1, 6, f) != 6)
        return -1;
    *nx = h[0] << 8 | h[1];
    *ny = h[2] << 8 | h[3];
    *nz = h[4] << 8 | h[5];
    if (fseek(f, 0, SEEK_END) != 0)
        return -1;
    long end = ftell(f);
    if (end < 6)
        return -1;
    *len = end - 6;
    return 0;
}

static enum iris_status check_open(FILE *f, const char *path, int *nx,
                                   int *ny, int *nz, int *bytes, char *err,
                                   size_t errlen)
{
    long len;
    if (header(f, nx, ny, nz, &len) != 0) {
        snprintf(err, errlen, "%s: truncated density file (no 6-byte "
                 "header)", path);
        return IRIS_EINVAL;
    }
    long long n = (long long)*nx * *ny * *nz;
    *bytes = n > 0 && len == 4 * n ? 4 : n > 0 && len == 2 * n ? 2
           : n > 0 && len == n ? 1 : 0;
    if (*bytes == 0) {
        snprintf(err, errlen, "%s: invalid density file size: %ld bytes "
                 "of voxels for %d x %d x %d (want 1, 2 or 4 bytes each)",
                 path, len, *nx, *ny, *nz);
        return IRIS_EINVAL;
    }
    return IRIS_OK;
}

enum iris_status iris_df3_check(const char *path, int *nx, int *ny, int *nz,
                                int *bytes, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return IRIS_EIO;
    }
    enum iris_status st = check_open(f, path, nx, ny, nz, bytes, err, errlen);
    fclose(f);
    return st;
}

enum iris_status iris_df3_read(const char *path, iris_df3 *out, char *err,
                               size_t errlen)
{
    memset(out, 0, sizeof *out);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return IRIS_EIO;
    }
    int nx, ny, nz, bytes;
    enum iris_status st = check_open(f, path, &nx, &ny, &nz, &bytes, err,
                                     errlen);
    if (st != IRIS_OK) {
        fclose(f);
        return st;
    }
    size_t n = (size_t)nx * ny * nz;
    unsigned char *raw = iris_malloc(n * bytes);
    float *v = iris_malloc(n * sizeof *v);
    if (!raw || !v) {
        iris_free(raw);
        iris_free(v);
        fclose(f);
        snprintf(err, errlen, "%s: out of memory", path);
        return IRIS_ENOMEM;
    }
    if (fseek(f, 6, SEEK_SET) != 0 || fread(raw, bytes, n, f) != n) {
        iris_free(raw);
        iris_free(v);
        fclose(f);
        snprintf(err, errlen, "%s: error reading the density file", path);
        return IRIS_EIO;
    }
    fclose(f);
    for (size_t i = 0; i < n; i++) {
        const unsigned char *b = raw + i * bytes;
        if (bytes == 1)
            v[i] = (float)(b[0] / 255.0);
        else if (bytes == 2)
            v[i] = (float)((b[0] << 8 | b[1]) / 65535.0);
        else
            v[i] = (float)(((uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 |
                            (uint32_t)b[2] << 8 | b[3]) / 4294967295.0);
    }
    iris_free(raw);
    out->nx = nx;
    out->ny = ny;
    out->nz = nz;
    out->v = v;
    return IRIS_OK;
}

void iris_df3_fini(iris_df3 *d)
{
    if (d) {
        iris_free(d->v);
        memset(d, 0, sizeof *d);
    }
}

static double at(const iris_df3 *d, size_t x, size_t y, size_t z)
{
    return d->v[(z * d->ny + y) * d->nx + x];
}

/* POV-Ray's intp3: the cubic through fb at t=0 and fc at t=1 with
** central-difference slopes, in float as POV-Ray computes it. */
static float intp3(float t, float fa, float fb, float fc, float fd)
{
    float b = (fc - fa) * 0.5f, d = (fd - fb) * 0.5f;
    float e = 2.0f * (fb - fc) + b + d;
    float f = -3.0f * (fb - fc) - 2.0f * b - d;
    return ((e * t + f) * t + b) * t + fb;
}

/* POV-Ray's zmax(i, n) on size_t: i % n, where i = 0 - 1 wraps to
** SIZE_MAX first (SIZE_MAX % n is n - 1 only for powers of two). */
static size_t zwrap(size_t i, size_t n)
{
    return i % n;
}

double iris_df3_density(const iris_df3 *d, int interpolate, double x,
                        double y, double z)
{
    if (!d || !d->v || d->nx <= 0 || d->ny <= 0 || d->nz <= 0)
        return 0.0;
    if (!(x >= 0.0 && x < 1.0 && y >= 0.0 && y < 1.0 && z >= 0.0 &&
          z < 1.0))
        return 0.0;
    size_t sx = (size_t)d->nx, sy = (size_t)d->ny, sz = (size_t)d->nz;
    double density;
    switch (interpolate % 10) {
    case 0: {
        size_t ix = (size_t)(x * sx), iy = (size_t)(y * sy),
               iz = (size_t)(z * sz);
        density = ix < sx && iy < sy && iz < sz ? at(d, ix, iy, iz) : 0.0;
        break;
    }
    case 1: {
        double xx = x * sx, yy = y * sy, zz = z * sz;
        size_t x1 = (size_t)xx, y1 = (size_t)yy, z1 = (size_t)zz;
        size_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
        xx -= floor(xx);
        yy -= floor(yy);
        zz -= floor(zz);
        double xi = 1.0 - xx, yi = 1.0 - yy;
        density = ((at(d, x1, y1, z1) * xi + at(d, x2, y1, z1) * xx) * yi +
                   (at(d, x1, y2, z1) * xi + at(d, x2, y2, z1) * xx) * yy) *
                      (1.0 - zz) +
                  ((at(d, x1, y1, z2) * xi + at(d, x2, y1, z2) * xx) * yi +
                   (at(d, x1, y2, z2) * xi + at(d, x2, y2, z2) * xx) * yy) *
                      zz;
        break;
    }
    default: {
        double xx = x * sx, yy = y * sy, zz = z * sz;
        size_t x1 = (size_t)xx, y1 = (size_t)yy, z1 = (size_t)zz;
        xx -= floor(xx);
        yy -= floor(yy);
        zz -= floor(zz);
        size_t k[4];
        for (int i = 0; i < 4; i++)
            k[i] = zwrap(z1 + (size_t)i - 1, sz);
        float p[4][4];
        for (size_t i = 0; i < 4; i++) {
            size_t ii = zwrap(i + x1 - 1, sx);
            for (size_t j = 0; j < 4; j++) {
                size_t jj = zwrap(j + y1 - 1, sy);
                p[i][j] = intp3((float)zz, (float)at(d, ii, jj, k[0]),
                                (float)at(d, ii, jj, k[1]),
                                (float)at(d, ii, jj, k[2]),
                                (float)at(d, ii, jj, k[3]));
            }
        }
        /* POV-Ray writes each row's result into p[0][i], so later rows
        ** read a p[0][*] already overwritten: kept, as it computes it */
        for (int i = 0; i < 4; i++)
            p[0][i] = intp3((float)yy, p[i][0], p[i][1], p[i][2], p[i][3]);
        density = intp3((float)xx, p[0][0], p[0][1], p[0][2], p[0][3]);
        break;
    }
    }
    return density < 0.0 ? 0.0 : density;
}
