/* SPDX-License-Identifier: MIT */
/*
** fnintern.c: the internal functions of functions.inc (internal(N)).
**
** Each one computes what POV-Ray 3.7's vm/fnintern.cpp computes for the
** same N (the numbers are functions.inc's), written from those formulas:
** arguments are x, y, z, then the parameters functions.inc documents.
** Where POV-Ray's code has quirks that change results (integer divisions
** in f_enneper, the extra negations of f_algbr_cyl1 and f_piriform) they
** are kept, since scenes were tuned against them. The noise functions use
** POV-Ray's own noise (material/noise.h). Loops driven by a parameter
** (octaves, tube counts) are capped so that no argument can hang a render.
** Numbers not listed return 0; the caller makes every result finite.
**
** Depends on: math/vec3.h, material/noise.h.
*/
#include "config.h"

#include <math.h>
#include <stdbool.h>

#include "iris/fn.h"
#include "material/noise.h"
#include "math/vec3.h"

/* POV-Ray's default noise generator (range-corrected), used by f_noise3d:
** the scene's global_settings noise_generator is not known here. */
#define DEFAULT_NOISE_GENERATOR 2

/* Octave and count loops stop here (POV-Ray has no limit: a huge value
** only hangs it). */
#define MAX_LOOP 1000

/* The arguments: x, y, z and up to 10 parameters p[0..9]. */
struct fargs {
    double x, y, z;
    double p[10];
};

/* Clamps k*r to [-10, 10], the form of POV-Ray's algebraic surfaces. */
static double clampk(double k, double r)
{
    return fmin(10.0, fmax(k * r, -10.0));
}

/* POV-Ray's ROT2D for the _2d curves: when p > 0 the curve in the x-y
** plane is revolved around y at distance d, then rotated by 'deg' in that
** plane. Updates x, y and their squares. */
static void rot2d(struct fargs *a, double *x2, double *y2, double p, double d,
                  double deg)
{
    if (!(p > 0))
        return;
    double r = sqrt(*x2 + a->z * a->z) - d;
    double th = deg * M_PI / 180;
    if (th != 0) {
        double nx = r * cos(th) - a->y * sin(th);
        a->y = r * sin(th) + a->y * cos(th);
        a->x = nx;
    } else {
        a->x = r;
    }
    *x2 = a->x * a->x;
    *y2 = a->y * a->y;
}

/* The cross-section of f_helix1/f_helix2/f_spiral: p = 1 circle, 0 square,
** else a superellipse with exponent 2/p. */
static double cross_section(double u, double v, double p)
{
    if (p == 1)
        return sqrt(u * u + v * v);
    if (p != 0) {
        double e = 2 / p;
        return pow(pow(fabs(u), e) + pow(fabs(v), e), p * 0.5);
    }
    return fmax(fabs(u), fabs(v));
}

/* A float parameter as an int without undefined conversions. */
static int to_int(double v)
{
    return v > -1e9 && v < 1e9 ? (int)v : 0;
}

/* POV-Ray's '(int)param & 3' choice of noise generator. */
static int generator(double v)
{
    return to_int(v) & 3;
}

static double noise_at(double x, double y, double z, int gen)
{
    return noise_value(v3(x, y, z), gen);
}

static double algbr_cyl(int n, struct fargs *a)
{
    double x2 = a->x * a->x, y2 = a->y * a->y;
    double *p = a->p;
    rot2d(a, &x2, &y2, p[2], p[3], p[4]);
    double x = a->x, y = a->y, r;
    switch (n) {
    case 0:
        x = fabs(x);
        r = -(x2 * x - x2 + y2);
        return -fmin(p[1], fmax(p[0] * r, -p[1]));
    case 1: r = -(2 * x2 * x2 - 3 * x2 * y + y2 - 2 * y2 * y + y2 * y2); break;
    case 2: r = -(x2 * x2 + x2 * y2 - 2 * x2 * y - x * y2 + y2); break;
    default: r = -(x2 * x2 + y2 * y2 + 2 * x2 * y2 + 3 * x2 * y - y2 * y); break;
    }
    return fmin(p[1], fmax(p[0] * r, -p[1]));
}

/* Sums of three Gaussian-like ellipsoids (f_cross_ellipsoids, ...). */
static double ellipsoid_terms(const struct fargs *a, double t[3])
{
    double x2 = a->x * a->x, y2 = a->y * a->y, z2 = a->z * a->z;
    const double *p = a->p;
    t[0] = exp(-(x2 * p[0] + y2 * p[0] + z2) * p[1]);
    t[1] = exp(-(x2 * p[0] + y2 + z2 * p[0]) * p[1]);
    t[2] = exp(-(x2 + y2 * p[0] + z2 * p[0]) * p[1]);
    return x2 + y2 + z2;
}

static double helix1(struct fargs *a)
{
    const double *p = a->p;
    double r = sqrt(a->x * a->x + a->z * a->z);
    double x = a->x == 0 && a->z == 0 ? 1e-6 : a->x;
    double th = fmod(atan2(a->z, x) * p[0] + a->y * p[1] * p[0], 2 * M_PI);
    if (th < 0)
        th += 2 * M_PI;
    double w = (th - M_PI) / p[4] / (p[1] * p[0]);
    double u = r - p[3];
    if (p[5] != 1 && p[6] != 0) {
        double c = cos(p[6] * M_PI / 180), s = sin(p[6] * M_PI / 180);
        double nu = u * c - w * s;
        w = u * s + w * c;
        u = nu;
    }
    double r2 = cross_section(u, w, p[5]);
    return -p[2] + fmin(p[3] + r, r2);
}

static double helix2(const struct fargs *a)
{
    const double *p = a->p;
    double th = a->y * p[1];
    double c = cos(th), s = sin(th);
    double x2 = a->x - p[3] * c, z2 = a->z - p[3] * s;
    double u = x2 * c + z2 * s, w = -x2 * s + z2 * c;
    return cross_section(u, w, p[5]) - p[2];
}

static double hex(const struct fargs *a, bool want_y)
{
    const double h = sqrt(3.0);
    double x1 = fabs(fmod(fabs(a->x), h) - h / 2);
    double y1 = fabs(fmod(fabs(a->y), 3) - 1.5);
    double x2 = h / 2 - x1, y2 = 1.5 - y1;
    if (x1 * x1 + y1 * y1 > x2 * x2 + y2 * y2) {
        x1 = x2;
        y1 = y2;
    }
    if (atan2(y1, x1) < M_PI / 6)
        return want_y ? y1 : x1;
    if (want_y)
        return fabs(-sin(M_PI / 3) * x1 + cos(M_PI / 3) * y1);
    return cos(M_PI / 3) * x1 + sin(M_PI / 3) * y1;
}

/* f_hetero_mf(x,y,z, H, lacunarity, octaves, offset, T, generator) */
static double hetero_mf(const struct fargs *a)
{
    const double *p = a->p;
    int gen = generator(p[5]);
    double x = a->x, y = a->y, z = a->z;
    double signal = noise_at(x, y, z, gen) * 2 - 1 + p[3];
    double step = pow(p[1], -p[0]), ea = step;
    x *= p[1];
    y *= p[1];
    z *= p[1];
    int powers = p[4] > MAX_LOOP ? MAX_LOOP : to_int(p[4]);
    for (int i = 1; i < p[2] && i < MAX_LOOP; i++) {
        double inc = (noise_at(x, y, z, gen) * 2 - 1 + p[3]) * ea;
        for (int k = powers; k > 0; k--)
            inc *= signal;
        signal += inc;
        x *= p[1];
        y *= p[1];
        z *= p[1];
        ea *= step;
    }
    double rem = p[2] - to_int(p[2]);
    if (rem != 0 && p[2] < MAX_LOOP) {
        double inc = (noise_at(x, y, z, gen) * 2 - 1 + p[3]) * ea;
        signal += rem * inc * signal;
    }
    return signal;
}

/* f_ridge(x,y,z, lambda, octaves, omega, offset, ridge, generator) */
static double ridge(const struct fargs *a)
{
    const double *p = a->p;
    int gen = generator(p[5]);
    double lambda = p[0], omega = p[2], off = p[3], rdg = p[4];
    int octaves = p[1] > MAX_LOOP ? MAX_LOOP : to_int(p[1]);
    double rscale = 1 / fmax(rdg, 1 - rdg), scale = 1 / fmax(off, 1 - off);
    double resid = p[1] - octaves;
    double l = lambda, o = omega, tot = 1;
    double value = fabs(noise_at(a->x, a->y, a->z, gen) - rdg) * rscale - off;
    for (int i = 2; i <= octaves; i++) {
        double v = fabs(noise_at(a->x * l, a->y * l, a->z * l, gen) - rdg) *
                   rscale;
        value += o * (v - off);
        tot += o;
        l *= lambda;
        o *= omega;
    }
    if (resid != 0 && p[1] <= MAX_LOOP) {
        double v = fabs(noise_at(a->x * l, a->y * l, a->z * l, gen) - rdg) *
                   rscale;
        value += o * (v - off) * resid;
        tot += o * resid;
    }
    return value * scale / tot;
}

/* f_ridged_mf(x,y,z, H, lacunarity, octaves, offset, gain, generator) */
static double ridged_mf(const struct fargs *a)
{
    const double *p = a->p;
    int gen = generator(p[5]);
    double x = a->x, y = a->y, z = a->z;
    double s = fabs(noise_at(x, y, z, gen) * 2 - 1);
    s = p[3] - s;
    s *= s;
    double result = s, freq = 1;
    for (int i = 1; i < p[2] && i < MAX_LOOP; i++) {
        x *= p[1];
        y *= p[1];
        z *= p[1];
        freq *= p[1];
        double w = fmin(fmax(s * p[4], 0.0), 1.0);
        s = fabs(noise_at(x, y, z, gen) * 2 - 1);
        s = p[3] - s;
        s *= s;
        s *= w;
        result += s * pow(freq, -p[0]);
    }
    return result;
}

/* One wave of f_mesh1: the distance to a cosine-bent thread. */
static double mesh_thread(double along, double period, double thick,
                          double h, double hscale)
{
    double r = fmod(along, period * 2);
    if (r < 0)
        r += period * 2;
    r = fabs(r - period) * thick;
    double r2 = h * hscale;
    return -sqrt(r2 * r2 + r * r);
}

/* f_mesh1(x,y,z, distance x, distance z, relative thickness, amplitude,
** relative amplitude) */
static double mesh1(const struct fargs *a)
{
    const double *p = a->p;
    double th = M_PI / p[0], ph = M_PI / p[1];
    double t = mesh_thread(a->x, p[0], p[2], a->y - cos(a->z * ph) * p[3],
                           p[4]);
    t = fmax(mesh_thread(a->x - p[0], p[0], p[2],
                         a->y + cos(a->z * ph) * p[3], p[4]), t);
    t = fmax(mesh_thread(a->z, p[1], p[2], a->y + cos(a->x * th) * p[3],
                         p[4]), t);
    t = fmax(mesh_thread(a->z - p[1], p[1], p[2],
                         a->y - cos(a->x * th) * p[3], p[4]), t);
    return -t;
}

static double spiral(const struct fargs *a)
{
    const double *p = a->p;
    double r = sqrt(a->x * a->x + a->z * a->z);
    double x = a->x == 0 && a->z == 0 ? 1e-6 : a->x;
    r += p[0] * atan2(a->z, x) / (2 * M_PI);
    double r2 = cross_section(fmod(r, p[0]) - p[0] * 0.5, a->y, p[5]);
    double d = sqrt(a->x * a->x + a->y * a->y + a->z * a->z);
    return -fmin(p[2] - d, p[1] - fmin(r2, d));
}

static double helical_torus(const struct fargs *a)
{
    const double *p = a->p;
    double r2 = sqrt(a->x * a->x + a->z * a->z);
    double x = a->x == 0 && a->z == 0 ? 1e-6 : a->x;
    double ph = atan2(x, a->z);
    double t = atan2(r2 - p[0], a->y);
    double r = sqrt((r2 - p[0]) * (r2 - p[0]) + a->y * a->y);
    double th = fmod(ph * p[1] + t * p[2], 2 * M_PI);
    if (th < 0)
        th += 2 * M_PI;
    t = atan2((th - M_PI) * p[8], r - p[5]);
    t = cos(t * p[7] + ph * p[9]) * p[3] + p[4];
    r2 = p[4] + p[5] - p[0] - r2;
    th -= M_PI;
    t -= fmin(sqrt((r - p[5]) * (r - p[5]) + th * th * p[6]), r + p[5]);
    return -fmax(r2, t);
}

/* The algebraic surfaces of the form clamp(k * r): r for each number. */
static bool algebraic(int n, struct fargs *a, double *out)
{
    double x = a->x, y = a->y, z = a->z;
    double x2 = x * x, y2 = y * y, z2 = z * z;
    const double *p = a->p;
    double r, q;
    switch (n) {
    case 4: /* f_bicorn */
        q = x2 + z2 + 2 * p[1] * y - p[1] * p[1];
        r = y2 * (p[1] * p[1] - (x2 + z2)) - q * q;
        break;
    case 5: /* f_bifolia */
        q = x2 + y2 + z2;
        r = -(q * q - p[1] * (x2 + z2) * y);
        break;
    case 8: { /* f_boy_surface */
        double w = 1 - z, s = x2 + y2, k = sqrt(2.0);
        r = p[1] * (64 * w * w * w * z2 * z -
                    48 * w * w * z2 * (3 * x2 + 3 * y2 + 2 * z2) +
                    12 * w * z * (27 * s * s - 24 * z2 * s +
                                  36 * k * y * z * (y2 - 3 * x2) +
                                  4 * z2 * z2) +
                    (9 * x2 + 9 * y2 - 2 * z2) *
                        (-81 * s * s - 72 * z2 * s +
                         108 * k * x * z * (x2 - 3 * y2) + 4 * z2 * z2));
        break;
    }
    case 11: r = x2 * z2 - y; break;                    /* f_crossed_trough */
    case 12: r = -(x2 * x - y2 * y - z); break;         /* f_cubic_saddle */
    case 13: case 43: /* f_cushion, f_odd */
        r = z2 * x2 - z2 * z2 - 2 * z * x2 + 2 * z2 * z + x2 - z2 -
            (x2 - z) * (x2 - z) - y2 * y2 - 2 * x2 * y2 - y2 * z2 +
            2 * y2 * z + y2;
        break;
    case 14: /* f_devils_curve */
        r = -(x2 * x2 + 2 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 +
              z2 * z2);
        break;
    case 15: /* f_devils_curve_2d */
        rot2d(a, &x2, &y2, p[3], p[4], p[5]);
        r = -(x2 * (x2 - p[1] * p[1]) - y2 * (y2 - p[2] * p[2]));
        break;
    case 16: { /* f_dupin_cyclid */
        double r2 = p[5] * p[5], ph = p[2] * p[2], th = p[4] * p[4];
        double p1 = ph - th - (p[3] + p[1]) * (p[3] + p[1]);
        double p2 = ph - th - (p[3] - p[1]) * (p[3] - p[1]);
        double p3 = p[3] * p[3], p4 = p[1] * p[1];
        r = -(p1 * p2 * (x2 * x2 + y2 * y2 + z2 * z2) +
              2 * (p1 * p2 * (x2 * y2 + x2 * z2 + y2 * z2)) +
              2 * r2 * ((-th - p3 + ph + p4) *
                            (2 * x * p[3] + 2 * y * p[4] - r2) -
                        4 * p[4] * ph * y) * (x2 + y2 + z2) +
              4 * r2 * r2 * (p[3] * x + p[4] * y) *
                  (-r2 + p[4] * y + p[3] * x) +
              4 * r2 * r2 * p4 * y2 + r2 * r2 * r2 * r2);
        break;
    }
    case 18: { /* f_enneper, with POV-Ray's integer divisions (2/3 = 0) */
        double zz = fabs(z) < 0.2 ? 0.2 : z;
        double a1 = (y2 - x2) / (2 * zz) + 2 * z2 / 9;
        double a2 = (y2 - x2) / (4 * zz);
        r = -(a1 * a1 * a1 - 6 * a2 * a2);
        break;
    }
    case 20: /* f_folium_surface */
        r = (y2 + z2) * (1 + (p[2] - 4 * p[1]) * x) + x2 * (1 + p[2]);
        break;
    case 21: /* f_folium_surface_2d */
        rot2d(a, &x2, &y2, p[3], p[4], p[5]);
        r = -(y2 * (1 + (p[2] - 4 * p[1]) * a->x) + x2 * (1 + p[2]));
        break;
    case 22: r = 0.5 * x2 * x2 * x + 0.5 * x2 * x2 - (y2 + z2); break;
    case 23: /* f_heart */
        q = 2 * x2 + y2 + z2 - 1;
        r = -(q * q * q - 0.1 * x2 * z2 * z - y2 * z2 * z);
        break;
    case 30: /* f_hunt_surface */
        q = x2 + y2 + z2 - 13;
        r = -(4 * q * q * q + 27 * (3 * x2 + y2 - 4 * z2 - 12) *
                                  (3 * x2 + y2 - 4 * z2 - 12));
        break;
    case 31: { /* f_hyperbolic_torus */
        double ph = p[1] * p[1], th = p[2] * p[2];
        r = -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * (ph + th) * x2 +
              y2 * y2 - 2 * y2 * z2 + 2 * (ph - th) * y2 + z2 * z2 +
              2 * (ph + th) * z2 + (ph - th) * (ph - th));
        break;
    }
    case 33: /* f_kampyle_of_eudoxus */
        r = -((y2 + z2) - p[2] * p[2] * x2 * x2 +
              p[2] * p[2] * p[1] * p[1] * x2);
        break;
    case 34: /* f_kampyle_of_eudoxus_2d (POV-Ray uses p1*p2 here) */
        rot2d(a, &x2, &y2, p[3], p[4], p[5]);
        r = -(y2 - p[2] * p[2] * x2 * x2 + p[2] * p[2] * p[1] * p[2] * x2);
        break;
    case 35: /* f_klein_bottle */
        q = x2 + y2 + z2 - 2 * y - 1;
        r = -((x2 + y2 + z2 + 2 * y - 1) * (q * q - 8 * z2) +
              16 * x * z * q);
        break;
    case 36: /* f_kummer_surface_v1 */
        r = -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 -
              x2 * z2 - y2 * z2 + 1);
        break;
    case 37: /* f_kummer_surface_v2 */
        r = -(x2 * x2 + y2 * y2 + z2 * z2 + p[1] * (x2 + y2 + z2) +
              p[2] * (x2 * y2 + x2 * z2 + y2 * z2) + p[3] * x * y * z - 1);
        break;
    case 38: r = -(x2 * x2 - x2 + y2 + z2); break; /* lemniscate_of_gerono */
    case 39: /* f_lemniscate_of_gerono_2d */
        rot2d(a, &x2, &y2, p[3], p[4], p[5]);
        r = -(y2 - p[2] * p[2] * p[1] * p[1] * x2 + p[2] * p[2] * x2 * x2);
        break;
    case 41: r = -(4 * x2 * (x2 + y2 + z2) - y2 * (1 - y2 - z2)); break;
    case 42: r = -(y2 * y + z2 * z - 6 * y * z); break; /* f_nodal_cubic */
    case 44: /* f_ovals_of_cassini */
        q = x2 + y2 + z2 + p[1] * p[1];
        r = -(q * q - p[3] * p[1] * p[1] * (x2 + z2) - p[2] * p[2]);
        break;
    case 45: r = -(x2 - y + z2); break;                 /* f_paraboloid */
    case 46: { /* f_parabolic_torus */
        double ph = p[1] * p[1], th = p[2] * p[2];
        r = -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z - (ph + th) * x2 +
              y2 * y2 - 2 * y2 * z + (ph - th) * y2 + z2 + (ph + th) * z +
              (ph - th) * (ph - th));
        break;
    }
    case 48: r = x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2); break;
    case 49: /* f_piriform: POV-Ray negates the clamped value */
        r = -((x2 * x2 - x2 * x) + y2 + z2);
        *out = -clampk(p[0], r);
        return true;
    case 50: /* f_piriform_2d */
        rot2d(a, &x2, &y2, p[4], p[5], p[6]);
        r = -(a->y * a->y - p[1] * p[3] * p[3] * x2 * a->x -
              p[2] * p[3] * p[3] * x2 * x2);
        break;
    case 54: r = -(x2 * x2 + z2 * z2 - y); break;       /* quartic_paraboloid */
    case 55: r = -(x2 * x2 - z2 * z2 - y); break;       /* f_quartic_saddle */
    case 56: /* f_quartic_cylinder */
        r = -((x2 + z2) * y2 + p[2] * p[2] * (x2 + z2) -
              p[2] * p[2] * p[1] * p[1]);
        break;
    case 65: r = -(x2 * y2 + x2 * z2 + y2 * z2 + x * y * z); break;
    case 66: /* f_strophoid */
        r = -((p[2] - x) * (y2 + z2) - p[3] * p[3] * p[1] * x2 -
              p[3] * p[3] * x2 * x);
        break;
    case 67: /* f_strophoid_2d */
        rot2d(a, &x2, &y2, p[4], p[5], p[6]);
        r = -((p[2] - a->x) * y2 - p[3] * p[3] * p[1] * x2 -
              p[3] * p[3] * x2 * a->x);
        break;
    case 71: { /* f_torus2 */
        double ph = p[1] * p[1], th = p[2] * p[2];
        r = -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 +
              2 * y2 * z2 - 2 * (ph + th) * x2 + 2 * (ph - th) * y2 -
              2 * (ph + th) * z2 + (ph - th) * (ph - th));
        break;
    }
    case 72: /* f_torus_gumdrop */
        q = y2 + z2;
        r = -(4 * (x2 * x2 + q * q) + 17 * x2 * q - 20 * (x2 + y2 + z2) +
              17);
        break;
    case 73: r = -(x2 - y * z2); break;                 /* f_umbrella */
    case 74: r = -(p[1] * (y - 1) + (x2 + z2) * y); break;
    case 75: /* f_witch_of_agnesi_2d */
        rot2d(a, &x2, &y2, p[3], p[4], p[5]);
        r = -(p[1] * p[1] * a->y + x2 * a->y - p[2]);
        break;
    default:
        return false;
    }
    *out = clampk(p[0], r);
    return true;
}

double iris_fn_internal(int n, const double *args, int n_args)
{
    struct fargs a = { 0, 0, 0, { 0 } };
    if (args) {
        a.x = n_args > 0 ? args[0] : 0;
        a.y = n_args > 1 ? args[1] : 0;
        a.z = n_args > 2 ? args[2] : 0;
        for (int i = 0; i < 10 && i + 3 < n_args; i++)
            a.p[i] = args[i + 3];
    }
    double x = a.x, y = a.y, z = a.z;
    double x2 = x * x, y2 = y * y, z2 = z * z;
    const double *p = a.p;
    double r = 0, t[3];
    if (algebraic(n, &a, &r))
        return isfinite(r) ? r : 0;
    switch (n) {
    case 0: case 1: case 2: case 3: r = algbr_cyl(n, &a); break;
    case 6: { /* f_blob: two blob components along x */
        double h = p[0] * 0.5;
        double u = fmin(((x + h) * (x + h) + y2 + z2) * p[2] * p[2], 1.0);
        double v = fmin(((x - h) * (x - h) + y2 + z2) * p[4] * p[4], 1.0);
        r = -(p[1] * (1 - u) * (1 - u) + p[3] * (1 - v) * (1 - v));
        break;
    }
    case 7: /* f_blob2 */
        r = exp(-(x2 + y2 + z2) * p[1]) +
            exp(-((x - p[0]) * (x - p[0]) + y2 + z2) * p[1]);
        r = p[3] - r * p[2];
        break;
    case 9: { /* f_comma */
        double xx = x == 0 && z == 0 ? 1e-4 : x;
        double th = atan2(z, xx);
        double q = sqrt((xx + p[0] * 0.25) * (xx + p[0] * 0.25) + z2);
        double u = cos(th * 0.5) * p[0] * 0.5 -
                   sqrt((q - p[0] * 0.75) * (q - p[0] * 0.75) + y2);
        u = fmin(z, u);
        q = p[0] * 0.5 - sqrt((xx - p[0] * 0.5) * (xx - p[0] * 0.5) + z2 + y2);
        r = -fmax(u, q);
        break;
    }
    case 10: /* f_cross_ellipsoids */
        ellipsoid_terms(&a, t);
        r = p[3] - fmax(fmax(t[0], t[1]), t[2]) * p[2];
        break;
    case 17: /* f_ellipsoid */
        r = sqrt(x2 * p[0] * p[0] + y2 * p[1] * p[1] + z2 * p[2] * p[2]);
        break;
    case 19: /* f_flange_cover */
        ellipsoid_terms(&a, t);
        r = p[3] - (t[0] + t[1] + t[2]) * p[2];
        break;
    case 24: r = helical_torus(&a); break;
    case 25: r = helix1(&a); break;
    case 26: r = helix2(&a); break;
    case 27: r = hex(&a, false); break;
    case 28: r = hex(&a, true); break;
    case 29: r = hetero_mf(&a); break;
    case 32: /* f_isect_ellipsoids */
        ellipsoid_terms(&a, t);
        r = p[3] - fmin(fmin(t[0], t[1]), t[2]) * p[2];
        break;
    case 40: r = mesh1(&a); break;
    case 47: r = atan2(sqrt(x2 + z2), y); break;        /* f_ph */
    case 51: { /* f_poly4 */
        double q = p[0] + p[1] * y + p[2] * y2 + p[3] * y2 * y +
                   p[4] * y2 * y2;
        r = -fmax(q, -5.0) + sqrt(x2 + z2);
        break;
    }
    case 52: { /* f_polytubes(x,y,z, number, profile coefficients) */
        double q = p[1] + p[2] * y + p[3] * y2 + p[4] * y2 * y +
                   p[5] * y2 * y2;
        double m = -10000;
        int count = p[0] > MAX_LOOP ? MAX_LOOP : to_int(p[0]);
        for (int i = 0; i < count; i++) {
            double dx = x - q * sin(2 * M_PI / p[0] * i);
            double dz = z - q * cos(2 * M_PI / p[0] * i);
            m = fmax(m, -sqrt(dx * dx + dz * dz));
        }
        r = -m;
        break;
    }
    case 53: { /* f_quantum */
        double xx = x == 0 && z == 0 ? 1e-6 : x;
        double q = sqrt(xx * xx + z2);
        double th = cos(atan2(q, y));
        q = sqrt(q * q + y2) * 2;
        /* POV-Ray writes 1/3 as 0.33333333: kept for equal values */
        double u = q * q * exp(-q * 0.33333333) * (3 * th * th - 1);
        r = (u * u - 12) * -0.1;
        break;
    }
    case 57: r = sqrt(x2 + y2 + z2); break;              /* f_r */
    case 58: r = ridge(&a); break;
    case 59: r = ridged_mf(&a); break;
    case 60: { /* f_rounded_box(x,y,z, radius, half sizes x, y, z) */
        double dx = fmax(fabs(x) - (p[1] - p[0]), 0);
        double dy = fmax(fabs(y) - (p[2] - p[0]), 0);
        double dz = fmax(fabs(z) - (p[3] - p[0]), 0);
        r = sqrt(dx * dx + dy * dy + dz * dz) - p[0] - 1e-6;
        break;
    }
    case 61: r = sqrt(x2 + y2 + z2) - p[0]; break;       /* f_sphere */
    case 62: /* f_spikes */
        ellipsoid_terms(&a, t);
        r = exp(-(x2 + y2 + z2) * p[3]) * p[4] - t[0] - t[1] - t[2];
        r = -r * p[2];
        break;
    case 63: /* f_spikes_2d */
        r = -(p[0] * cos(p[1] * x) * cos(p[2] * z) *
                  exp(-p[3] * (x2 + z2)) - y);
        break;
    case 64: r = spiral(&a); break;
    case 68: { /* f_superellipsoid(x,y,z, e, n) */
        if (p[0] <= 0 || p[1] <= 0)
            return 0;
        double e = 2 / p[0], nn = 1 / p[1];
        double xy = pow(pow(fabs(x), e) + pow(fabs(y), e), p[0] * nn);
        r = 1 - pow(xy + pow(fabs(z), 2 * nn), p[1] * 0.5);
        break;
    }
    case 69: r = atan2(x, z); break;                     /* f_th */
    case 70: { /* f_torus(x,y,z, major, minor) */
        double d = sqrt(x2 + z2) - p[0];
        r = sqrt(d * d + y2) - p[1];
        break;
    }
    case 76: /* f_noise3d */
        r = noise_at(x, y, z, DEFAULT_NOISE_GENERATOR);
        break;
    case 78: /* f_noise_generator(x,y,z, generator) */
        r = noise_at(x, y, z, generator(p[0]));
        break;
    default:
        r = 0;
        break;
    }
    return isfinite(r) ? r : 0;
}

void iris_fn_vturbulence(double lambda, double omega, double octaves,
                         const double p[3], double out[3])
{
    struct noise_turb t;
    t.lambda = lambda;
    t.omega = omega;
    t.octaves = !(octaves >= 1) ? 1 : octaves > 10 ? 10 : (int)octaves;
    vec3 d = noise_dturbulence(v3(p[0], p[1], p[2]), &t);
    out[0] = d.x;
    out[1] = d.y;
    out[2] = d.z;
}
