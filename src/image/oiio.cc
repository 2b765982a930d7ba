// SPDX-License-Identifier: MIT
/*
** oiio.cc: the image module (iris-oiio.so): files through OpenImageIO.
**
** This is the project's only C++ file, loaded by image_io.c on first use
** (see image_module.h for why it is a module). It moves pixels between
** files and memory and nothing else: the conversions are in image_io.c.
** Writes go to a temporary file in the target directory, renamed into
** place only when complete, so a failed or interrupted write never leaves
** a partial image under the requested name.
*/
#include "config.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <unistd.h>

extern "C" {
#include "image/image_module.h"
}

using namespace OIIO;

namespace {

void set_err(char *err, size_t errlen, const std::string &msg)
{
    if (err && errlen)
        std::snprintf(err, errlen, "%s", msg.c_str());
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

/* A temporary name in the same directory that keeps the extension, so
** that OpenImageIO still picks the format from it. */
std::string temp_name(const std::string &path)
{
    size_t slash = path.find_last_of('/');
    std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
    std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
    return dir + "." + base + ".tmp" + std::to_string((long)getpid()) + "." + lower_ext(path);
}

int write_file(const char *cpath, int w, int h, int nch, enum oiio_type type,
               const void *pixels, const char *colorspace, char *err,
               size_t errlen)
{
    std::string path(cpath);
    TypeDesc td = type == OIIO_FLOAT ? TypeDesc::FLOAT
                : type == OIIO_UINT16 ? TypeDesc::UINT16 : TypeDesc::UINT8;
    ImageSpec spec(w, h, nch, td);
    spec.attribute("oiio:ColorSpace", colorspace);
    if (lower_ext(path) == "exr") {
        spec.attribute("compression", "zip");
        /* OpenImageIO's EXR writer stamps the current time (capDate) into
        ** the header unless DateTime is set: two renders of one scene
        ** would then differ byte for byte. A fixed value keeps the file a
        ** function of the image alone. */
        spec.attribute("DateTime", "");
    }
    std::string tmp = temp_name(path);
    auto out = ImageOutput::create(tmp);
    if (!out) {
        set_err(err, errlen, path + ": cannot write this format: " + geterror());
        return -1;
    }
    if (!out->open(tmp, spec)) {
        set_err(err, errlen, path + ": " + out->geterror());
        std::remove(tmp.c_str());
        return -1;
    }
    bool ok = out->write_image(td, pixels);
    ok = out->close() && ok;
    if (!ok) {
        set_err(err, errlen, path + ": " + out->geterror());
        std::remove(tmp.c_str());
        return -1;
    }
    if (std::rename(tmp.c_str(), path.c_str()) != 0) {
        set_err(err, errlen, path + ": cannot rename the finished image into place: " + std::strerror(errno));
        std::remove(tmp.c_str());
        return -1;
    }
    return 0;
}

int read_file(const char *cpath, int *w, int *h, int *nch, float **pixels,
              int *srgb, char *err, size_t errlen)
{
    std::string path(cpath);
    *pixels = nullptr;
    auto in = ImageInput::open(path);
    if (!in) {
        set_err(err, errlen, path + ": " + geterror());
        return -1;
    }
    const ImageSpec &spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0 ||
        (long long)spec.width * spec.height * spec.nchannels > (1LL << 30)) {
        set_err(err, errlen, path + ": unusable image size");
        return -1;
    }
    size_t n = (size_t)spec.width * spec.height * spec.nchannels;
    float *buf = static_cast<float *>(std::malloc(n * sizeof(float)));
    if (!buf) {
        set_err(err, errlen, path + ": out of memory");
        return -1;
    }
    if (!in->read_image(0, 0, 0, spec.nchannels, TypeDesc::FLOAT, buf)) {
        set_err(err, errlen, path + ": " + in->geterror());
        std::free(buf);
        return -1;
    }
    std::string cs = spec.get_string_attribute("oiio:ColorSpace");
    *srgb = !spec.format.is_floating_point() && cs != "Linear" && cs != "linear";
    *w = spec.width;
    *h = spec.height;
    *nch = spec.nchannels;
    *pixels = buf;
    in->close();
    return 0;
}

const struct iris_oiio_api api = { IRIS_OIIO_ABI, write_file, read_file };

} // namespace

extern "C" __attribute__((visibility("default")))
const struct iris_oiio_api *iris_oiio_module(void)
{
    return &api;
}
