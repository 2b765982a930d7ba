// SPDX-License-Identifier: MIT
/*
** oiio.cc: image files through OpenImageIO, behind the C API of image.h.
**
** This is the project's only C++ file. It converts the renderer's linear
** float pixels to what each format expects: 8/16-bit formats get the sRGB
** curve and POV-Ray's rounding (floor(clip(v)·max + 0.5)); float formats
** (exr, hdr, pfm) stay linear and 32-bit, so bright pixels never overflow
** to Inf as half floats would. Writes go to a temporary file in the target
** directory, renamed into place only when complete.
*/
#include "config.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

extern "C" {
#include "iris/image.h"
}

using namespace OIIO;

namespace {

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen) {
        std::snprintf(err, errlen, "%s", msg.c_str());
    }
}

std::string lower_ext(const std::string &path)
{
    size_t dot = path.find_last_of('.');
    size_t slash = path.find_last_of('/');
    if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
        return "";
    std::string e = path.substr(dot + 1);
    std::transform(e.begin(), e.end(), e.begin(), ::tolower);
    return e;
}

bool is_float_format(const std::string &ext)
{
    return ext == "exr" || ext == "hdr" || ext == "pfm";
}

/* A temporary name in the same directory that keeps the extension, so
** that OpenImageIO still picks the format from it. */
std::string temp_name(const std::string &path)
{
    size_t slash = path.find_last_of('/');
    std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    std::string ext = lower_ext(path);
    return dir + "." + base + ".tmp" + std::to_string((long)getpid()) + "." + ext;
}

} // namespace

extern "C" enum iris_status iris_image_write(const iris_image *img,
                                             const char *cpath, int bits,
                                             enum iris_encoding enc,
                                             char *err, size_t errlen)
{
    std::string path(cpath);
    std::string ext = lower_ext(path);
    if (ext.empty()) {
        set_err(err, errlen, path + ": the output name needs an extension (png, exr, tif, hdr, jpg, pfm)");
        return IRIS_EINVAL;
    }
    bool floats = is_float_format(ext);
    if (bits == 0)
        bits = 8;
    if (ext == "jpg" || ext == "jpeg")
        bits = 8;
    const int w = img->width, h = img->height, nch = 3;
    const size_t n = (size_t)w * (size_t)h;
    ImageSpec spec(w, h, nch, floats ? TypeDesc::FLOAT : bits == 16 ? TypeDesc::UINT16 : TypeDesc::UINT8);

    /* Convert: non-finite values become 0, never reach a file. */
    std::vector<float> fbuf;
    std::vector<unsigned char> b8;
    std::vector<unsigned short> b16;
    const void *data;
    if (floats) {
        fbuf.resize(n * nch);
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < nch; c++) {
                float v = img->pixels[i * 4 + c];
                fbuf[i * nch + c] = std::isfinite(v) ? v : 0.0f;
            }
        data = fbuf.data();
        spec.attribute("oiio:ColorSpace", "Linear");
        if (ext == "exr")
            spec.attribute("compression", "zip");
    } else {
        double maxv = bits == 16 ? 65535.0 : 255.0;
        if (bits == 16)
            b16.resize(n * nch);
        else
            b8.resize(n * nch);
        for (size_t i = 0; i < n; i++)
            for (int c = 0; c < nch; c++) {
                double v = img->pixels[i * 4 + c];
                if (!std::isfinite(v))
                    v = 0;
                v = enc == IRIS_ENC_SRGB ? iris_srgb_encode(v) : v;
                v = std::min(1.0, std::max(0.0, v));
                double q = std::floor(v * maxv + 0.5);
                if (bits == 16)
                    b16[i * nch + c] = (unsigned short)q;
                else
                    b8[i * nch + c] = (unsigned char)q;
            }
        data = bits == 16 ? (const void *)b16.data() : (const void *)b8.data();
        spec.attribute("oiio:ColorSpace", enc == IRIS_ENC_SRGB ? "sRGB" : "Linear");
    }

    std::string tmp = temp_name(path);
    auto out = ImageOutput::create(tmp);
    if (!out) {
        set_err(err, errlen, path + ": cannot write this format: " + geterror());
        return IRIS_EINVAL;
    }
    if (!out->open(tmp, spec)) {
        set_err(err, errlen, path + ": " + out->geterror());
        std::remove(tmp.c_str());
        return IRIS_EIO;
    }
    bool ok = out->write_image(spec.format, data);
    ok = out->close() && ok;
    if (!ok) {
        set_err(err, errlen, path + ": " + out->geterror());
        std::remove(tmp.c_str());
        return IRIS_EIO;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        set_err(err, errlen, path + ": cannot rename the finished image into place: " + std::strerror(errno));
        std::remove(tmp.c_str());
        return IRIS_EIO;
    }
    return IRIS_OK;
}

extern "C" enum iris_status iris_image_read(iris_image *img, const char *cpath,
                                            char *err, size_t errlen)
{
    std::string path(cpath);
    img->width = img->height = 0;
    img->pixels = nullptr;
    auto in = ImageInput::open(path);
    if (!in) {
        set_err(err, errlen, path + ": " + geterror());
        return IRIS_EIO;
    }
    const ImageSpec &spec = in->spec();
    int w = spec.width, h = spec.height, nch = spec.nchannels;
    if (w <= 0 || h <= 0 || nch <= 0 || (long long)w * h > (1LL << 28)) {
        set_err(err, errlen, path + ": unusable image size");
        return IRIS_EINVAL;
    }
    std::vector<float> buf((size_t)w * h * nch);
    if (!in->read_image(0, 0, 0, nch, TypeDesc::FLOAT, buf.data())) {
        set_err(err, errlen, path + ": " + in->geterror());
        return IRIS_EIO;
    }
    /* Integer files are sRGB-encoded unless they say otherwise. */
    bool decode = !spec.format.is_floating_point();
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    if (cs == "Linear" || cs == "linear")
        decode = false;
    enum iris_status st = iris_image_init(img, w, h);
    if (st != IRIS_OK)
        return st;
    for (size_t i = 0; i < (size_t)w * h; i++) {
        float px[4] = { 0, 0, 0, 1 };
        if (nch >= 3) {
            for (int c = 0; c < 3; c++)
                px[c] = buf[i * nch + c];
            if (nch >= 4)
                px[3] = buf[i * nch + 3];
        } else {
            px[0] = px[1] = px[2] = buf[i * nch];
            if (nch == 2)
                px[3] = buf[i * nch + 1];
        }
        for (int c = 0; c < 3; c++) {
            float v = std::isfinite(px[c]) ? px[c] : 0.0f;
            img->pixels[i * 4 + c] = decode ? (float)iris_srgb_decode(v) : v;
        }
        img->pixels[i * 4 + 3] = px[3];
    }
    in->close();
    return IRIS_OK;
}
