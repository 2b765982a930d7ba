/* SPDX-License-Identifier: MIT */
/*
** eyepass.c: the eye pass: tiles over threads and POV-Ray's antialiasing
** (see eyepass.h).
**
** DESIGN. The image is cut into 32 x 32 tiles, POV-Ray's block size, and
** par_for() hands them to the threads. POV-Ray's antialiasing depends on
** the tile: method 1 compares each pixel with its left and upper
** neighbours, tracing (but never supersampling) the row above and the
** column left of the tile; method 2 traces the tile's pixel corners. Doing
** the same here supersamples the pixels POV-Ray supersamples (the border
** samples, traced twice by POV-Ray, are shared between neighbouring tiles
** here: struct edge_px). Every random
** number (AA jitter, area-light jitter, wavelengths) comes from a stream
** keyed by the sample's image position, never by the thread, so the image
** does not depend on the thread count.
*/
#include "config.h"

#include <math.h>
#include <stdatomic.h>
#include <string.h>

#include "render/camera.h"
#include "render/camray.h"
#include "render/eyepass.h"
#include "render/eyespectrum.h"
#include "render/focalblur.h"
#include "render/gather.h"
#include "render/jitter.h"
#include "render/meshcam.h"
#include "util/mem.h"
#include "util/thread.h"

#define TILE 32

/* Without AA methods 1 and 2 and radiosity nothing of a tile is shared by
** its pixels, and each tile is cut into BANDS work items of TILE/BANDS
** rows: with 20 tiles (160x120) a pass ended with one thread finishing
** the last tile alone, up to a tile's time (~5% of the pass on 2
** threads); a band is a quarter of that. */
#define BANDS 4

/* A sample's channels: linear r, g, b, then POV-Ray's transmit channel
** (what the sample saw of the background; alpha = 1 - it under +UA). */
#define NCH 4

/* ------------------------------------------------------------------ */
/* Sampling                                                             */
/* ------------------------------------------------------------------ */

struct px;
struct edge_px;

struct job {
    const iris_scene *scene;
    const iris_render_options *opts;
    const struct tracer *tracer;
    struct trace_ctx *ctx;     /* one per thread */
    struct interior_stack cam_stack;
    struct cam_pinhole pinhole; /* perspective camera without normal{} */
    bool has_pinhole;
    struct cam_axes axes;      /* the other cameras' (camera_ray_axes) */
    bool ortho;
    bool blur;                 /* focal blur (fb) */
    bool one_ray;              /* a sample is one ray: no blur, no mesh
                                  camera (trace_sample) */
    bool px_linear;            /* pixels in linear light as they are: no
                                  legacy or working gamma (put_pixel) */
    /* A pinhole ray's tmin: trace_ray() takes accel_origin_epsilon() of
    ** a ray with tmin 0, and for rays from the camera's location, every
    ** pinhole ray without focal blur, that is one number per render.
    ** Given as the ray's tmin it comes back unchanged (leave_eps(): it
    ** is positive and at most the scene's epsilon; a value that is not,
    ** and every other camera's rays, 0: trace_ray() asks as before). */
    double pin_tmin;
    struct focal_blur fb;
    struct containing_list blur_cl; /* the objects that may hold a blur
                                       (orthographic, mesh camera) ray's
                                       origin (n = 0: not built) */
    bool has_blur_cl;
    iris_image *out;
    int x0, y0, x1, y1;        /* render window, inclusive, 0-based */
    int tiles_x, tiles_y;
    int bands;                 /* work items a tile (BANDS or 1) */
    double aa_threshold, jitter;
    struct eye_aa_gamma gam;   /* the AA comparison's gamma */
    int aa_depth;
    enum iris_aa_method aa;
    atomic_ullong nan_count;
    atomic_int tiles_done;
    atomic_int interrupted;
    atomic_int alloc_failed;
    struct eye_srgb *srgb;     /* legacy gamma: put_pixel's decode */
    struct px **tile_buf;      /* per thread: method 1's tile buffer,
                                  allocated at its first tile */
    struct edge_px *edge_rows; /* method 1: each tile row's last row */
    struct edge_px *edge_cols; /* ... each tile column's last column */
};

/* llround() for the finite, small values below, without its library
** call (once per sample): v - trunc(v) is exact, so halves round away
** from zero exactly as llround() does. The two comparisons are added as
** integers, not branched on: the fraction of a jittered sample's
** position is random (callgrind's branch model mispredicted these
** branches on most samples). */
static int64_t round_half_away(double v)
{
    int64_t i = (int64_t)v;
    double f = v - (double)i;
    return i + (int64_t)(f >= 0.5) - (int64_t)(f <= -0.5);
}

/* A stream key from an image position, so that a sample gets the same
** random numbers whichever tile or thread traces it. */
static uint64_t pos_key(double x, double y)
{
    int64_t ix = round_half_away(x * 4096.0);
    int64_t iy = round_half_away(y * 4096.0);
    return ((uint64_t)ix << 32) ^ (uint64_t)iy ^ ((uint64_t)iy << 17);
}

/* The ray of any camera but the pinhole (cam_pinhole_ray): the mesh
** camera's numbered ray, or camera_ray_raw()'s with the axes worked out
** once (j->axes). Out of trace_one(): there its second call made the
** pinhole's every sample dearer (01_sphere_plane +0.3 %). */
static __attribute__((noinline)) bool other_camera_ray(const struct job *j,
                                                      double x, double y,
                                                      int nr, ray *r,
                                                      vec3 *raw)
{
    const iris_camera *cam = &j->scene->camera;
    if (cam->kind == IRIS_CAM_MESH)
        return camera_ray_numbered(cam, j->opts->width, j->opts->height, x,
                                   y, nr, r, raw);
    return camera_ray_axes(cam, &j->axes, j->opts->width, j->opts->height, x,
                           y, r, raw);
}

/* Traces one camera ray through image point (x, y): the pinhole ray, or
** with focal blur blur ray 'nr' of the sample at (bx, by). Returns whether
** it split into wavelengths (then rgb may lie outside the sRGB gamut). */
static bool trace_one(struct job *j, struct trace_ctx *c, double x,
                      double y, int nr, double bx, double by, double rgb[NCH])
{
    /* blur rays of one sample may share an image position: their streams
    ** are told apart by the ray number */
    rng_lazy_seed(&c->rng, j->opts->seed, 1,
                  pos_key(x, y) ^ ((uint64_t)nr * 0x9e3779b97f4a7c15u));
    /* Only the used part of the interior stack is set: clearing and
    ** copying the whole struct cost more than a simple scene's shading. */
    struct tray r;
    r.reflected = false;
    r.lambda = 0.0;
    r.tmin = j->pin_tmin;
    rgb[0] = rgb[1] = rgb[2] = 0.0;
    rgb[3] = 1.0;              /* no ray: transparent, as POV-Ray has it */
    c->spectral = false;
    vec3 raw;
    if (j->has_pinhole ? !cam_pinhole_ray(&j->pinhole, x, y, &r.r, &raw)
                       : !other_camera_ray(j, x, y, nr, &r.r, &raw))
        return false;
    if (j->blur) {
        focal_blur_ray(&j->fb, &j->scene->camera, bx, by, nr, raw, &r.r);
        /* the aperture moves the origin: which interiors hold it is
        ** asked again, as POV-Ray does for blurred rays (of the objects
        ** near the aperture: the others cannot hold it) */
        if (j->has_blur_cl)
            trace_containing_from(j->tracer, &j->blur_cl, r.r.o, &r.st);
        else
            trace_containing(j->tracer, r.r.o, &r.st);
    } else if (j->ortho) {
        /* every ray has its own origin: of the objects near the origins */
        if (j->has_blur_cl)
            trace_containing_from(j->tracer, &j->blur_cl, r.r.o, &r.st);
        else
            trace_containing(j->tracer, r.r.o, &r.st);
    } else {
        r.st.n = j->cam_stack.n;
        for (int i = 0; i < r.st.n; i++)
            r.st.e[i] = j->cam_stack.e[i];
    }
    c->level = 0;
    c->n.camera++;
    trace_ray(c, &r, 1.0, false, rgb);
    rgb[3] = c->transm;
    /* v * 0 is 0 for finite v, NaN for an infinity or NaN: one test for
    ** the four channels */
    if (!(rgb[0] * 0.0 + rgb[1] * 0.0 + rgb[2] * 0.0 + rgb[3] * 0.0 == 0.0)) {
        rgb[0] = rgb[1] = rgb[2] = rgb[3] = 0.0;
        atomic_fetch_add(&j->nan_count, 1);
    }
    return c->spectral;
}

/* A mesh camera's sample (POV-Ray's TracePixel): the mean of the
** rays_per_pixel rays that have a face; none gives transparent black. */
static bool meshcam_sample(struct job *j, struct trace_ctx *c, double x,
                           double y, double rgb[NCH])
{
    const iris_camera *cam = &j->scene->camera;
    double sum[NCH] = { 0, 0, 0, 0 };
    int n = 0;
    bool spectral = false;
    for (int nr = 0; nr < cam->mesh_rays_per_pixel; nr++) {
        ray probe;
        vec3 raw;
        if (!camera_ray_numbered(cam, j->opts->width, j->opts->height, x, y,
                                 nr, &probe, &raw))
            continue;
        double col[NCH];
        spectral |= trace_one(j, c, x, y, nr, x, y, col);
        for (int k = 0; k < NCH; k++)
            sum[k] += col[k];
        n++;
    }
    for (int k = 0; k < NCH; k++)
        rgb[k] = n ? sum[k] / n : 0.0;
    if (!n)
        rgb[3] = 1.0;
    return spectral;
}

/* trace_sample() of a mesh camera or with focal blur: the mesh camera's
** rays, or POV-Ray's focal blur loop (focalblur.h): batches of blur
** rays, each at its own sub-pixel position, until the confidence test
** passes or blur_samples are in. A call of its own: its locals made
** every sample's call of trace_sample() save and restore them (29
** instructions a sample, 1.5 % of a simple scene's eye pass). */
static __attribute__((noinline)) bool trace_sample_multi(struct job *j,
                                                        struct trace_ctx *c,
                                                        double x, double y,
                                                        double rgb[NCH])
{
    if (!j->blur)
        return meshcam_sample(j, c, x, y, rgb);
    const struct focal_blur *fb = &j->fb;
    int seed = focal_blur_seed(x, y);
    double sum[NCH] = { 0, 0, 0, 0 }, s2[NCH] = { 0, 0, 0, 0 };
    int nr = 0, level = 0;
    bool spectral = false;
    do {
        int batch = 4;
        if (fb->batches && fb->batches[level] > 0)
            batch = fb->batches[level++];
        for (int i = 0; i < batch && nr < fb->samples; i++, nr++) {
            double dx, dy, col[NCH];
            focal_blur_subpixel(seed, nr, &dx, &dy);
            spectral |= trace_one(j, c, x + dx, y + dy, nr, x + dx, y + dy,
                                  col);
            for (int k = 0; k < NCH; k++)
                sum[k] += col[k];
            for (int k = 0; k < NCH; k++)
                s2[k] += col[k] * col[k];
        }
    } while (!focal_blur_converged(fb, nr, sum, s2) && nr < fb->samples);
    for (int k = 0; k < NCH; k++)
        rgb[k] = sum[k] / nr;
    return spectral;
}

/* The image sample at (x, y): one camera ray (j->one_ray), else
** trace_sample_multi()'s rays. Returns whether a ray split into
** wavelengths. */
static inline bool trace_sample(struct job *j, struct trace_ctx *c, double x,
                                double y, double rgb[NCH])
{
    if (j->one_ray)
        return trace_one(j, c, x, y, 0, x, y, rgb);
    return trace_sample_multi(j, c, x, y, rgb);
}

/* A traced sample of the AA buffers: its colour and, once, the colour the
** AA threshold compares (gamma-adjusted, §4.1), so that the pow() calls
** are not repeated at every comparison. */
struct px {
    double c[NCH];
    double g[3];               /* c^(1/aa_gamma), see px_gamma */
    double gerr;               /* bound on sum |g - exact g|, 0: exact */
    bool done;                 /* already supersampled (or not allowed) */
    bool spectral;             /* a sample split into wavelengths */
};

/* Method 1's tiles trace the row above and the column left of them, which
** are the last row and column of the neighbouring tiles: POV-Ray traces
** these samples twice (6 % of a 32 x 32 tile's first samples). iris
** keeps each tile's last row and column as the tile traces them, before
** any supersampling, and a later tile takes them from here when they are
** ready; otherwise (its neighbour is still at work on the other thread,
** or the neighbour is outside the window) it traces them itself. A first
** sample is a function of its image position only (its random streams
** are keyed by it, eyepass.c's head), so both ways give the same values
** to the bit, and the image does not depend on which was taken. Not
** under radiosity: there a sample reads its own tile's records
** (gather_tile_begin). 'n' is the sample's share of POV-Ray's statistics,
** added to the statistics of the tile that takes it, so the counts stay
** POV-Ray's (tests/render/raycounts.sh); rays_traced counts what was
** traced. */
struct edge_px {
    struct px p;
    struct trace_counts n;
    atomic_int ready;          /* p and n are written (release/acquire) */
};

void eye_aa_gamma_init(struct eye_aa_gamma *a, double aa_gamma)
{
    a->e = aa_gamma > 0 ? 1.0 / aa_gamma : 1.0;
    a->ef = (float)a->e;
    /* powf is within 1 ulp (2^-23 relative, glibc's documents 0.82);
    ** rounding the input to float adds e * 2^-24, rounding the exponent
    ** |e - ef| |ln v| with |ln v| <= 14 on [1e-6, 1e6]. Doubled for the
    ** rounding of the sums that use the bound. With e <= 4, v^e stays in
    ** float's normal range there. */
    a->fast = a->e != 1.0 && a->e > 0.0 && a->e <= 4.0;
    a->rel = 2.0 * (a->e * 0x1p-24 + fabs(a->e - (double)a->ef) * 14.0 +
                    0x1p-23);
    /* The table: linear interpolation of f(v) = v^e over a segment
    ** [x0, x0 (1 + 1/128)] errs by at most h^2/8 max|f''| with h = x0/128,
    ** and for 0 < e < 1 |f''| = e (1 - e) v^(e-2) is largest at x0, so by
    ** e (1 - e) / (8 * 128^2) of f(x0) <= f(v). The first octave's
    ** entries come from pow() (within an ulp), each further octave's from
    ** the one below times 2^e (half an ulp more per octave, 23 octaves:
    ** 12 ulps, 3e-15), and the interpolation adds a few roundings: 1e-14
    ** covers them. Doubled, as rel is. Half the cost of powf(); the table
    ** costs 129 pow() calls per render. */
    a->lut = a->e > 0.0 && a->e < 1.0;
    a->lut_rel = 2.0 * (a->e * (1.0 - a->e) / (8.0 * 128.0 * 128.0) + 1e-14);
    if (a->lut) {
        double step = pow(2.0, a->e);
        for (int i = 0; i <= EYE_AA_LUT_N; i++)
            a->tab[i] = i < 128 ? pow(ldexp(1.0 + i / 128.0, EYE_AA_LUT_LO),
                                      a->e)
                                : a->tab[i - 128] * step;
    }
}

/* v^e from the table, for v in [2^EYE_AA_LUT_LO, 2^EYE_AA_LUT_HI) (else
** false). The double's exponent and top 7 mantissa bits pick the segment;
** its 45 lower mantissa bits are, exactly, where v lies in it. */
static inline bool aa_lut(const struct eye_aa_gamma *a, double v, double *g)
{
    uint64_t bits;
    memcpy(&bits, &v, sizeof bits);
    int64_t i = (int64_t)(bits >> 45) - (int64_t)(1023 + EYE_AA_LUT_LO) * 128;
    if (i < 0 || i >= EYE_AA_LUT_N)
        return false;
    double t = (double)(bits & ((UINT64_C(1) << 45) - 1)) * 0x1p-45;
    *g = a->tab[i] + t * (a->tab[i + 1] - a->tab[i]);
    return true;
}

/* eye_aa_gamma_apply(), inline in px_gamma() (once or twice a pixel: its
** call and the reloads of 'a' per channel were a third of its cost) */
static inline double aa_gamma_apply(const struct eye_aa_gamma *a,
                                    const double c[3], double g[3])
{
    double err = 0.0;
    if (a->lut) {
        /* the usual exponent, 0 < e < 1: the tests below come down to
        ** v = 0 and the table (the others only off the table's range) */
        bool all = true;
        for (int k = 0; k < 3; k++) {
            double v = c[k] > 0.0 ? c[k] : 0.0;
            if (v == 0.0)
                g[k] = v;
            else if (aa_lut(a, v, &g[k]))
                err += g[k] * a->lut_rel;
            else
                all = false;
        }
        if (all)
            return err;
        err = 0.0;             /* some channel off the table: all again */
    }
    for (int k = 0; k < 3; k++) {
        double v = c[k] > 0.0 ? c[k] : 0.0; /* fmax(c, 0): no call */
        if (a->e == 1.0 || (v == 0.0 && a->e > 0.0)) {
            g[k] = v;            /* pow(v, 1) = v, pow(0, e > 0) = 0 */
        } else if (a->lut && aa_lut(a, v, &g[k])) {
            err += g[k] * a->lut_rel;
        } else if (a->fast && v >= 1e-6 && v <= 1e6) {
            g[k] = powf((float)v, a->ef);
            err += g[k] * a->rel;
        } else {
            g[k] = pow(v, a->e);
        }
    }
    return err;
}

double eye_aa_gamma_apply(const struct eye_aa_gamma *a, const double c[3],
                          double g[3])
{
    return aa_gamma_apply(a, c, g);
}

/* g(v) = ((v + 0.055) / 1.055)^2.4, iris_srgb_decode() above 0.04045.
** Segment i starts at v0 = i / N; with x0 = (v0 + 0.055) / 1.055 and
** a = 1 / 1.055 its Taylor coefficients are g(v0) = x0^2.4, then
** 2.4 a x0^1.4, 2.4 * 1.4 / 2 a^2 x0^0.4 and 2.4 * 1.4 * 0.4 / 6 a^3
** x0^-0.6, each from the one pow() x0^2.4 by divisions by x0. The cubic's
** error on a segment is at most max|g''''| / 24 d^4 with d < 1/1024 and
** |g''''| = 2.4 * 1.4 * 0.4 * 0.6 a^4 x^-1.6, largest at the lowest
** segment used (i = 41, x0 = 0.09008, x0^-1.6 = 47.1): 1.28 * 9.1e-13 =
** 1.2e-12, relative to g >= g(0.04045) = 0.00313 3.7e-10. The rounding
** of the coefficients (a few ulps each, on terms no larger than g) and
** of the Horner sum, and the exact path's own (x rounded twice, then
** pow() within an ulp: under 1e-15 relative) add under 1e-14:
** EYE_SRGB_REL = 1e-9 bounds it all with a margin of 2.5. */
void eye_srgb_init(struct eye_srgb *s)
{
    const double a = 1.0 / 1.055;
    memset(s->coef, 0, sizeof s->coef);
    for (int i = (int)(0.04045 * EYE_SRGB_N); i < EYE_SRGB_N; i++) {
        double x0 = ((double)i / EYE_SRGB_N + 0.055) / 1.055;
        double p = pow(x0, 2.4);
        s->coef[i][0] = p;
        s->coef[i][1] = 2.4 * a * p / x0;
        s->coef[i][2] = 2.4 * 1.4 / 2.0 * a * a * p / (x0 * x0);
        s->coef[i][3] = 2.4 * 1.4 * 0.4 / 6.0 * a * a * a * p /
                        (x0 * x0 * x0);
    }
    s->at_one = (float)iris_srgb_decode(1.0);
}

double eye_srgb_cubic(const struct eye_srgb *s, double v)
{
    /* v * N is exact (N a power of 2), so is d = v - i / N (Sterbenz:
    ** i / N <= v < 2 i / N for i >= 1) */
    int i = (int)(v * EYE_SRGB_N);
    double d = v - (double)i / EYE_SRGB_N;
    const double *c = s->coef[i];
    return c[0] + d * (c[1] + d * (c[2] + d * c[3]));
}

float eye_srgb_decode(const struct eye_srgb *s, double v)
{
    if (v == 1.0)              /* every clipped channel */
        return s->at_one;
    if (!(v > 0.04045) || !(v < 1.0))
        return (float)iris_srgb_decode(v);
    double y = eye_srgb_cubic(s, v);
    /* pow()'s value lies in [y (1 - rel), y (1 + rel)]; rounding to float
    ** is monotonic, so when both ends round alike so does it */
    float lo = (float)(y * (1.0 - EYE_SRGB_REL));
    float hi = (float)(y * (1.0 + EYE_SRGB_REL));
    if (lo == hi)
        return lo;
    return (float)iris_srgb_decode(v);
}

/* The gamma-adjusted colour, fast (with an error bound) or exact. The
** fast one costs half of pow(); aa_differs() redoes it exactly when the
** bound does not settle the threshold test, so the AA decisions, and the
** image, are those of pow() (2.5: 3 pow() per sample were 5% of render
** time). */
static void px_gamma(const struct job *j, struct px *p)
{
    p->gerr = aa_gamma_apply(&j->gam, p->c, p->g);
}

static void px_gamma_exact(const struct job *j, struct px *p)
{
    if (p->gerr == 0.0)
        return;
    for (int k = 0; k < 3; k++)
        p->g[k] = pow(fmax(p->c[k], 0.0), j->gam.e);
    p->gerr = 0.0;
}

/* The difference the AA threshold is compared with: POV-Ray's
** Colour_Distance_RGBT, the gamma-adjusted colour and the transmit
** channel as it is (under +UA the background's edges; a camera ray that
** does not exist has transmit 1 also without). */
static double aa_distance(const struct px *a, const struct px *b)
{
    return fabs(a->g[0] - b->g[0]) + fabs(a->g[1] - b->g[1]) +
           fabs(a->g[2] - b->g[2]) + fabs(a->c[3] - b->c[3]);
}

/* aa_differs() once the fast distance cannot settle it: with the exact
** values (rare: a call of its own, so that the common case inlines) */
static __attribute__((noinline)) bool aa_differs_exact(const struct job *j,
                                                       struct px *a,
                                                       struct px *b)
{
    px_gamma_exact(j, a);
    px_gamma_exact(j, b);
    return aa_distance(a, b) >= j->aa_threshold;
}

/* Whether a and b differ by the AA threshold, as with exact pow(): the
** fast distance is off by at most a->gerr + b->gerr, so only a distance
** that close to the threshold needs the exact values. Inline: asked
** twice per pixel. */
static inline bool aa_differs(const struct job *j, struct px *a, struct px *b)
{
    double d = aa_distance(a, b), e = a->gerr + b->gerr;
    if (e > 0.0 && fabs(d - j->aa_threshold) <= e)
        return aa_differs_exact(j, a, b);
    return d >= j->aa_threshold;
}

/* Method 1: (centre + R x R jittered samples) / (R^2 + 1). Returns
** whether a sample split into wavelengths. */
static bool supersample(struct job *j, struct trace_ctx *c, double x, double y,
                        double col[NCH])
{
    bool spectral = false;
    int R = j->aa_depth;
    double step = 1.0 / R, range = 0.5 - step * 0.5;
    double js = j->jitter / R;
    for (int iy = 0; iy < R; iy++)
        for (int ix = 0; ix < R; ix++) {
            double xx = -range + ix * step, yy = -range + iy * step;
            double sx = x + xx, sy = y + yy;
            if (js > 0.0) {
                double rx, ry;
                jitter2d(sx, sy, &rx, &ry);
                sx += rx * js;
                sy += ry * js;
            }
            double s[NCH];
            spectral |= trace_sample(j, c, sx, sy, s);
            for (int k = 0; k < NCH; k++)
                col[k] += s[k];
        }
    for (int k = 0; k < NCH; k++)
        col[k] /= R * R + 1;
    return spectral;
}

/* Stratified supersampling: R x R samples, one per jittered stratum. */
static bool stratified(struct job *j, struct trace_ctx *c, int x, int y,
                       double col[NCH])
{
    int R = j->aa_depth;
    bool spectral = false;
    col[0] = col[1] = col[2] = col[3] = 0.0;
    rng r;
    rng_seed(&r, j->opts->seed, 3, (uint64_t)y * 65536u + (uint64_t)x);
    for (int iy = 0; iy < R; iy++)
        for (int ix = 0; ix < R; ix++) {
            double ux = j->jitter > 0 ? rng_uniform(&r) : 0.5;
            double uy = j->jitter > 0 ? rng_uniform(&r) : 0.5;
            double s[NCH];
            spectral |= trace_sample(j, c, x - 0.5 + (ix + ux) / R,
                                     y - 0.5 + (iy + uy) / R, s);
            for (int k = 0; k < NCH; k++)
                col[k] += s[k];
        }
    for (int k = 0; k < NCH; k++)
        col[k] /= R * R;
    return spectral;
}

/* put_pixel()'s colour, every case: the samples were summed unclipped;
** only here does the colour enter the gamut: a pixel with spectral
** samples keeps its luminance (eye_gamut_map), an RGB one has its
** negative channels clipped to 0 as POV-Ray does. */
static __attribute__((noinline)) void pixel_colour(struct job *j,
                                                   const double in[NCH],
                                                   bool spectral, float *px)
{
    const struct tracer *t = j->tracer;
    double col[3] = { in[0], in[1], in[2] };
    if (!isfinite(col[0]) || !isfinite(col[1]) || !isfinite(col[2])) {
        col[0] = col[1] = col[2] = 0.0;
        atomic_fetch_add(&j->nan_count, 1);
    }
    if (spectral)
        eye_gamut_map(col);
    for (int k = 0; k < 3; k++) {
        /* fmax(col, 0) without libm's call (col is finite here), -0 kept
        ** as glibc's fmax(-0, 0) keeps it */
        double v = col[k] < 0.0 ? 0.0 : col[k];
        /* from the working gamma space to linear light (§3.9); fmin(v, 1)
        ** without libm's call (v is finite) */
        if (t->gamma_off) {
            px[k] = eye_srgb_decode(j->srgb, v < 1.0 ? v : 1.0);
            continue;
        }
        if (t->working_gamma != 1.0)
            v = pow(v, t->working_gamma);
        px[k] = (float)v;
    }
}

/* Writes pixel (x, y) from the mean of its samples (pixel_colour). Under
** +UA the alpha is 1 - the mean transmit, and the colour stays
** premultiplied by it (a transparent background contributes no colour).
** The usual pixels (finite, RGB, in a linear working space, j->px_linear,
** or a legacy scene's, j->srgb) are pixel_colour()'s work done here
** without its other tests: they cost about half of this function's
** instructions per pixel. */
static void put_pixel(struct job *j, int x, int y, const double in[NCH],
                      bool spectral)
{
    const struct tracer *t = j->tracer;
    /* interrupted: the pixel's rays may have stopped (trace_stopped) */
    if (t->interrupt && *t->interrupt)
        return;
    float *px = &j->out->pixels[((size_t)y * j->out->width + x) * 4];
    /* v * 0 is 0 for finite v, NaN for an infinity or NaN */
    if (j->px_linear && !spectral &&
        in[0] * 0.0 + in[1] * 0.0 + in[2] * 0.0 == 0.0) {
        for (int k = 0; k < 3; k++)
            px[k] = (float)(in[k] < 0.0 ? 0.0 : in[k]);
    } else if (j->srgb && !spectral &&
               in[0] * 0.0 + in[1] * 0.0 + in[2] * 0.0 == 0.0) {
        /* a legacy scene's pixel, likewise */
        for (int k = 0; k < 3; k++) {
            double v = in[k] < 0.0 ? 0.0 : in[k];
            px[k] = eye_srgb_decode(j->srgb, v < 1.0 ? v : 1.0);
        }
    } else {
        pixel_colour(j, in, spectral, px);
    }
    double a = isfinite(in[3]) ? 1.0 - in[3] : 1.0;
    px[3] = j->opts->alpha ? (float)(a < 0.0 ? 0.0 : a > 1.0 ? 1.0 : a) : 1.0f;
}

/* The tile's pixel (x, y) in a buffer with one extra row and column on
** the top and left. */
#define TB(buf, x, y) (buf)[((y) - ty0 + 1) * (tw + 2) + ((x) - tx0 + 1)]

/* d += a - b, count by count: a sample's share of the statistics (the
** counts after it less those before) added where it is used. */
static void counts_add_diff(struct trace_counts *d,
                            const struct trace_counts *a,
                            const struct trace_counts *b)
{
    d->rays += a->rays - b->rays;
    d->camera += a->camera - b->camera;
    d->reflected += a->reflected - b->reflected;
    d->refracted += a->refracted - b->refracted;
    d->transmitted += a->transmitted - b->transmitted;
    d->shadow_tests += a->shadow_tests - b->shadow_tests;
    d->shadow_hits += a->shadow_hits - b->shadow_hits;
}

/* The shared sample of image position (x, y) if it is one of a tile's
** last row or column (struct edge_px), else NULL. */
static struct edge_px *edge_at(const struct job *j, int x, int y)
{
    if (!j->edge_rows)
        return NULL;
    int dx = x - j->x0, dy = y - j->y0;
    if (dx < 0 || dy < 0 || x > j->x1 || y > j->y1)
        return NULL;
    if (dy % TILE == TILE - 1 && y < j->y1)
        return &j->edge_rows[(size_t)(dy / TILE) * (j->x1 - j->x0 + 1) + dx];
    if (dx % TILE == TILE - 1 && x < j->x1)
        return &j->edge_cols[(size_t)(dx / TILE) * (j->y1 - j->y0 + 1) + dy];
    return NULL;
}

/* A border sample of a tile, (x, y) outside it: the neighbour's shared
** sample when ready, else traced here. Either way it is not supersampled
** ('done'). */
static void border_sample(struct job *j, struct trace_ctx *c, int x, int y,
                          struct px *p)
{
    struct edge_px *e = edge_at(j, x, y);
    if (e && atomic_load_explicit(&e->ready, memory_order_acquire)) {
        *p = e->p;
        counts_add_diff(&c->n, &e->n, &(struct trace_counts){ 0 });
    } else {
        p->spectral = trace_sample(j, c, x, y, p->c);
        px_gamma(j, p);
    }
    p->done = true;
}

/* A tile's first sample of (x, y), traced and gamma-adjusted; kept in
** 'e' for the neighbour when (x, y) is in the tile's last row or column
** (edge_at(), else NULL). */
static void first_sample(struct job *j, struct trace_ctx *c, int x, int y,
                         struct px *p, struct edge_px *e)
{
    p->done = false;
    if (!e) {
        p->spectral = trace_sample(j, c, x, y, p->c);
        px_gamma(j, p);
        return;
    }
    struct trace_counts before = c->n;
    p->spectral = trace_sample(j, c, x, y, p->c);
    px_gamma(j, p);
    e->p = *p;
    e->n = (struct trace_counts){ 0 };
    counts_add_diff(&e->n, &c->n, &before);
    atomic_store_explicit(&e->ready, 1, memory_order_release);
}

/* Method 1 over one tile. The buffer 'buf' of (TILE + 2)^2 samples is the
** thread's, reused from tile to tile without clearing (a calloc per tile
** was 1 % of a simple scene's render): every sample is written before it
** is read, 'done' included. */
static void tile_method1(struct job *j, struct trace_ctx *c, struct px *buf,
                         int tx0, int ty0, int tx1, int ty1)
{
    int tw = tx1 - tx0 + 1;
    for (int x = tx0; x <= tx1; x++)
        border_sample(j, c, x, ty0 - 1, &TB(buf, x, ty0 - 1));
    for (int y = ty0; y <= ty1; y++) {
        border_sample(j, c, tx0 - 1, y, &TB(buf, tx0 - 1, y));
        for (int x = tx0; x <= tx1; x++) {
            struct px *cur = &TB(buf, x, y), *left = &TB(buf, x - 1, y),
                      *top = &TB(buf, x, y - 1);
            first_sample(j, c, x, y, cur,
                         x == tx1 || y == ty1 ? edge_at(j, x, y) : NULL);
            bool ldiff = aa_differs(j, left, cur);
            bool tdiff = aa_differs(j, top, cur);
            bool sl = !left->done && ldiff, st = !top->done && tdiff;
            bool sc = ldiff || tdiff;
            if (sl) {
                left->spectral |= supersample(j, c, x - 1, y, left->c);
                px_gamma(j, left);
            }
            if (st) {
                top->spectral |= supersample(j, c, x, y - 1, top->c);
                px_gamma(j, top);
            }
            if (sc) {
                cur->spectral |= supersample(j, c, x, y, cur->c);
                px_gamma(j, cur);
            }
            if (sl) left->done = true;
            if (st) top->done = true;
            if (sc) cur->done = true;
        }
    }
    for (int y = ty0; y <= ty1; y++)
        for (int x = tx0; x <= tx1; x++)
            put_pixel(j, x, y, TB(buf, x, y).c, TB(buf, x, y).spectral);
}

/* Method 2's per-pixel subdivision buffer of (2^R + 1)^2 samples. */
struct subdiv {
    int size;                  /* 2^R + 1 */
    struct px *s;
};

static struct px *sd_at(struct subdiv *b, int x, int y)
{
    return &b->s[y * b->size + x];
}

/* POV-Ray's SubdivideOnePixel. */
static void subdivide(struct job *j, struct trace_ctx *c, double x, double y,
                      double d, int bx, int by, int bstep, struct subdiv *b,
                      double res[NCH], int level, double js)
{
    struct px *c00 = sd_at(b, bx, by), *c02 = sd_at(b, bx, by + bstep),
              *c20 = sd_at(b, bx + bstep, by),
              *c22 = sd_at(b, bx + bstep, by + bstep);
    int h = bstep / 2;
    if (level > 0 && h > 0 &&
        (aa_differs(j, c00, c02) || aa_differs(j, c00, c20) ||
         aa_differs(j, c00, c22) || aa_differs(j, c02, c20) ||
         aa_differs(j, c02, c22) || aa_differs(j, c20, c22))) {
        const struct { int bx, by; double dx, dy; } mids[5] = {
            { bx, by + h, -d, 0 }, { bx + h, by, 0, -d },
            { bx + bstep, by + h, d, 0 }, { bx + h, by + bstep, 0, d },
            { bx + h, by + h, 0, 0 } };
        for (int i = 0; i < 5; i++) {
            struct px *p = sd_at(b, mids[i].bx, mids[i].by);
            if (p->done)
                continue;
            double sx = x + mids[i].dx, sy = y + mids[i].dy;
            if (js > 0.0) {
                double rx, ry;
                jitter2d(sx, sy, &rx, &ry);
                sx += rx * js;
                sy += ry * js;
            }
            p->spectral = trace_sample(j, c, sx, sy, p->c);
            px_gamma(j, p);
            p->done = true;
        }
        double d2 = d * 0.5, r[4][NCH];
        subdivide(j, c, x - d2, y - d2, d2, bx, by, h, b, r[0], level - 1, js);
        subdivide(j, c, x - d2, y + d2, d2, bx, by + h, h, b, r[1], level - 1,
                  js);
        subdivide(j, c, x + d2, y - d2, d2, bx + h, by, h, b, r[2], level - 1,
                  js);
        subdivide(j, c, x + d2, y + d2, d2, bx + h, by + h, h, b, r[3],
                  level - 1, js);
        for (int k = 0; k < NCH; k++)
            res[k] = (r[0][k] + r[1][k] + r[2][k] + r[3][k]) / 4.0;
    } else {
        for (int k = 0; k < NCH; k++)
            res[k] = (c00->c[k] + c02->c[k] + c20->c[k] + c22->c[k]) / 4.0;
    }
}

static void tile_method2(struct job *j, struct trace_ctx *c, int tx0,
                         int ty0, int tx1, int ty1)
{
    int tw = tx1 - tx0 + 1, th = ty1 - ty0 + 1;
    int R = j->aa_depth, sub = 1 << R;
    struct px *corners = iris_calloc((size_t)(tw + 1) * (th + 1),
                                     sizeof *corners);
    struct subdiv b = { sub + 1, iris_calloc((size_t)(sub + 1) * (sub + 1),
                                              sizeof(struct px)) };
    if (!corners || !b.s) {
        iris_free(corners);
        iris_free(b.s);
        atomic_store(&j->alloc_failed, 1);
        return;
    }
    for (int y = ty0; y <= ty1 + 1; y++)
        for (int x = tx0; x <= tx1 + 1; x++) {
            struct px *p = &corners[(y - ty0) * (tw + 1) + (x - tx0)];
            p->spectral = trace_sample(j, c, x - 0.5, y - 0.5, p->c);
            px_gamma(j, p);
        }
    double js = j->jitter / (double)(sub + 1);
    for (int y = ty0; y <= ty1; y++)
        for (int x = tx0; x <= tx1; x++) {
            memset(b.s, 0, (size_t)b.size * b.size * sizeof *b.s);
            *sd_at(&b, 0, 0) = corners[(y - ty0) * (tw + 1) + (x - tx0)];
            *sd_at(&b, 0, sub) = corners[(y - ty0 + 1) * (tw + 1) + (x - tx0)];
            *sd_at(&b, sub, 0) = corners[(y - ty0) * (tw + 1) + (x - tx0 + 1)];
            *sd_at(&b, sub, sub) =
                corners[(y - ty0 + 1) * (tw + 1) + (x - tx0 + 1)];
            sd_at(&b, 0, 0)->done = sd_at(&b, 0, sub)->done =
                sd_at(&b, sub, 0)->done = sd_at(&b, sub, sub)->done = true;
            double col[NCH];
            subdivide(j, c, x, y, 0.5, 0, 0, sub, &b, col, R - 1, js);
            /* the buffer holds the samples this pixel used (the rest
            ** were cleared) */
            bool spectral = false;
            for (int i = 0; i < b.size * b.size; i++)
                spectral |= b.s[i].spectral;
            put_pixel(j, x, y, col, spectral);
        }
    iris_free(corners);
    iris_free(b.s);
}

static void run_tile(void *ctx, int64_t item, int thread)
{
    struct job *j = ctx;
    struct trace_ctx *c = &j->ctx[thread];
    if (atomic_load(&j->interrupted) ||
        (j->opts->interrupt && *j->opts->interrupt)) {
        atomic_store(&j->interrupted, 1);
        return;
    }
    int band = (int)(item % j->bands);
    item /= j->bands;
    int tx = (int)(item % j->tiles_x), ty = (int)(item / j->tiles_x);
    int x0 = j->x0 + tx * TILE, y0 = j->y0 + ty * TILE;
    int x1 = x0 + TILE - 1 < j->x1 ? x0 + TILE - 1 : j->x1;
    int y1 = y0 + TILE - 1 < j->y1 ? y0 + TILE - 1 : j->y1;
    if (j->bands > 1) { /* rows of the tile: the default case below */
        int rows = TILE / j->bands;
        y0 += band * rows;
        y1 = y0 + rows - 1 < y1 ? y0 + rows - 1 : y1;
    }
    gather_tile_begin(c); /* radiosity records stay in their tile */
    switch (j->aa) {
    case IRIS_AA_POV1:
        if (!j->tile_buf[thread])
            j->tile_buf[thread] = iris_malloc((size_t)(TILE + 2) *
                                              (TILE + 2) * sizeof(struct px));
        if (!j->tile_buf[thread]) {
            atomic_store(&j->alloc_failed, 1);
            break;
        }
        tile_method1(j, c, j->tile_buf[thread], x0, y0, x1, y1);
        break;
    case IRIS_AA_POV2:
        tile_method2(j, c, x0, y0, x1, y1);
        break;
    default:
        for (int y = y0; y <= y1; y++)
            for (int x = x0; x <= x1; x++) {
                double col[NCH];
                bool spectral = j->aa == IRIS_AA_STRATIFIED
                                    ? stratified(j, c, x, y, col)
                                    : trace_sample(j, c, x, y, col);
                put_pixel(j, x, y, col, spectral);
            }
        break;
    }
    int done = atomic_fetch_add(&j->tiles_done, 1) + 1;
    if (thread == 0 && j->opts->progress)
        j->opts->progress(j->opts->progress_user, "render",
                          (double)done /
                              (j->tiles_x * j->tiles_y * j->bands));
}

/* The shared last rows and columns of method 1's tiles (struct edge_px):
** one entry per 16 pixels, about 8.5 bytes a pixel, half the image's own
** floats. Past 2^20 entries (about 16 million pixels, 140 MB), or without
** the memory, every tile traces its borders, as POV-Ray does. */
static void edges_alloc(struct job *j)
{
    size_t w = (size_t)(j->x1 - j->x0 + 1), h = (size_t)(j->y1 - j->y0 + 1);
    size_t nr = (size_t)(j->tiles_y - 1) * w, nc = (size_t)(j->tiles_x - 1) * h;
    if (nr + nc == 0 || nr + nc > ((size_t)1 << 20))
        return;
    j->edge_rows = iris_calloc(nr ? nr : 1, sizeof *j->edge_rows);
    j->edge_cols = iris_calloc(nc ? nc : 1, sizeof *j->edge_cols);
    if (!j->edge_rows || !j->edge_cols) {
        iris_free(j->edge_rows);
        iris_free(j->edge_cols);
        j->edge_rows = j->edge_cols = NULL;
        return;
    }
    for (size_t i = 0; i < nr; i++)
        atomic_init(&j->edge_rows[i].ready, 0);
    for (size_t i = 0; i < nc; i++)
        atomic_init(&j->edge_cols[i].ready, 0);
}

static int clampi(int v, int lo, int hi)
{
    return v < lo ? lo : v > hi ? hi : v;
}

/* The objects that may hold a blur ray's origin: the camera location
** moved by up to radius·(0.5 + 2·max_jitter) along xperp and yperp
** (focal_blur_ray(): grid points within 0.5, jitter within 2·max_jitter
** of the radius), padded; trace_containing_from() asks every object for
** an origin outside the box, so the bound need only be usually right. */
static bool blur_origins(const struct tracer *t, const struct focal_blur *fb,
                         const iris_camera *cam, struct containing_list *cl)
{
    double r = fb->radius * (0.5 + 2.0 * fabs(fb->max_jitter));
    vec3 e = v3(fabs(fb->xperp.x) + fabs(fb->yperp.x),
                fabs(fb->xperp.y) + fabs(fb->yperp.y),
                fabs(fb->xperp.z) + fabs(fb->yperp.z));
    double pad = 1e-6 * (r + v3_len(cam->location)) + 1e-9;
    e = v3_add(v3_scale(e, r), v3(pad, pad, pad));
    if (!isfinite(e.x) || !isfinite(e.y) || !isfinite(e.z))
        return false;
    return trace_containing_list(t, v3_sub(cam->location, e),
                                 v3_add(cam->location, e), cl);
}

/* The objects that may hold the origin of an orthographic or mesh
** camera's ray: the box of the orthographic origins at the window's four
** corners (an origin is linear in the image position), or of every mesh
** camera origin (meshcam.h), padded. An origin outside the box is still
** asked of every object. */
static bool eye_origins(const struct tracer *t, const struct job *j,
                        struct containing_list *cl)
{
    const iris_camera *cam = &j->scene->camera;
    vec3 lo = v3(INFINITY, INFINITY, INFINITY), hi = v3_neg(lo);
    if (cam->kind == IRIS_CAM_MESH) {
        if (!meshcam_origin_box(cam, &lo, &hi))
            return false;
    } else {
        for (int c = 0; c < 4; c++) {
            ray r;
            vec3 raw;
            if (!camera_ray_numbered(cam, j->opts->width, j->opts->height,
                                     c & 1 ? j->x1 + 0.5 : j->x0 - 0.5,
                                     c & 2 ? j->y1 + 0.5 : j->y0 - 0.5, 0,
                                     &r, &raw))
                return false;
            lo = v3(fmin(lo.x, r.o.x), fmin(lo.y, r.o.y), fmin(lo.z, r.o.z));
            hi = v3(fmax(hi.x, r.o.x), fmax(hi.y, r.o.y), fmax(hi.z, r.o.z));
        }
    }
    double pad = 1e-6 * (v3_len(lo) + v3_len(hi) + v3_len(v3_sub(hi, lo))) +
                 1e-9;
    if (!isfinite(pad))
        return false;
    return trace_containing_list(t, v3_sub(lo, v3(pad, pad, pad)),
                                 v3_add(hi, v3(pad, pad, pad)), cl);
}

bool eye_window(const iris_render_options *opts, int *x0, int *x1, int *y0,
                int *y1)
{
    int w = opts->width, h = opts->height;
    *x0 = opts->start_col > 0 ? clampi(opts->start_col - 1, 0, w - 1) : 0;
    *x1 = opts->end_col > 0 ? clampi(opts->end_col - 1, 0, w - 1) : w - 1;
    *y0 = opts->start_row > 0 ? clampi(opts->start_row - 1, 0, h - 1) : 0;
    *y1 = opts->end_row > 0 ? clampi(opts->end_row - 1, 0, h - 1) : h - 1;
    return *x1 >= *x0 && *y1 >= *y0;
}

enum iris_status eyepass_run(const struct tracer *tr,
                             const iris_render_options *opts, int threads,
                             iris_image *out, iris_render_stats *stats)
{
    const iris_scene *scene = tr->scene;
    struct job j;
    memset(&j, 0, sizeof j);
    j.scene = scene;
    j.opts = opts;
    j.out = out;
    j.tracer = tr;
    if (!eye_window(opts, &j.x0, &j.x1, &j.y0, &j.y1))
        return IRIS_EINVAL;
    j.tiles_x = (j.x1 - j.x0) / TILE + 1;
    j.tiles_y = (j.y1 - j.y0) / TILE + 1;
    j.aa = opts->aa;
    j.aa_depth = opts->aa_depth < 1 ? 1 : opts->aa_depth > 9 ? 9 : opts->aa_depth;
    j.aa_threshold = opts->aa_threshold;
    /* POV-Ray compares colours encoded by the AA gamma from linear light:
    ** its curve decodes the working gamma first (view.cpp's transcoding
    ** curve, one power law for the two), so under assumed_gamma 2.2 the
    ** exponent is 2.2/2.5, not 1/2.5 (AA decisions, and the pixels
    ** supersampled, as POV-Ray's) */
    double aa_wg = tr->gamma_off ? 1.0 : tr->working_gamma;
    eye_aa_gamma_init(&j.gam, (opts->aa_gamma > 0 ? opts->aa_gamma : 1.0) /
                                  aa_wg);
    /* POV-Ray clips the jitter amount to [0, 1] */
    j.jitter = opts->jitter ? fmin(fmax(opts->jitter_amount, 0.0), 1.0) : 0.0;
    j.ortho = scene->camera.kind == IRIS_CAM_ORTHOGRAPHIC ||
              scene->camera.kind == IRIS_CAM_MESH;
    j.has_pinhole = cam_pinhole_setup(&j.pinhole, &scene->camera,
                                      opts->width, opts->height);
    camera_axes(&scene->camera, &j.axes);
    if (threads < 1)
        threads = 1;
    trace_containing(tr, scene->camera.location, &j.cam_stack);
    /* radiosity{}: a copy of the tracer carries the pass's gather cache
    ** (gather_begin below, once the contexts point at the copy) */
    struct tracer gt = *tr;
    tr = j.tracer = &gt;
    j.blur = focal_blur_wanted(&scene->camera);
    j.one_ray = !j.blur && scene->camera.kind != IRIS_CAM_MESH;
    j.px_linear = !tr->gamma_off && tr->working_gamma == 1.0;
    if (j.has_pinhole && !j.blur) {
        double e = accel_origin_epsilon(j.pinhole.location, tr->q.eps);
        j.pin_tmin = e > 0.0 && e <= tr->q.eps ? e : 0.0;
    }
    if (j.blur && !focal_blur_init(&j.fb, &scene->camera))
        return IRIS_ENOMEM;
    if (j.blur)
        j.has_blur_cl = blur_origins(tr, &j.fb, &scene->camera, &j.blur_cl);
    else if (j.ortho)
        j.has_blur_cl = eye_origins(tr, &j, &j.blur_cl);
    j.ctx = iris_calloc((size_t)threads, sizeof *j.ctx);
    j.tile_buf = iris_calloc((size_t)threads, sizeof *j.tile_buf);
    if (tr->gamma_off) {
        j.srgb = iris_malloc(sizeof *j.srgb);
        if (j.srgb)
            eye_srgb_init(j.srgb);
    }
    if (!j.ctx || !j.tile_buf || (tr->gamma_off && !j.srgb)) {
        iris_free(j.ctx);
        iris_free(j.tile_buf);
        iris_free(j.srgb);
        if (j.blur)
            focal_blur_fini(&j.fb);
        return IRIS_ENOMEM;
    }
    enum iris_status st = IRIS_OK;
    int n_ctx = 0;
    for (; n_ctx < threads; n_ctx++)
        if (!trace_ctx_init(&j.ctx[n_ctx], tr)) {
            trace_ctx_fini(&j.ctx[n_ctx]);
            st = IRIS_ENOMEM;
            break;
        }
    if (st == IRIS_OK)
        st = gather_begin(&gt, opts, threads, &j.cam_stack);
    if (st == IRIS_OK) {
        atomic_init(&j.nan_count, 0);
        atomic_init(&j.tiles_done, 0);
        atomic_init(&j.interrupted, 0);
        atomic_init(&j.alloc_failed, 0);
        /* the tile loop's CPU time: what the render costs whatever the
        ** load (its wall time is also the scheduler's doing) */
        j.bands = j.aa == IRIS_AA_POV1 || j.aa == IRIS_AA_POV2 || gt.gather
                      ? 1
                      : BANDS;
        if (j.aa == IRIS_AA_POV1 && !gt.gather)
            edges_alloc(&j);
        par_for_timed(threads, (int64_t)j.tiles_x * j.tiles_y * j.bands,
                      run_tile, &j,
                      stats ? &stats->time_render_cpu_s : NULL);
        if (atomic_load(&j.alloc_failed))
            st = IRIS_ENOMEM;
        else if (atomic_load(&j.interrupted))
            st = IRIS_EINTR;
        else if (opts->progress)
            opts->progress(opts->progress_user, "render", 1.0);
    }
    if (stats) {
        for (int i = 0; i < n_ctx; i++) {
            const struct trace_counts *n = &j.ctx[i].n;
            stats->rays_traced += j.ctx[i].rays;
            stats->rays += n->rays;
            stats->rays_camera += n->camera;
            stats->rays_reflected += n->reflected;
            stats->rays_refracted += n->refracted;
            stats->rays_transmitted += n->transmitted;
            stats->shadow_tests += n->shadow_tests;
            stats->shadow_hits += n->shadow_hits;
        }
        stats->threads = threads;
        stats->passes = 1;
        stats->nan_pixels += atomic_load(&j.nan_count);
    }
    for (int i = 0; i < n_ctx; i++)
        trace_ctx_fini(&j.ctx[i]);
    iris_free(j.ctx);
    for (int i = 0; i < threads; i++)
        iris_free(j.tile_buf[i]);
    iris_free(j.tile_buf);
    iris_free(j.edge_rows);
    iris_free(j.edge_cols);
    iris_free(j.srgb);
    gather_end(&gt);
    if (j.blur)
        focal_blur_fini(&j.fb);
    if (j.has_blur_cl)
        trace_containing_list_free(&j.blur_cl);
    return st;
}
