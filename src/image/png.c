/* SPDX-License-Identifier: MIT */
/*
** png.c: PNG files through libpng (see png.h for why not the module).
*/
#include "config.h"

#include "image/png.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The temporary name: same directory, dot-prefixed, process-unique. */
static void temp_name(char *out, size_t len, const char *path)
{
    const char *slash = strrchr(path, '/');
    int dirlen = slash ? (int)(slash - path + 1) : 0;
    snprintf(out, len, "%.*s.%s.tmp%ld", dirlen, path, slash ? slash + 1 : path,
             (long)getpid());
}

int png_write_rgb(const char *path, int width, int height, int bits, int nch,
                  const void *pixels, int srgb, char *err, size_t errlen)
{
    char tmp[4096];
    temp_name(tmp, sizeof tmp, path);
    FILE *f = fopen(tmp, "wb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytep *rows = calloc((size_t)height, sizeof *rows);
    /* libpng reports errors by longjmp; everything below is released on
    ** both paths. */
    if (!png || !info || !rows || setjmp(png_jmpbuf(png))) {
        snprintf(err, errlen, "%s: cannot write the PNG file", path);
        png_destroy_write_struct(&png, &info);
        free(rows);
        fclose(f);
        remove(tmp);
        return -1;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, bits,
                 nch == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (srgb)
        png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    else
        png_set_gAMA(png, info, 1.0);
    png_write_info(png, info);
    if (bits == 16)
        png_set_swap(png); /* native uint16 to PNG's big-endian */
    size_t stride = (size_t)width * (nch == 4 ? 4 : 3) * (bits == 16 ? 2 : 1);
    for (int y = 0; y < height; y++)
        rows[y] = (png_bytep)pixels + (size_t)y * stride;
    png_write_image(png, rows);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    free(rows);
    if (fclose(f) != 0) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        remove(tmp);
        return -1;
    }
    if (rename(tmp, path) != 0) {
        snprintf(err, errlen, "%s: cannot rename the finished image into place: %s",
                 path, strerror(errno));
        remove(tmp);
        return -1;
    }
    return 0;
}

int png_read_samples(const char *path, bool keep_indices,
                     struct png_samples *out_s, char *err, size_t errlen)
{
    memset(out_s, 0, sizeof *out_s);
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s: %s", path, strerror(errno));
        return -1;
    }
    unsigned char sig[8];
    if (fread(sig, 1, 8, f) != 8 || png_sig_cmp(sig, 0, 8) != 0) {
        fclose(f);
        return 1;
    }
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png ? png_create_info_struct(png) : NULL;
    png_bytep *volatile rows = NULL;
    unsigned char *volatile data = NULL;
    unsigned short *volatile out = NULL;
    if (!png || !info || setjmp(png_jmpbuf(png))) {
        snprintf(err, errlen, "%s: not a readable PNG file", path);
        png_destroy_read_struct(&png, &info, NULL);
        free(rows);
        free(data);
        free(out);
        fclose(f);
        return -1;
    }
    png_init_io(png, f);
    png_set_sig_bytes(png, 8);
    png_set_user_limits(png, 1 << 16, 1 << 16);
    png_read_info(png, info);
    int type = png_get_color_type(png, info);
    bool indexed = keep_indices && type == PNG_COLOR_TYPE_PALETTE;
    if (indexed)
        png_set_packing(png);     /* 1, 2, 4-bit indices to bytes */
    else if (keep_indices && !(type & PNG_COLOR_MASK_COLOR))
        png_set_expand_gray_1_2_4_to_8(png);
    else if (!keep_indices)
        png_set_expand(png);      /* palette, low bit depths, tRNS */
    png_set_swap(png);            /* 16-bit samples in native order */
    png_read_update_info(png, info);
    png_uint_32 w = png_get_image_width(png, info);
    png_uint_32 h = png_get_image_height(png, info);
    int nch = png_get_channels(png, info);
    int depth = png_get_bit_depth(png, info);
    size_t rowbytes = png_get_rowbytes(png, info);
    if ((size_t)w * h * (size_t)nch > (1u << 30))
        png_error(png, "too large");
    data = malloc(rowbytes * h);
    rows = malloc(sizeof *rows * h);
    out = malloc(sizeof *out * (size_t)w * h * (size_t)nch);
    if (!data || !rows || !out)
        png_error(png, "out of memory");
    for (png_uint_32 y = 0; y < h; y++)
        rows[y] = data + y * rowbytes;
    png_read_image(png, rows);
    png_read_end(png, NULL);
    size_t n = (size_t)w * h * (size_t)nch;
    for (size_t i = 0; i < n; i++)
        out[i] = depth == 16 ? ((const unsigned short *)data)[i] : data[i];
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    free(data);
    fclose(f);
    out_s->width = (int)w;
    out_s->height = (int)h;
    out_s->channels = nch;
    out_s->depth = depth;
    out_s->indexed = indexed;
    out_s->grey = !(type & PNG_COLOR_MASK_COLOR);
    out_s->v = out;
    return 0;
}

int png_read_float(const char *path, int *width, int *height, int *channels,
                   float **pixels, char *err, size_t errlen)
{
    *pixels = NULL;
    struct png_samples s;
    int rc = png_read_samples(path, false, &s, err, errlen);
    if (rc != 0)
        return rc;
    size_t n = (size_t)s.width * s.height * (size_t)s.channels;
    float *out = malloc(sizeof *out * (n ? n : 1));
    if (!out) {
        snprintf(err, errlen, "%s: out of memory", path);
        free(s.v);
        return -1;
    }
    float scale = s.depth == 16 ? 1.0f / 65535.0f : 1.0f / 255.0f;
    for (size_t i = 0; i < n; i++)
        out[i] = s.v[i] * scale;
    free(s.v);
    *width = s.width;
    *height = s.height;
    *channels = s.channels;
    *pixels = out;
    return 0;
}
