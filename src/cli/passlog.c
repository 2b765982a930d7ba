/* SPDX-License-Identifier: MIT */
/*
** passlog.c: the progressive pass callback of the iris command (see
** passlog.h).
**
** The error log has one line per pass, `time_s,passes,photons,rmse,
** rel_rmse,bias`, in linear values over the rendered window's RGB: rmse is
** the root mean square difference, rel_rmse that divided by the root mean
** square of the reference (so 0.03 is "3% of the image's level"), bias the
** mean signed difference. Lines are flushed as they are written, so a
** benchmark can read the log of a run that was stopped.
**
** The image is written after pass 1, 2, 4, 8, then every 16 passes, and
** whenever 5 s went by since the last write; main.c writes it at the end.
*/
#include "config.h"

#include "cli/passlog.h"

#include <math.h>
#include <string.h>

#define WRITE_EVERY_S 5.0
#define WRITE_EVERY_PASSES 16

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

int passlog_open(struct passlog *l, const iris_render_options *ro,
                 const char *reference, const char *csv_path, bool verbose,
                 const char *out_name, int out_bits, char *err,
                 size_t errlen)
{
    memset(l, 0, sizeof *l);
    l->verbose = verbose;
    l->out_name = out_name;
    l->out_bits = out_bits;
    l->x0 = ro->start_col > 0 ? clampi(ro->start_col - 1, 0, ro->width - 1) : 0;
    l->x1 = ro->end_col > 0 ? clampi(ro->end_col - 1, 0, ro->width - 1)
                            : ro->width - 1;
    l->y0 = ro->start_row > 0 ? clampi(ro->start_row - 1, 0, ro->height - 1) : 0;
    l->y1 = ro->end_row > 0 ? clampi(ro->end_row - 1, 0, ro->height - 1)
                            : ro->height - 1;
    if (csv_path && !reference) {
        snprintf(err, errlen, "--error-log needs --reference");
        return -1;
    }
    if (reference) {
        char msg[256] = "";
        if (iris_image_read(&l->ref, reference, msg, sizeof msg) != IRIS_OK) {
            snprintf(err, errlen, "%s: cannot read the reference: %s",
                     reference, msg);
            memset(&l->ref, 0, sizeof l->ref);
            return -1;
        }
        if (l->ref.width != ro->width || l->ref.height != ro->height) {
            snprintf(err, errlen, "%s: the reference is %dx%d, the image "
                     "%dx%d", reference, l->ref.width, l->ref.height,
                     ro->width, ro->height);
            passlog_close(l);
            return -1;
        }
    }
    if (csv_path) {
        l->csv = fopen(csv_path, "a");
        if (!l->csv) {
            snprintf(err, errlen, "%s: cannot open the error log", csv_path);
            passlog_close(l);
            return -1;
        }
        fseek(l->csv, 0, SEEK_END);
        if (ftell(l->csv) == 0)
            fputs("time_s,passes,photons,rmse,rel_rmse,bias\n", l->csv);
        fflush(l->csv);
    }
    return 0;
}

void passlog_close(struct passlog *l)
{
    if (l->csv)
        fclose(l->csv);
    l->csv = NULL;
    if (l->ref.pixels)
        iris_image_fini(&l->ref);
    memset(&l->ref, 0, sizeof l->ref);
}

void passlog_error(const struct passlog *l, const iris_image *img,
                   struct pass_error *e)
{
    double se = 0.0, sr = 0.0, sd = 0.0;
    long n = 0;
    for (int y = l->y0; y <= l->y1; y++)
        for (int x = l->x0; x <= l->x1; x++) {
            size_t i = ((size_t)y * (size_t)img->width + (size_t)x) * 4;
            for (int k = 0; k < 3; k++) {
                double a = img->pixels[i + k], r = l->ref.pixels[i + k];
                if (!isfinite(a) || !isfinite(r))
                    continue;
                se += (a - r) * (a - r);
                sr += r * r;
                sd += a - r;
                n++;
            }
        }
    e->rmse = n ? sqrt(se / n) : 0.0;
    e->rel_rmse = sr > 0.0 ? sqrt(se / sr) : 0.0;
    e->bias = n ? sd / n : 0.0;
}

/* Intermediate writes: after passes 1, 2, 4, 8, every 16, every 5 s. */
static bool write_due(const struct passlog *l, const iris_pass_info *info)
{
    int p = info->passes;
    if (p - l->last_write_passes <= 0)
        return false;
    if (p <= 8)
        return (p & (p - 1)) == 0;
    return p % WRITE_EVERY_PASSES == 0 ||
           info->time_s - l->last_write_s >= WRITE_EVERY_S;
}

void passlog_on_pass(void *user, const iris_image *avg,
                     const iris_pass_info *info)
{
    struct passlog *l = user;
    l->calls++;
    struct pass_error e = { 0, 0, 0 };
    bool have_ref = l->ref.pixels != NULL;
    if (have_ref)
        passlog_error(l, avg, &e);
    if (l->csv) {
        fprintf(l->csv, "%.4f,%d,%llu,%.8g,%.8g,%.8g\n", info->time_s,
                info->passes, (unsigned long long)info->photons, e.rmse,
                e.rel_rmse, e.bias);
        fflush(l->csv);
    }
    if (l->verbose) {
        fprintf(stderr, "iris: pass %d  %.2f s  %llu photons  radius x%.3f",
                info->passes, info->time_s,
                (unsigned long long)info->photons, info->radius_scale);
        if (have_ref)
            fprintf(stderr, "  rmse %.5g  rel_rmse %.4f  bias %+.4g",
                    e.rmse, e.rel_rmse, e.bias);
        fputc('\n', stderr);
    }
    if (l->out_name && write_due(l, info)) {
        char err[256] = "";
        /* a failed write is said once: the run goes on (the disk may
        ** recover), and main.c's final write reports again */
        if (iris_image_write(avg, l->out_name, l->out_bits, IRIS_ENC_SRGB,
                             err, sizeof err) != IRIS_OK &&
            !l->write_failed) {
            fprintf(stderr, "iris: warning: %s\n", err);
            l->write_failed = true;
        }
        l->last_write_s = info->time_s;
        l->last_write_passes = info->passes;
    }
}
