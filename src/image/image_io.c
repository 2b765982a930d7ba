/* SPDX-License-Identifier: MIT */
/*
** image_io.c: image files: the conversions, and the image module loader.
**
** iris_image_write() turns linear float pixels into what each format
** wants: 8/16-bit formats get the sRGB curve and POV-Ray's rounding
** (floor(clip(v)·max + 0.5)); float formats (exr, hdr, pfm) stay linear
** and 32-bit, so bright pixels never overflow to Inf as half floats
** would. NaN and Inf never reach a file. PNG files go through libpng
** (png.c); every other format through the OpenImageIO module
** (image_module.h), loaded once, on first use.
**
** The module is looked for in $IRIS_MODULE_DIR, then where it is
** installed (IRIS_PKGLIBDIR), then in '.libs' beside the running program
** (a build tree, where libtool leaves it).
*/
#include "config.h"

#include <dlfcn.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <unistd.h>

#include "image/image_module.h"
#include "image/png.h"
#include "iris/image.h"
#include "util/mem.h"

#define MODULE_NAME "iris-oiio.so"

static pthread_once_t module_once = PTHREAD_ONCE_INIT;
static const struct iris_oiio_api *module;
static char module_error[PATH_MAX + 64];

/* Tries one directory; true when the module is loaded. */
static int try_dir(const char *dir)
{
    char path[PATH_MAX];
    if (!dir || !*dir)
        return 0;
    snprintf(path, sizeof path, "%s/%s", dir, MODULE_NAME);
    void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        if (access(path, F_OK) == 0)
            snprintf(module_error, sizeof module_error, "%s", dlerror());
        return 0;
    }
    iris_oiio_entry_fn entry = (iris_oiio_entry_fn)(uintptr_t)dlsym(h, IRIS_OIIO_ENTRY);
    const struct iris_oiio_api *api = entry ? entry() : NULL;
    if (!api || api->abi != IRIS_OIIO_ABI) {
        snprintf(module_error, sizeof module_error, "%s: not a matching iris image module", path);
        dlclose(h);
        return 0;
    }
    module = api;
    return 1;
}

static void load_module(void)
{
    snprintf(module_error, sizeof module_error,
             "the image module %s was not found (set IRIS_MODULE_DIR, or reinstall iris)",
             MODULE_NAME);
    if (try_dir(getenv("IRIS_MODULE_DIR")) || try_dir(IRIS_PKGLIBDIR))
        return;
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 8);
    if (n > 0) {
        exe[n] = 0;
        char *slash = strrchr(exe, '/');
        if (slash) {
            strcpy(slash, "/.libs");
            if (try_dir(exe))
                return;
            *slash = 0;
            try_dir(exe);
        }
    }
}

static const struct iris_oiio_api *get_module(char *err, size_t errlen)
{
    pthread_once(&module_once, load_module);
    if (!module && err && errlen)
        snprintf(err, errlen, "%s", module_error);
    return module;
}

static const char *extension(const char *path)
{
    const char *slash = strrchr(path, '/');
    const char *dot = strrchr(slash ? slash : path, '.');
    return dot && dot[1] ? dot + 1 : NULL;
}

enum iris_status iris_image_write(const iris_image *img, const char *path,
                                  int bits, enum iris_encoding enc, char *err,
                                  size_t errlen)
{
    return iris_image_write_alpha(img, path, bits, enc, false, err, errlen);
}

/* A premultiplied pixel to straight alpha as POV-Ray 3.7 encodes it
** (encoding.cpp GetEncodedRGBAValue): brightness above alpha raises the
** alpha (so that clipping does not kill highlights on glass), then the
** colour is divided by it. Brightness is POV-Ray's greyscale. */
static void unpremultiply(double c[4])
{
    double a = c[3] < 0 ? 0 : c[3] > 1 ? 1 : c[3];
    double bright = 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
    if (bright > a)
        a = bright < 1.0 ? bright : 1.0;
    for (int k = 0; k < 3; k++)
        c[k] = a > 0 ? c[k] / a : 0.0;
    c[3] = a;
}

enum iris_status iris_image_write_alpha(const iris_image *img,
                                        const char *path, int bits,
                                        enum iris_encoding enc, bool alpha,
                                        char *err, size_t errlen)
{
    const char *ext = extension(path);
    if (!ext) {
        snprintf(err, errlen, "%s: the output name needs an extension (png, exr, tif, hdr, jpg, pfm)", path);
        return IRIS_EINVAL;
    }
    int is_png = !strcasecmp(ext, "png");
    const struct iris_oiio_api *m = is_png ? NULL : get_module(err, errlen);
    if (!is_png && !m)
        return IRIS_EIO;
    int floats = !strcasecmp(ext, "exr") || !strcasecmp(ext, "hdr") || !strcasecmp(ext, "pfm");
    if (bits != 16 || !strcasecmp(ext, "jpg") || !strcasecmp(ext, "jpeg"))
        bits = 8;
    const int nch = alpha ? 4 : 3;
    size_t n = (size_t)img->width * (size_t)img->height;
    size_t size = floats ? sizeof(float) : bits == 16 ? 2 : 1;
    void *buf = iris_calloc(n * nch, size);
    if (!buf)
        return IRIS_ENOMEM;
    double maxv = bits == 16 ? 65535.0 : 255.0;
    for (size_t i = 0; i < n; i++) {
        double px[4];
        for (int c = 0; c < 4; c++) {
            px[c] = img->pixels[i * 4 + c];
            if (!isfinite(px[c]))
                px[c] = 0; /* never a NaN or Inf in a file */
        }
        if (alpha && !floats)
            unpremultiply(px);
        for (int c = 0; c < nch; c++) {
            double v = px[c];
            if (floats) {
                ((float *)buf)[i * nch + c] = (float)v;
                continue;
            }
            if (enc == IRIS_ENC_SRGB && c < 3)
                v = iris_srgb_encode(v);
            v = v < 0 ? 0 : v > 1 ? 1 : v;
            double q = floor(v * maxv + 0.5);
            if (bits == 16)
                ((unsigned short *)buf)[i * nch + c] = (unsigned short)q;
            else
                ((unsigned char *)buf)[i * nch + c] = (unsigned char)q;
        }
    }
    const char *cs = floats || enc == IRIS_ENC_LINEAR ? "Linear" : "sRGB";
    enum oiio_type type = floats ? OIIO_FLOAT : bits == 16 ? OIIO_UINT16 : OIIO_UINT8;
    int rc = is_png ? png_write_rgb(path, img->width, img->height, bits, nch,
                                    buf, enc == IRIS_ENC_SRGB, err, errlen)
                    : m->write(path, img->width, img->height, nch, type, buf, cs,
                               err, errlen);
    iris_free(buf);
    return rc == 0 ? IRIS_OK : IRIS_EIO;
}

enum iris_status iris_image_read(iris_image *img, const char *path, char *err,
                                 size_t errlen)
{
    img->width = img->height = 0;
    img->pixels = NULL;
    int w, h, nch, srgb = 1;
    float *buf;
    /* PNG through libpng; 8/16-bit PNGs are sRGB-encoded, as POV-Ray and
    ** iris write them */
    int rc = png_read_float(path, &w, &h, &nch, &buf, err, errlen);
    if (rc < 0)
        return IRIS_EIO;
    if (rc > 0) {
        const struct iris_oiio_api *m = get_module(err, errlen);
        if (!m)
            return IRIS_EIO;
        if (m->read(path, &w, &h, &nch, &buf, &srgb, err, errlen) != 0)
            return IRIS_EIO;
    }
    enum iris_status st = iris_image_init(img, w, h);
    if (st != IRIS_OK) {
        free(buf);
        if (err && errlen)
            snprintf(err, errlen, "%s: %s", path, iris_status_str(st));
        return st;
    }
    for (size_t i = 0; i < (size_t)w * h; i++) {
        const float *s = buf + i * nch;
        float px[4] = { 0, 0, 0, 1 };
        if (nch >= 3) {
            px[0] = s[0]; px[1] = s[1]; px[2] = s[2];
            if (nch >= 4)
                px[3] = s[3];
        } else {
            px[0] = px[1] = px[2] = s[0];
            if (nch == 2)
                px[3] = s[1];
        }
        for (int c = 0; c < 3; c++) {
            float v = isfinite(px[c]) ? px[c] : 0.0f;
            img->pixels[i * 4 + c] = srgb ? (float)iris_srgb_decode(v) : v;
        }
        img->pixels[i * 4 + 3] = px[3];
    }
    free(buf);
    return IRIS_OK;
}
