/* SPDX-License-Identifier: MIT */
/*
** passlog.h: what the iris command does after each progressive pass: the
** error against a reference image (--reference, --error-log, --verbose)
** and the image written every few passes or seconds.
**
** Depends on: include/iris (images, render options). Used by: main.c.
*/
#ifndef IRIS_CLI_PASSLOG_H
#define IRIS_CLI_PASSLOG_H

#include <stdbool.h>
#include <stdio.h>

#include "iris/iris.h"

/* The error of an image against the reference, linear values over the
** rendered window, RGB. */
struct pass_error {
    double rmse;               /* sqrt(mean (img - ref)^2) */
    double rel_rmse;           /* rmse / sqrt(mean ref^2) */
    double bias;               /* mean (img - ref) */
};

struct passlog {
    iris_image ref;            /* pixels NULL: no reference */
    FILE *csv;                 /* --error-log, or NULL */
    bool verbose;
    const char *out_name;      /* the image written every few passes */
    int out_bits;
    int x0, y0, x1, y1;        /* rendered window, 0-based inclusive */
    double last_write_s;       /* time_s of the last intermediate write */
    int last_write_passes;
    bool write_failed;         /* an intermediate write failed: said once */
    int calls;                 /* passes logged */
};

/*
** Opens the reference (any format iris_image_read reads; it must have the
** image's size) and the CSV log (appended to; the header is written when
** the file is empty). Either may be NULL. Returns 0, or -1 with a message
** in 'err'.
*/
int passlog_open(struct passlog *l, const iris_render_options *ro,
                 const char *reference, const char *csv_path, bool verbose,
                 const char *out_name, int out_bits, char *err,
                 size_t errlen);

void passlog_close(struct passlog *l);

/* The error of 'img' against the reference of 'l' (which must be set). */
void passlog_error(const struct passlog *l, const iris_image *img,
                   struct pass_error *e);

/* An iris_pass_fn: logs the pass, writes the image now and then. */
void passlog_on_pass(void *user, const iris_image *avg,
                     const iris_pass_info *info);

#endif
