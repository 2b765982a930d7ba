/* SPDX-License-Identifier: MIT */
/*
** error_plot.c: a log-log plot of error against wall time, as a PNG, from
** the CSV logs of iris --error-log (and of bench/error-vs-time.sh's
** POV-Ray runs, written in the same columns).
**
** Usage: error_plot out.png NAME=log.csv [NAME=log.csv ...]
**        error_plot --error REF IMG   (prints rmse,rel_rmse,bias)
**
** Each log is one series: rel_rmse (y) against time_s (x), both on
** logarithmic axes whose decades are found from the data; series 1 is
** drawn as a line with dots, the others with squares at each point and a
** line between them, in distinct colours. Decade ticks are labelled
** (10^k written as 1e<k>) with a 3x5 pixel font; the legend numbers the
** series in their colours and stdout says which is which. No dependencies beyond iris_image_write:
** the axes, points and text are drawn pixel by pixel.
*/
#include "config.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iris/image.h"

#define W 720
#define H 480
#define ML 70   /* margins: left, right, top, bottom */
#define MR 20
#define MT 20
#define MB 50
#define MAX_SERIES 8
#define MAX_POINTS 100000

struct series {
    const char *name;
    int n;
    double *t, *e;
};

static const float COLOURS[MAX_SERIES][3] = {
    { 0.85f, 0.10f, 0.10f }, { 0.10f, 0.25f, 0.85f }, { 0.10f, 0.60f, 0.15f },
    { 0.80f, 0.50f, 0.00f }, { 0.55f, 0.10f, 0.70f }, { 0.00f, 0.60f, 0.65f },
    { 0.40f, 0.40f, 0.40f }, { 0.60f, 0.30f, 0.10f } };

static iris_image img;

static void put(int x, int y, const float c[3])
{
    if (x < 0 || y < 0 || x >= W || y >= H)
        return;
    float *p = &img.pixels[((size_t)y * W + x) * 4];
    p[0] = c[0];
    p[1] = c[1];
    p[2] = c[2];
    p[3] = 1.0f;
}

static void line(double x0, double y0, double x1, double y1, const float c[3])
{
    int n = (int)fmax(fabs(x1 - x0), fabs(y1 - y0)) + 1;
    for (int i = 0; i <= n; i++) {
        double t = (double)i / n;
        put((int)lround(x0 + (x1 - x0) * t), (int)lround(y0 + (y1 - y0) * t),
            c);
    }
}

/* 3x5 glyphs, rows top to bottom, bit 2 = left column. */
static const char *GLYPHS = "0123456789e-.%";
static const unsigned char FONT[][5] = {
    { 7, 5, 5, 5, 7 }, { 2, 6, 2, 2, 7 }, { 7, 1, 7, 4, 7 }, { 7, 1, 7, 1, 7 },
    { 5, 5, 7, 1, 1 }, { 7, 4, 7, 1, 7 }, { 7, 4, 7, 5, 7 }, { 7, 1, 1, 1, 1 },
    { 7, 5, 7, 5, 7 }, { 7, 5, 7, 1, 7 }, { 0, 7, 7, 4, 7 }, { 0, 0, 7, 0, 0 },
    { 0, 0, 0, 0, 2 }, { 5, 1, 2, 4, 5 } };

/* Draws 'text' at (x, y) with 'scale'-pixel dots; characters without a
** glyph are blanks. */
static void text(int x, int y, const char *s, int scale, const float c[3])
{
    for (; *s; s++, x += 4 * scale) {
        const char *g = *s ? strchr(GLYPHS, *s) : NULL;
        if (!g)
            continue;
        const unsigned char *rows = FONT[g - GLYPHS];
        for (int r = 0; r < 5; r++)
            for (int b = 0; b < 3; b++)
                if (rows[r] & (4 >> b))
                    for (int dy = 0; dy < scale; dy++)
                        for (int dx = 0; dx < scale; dx++)
                            put(x + b * scale + dx, y + r * scale + dy, c);
    }
}

/* Reads the time_s and rel_rmse columns of a log. */
static int read_log(const char *path, struct series *s)
{
    FILE *f = fopen(path, "r");
    if (!f)
        return -1;
    char buf[1024];
    int ct = -1, ce = -1;
    if (fgets(buf, sizeof buf, f)) {
        int col = 0;
        for (char *tok = strtok(buf, ",\n"); tok; tok = strtok(NULL, ",\n"),
                  col++) {
            if (!strcmp(tok, "time_s"))
                ct = col;
            if (!strcmp(tok, "rel_rmse"))
                ce = col;
        }
    }
    s->t = malloc(MAX_POINTS * sizeof *s->t);
    s->e = malloc(MAX_POINTS * sizeof *s->e);
    if (ct < 0 || ce < 0 || !s->t || !s->e) {
        fclose(f);
        return -1;
    }
    while (s->n < MAX_POINTS && fgets(buf, sizeof buf, f)) {
        double v[16];
        int col = 0;
        char *p = buf;
        while (col < 16) {
            char *end;
            v[col++] = strtod(p, &end);
            p = strchr(end, ',');
            if (!p)
                break;
            p++;
        }
        if (ct < col && ce < col && v[ct] > 0 && v[ce] > 0 &&
            isfinite(v[ct]) && isfinite(v[ce])) {
            s->t[s->n] = v[ct];
            s->e[s->n] = v[ce];
            s->n++;
        }
    }
    fclose(f);
    return 0;
}

/*
** error_plot --error REF IMG: prints "rmse,rel_rmse,bias" of IMG against
** REF over all pixels' RGB, as iris --error-log defines them (passlog.c),
** for images made by other renderers.
*/
static int image_error(const char *ref_path, const char *img_path)
{
    iris_image ref, im;
    char err[256] = "";
    if (iris_image_read(&ref, ref_path, err, sizeof err) != IRIS_OK ||
        iris_image_read(&im, img_path, err, sizeof err) != IRIS_OK) {
        fprintf(stderr, "error_plot: %s\n", err);
        return 1;
    }
    if (ref.width != im.width || ref.height != im.height) {
        fprintf(stderr, "error_plot: the images differ in size\n");
        return 1;
    }
    double se = 0, sr = 0, sd = 0;
    size_t n = 0;
    for (size_t i = 0; i < (size_t)ref.width * ref.height; i++)
        for (int k = 0; k < 3; k++) {
            double a = im.pixels[i * 4 + k], r = ref.pixels[i * 4 + k];
            if (!isfinite(a) || !isfinite(r))
                continue;
            se += (a - r) * (a - r);
            sr += r * r;
            sd += a - r;
            n++;
        }
    printf("%.8g,%.8g,%.8g\n", n ? sqrt(se / n) : 0.0,
           sr > 0 ? sqrt(se / sr) : 0.0, n ? sd / n : 0.0);
    iris_image_fini(&ref);
    iris_image_fini(&im);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 4 && !strcmp(argv[1], "--error"))
        return image_error(argv[2], argv[3]);
    if (argc < 3 || argc - 2 > MAX_SERIES) {
        fprintf(stderr, "usage: error_plot out.png NAME=log.csv ... "
                        "(at most %d)\n", MAX_SERIES);
        return 2;
    }
    struct series s[MAX_SERIES];
    memset(s, 0, sizeof s);
    int ns = argc - 2;
    double t0 = INFINITY, t1 = -INFINITY, e0 = INFINITY, e1 = -INFINITY;
    for (int i = 0; i < ns; i++) {
        char *eq = strchr(argv[i + 2], '=');
        if (!eq) {
            fprintf(stderr, "error_plot: %s: expected NAME=log.csv\n",
                    argv[i + 2]);
            return 2;
        }
        *eq = 0;
        s[i].name = argv[i + 2];
        if (read_log(eq + 1, &s[i]) != 0) {
            fprintf(stderr, "error_plot: %s: cannot read the log\n", eq + 1);
            return 1;
        }
        for (int k = 0; k < s[i].n; k++) {
            t0 = fmin(t0, s[i].t[k]);
            t1 = fmax(t1, s[i].t[k]);
            e0 = fmin(e0, s[i].e[k]);
            e1 = fmax(e1, s[i].e[k]);
        }
    }
    if (!(t1 >= t0) || !(e1 >= e0)) {
        fprintf(stderr, "error_plot: no points\n");
        return 1;
    }
    /* whole decades around the data */
    int dt0 = (int)floor(log10(t0)), dt1 = (int)ceil(log10(t1));
    int de0 = (int)floor(log10(e0)), de1 = (int)ceil(log10(e1));
    if (dt1 == dt0)
        dt1++;
    if (de1 == de0)
        de1++;
    if (iris_image_init(&img, W, H) != IRIS_OK)
        return 1;
    for (size_t i = 0; i < (size_t)W * H * 4; i++)
        img.pixels[i] = 1.0f;
    const float black[3] = { 0, 0, 0 }, grey[3] = { 0.85f, 0.85f, 0.85f };
    double pw = W - ML - MR, ph = H - MT - MB;
#define PX(t) (ML + pw * (log10(t) - dt0) / (dt1 - dt0))
#define PY(e) (MT + ph * (1.0 - (log10(e) - de0) / (de1 - de0)))
    char lab[32];
    for (int d = dt0; d <= dt1; d++) {
        double x = PX(pow(10, d));
        line(x, MT, x, MT + ph, grey);
        for (int m = 2; m < 10 && d < dt1; m++) /* minor ticks */
            line(PX(m * pow(10, d)), MT + ph, PX(m * pow(10, d)),
                 MT + ph - 4, black);
        snprintf(lab, sizeof lab, "1e%d", d);
        text((int)x - 6, (int)(MT + ph + 8), lab, 2, black);
    }
    for (int d = de0; d <= de1; d++) {
        double y = PY(pow(10, d));
        line(ML, y, ML + pw, y, grey);
        for (int m = 2; m < 10 && d < de1; m++)
            line(ML, PY(m * pow(10, d)), ML + 4, PY(m * pow(10, d)), black);
        snprintf(lab, sizeof lab, "1e%d", d);
        text(ML - 40, (int)y - 5, lab, 2, black);
    }
    line(ML, MT, ML, MT + ph, black);
    line(ML, MT + ph, ML + pw, MT + ph, black);
        for (int i = 0; i < ns; i++) {
        const float *c = COLOURS[i];
        for (int k = 0; k < s[i].n; k++) {
            double x = PX(s[i].t[k]), y = PY(s[i].e[k]);
            if (k > 0)
                line(PX(s[i].t[k - 1]), PY(s[i].e[k - 1]), x, y, c);
            int r = i == 0 ? 1 : 3;
            for (int dy = -r; dy <= r; dy++)
                for (int dx = -r; dx <= r; dx++)
                    if (i == 0 || abs(dx) == r || abs(dy) == r)
                        put((int)lround(x) + dx, (int)lround(y) + dy, c);
        }
        /* legend: a swatch and the series number; names on stdout */
        int ly = MT + 8 + 16 * i;
        for (int dy = 0; dy < 8; dy++)
            for (int dx = 0; dx < 16; dx++)
                put(W - MR - 60 + dx, ly + dy, c);
        snprintf(lab, sizeof lab, "%d", i + 1);
        text(W - MR - 38, ly - 1, lab, 2, c);
        static const char *cname[MAX_SERIES] = { "red", "blue", "green",
            "orange", "purple", "teal", "grey", "brown" };
        printf("%d %s: %s (%d points)\n", i + 1, cname[i], s[i].name,
               s[i].n);
        free(s[i].t);
        free(s[i].e);
    }
    char err[256] = "";
    enum iris_status st = iris_image_write(&img, argv[1], 8, IRIS_ENC_LINEAR,
                                           err, sizeof err);
    iris_image_fini(&img);
    if (st != IRIS_OK) {
        fprintf(stderr, "error_plot: %s\n", err);
        return 1;
    }
    return 0;
}
