/* SPDX-License-Identifier: MIT */
/*
** gif_indices.c: the palette indices of a GIF file's first image
** (gif_indices.h), decoded from the GIF 89a format: header, logical
** screen, optional colour tables, extension blocks skipped, then one image
** descriptor and its LZW data in sub-blocks of at most 255 bytes.
*/
#include "config.h"

#include "image/gif_indices.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "util/mem.h"

/* GIF files are small; a limit keeps a corrupt size from allocating much. */
#define GIF_MAX_BYTES (256L << 20)
#define GIF_MAX_PIXELS (64L << 20)

struct gif_in {
    const uint8_t *b;
    size_t n, pos;
};

static int byte_at(struct gif_in *in)
{
    return in->pos < in->n ? in->b[in->pos++] : -1;
}

static int u16_at(struct gif_in *in)
{
    int lo = byte_at(in), hi = byte_at(in);
    return lo < 0 || hi < 0 ? -1 : lo | hi << 8;
}

/* Skips a chain of sub-blocks (size byte, data, ..., size 0). */
static int skip_sub_blocks(struct gif_in *in)
{
    for (;;) {
        int k = byte_at(in);
        if (k < 0)
            return -1;
        if (k == 0)
            return 0;
        in->pos += (size_t)k;
    }
}

/* The LZW data's sub-blocks joined into one buffer (malloc'ed). */
static uint8_t *join_sub_blocks(struct gif_in *in, size_t *len)
{
    size_t cap = 4096, n = 0;
    uint8_t *out = malloc(cap);
    if (!out)
        return NULL;
    for (;;) {
        int k = byte_at(in);
        if (k <= 0)
            break; /* the terminator, or a truncated file: decode what is there */
        if (in->pos + (size_t)k > in->n)
            k = (int)(in->n - in->pos);
        if (n + (size_t)k > cap) {
            cap = 2 * (n + (size_t)k);
            uint8_t *t = realloc(out, cap);
            if (!t) {
                free(out);
                return NULL;
            }
            out = t;
        }
        memcpy(out + n, in->b + in->pos, (size_t)k);
        n += (size_t)k;
        in->pos += (size_t)k;
    }
    *len = n;
    return out;
}

/* The LZW decoder: codes are read LSB first, 'min_size'+1 bits growing to
** 12; a clear code resets the table, the end code stops. Decoded indices
** go into 'pix' in stream order, at most 'npix' of them. */
static void lzw_decode(const uint8_t *d, size_t len, int min_size,
                       uint8_t *pix, size_t npix)
{
    static const int MAXC = 4096;
    uint16_t prefix[4096];
    uint8_t suffix[4096], stack[4097];
    int clear = 1 << min_size, end = clear + 1;
    int size = min_size + 1, next = clear + 2, prev = -1;
    uint8_t first = 0;
    uint32_t acc = 0;
    int nbits = 0;
    size_t at = 0, out = 0;
    for (int i = 0; i < clear; i++) {
        prefix[i] = 0;
        suffix[i] = (uint8_t)i;
    }
    while (out < npix) {
        while (nbits < size && at < len) {
            acc |= (uint32_t)d[at++] << nbits;
            nbits += 8;
        }
        if (nbits < size)
            return;
        int code = (int)(acc & ((1u << size) - 1));
        acc >>= size;
        nbits -= size;
        if (code == clear) {
            size = min_size + 1;
            next = clear + 2;
            prev = -1;
            continue;
        }
        if (code == end)
            return;
        if (prev < 0) {
            if (code >= clear)
                return; /* corrupt: the first code must be a literal */
            pix[out++] = (uint8_t)code;
            first = (uint8_t)code;
            prev = code;
            continue;
        }
        int sp = 0, c = code;
        if (code >= next) {
            if (code > next)
                return; /* corrupt */
            stack[sp++] = first;
            c = prev;
        }
        while (c >= clear && sp < MAXC) {
            stack[sp++] = suffix[c];
            c = prefix[c];
        }
        stack[sp++] = (uint8_t)c;
        first = (uint8_t)c;
        while (sp > 0 && out < npix)
            pix[out++] = stack[--sp];
        if (next < MAXC) {
            prefix[next] = (uint16_t)prev;
            suffix[next] = first;
            next++;
            if (next == 1 << size && size < 12)
                size++;
        }
        prev = code;
    }
}

static uint8_t *slurp(const char *path, size_t *len, char *err, size_t errlen)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: cannot open", path);
        return NULL;
    }
    uint8_t *b = NULL;
    long n = -1;
    if (fseek(f, 0, SEEK_END) == 0)
        n = ftell(f);
    if (n < 0 || n > GIF_MAX_BYTES || fseek(f, 0, SEEK_SET) != 0 ||
        !(b = malloc(n ? (size_t)n : 1)) || fread(b, 1, (size_t)n, f) != (size_t)n) {
        snprintf(err, errlen, "%s: cannot read the GIF file", path);
        free(b);
        fclose(f);
        return NULL;
    }
    fclose(f);
    *len = (size_t)n;
    return b;
}

int gif_is_gif(const char *path)
{
    char sig[6];
    FILE *f = fopen(path, "rb");
    if (!f)
        return 0;
    size_t n = fread(sig, 1, sizeof sig, f);
    fclose(f);
    return n == 6 && (memcmp(sig, "GIF87a", 6) == 0 ||
                      memcmp(sig, "GIF89a", 6) == 0);
}

int gif_read_indices(const char *path, uint8_t **idx, int *width,
                     int *height, char *err, size_t errlen)
{
    *idx = NULL;
    *width = *height = 0;
    size_t len;
    uint8_t *b = slurp(path, &len, err, errlen);
    if (!b)
        return -1;
    struct gif_in in = { b, len, 6 };
    if (len < 13) {
        snprintf(err, errlen, "%s: truncated GIF file", path);
        free(b);
        return -1;
    }
    in.pos = 10;
    int packed = byte_at(&in);
    in.pos = 13;
    if (packed & 0x80)
        in.pos += 3u * (2u << (packed & 7));
    for (;;) {
        int tag = byte_at(&in);
        if (tag == 0x21) { /* extension: label, sub-blocks */
            if (byte_at(&in) < 0 || skip_sub_blocks(&in) < 0)
                break;
            continue;
        }
        if (tag != 0x2C)
            break; /* the trailer, or garbage before any image */
        in.pos += 4; /* left, top */
        int w = u16_at(&in), h = u16_at(&in), ipacked = byte_at(&in);
        if (w <= 0 || h <= 0 || ipacked < 0 || (long)w * h > GIF_MAX_PIXELS)
            break;
        if (ipacked & 0x80)
            in.pos += 3u * (2u << (ipacked & 7));
        int min_size = byte_at(&in);
        if (min_size < 2 || min_size > 11)
            break;
        size_t dlen = 0;
        uint8_t *data = join_sub_blocks(&in, &dlen);
        uint8_t *pix = calloc((size_t)w * h, 1);
        if (!data || !pix) {
            free(data);
            free(pix);
            snprintf(err, errlen, "%s: out of memory", path);
            free(b);
            return -1;
        }
        /* Rows in the order they are stored, also in an interlaced file:
        ** POV-Ray 3.7's reader (gif.cpp) tests the interlace bit of a
        ** stale byte, so it never reorders the rows (3.8 refuses such
        ** files); iris draws what 3.7 draws. */
        lzw_decode(data, dlen, min_size, pix, (size_t)w * h);
        free(data);
        free(b);
        *idx = pix;
        *width = w;
        *height = h;
        return 0;
    }
    snprintf(err, errlen, "%s: no image in the GIF file", path);
    free(b);
    return -1;
}

int gif_read_heights(const char *path, double **heights, int *width,
                     int *height, char *err, size_t errlen)
{
    uint8_t *idx;
    int w, h;
    *heights = NULL;
    if (gif_read_indices(path, &idx, &w, &h, err, errlen) != 0)
        return -1;
    size_t plen = strlen(path);
    int pot = plen >= 4 && strcasecmp(path + plen - 4, ".pot") == 0;
    if (pot && w % 2 != 0) {
        /* POV-Ray refuses it too ("Invalid width for POT file") */
        snprintf(err, errlen, "%s: a POT file needs an even width", path);
        free(idx);
        return -1;
    }
    int fw = pot ? w / 2 : w;
    double *out = iris_malloc(sizeof *out * (size_t)fw * h);
    if (!out) {
        snprintf(err, errlen, "%s: out of memory", path);
        free(idx);
        return -1;
    }
    for (int y = 0; y < h; y++)
        for (int x = 0; x < fw; x++) {
            const uint8_t *row = idx + (size_t)y * w;
            unsigned v = pot ? (unsigned)row[x] << 8 | row[x + fw]
                             : (unsigned)row[x] * 256u;
            out[(size_t)y * fw + x] = v / 65536.0;
        }
    free(idx);
    *heights = out;
    *width = fw;
    *height = h;
    return 0;
}
