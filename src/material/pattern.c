/* SPDX-License-Identifier: MIT */
/*
** pattern.c: pattern functions, warps and wave shaping, as POV-Ray 3.7
** computes them (source/backend/pattern/pattern.cpp, warps.cpp), so that
** a pattern and its colour map land on the same pixels as in POV-Ray.
**
** Kind-specific numbers read from iris_pattern.params[] (the parser's
** layout): spiral arms (params[0]); agate_turb (params[0], 0 = POV-Ray's
** 1.0); quilted control0/control1 (params[0], params[1]; the parser
** sets POV-Ray's 1, 1); crackle form (params[0..2], all 0 = <-1, 1,
** 0>), metric (params[3], 0 = 2), offset (params[4]), solid (params[5]
** != 0);
** mandel/julia interior type and factor, exterior type and factor
** (params[0..3], used when params[5] != 0), exponent (params[6]).
*/
#include "config.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>

#include "iris/fn.h"
#include "material/fractal_pattern.h"
#include "material/listpat.h"
#include "material/mat_internal.h"
#include "material/noise.h"
#include "material/tiling.h"
#include "math/transform.h"

#define PAT_EPSILON 1e-10
#define COORD_LIMIT 1.0e17

/* fmin(fmax(v, -COORD_LIMIT), COORD_LIMIT), NaN giving -COORD_LIMIT as
** there, in comparisons: without -ffinite-math-only GCC calls libm's
** fmin and fmax, six calls per pattern evaluation. Written in the forms
** of SSE2's maxsd and minsd (a NaN first operand gives the second), which
** GCC then emits, two instructions and no branch per coordinate. */
static inline double coord_clamp(double v)
{
    v = v > -COORD_LIMIT ? v : -COORD_LIMIT;
    return v < COORD_LIMIT ? v : COORD_LIMIT;
}

/* fmod(v, 1.0) for v >= 0 or NaN, without the library call: for v >= 1
** the subtraction is exact (floor(v) >= v / 2, Sterbenz), as fmod is, so
** the bits agree; below 1 both give v. +inf and NaN give NaN either way
** (the callers' isfinite test then takes 0). */
static inline double mod1_nonneg(double v)
{
    return v < 1.0 ? v : v - floor(v);
}

/* POV-Ray's PatternRands (noise.c builds the table with the noise's). */
double pat_rand(unsigned long i)
{
    return noise_pattern_rand(i);
}

/* ------------------------------------------------------------------ */
/* Warps                                                                */
/* ------------------------------------------------------------------ */

/* The parser fills in the defaults (octaves 6, omega 0.5, lambda 2), so the
** values are taken as given: POV-Ray 3.7 uses `omega 0` and `lambda 0`
** literally (omega 0 keeps only the first octave, lambda 0 samples every
** later octave at the origin) and clamps octaves to 1..10. */
static struct noise_turb turb_params(const iris_warp *w)
{
    struct noise_turb t;
    t.octaves = w->octaves < 1 ? 1 : w->octaves > 10 ? 10 : w->octaves;
    t.omega = w->omega;
    t.lambda = w->lambda;
    return t;
}

/* The classic turbulence (see material.h): the last warp when it is a
** turbulence warp, as the parser keeps it. */
static const iris_warp *classic_turb(const iris_pattern *pat)
{
    if (pat->n_warps > 0 &&
        pat->warps[pat->n_warps - 1].kind == IRIS_WARP_TURBULENCE)
        return &pat->warps[pat->n_warps - 1];
    return NULL;
}

static bool uses_own_turb(enum iris_pattern_kind k)
{
    return k == IRIS_PAT_MARBLE || k == IRIS_PAT_WOOD;
}

static double repeat_axis(vec3 v, int axis)
{
    return v3_comp(v, axis);
}

static vec3 set_axis(vec3 v, int axis, double x)
{
    if (axis == 0) v.x = x;
    else if (axis == 1) v.y = x;
    else v.z = x;
    return v;
}

static vec3 warp_repeat(const iris_warp *w, vec3 p)
{
    int axis = w->repeat.x != 0 ? 0 : w->repeat.y != 0 ? 1 : 2;
    double width = repeat_axis(w->repeat, axis);
    if (width == 0)
        return p;
    double blk = floor(repeat_axis(p, axis) / width);
    vec3 r = set_axis(p, axis, repeat_axis(p, axis) - blk * width);
    if (((long long)blk) & 1) {
        /* flip: components of 'flip' that are 1 mirror that axis */
        vec3 f = v3(w->flip.x != 0 ? -1 : 1, w->flip.y != 0 ? -1 : 1,
                    w->flip.z != 0 ? -1 : 1);
        r = v3_mul(r, f);
        if (repeat_axis(f, axis) < 0)
            r = set_axis(r, axis, width + repeat_axis(r, axis));
    }
    return v3_madd(r, w->offset, blk);
}

/*
** black_hole, with POV-Ray's repeat (a copy of the hole in every block of
** the repeat vector's size; a component below 1e-10 does not repeat) and
** its turbulence (each copy's centre moved by up to that vector, by
** PatternRands of the block's Hash3d, as POV-Ray's WarpRands).
*/
static vec3 warp_black_hole(const iris_warp *w, vec3 p)
{
    vec3 c = w->centre;
    vec3 r = w->repeat;
    if (r.x != 0 || r.y != 0 || r.z != 0) {
        int bx = r.x >= 1e-10 ? (int)floor(p.x / r.x) : 0;
        int by = r.y >= 1e-10 ? (int)floor(p.y / r.y) : 0;
        int bz = r.z >= 1e-10 ? (int)floor(p.z / r.z) : 0;
        vec3 u = w->turbulence;
        if (u.x != 0 || u.y != 0 || u.z != 0) {
            vec3 k = noise_pattern_rand3(
                (unsigned long)noise_hash3d(bx, by, bz));
            c.x += k.x * u.x;
            c.y += k.y * u.y;
            c.z += k.z * u.z;
        }
        c = v3_add(c, v3(r.x * bx, r.y * by, r.z * bz));
    }
    vec3 delta = v3_sub(p, c);
    double len = v3_len(delta);
    if (w->radius <= 0 || len >= w->radius)
        return p;
    len = (w->radius - len) / w->radius;
    double power = w->falloff != 0 ? w->falloff : 2.0;
    double strength = pow(len, power) * (w->strength != 0 ? w->strength : 1);
    if (strength > 1.0)
        strength = 1.0;
    return v3_madd(p, delta, w->inverse ? -strength : strength);
}

/* The angle of (x, z) around +y from +x, in [0, 2 pi), as POV-Ray's
** mapping warps measure it. */
static double warp_theta(double x, double z, double len)
{
    if (z == 0.0)
        return x > 0 ? 0.0 : M_PI;
    double theta = acos(fmin(fmax(x / len, -1.0), 1.0));
    return z < 0.0 ? 2.0 * M_PI - theta : theta;
}

/*
** The mapping warps (POV-Ray's warp_planar, warp_spherical,
** warp_cylindrical, warp_toroidal): a point becomes (u, v, distance) of
** the surface's parameterisation, u and v in [0, 1) scaled by
** distance^dist_exp, laid out in the plane the orientation vector faces
** (z by default). A point on the axis, where the angle is undefined,
** stays where it is, as in POV-Ray.
*/
static vec3 warp_mapping(const iris_warp *w, vec3 q)
{
    double x = q.x, y = q.y, z = q.z;
    double de = w->dist_exp;
    switch (w->kind) {
    case IRIS_WARP_PLANAR:
        z = w->offset.x;
        break;
    case IRIS_WARP_SPHERICAL: {
        double dist = v3_len(q);
        if (dist == 0.0)
            return q;
        double nx = x / dist, ny = y / dist, nz = z / dist;
        double phi = 0.5 + asin(fmin(fmax(ny, -1.0), 1.0)) / M_PI;
        double len = sqrt(nx * nx + nz * nz);
        double theta = len == 0.0 ? 0.0
                                  : warp_theta(nx, nz, len) / (2.0 * M_PI);
        double k = de == 1.0 ? dist : de != 0.0 ? pow(dist, de) : 1.0;
        x = theta * k;
        y = phi * k;
        z = dist;
        break;
    }
    case IRIS_WARP_CYLINDRICAL: {
        double len = sqrt(x * x + z * z);
        if (len == 0.0)
            return q;
        double theta = warp_theta(x, z, len) / (2.0 * M_PI);
        double k = de == 1.0 ? len : de != 0.0 ? pow(len, de) : 1.0;
        x = theta * k;
        z = len;
        break;
    }
    default: { /* toroidal */
        double r0 = w->major_radius != 0 ? w->major_radius : 1.0;
        double len = sqrt(x * x + z * z);
        if (len == 0.0)
            return q;
        double theta = warp_theta(x, z, len) / (2.0 * M_PI);
        double dx = len - r0;
        double tl = sqrt(dx * dx + y * y);
        double phi = tl == 0.0 ? 0.0
                               : acos(fmin(fmax(-dx / tl, -1.0), 1.0));
        if (y > 0.0)
            phi = 2.0 * M_PI - phi;
        phi /= 2.0 * M_PI;
        double k = de == 1.0 ? tl : de != 0.0 ? pow(tl, de) : 1.0;
        x = theta * k;
        y = phi * k;
        z = tl;
        break;
    }
    }
    vec3 o = w->orientation;
    double ol = v3_len(o);
    if (ol > 0.0)
        o = v3_scale(o, 1.0 / ol);
    else
        o = v3(0, 0, 1);
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0)
        return v3(x, y, z);
    /* POV-Ray's blend of the three axis-aligned layouts by the
    ** orientation's components. */
    return v3(o.x * z + o.y * x + o.z * x,
              o.x * y - o.y * z + o.z * y,
              -o.x * x + o.y * y + o.z * z);
}

static vec3 apply_warp(const iris_warp *w, vec3 q)
{
    switch (w->kind) {
    case IRIS_WARP_TURBULENCE: {
        struct noise_turb t = turb_params(w);
        vec3 d = noise_dturbulence(q, &t);
        return v3_add(q, v3_mul(d, w->turbulence));
    }
    case IRIS_WARP_REPEAT:
        return warp_repeat(w, q);
    case IRIS_WARP_BLACK_HOLE:
        return warp_black_hole(w, q);
    case IRIS_WARP_TRANSFORM:
        return xf_inv_point(&w->transform, q);
    case IRIS_WARP_PLANAR:
    case IRIS_WARP_SPHERICAL:
    case IRIS_WARP_CYLINDRICAL:
    case IRIS_WARP_TOROIDAL:
        return warp_mapping(w, q);
    default:
        return q;
    }
}

/* The warps of pat_space(), last written first, the classic turbulence
** last of all. Out of line: most patterns have none, and pat_space()
** stays small enough to need no stack frame then. */
static __attribute__((noinline)) vec3 apply_warps(const iris_pattern *pat,
                                                  vec3 q)
{
    const iris_warp *classic = classic_turb(pat);
    int n = classic ? pat->n_warps - 1 : pat->n_warps;
    for (int i = n - 1; i >= 0; i--)
        q = apply_warp(&pat->warps[i], q);
    if (classic && !uses_own_turb(pat->kind))
        q = apply_warp(classic, q);
    return q;
}

/* xf_inv_point() (math/transform.c), inline here: most patterns are
** scaled or moved, and take it once per evaluation. The same operations
** in the same order, so the same bits. */
static inline vec3 pattern_point(const iris_transform *t, vec3 p)
{
    const double (*m)[4] = t->inv;
    return v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
              m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
              m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

vec3 pat_space(const struct mat_ctx *ctx, const iris_pattern *pat, vec3 p)
{
    (void)ctx;
    vec3 q = pat->has_transform ? pattern_point(&pat->transform, p) : p;
    if (pat->n_warps > 0)
        q = apply_warps(pat, q);
    q.x = coord_clamp(q.x);
    q.y = coord_clamp(q.y);
    q.z = coord_clamp(q.z);
    return q;
}

vec3 pat_warp_world(const struct mat_ctx *ctx, const iris_pattern *pat,
                    vec3 p)
{
    if (pat->n_warps == 0)
        return p;
    const iris_warp *classic = classic_turb(pat);
    if (pat->n_warps == 1 && classic && uses_own_turb(pat->kind))
        return p;
    vec3 q = pat_space(ctx, pat, p);
    /* back through every transform (the map entries carry them all),
    ** also those written before a warp, kept as TRANSFORM entries */
    for (int i = 0; i < pat->n_warps; i++)
        if (pat->warps[i].kind == IRIS_WARP_TRANSFORM)
            q = xf_point(&pat->warps[i].transform, q);
    return pat->has_transform ? xf_point(&pat->transform, q) : q;
}

/* ------------------------------------------------------------------ */
/* Pattern functions                                                    */
/* ------------------------------------------------------------------ */

int pat_noise_generator(const struct mat_ctx *ctx, const iris_pattern *pat)
{
    int g = pat->noise_generator;
    if (g < 1 || g > 3)
        g = ctx ? ctx->noise_generator : 2;
    return g;
}

bool pat_is_list(enum iris_pattern_kind kind)
{
    return kind == IRIS_PAT_CHECKER || kind == IRIS_PAT_HEXAGON ||
           kind == IRIS_PAT_BRICK || kind == IRIS_PAT_OBJECT ||
           kind == IRIS_PAT_SQUARE || kind == IRIS_PAT_TRIANGULAR ||
           kind == IRIS_PAT_CUBIC || kind == IRIS_PAT_IMAGE_MAP;
}

/* POV-Ray's density clipping for boxed, spherical, cylindrical, planar. */
static double clip_density(double r)
{
    if (r < 0.0)
        return 1.0;
    if (r > 1.0)
        return 0.0;
    return 1.0 - r;
}

/* floor(v) for checker(): the same value (but +0 for -0, which the
** parity below does not see) in half the instructions of GCC's inline
** floor() for plain SSE2. For |v| < 2^62 the truncation to int64_t is
** exact, as is its conversion back (|i| < 2^53, or v is already an
** integer); outside that, and for NaN, floor() itself. */
static inline double checker_floor(double v)
{
    if (!(fabs(v) < 0x1p62))
        return floor(v);
    double f = (double)(int64_t)v;
    return f > v ? f - 1.0 : f;
}

static double checker(vec3 p)
{
    double s = checker_floor(p.x + PAT_EPSILON) +
               checker_floor(p.y + PAT_EPSILON) +
               checker_floor(p.z + PAT_EPSILON);
    long long v = (long long)s;
    return (v & 1) ? 1.0 : 0.0;
}

/* Fractional part in [0, 1) of 'v' after POV-Ray's truncation. */
static double frac_trunc(double v)
{
    double f = v - (double)(long long)v;
    return f < 0.0 ? f + 1.0 : f;
}

static __attribute__((noinline)) double brick(const iris_pattern *pat,
                                              vec3 p)
{
    double mortar = pat->mortar;
    vec3 size = pat->brick_size;
    if (size.x == 0 && size.y == 0 && size.z == 0)
        size = v3(8, 3, 4.5);
    if (size.x == 0 || size.y == 0 || size.z == 0)
        return 1.0;
    double fudge = PAT_EPSILON + mortar;
    double x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
    double mw = mortar / size.x, mh = mortar / size.y, md = mortar / size.z;
    if (frac_trunc(y / size.y) <= mh)
        return 0.0;
    double by = frac_trunc(y / size.y * 0.5);
    if (frac_trunc(x / size.x) <= mw && by <= 0.5)
        return 0.0;
    if (frac_trunc(x / size.x + 0.5) <= mw && by > 0.5)
        return 0.0;
    if (frac_trunc(z / size.z) <= md && by > 0.5)
        return 0.0;
    if (frac_trunc(z / size.z + 0.5) <= md && by <= 0.5)
        return 0.0;
    return 1.0;
}

/* The hexagon tiling on a grid of half-triangles (xfactor 0.5, zfactor
** sqrt(3)/2), three colours 0, 1, 2. */
static __attribute__((noinline)) double hexagon(vec3 p)
{
    static const int straight_a[6] = { 0, 1, 1, 2, 2, 0 };  /* xm 0, 5 */
    static const int straight_b[6] = { 2, 2, 0, 0, 1, 1 };  /* xm 2, 3 */
    static const int below[6] = { 0, 2, 1, 0, 2, 1 };       /* zl/xl < 1 */
    static const int above[6] = { 2, 1, 0, 2, 1, 0 };
    double x = fabs(p.x);
    double z = p.z < 0.0 ? 5.196152424 - fabs(p.z) : p.z;
    double xs = x / 0.5, zs = z / 0.866025404;
    xs -= floor(xs / 6.0) * 6.0;
    zs -= floor(zs / 6.0) * 6.0;
    int xm = (int)floor(xs) % 6, zm = (int)floor(zs) % 6;
    if (xm < 0) xm += 6;
    if (zm < 0) zm += 6;
    switch (xm) {
    case 0: case 5:
        return straight_a[zm];
    case 2: case 3:
        return straight_b[zm];
    default: {
        double xl = xs - xm, zl = zs - zm;
        if ((xm + zm) % 2 == 1)
            xl = 1.0 - xl;
        if (xl == 0.0)
            xl = 0.0001;
        return (zl / xl) < 1.0 ? below[zm] : above[zm];
    }
    }
}

static double granite(vec3 p, int gen)
{
    double sum = 0.0, freq = 1.0;
    vec3 t1 = v3_scale(p, 4.0);
    for (int i = 0; i < 6; i++, freq *= 2.0) {
        double n = noise_value(v3_scale(t1, freq), gen), temp;
        if (gen == 1) {
            temp = fabs(0.5 - n);
        } else {
            temp = fabs(1.0 - 2.0 * n);
            if (temp > 0.5)
                temp = 0.5;
        }
        sum += temp / freq;
    }
    return sum;
}

static double wrinkles(vec3 p, int gen)
{
    double lambda = 2.0, omega = 0.5, value;
    if (gen > 1)
        value = fmin(fmax(noise_value(p, gen) * 2.0 - 0.5, 0.0), 1.0);
    else
        value = noise_value(p, gen);
    for (int i = 1; i < 10; i++) {
        double n = noise_value(v3_scale(p, lambda), gen);
        if (gen > 1)
            value += omega * fmin(fmax(n * 2.0 - 0.5, 0.0), 1.0);
        else
            value += omega * n;
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

static double turb_value(const iris_pattern *pat, vec3 p, int gen,
                         double scale_x)
{
    const iris_warp *w = classic_turb(pat);
    if (!w)
        return 0.0;
    struct noise_turb t = turb_params(w);
    return scale_x * noise_turbulence(p, &t, gen);
}

static double agate(const iris_pattern *pat, vec3 p, int gen)
{
    double scale = pat->params[0] != 0 ? pat->params[0] : 1.0;
    struct noise_turb t = { 6, 0.5, 2.0 };
    const iris_warp *w = classic_turb(pat);
    if (w)
        t = turb_params(w);
    double turb = scale * noise_turbulence(p, &t, gen);
    double n = 0.5 * (noise_cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
    if (n < 0.0)
        return 0.0;
    return pow(fmin(1.0, n), 0.77);
}

static double wood(const iris_pattern *pat, vec3 p)
{
    double px = 0.0, py = 0.0;
    const iris_warp *w = classic_turb(pat);
    if (w) {
        struct noise_turb t = turb_params(w);
        vec3 d = noise_dturbulence(p, &t);
        px = noise_cycloidal((p.x + d.x) * w->turbulence.x);
        py = noise_cycloidal((p.y + d.y) * w->turbulence.y);
    }
    px += p.x;
    py += p.y;
    return sqrt(px * px + py * py);
}

static double spiral_phase(vec3 p, double *rad)
{
    *rad = sqrt(p.x * p.x + p.y * p.y);
    if (*rad == 0.0)
        return 0.0;
    if (p.x < 0.0)
        return 3.0 * M_PI_2 - asin(p.y / *rad);
    return M_PI_2 + asin(p.y / *rad);
}

static double quilt_cubic(double t, double p1, double p2)
{
    double it = 1 - t;
    double v = t * t * t + 3.0 * t * it * it * p1 + 3.0 * t * t * it * p2;
    return v * 1.154700538; /* POV-Ray: 1/sqrt(3/4) */
}

vec3 pat_quilt_vector(const iris_pattern *pat, vec3 p)
{
    /* the parser sets POV-Ray's defaults, 1 and 1; 0 and 0 are a legal
    ** choice (a t³ profile), not "unset" */
    double c0 = pat->params[0], c1 = pat->params[1];
    vec3 v = v3(p.x - floor(p.x) - 0.5, p.y - floor(p.y) - 0.5,
                p.z - floor(p.z) - 0.5);
    return v3_scale(v, quilt_cubic(v3_len(v), c0, c1));
}

static double quilted(const iris_pattern *pat, vec3 p)
{
    vec3 v = pat_quilt_vector(pat, p);
    return (fabs(v.x) + fabs(v.y) + fabs(v.z)) / 3.0;
}

/* POV-Ray's wrap of a slope value into [0, 1): 1 itself, a very common
** value, stays at the top of the map (1 - EPSILON) instead of wrapping. */
static double slope_wrap(double v)
{
    if (v >= 1.0 && v - 1.0 < 1e-10)
        return v - 1e-10;
    return v < 0.0 ? 1.0 + fmod(v, 1.0) : fmod(v, 1.0);
}

/* A lo, hi range as POV-Ray keeps it: hi == lo != 0 means no range. */
static double slope_rescale(double v, double lo, double hi)
{
    if (hi == lo)
        return v;
    return (v - lo) / (hi - lo);
}

/*
** slope (layout in the parser: params[0..1] the slope range, [2..3] the
** altitude range, [4..6] the altitude vector, [7] point_at): the angle
** of the surface normal (the one facing the ray) to the slope vector,
** asin(n . v) mapped from [-90, 90] degrees to [0, 1], mixed with the
** point's height along the altitude vector in proportion to the two
** vectors' lengths. POV-Ray 3.7's slope_pattern.
*/
static double slope(const iris_pattern *pat, vec3 p,
                    const struct mat_point *pt)
{
    if (!pt)
        return 0.0;
    const double *k = pat->params;
    vec3 alt = v3(k[4], k[5], k[6]);
    double slen = 1.0, alen = 0.0, c;
    if (k[7] != 0) {
        c = v3_dot(pt->n, v3_norm(v3_sub(pat->vector, pt->p)));
    } else {
        slen = v3_len(pat->vector);
        alen = v3_len(alt);
        if (slen + alen == 0)
            return 0.0;
        c = slen > 0 ? v3_dot(pt->n, v3_scale(pat->vector, 1 / slen)) : 0;
        slen /= slen + alen;
        alen = 1.0 - slen;
    }
    c = fmax(-1.0, fmin(1.0, c));
    double v1 = slope_rescale((asin(c) / M_PI * 2 + 1.0) * 0.5, k[0], k[1]);
    if (alen == 0)
        return slope_wrap(v1);
    double v2 = slope_rescale(v3_dot(p, v3_scale(alt, 1 / v3_len(alt))),
                              k[2], k[3]);
    return slope_wrap(slen * v1 + alen * v2);
}

static double waves_sum(const struct mat_ctx *ctx, const iris_pattern *pat,
                        vec3 p, bool ripples)
{
    int n = ctx && ctx->n_waves > 0 ? ctx->n_waves : 10;
    double sum = 0.0;
    for (int i = 0; i < n; i++) {
        vec3 src;
        double f;
        noise_wave_source(i, &src, &f);
        double len = v3_len(v3_sub(p, src));
        if (len == 0.0)
            len = 1.0;
        if (ripples) {
            sum += noise_cycloidal(len * pat->frequency + pat->phase);
        } else {
            sum += noise_cycloidal(len * pat->frequency * f + pat->phase) / f;
        }
    }
    if (ripples)
        return 0.5 * (1.0 + sum / n);
    return 0.2 * (2.5 + sum / n);
}

/* Metric distance of crackle. */
static double crackle_dist(vec3 d, double metric)
{
    if (metric == 2)
        return d.x * d.x + d.y * d.y + d.z * d.z;
    if (metric == 1)
        return fabs(d.x) + fabs(d.y) + fabs(d.z);
    return pow(fabs(d.x), metric) + pow(fabs(d.y), metric) +
           pow(fabs(d.z), metric);
}

/* The distance along one axis from 'x' to the unit interval [c, c + 1]. */
static double box_gap(double x, int c)
{
    if (x < c)
        return c - x;
    if (x > c + 1.0)
        return x - (c + 1.0);
    return 0.0;
}

/* The random point POV-Ray picks in the unit cube at (x, y, z). */
static vec3 cube_point(int x, int y, int z)
{
    vec3 r = noise_pattern_rand3(
        (unsigned long)noise_hash3d(x & 0xFFF, y & 0xFFF, z & 0xFFF));
    return v3(x + r.x, y + r.y, z + r.z);
}

/*
** The cube points around the last cell a thread asked about. Neighbouring
** samples mostly fall in the same unit cell, and a point costs a hash and
** three table reads; POV-Ray keeps a per-thread cache for the same
** reason. The points are a pure function of the cube, so the pattern's
** values do not change.
*/
struct crackle_cache {
    bool valid;
    int fx, fy, fz;
    uint64_t have[2];          /* bit i: pts[i] is filled */
    vec3 pts[125];             /* index (dx+2)*25 + (dy+2)*5 + (dz+2) */
};
static _Thread_local struct crackle_cache crackle_tls;

static vec3 cached_cube_point(struct crackle_cache *cc, int dx, int dy,
                              int dz)
{
    int i = (dx + 2) * 25 + (dy + 2) * 5 + (dz + 2);
    uint64_t bit = (uint64_t)1 << (i & 63);
    if (!(cc->have[i >> 6] & bit)) {
        cc->pts[i] = cube_point(cc->fx + dx, cc->fy + dy, cc->fz + dz);
        cc->have[i >> 6] |= bit;
    }
    return cc->pts[i];
}

/* Cube point 'c' among the three nearest so far (m1 <= m2 <= m3; 'best'
** the nearest point). */
static inline void crackle_keep(vec3 c, vec3 p, double metric, double *m1,
                                double *m2, double *m3, vec3 *best)
{
    double s = crackle_dist(v3_sub(c, p), metric);
    if (s < *m1) {
        *m3 = *m2; *m2 = *m1; *m1 = s; *best = c;
    } else if (s < *m2) {
        *m3 = *m2; *m2 = s;
    } else if (s < *m3) {
        *m3 = s;
    }
}

static double crackle(const struct mat_ctx *ctx, const iris_pattern *pat,
                      vec3 p)
{
    double metric = pat->params[3] != 0 ? pat->params[3] : 2.0;
    double offset = pat->params[4];
    bool solid = pat->params[5] != 0;
    vec3 form = v3(pat->params[0], pat->params[1], pat->params[2]);
    if (form.x == 0 && form.y == 0 && form.z == 0)
        form = v3(-1, 1, 0);
    int fx = (int)floor(p.x - PAT_EPSILON), fy = (int)floor(p.y - PAT_EPSILON),
        fz = (int)floor(p.z - PAT_EPSILON);
    double m1 = INFINITY, m2 = INFINITY, m3 = INFINITY;
    vec3 best = p;
    struct crackle_cache *cc = &crackle_tls;
    if (!cc->valid || cc->fx != fx || cc->fy != fy || cc->fz != fz) {
        cc->valid = true;
        cc->fx = fx;
        cc->fy = fy;
        cc->fz = fz;
        cc->have[0] = cc->have[1] = 0;
    }
    /*
    ** A 5x5x5 neighbourhood holds every candidate POV-Ray's 81 cubes do.
    ** The inner 3x3x3 cubes go first; an outer cube is skipped when even
    ** its nearest corner is no closer than the third distance found, which
    ** leaves the three smallest distances exactly as the full search has
    ** them.
    */
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dz = -1; dz <= 1; dz++)
                crackle_keep(cached_cube_point(cc, dx, dy, dz), p, metric,
                             &m1, &m2, &m3, &best);
    /*
    ** The outer cubes, in the same order. A cube's gap per axis depends on
    ** that axis alone (five values each). Every outer cube lies two cells
    ** away along some axis, so its gap distance is at least that axis'
    ** term alone (a sum of non-negative terms rounds to no less than any
    ** of them): when the least such term is no closer than the third
    ** distance, which the outer cubes can only lower, each of them fails
    ** the test above and the whole shell is skipped (the usual case: the
    ** three nearest of the 27 inner points lie within one cell).
    */
    double gap[3][5];
    for (int k = 0; k < 5; k++) {
        gap[0][k] = box_gap(p.x, fx + k - 2);
        gap[1][k] = box_gap(p.y, fy + k - 2);
        gap[2][k] = box_gap(p.z, fz + k - 2);
    }
    bool shell = true;
    if (metric > 0) {
        double lb = INFINITY;
        for (int k = 0; k < 5; k += 4) {
            double gx = crackle_dist(v3(gap[0][k], 0, 0), metric),
                   gy = crackle_dist(v3(0, gap[1][k], 0), metric),
                   gz = crackle_dist(v3(0, 0, gap[2][k]), metric);
            lb = fmin(lb, fmin(gx, fmin(gy, gz)));
        }
        shell = !(lb >= m3);
    }
    for (int dx = -2; dx <= 2 && shell; dx++)
        for (int dy = -2; dy <= 2; dy++)
            for (int dz = -2; dz <= 2; dz++) {
                if (abs(dx) <= 1 && abs(dy) <= 1 && abs(dz) <= 1)
                    continue;
                if (metric > 0 &&
                    crackle_dist(v3(gap[0][dx + 2], gap[1][dy + 2],
                                    gap[2][dz + 2]),
                                 metric) >= m3)
                    continue;
                crackle_keep(cached_cube_point(cc, dx, dy, dz), p, metric,
                             &m1, &m2, &m3, &best);
            }
    if (offset != 0) {
        double o = metric == 2 ? offset * offset
                 : metric == 1 ? offset : pow(offset, metric);
        m1 += o; m2 += o; m3 += o;
    }
    double tf;
    if (solid) {
        tf = noise_value(best, pat_noise_generator(ctx, pat));
    } else if (metric == 2) {
        tf = form.x * sqrt(m1) + form.y * sqrt(m2) + form.z * sqrt(m3);
    } else if (metric == 1) {
        tf = form.x * m1 + form.y * m2 + form.z * m3;
    } else {
        tf = form.x * pow(m1, 1.0 / metric) + form.y * pow(m2, 1.0 / metric) +
             form.z * pow(m3, 1.0 / metric);
    }
    return fmax(fmin(tf, 1.0), 0.0);
}

/* POV-Ray's fractal colouring (FractalPattern::ExteriorColour and
** InteriorColour), for a point that escaped at step k with z = (a, b),
** or never did, z = (a, b) then and mind2 the least |z|^2 on the way. */
static double fractal_exterior(int type, double f, int k, int it_max,
                               double a, double b)
{
    switch (type) {
    case 0: return f;
    case 1: return (double)k / it_max;
    case 2: return a * f;
    case 3: return b * f;
    case 4: return a * a * f;
    case 5: return b * b * f;
    case 6: return sqrt(a * a + b * b) * f;
    case 7: return f >= 1 ? (double)(k % (unsigned)f) / f : 0.0;
    case 8: return f > 0 ? (double)(k % (unsigned)(1 + f)) / f : 0.0;
    default: return 0.0;
    }
}

static double fractal_interior(int type, double f, double a, double b,
                               double mind2)
{
    switch (type) {
    case 0: return f;
    case 1: return sqrt(mind2) * f;
    case 2: return a * f;
    case 3: return b * f;
    case 4: return a * a * f;
    case 5: return b * b * f;
    case 6: return a * a + b * b * f; /* sic: POV-Ray's precedence */
    default: return 0.0;
    }
}

/*
** The mandel and julia patterns (POV-Ray's mandel_pattern, julia_pattern
** and their higher-exponent forms): z -> z^n + c from z = (x, y), c = the
** point (mandel) or the pattern's constant (julia), for 'iterations'
** steps. The colouring types are the parser's params[0..3] (interior
** type and factor, exterior type and factor) when params[5] != 0; else
** POV-Ray's defaults: a point that escapes |z| > 2 at step k gets
** k / iterations (exterior type 1), one that never does gets 1 (interior
** type 0).
*/
static double fractal(const iris_pattern *pat, vec3 p, bool julia)
{
    bool given = pat->params[5] != 0;
    int itype = given ? (int)pat->params[0] : 0;
    int etype = given ? (int)pat->params[2] : 1;
    double ifac = given ? pat->params[1] : 1.0;
    double efac = given ? pat->params[3] : 1.0;
    int it_max = pat->iterations > 0 ? pat->iterations : 1;
    /* the loop stops at the cap, the colouring keeps it_max: a point
    ** escaping before the cap gets the colour an uncapped run gives */
    int it_run = it_max < IRIS_PATTERN_MAX_ITERATIONS
                     ? it_max : IRIS_PATTERN_MAX_ITERATIONS;
    if (pat->params[7] == 1 || pat->params[7] == 2) {
        /* magnet 1/2 (fractal_pattern.c) */
        int k;
        double ma, mb, m2;
        if (pat_magnet((int)pat->params[7], julia, p.x, p.y,
                       pat->complex_c.u, pat->complex_c.v, it_run, &k, &ma,
                       &mb, &m2))
            return fractal_exterior(etype, efac, k, it_max, ma, mb);
        return fractal_interior(itype, ifac, ma, mb, m2);
    }
    int n = (int)lround(pat->params[6]);
    if (n < 2 || n > 33)
        n = 2;
    double a = p.x, b = p.y;
    double ca = julia ? pat->complex_c.u : p.x;
    double cb = julia ? pat->complex_c.v : p.y;
    double mind2 = a * a + b * b;
    for (int k = 0; k < it_run; k++) {
        double ra = a, rb = b;
        for (int e = 1; e < n; e++) {
            double t = ra * a - rb * b;
            rb = ra * b + rb * a;
            ra = t;
        }
        a = ra + ca;
        b = rb + cb;
        double d2 = a * a + b * b;
        if (d2 < mind2)
            mind2 = d2;
        if (d2 > 4.0)
            return fractal_exterior(etype, efac, k, it_max, a, b);
    }
    return fractal_interior(itype, ifac, a, b, mind2);
}

static double function_value(const iris_pattern *pat, vec3 p)
{
    if (!pat->fn)
        return 0.0;
    double args[3] = { p.x, p.y, p.z };
    double v = iris_fn_eval(pat->fn, args, 3);
    if (!isfinite(v))
        return 0.0;
    return v > 1.0 ? mod1_nonneg(v) : v;
}

/* raw_value() of the kinds not handled inline there. */
static __attribute__((noinline)) double
raw_value_other(const struct mat_ctx *ctx, const iris_pattern *pat, vec3 p,
                const struct mat_point *pt)
{
    int gen = pat_noise_generator(ctx, pat);
    switch (pat->kind) {
    case IRIS_PAT_AGATE: return agate(pat, p, gen);
    case IRIS_PAT_BOZO: case IRIS_PAT_SPOTTED: case IRIS_PAT_BUMPS:
        return noise_value(p, gen);
    case IRIS_PAT_CELLS:
        return fmin(pat_rand((unsigned long)noise_hash3d(
                        (int)floor(p.x + PAT_EPSILON),
                        (int)floor(p.y + PAT_EPSILON),
                        (int)floor(p.z + PAT_EPSILON))), 1.0);
    case IRIS_PAT_CRACKLE: return crackle(ctx, pat, p);
    case IRIS_PAT_GRANITE: return granite(p, gen);
    case IRIS_PAT_LEOPARD: {
        double s = (sin(p.x) + sin(p.y) + sin(p.z)) / 3.0;
        return s * s;
    }
    case IRIS_PAT_MARBLE:
        return p.x + turb_value(pat, p, gen,
                                classic_turb(pat) ? classic_turb(pat)->turbulence.x : 0);
    case IRIS_PAT_RADIAL:
        if (fabs(p.x) < 0.001 && fabs(p.z) < 0.001)
            return 0.25;
        return 0.25 + (atan2(p.x, p.z) + M_PI) / (2 * M_PI);
    case IRIS_PAT_SPIRAL1: case IRIS_PAT_SPIRAL2: {
        double rad, phi = spiral_phase(p, &rad);
        const iris_warp *w = classic_turb(pat);
        double turb = w ? turb_value(pat, p, gen, w->turbulence.x) : 0.0;
        double v = p.z + rad + pat->params[0] * phi / (2 * M_PI) + turb;
        if (pat->kind == IRIS_PAT_SPIRAL1)
            return v;
        return noise_triangle_wave(rad) + noise_triangle_wave(v);
    }
    case IRIS_PAT_WOOD: return wood(pat, p);
    case IRIS_PAT_MANDEL: return fractal(pat, p, false);
    case IRIS_PAT_JULIA: return fractal(pat, p, true);
    case IRIS_PAT_WAVES: return waves_sum(ctx, pat, p, false);
    case IRIS_PAT_RIPPLES: return waves_sum(ctx, pat, p, true);
    case IRIS_PAT_WRINKLES: return wrinkles(p, gen);
    case IRIS_PAT_DENTS: {
        double n = noise_value(p, gen);
        return n * n * n;
    }
    case IRIS_PAT_QUILTED: return quilted(pat, p);
    case IRIS_PAT_FUNCTION: return function_value(pat, p);
    case IRIS_PAT_PLANAR: return clip_density(fabs(p.y));
    case IRIS_PAT_BOXED:
        return clip_density(fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
    case IRIS_PAT_SPHERICAL: return clip_density(v3_len(p));
    case IRIS_PAT_CYLINDRICAL:
        return clip_density(sqrt(p.x * p.x + p.z * p.z));
    case IRIS_PAT_IMAGE_PATTERN: {
        iris_colour c;
        if (!pat->image || !mat_image_lookup(ctx, pat->image, p, &c))
            return 0.0;
        /* POV-Ray's image_pattern uses the grey level (use_alpha: alpha) */
        if (pat->image->use_alpha)
            return 1.0 - c.t;
        return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
    }
    case IRIS_PAT_SLOPE: return slope(pat, p, pt);
    case IRIS_PAT_DENSITY_FILE: return mat_density_file(ctx, pat, p);
    case IRIS_PAT_OBJECT:
        /* POV-Ray's ObjectPattern: entry 1 inside the object, 0 outside */
        return pat->object &&
               objpat_inside(ctx ? &ctx->objpats : NULL, pat->object, p);
    default:
        return 0.0;
    }
}

/* The raw pattern function, before frequency and wave shaping. The
** commonest cheap kinds are computed here, inline in pat_eval_at(), or
** (brick, hexagon, the tilings) in small functions of their own, out of
** line so as not to enlarge pat_eval_at()'s frame; the others (noise,
** cells, fractals, images: large, with a stack frame to match) in
** raw_value_other(). */
static inline double raw_value(const struct mat_ctx *ctx,
                               const iris_pattern *pat, vec3 p,
                               const struct mat_point *pt)
{
    switch (pat->kind) {
    case IRIS_PAT_CHECKER: return checker(p);
    case IRIS_PAT_BRICK: return brick(pat, p);
    case IRIS_PAT_HEXAGON: return hexagon(p);
    case IRIS_PAT_SQUARE: return pattern_square(p);
    case IRIS_PAT_TRIANGULAR: return pattern_triangular(p);
    case IRIS_PAT_CUBIC: return pattern_cubic(p);
    case IRIS_PAT_TILING: return pattern_tiling(pat->params[0], p);
    case IRIS_PAT_GRADIENT: {
        double r = v3_dot(p, pat->vector);
        return r > 1.0 ? mod1_nonneg(r) : r;
    }
    case IRIS_PAT_ONION: return mod1_nonneg(v3_len(p));
    default: return raw_value_other(ctx, pat, p, pt);
    }
}

/* pat_eval_at(), inline in pat_value() too: its call there (the point
** passed on the stack, a second frame) was a fifth of a checker's cost. */
static inline double eval_at(const struct mat_ctx *ctx,
                             const iris_pattern *pat, vec3 q,
                             const struct mat_point *pt)
{
    double v = raw_value(ctx, pat, q, pt);
    if (pat_is_list(pat->kind) || pat->kind == IRIS_PAT_AVERAGE)
        return v;
    if (!isfinite(v))
        v = 0.0;
    if (pat->frequency != 0.0) {
        v = v * pat->frequency + pat->phase;
        /* fmod(v, 1.00001) is v itself on [0, 1.00001) (-0 included):
        ** the library call only for the values it changes */
        if (!(v >= 0.0 && v < 1.00001))
            v = fmod(v, 1.00001);
    }
    if (v < 0.0)
        v -= floor(v);
    switch (pat->wave) {
    case IRIS_WAVE_SINE: v = (1.0 + noise_cycloidal(v)) * 0.5; break;
    case IRIS_WAVE_TRIANGLE: v = noise_triangle_wave(v); break;
    case IRIS_WAVE_SCALLOP: v = fabs(noise_cycloidal(v * 0.5)); break;
    case IRIS_WAVE_CUBIC: v = v * v * (-2.0 * v + 3.0); break;
    case IRIS_WAVE_POLY: v = pow(v, pat->wave_exponent); break;
    default: break;
    }
    return isfinite(v) ? v : 0.0;
}

double pat_eval_at(const struct mat_ctx *ctx, const iris_pattern *pat,
                   vec3 q, const struct mat_point *pt)
{
    return eval_at(ctx, pat, q, pt);
}

vec3 pat_input(const iris_pattern *pat, vec3 p, const struct mat_point *pt)
{
    if (pat->uv_mapping && pt)
        return v3(pt->uv.u, pt->uv.v, 0.0);
    return p;
}

double pat_value(const struct mat_ctx *ctx, const iris_pattern *pat, vec3 p,
                 const struct mat_point *pt)
{
    return eval_at(ctx, pat, pat_space(ctx, pat, pat_input(pat, p, pt)), pt);
}
