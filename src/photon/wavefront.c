/* SPDX-License-Identifier: MIT */
/*
** wavefront.c: caustic photons of scenes of spheres, planes and convex
** objects traced eight at a time (wavefront.h).
**
** WHY. The scalar tracer (trace.c) spends ~2,500 instructions and one
** chain of ~20 dependent divisions and square roots on a photon of the
** clear-ball caustic (docs/photons.md, Throughput): its latency alone
** bounds it near 2 M photons a second. Here a batch's photons sit in
** structure-of-arrays lanes; each step intersects every live lane with
** every primitive, then applies the surface's event to all of them at
** once (deposit, Fresnel roulette, refraction at the lane's n(lambda),
** mirror and filter roulettes), and packs the survivors to the front
** (compaction), so eight independent chains run side by side in 256-bit
** registers and nothing is asked per hit that does not depend on the
** photon: each primitive's surface (texture, flags, index) is resolved
** once per build into 8-entry tables that a lane reads with one
** permutation of its primitive number.
**
** THE SAME ESTIMATOR. Emission follows shoot.c (ring cell, POV-Ray's
** jitter in pass 0, a uniform point of the cell after; the spot and
** cylinder attenuation; the lattice wavelength), transport trace.c (the
** exact unpolarised Fresnel probability, reflection off the outside only
** with 'reflection on', n(lambda) for dispersive interiors, a mirror's
** and a filter's roulette p/(p+q), the deposit after >= 1 bounce with
** D^2). What differs: single precision, and the random numbers, which
** come from a counter-based hash of (seed, pass, photon index, draw)
** instead of the scalar stream: the map does not depend on the thread
** count, but it is another sample of the same distribution, not the
** scalar map record for record.
**
** SIBLING WAVELENGTHS. In a scene without coloured filters, under a
** light of flat emission a path is chromatic only through a dispersive
** interior, where the scalar tracer collapses the siblings to sibling 0
** (its lattice wavelength) with their whole power: exactly the one
** wavelength a lane carries. Paths that never meet dispersion are stored
** white, as the scalar tracer stores them. A light whose emission varies
** with lambda (a coloured light) makes every path chromatic: the scalar
** tracer stores one record per sibling, each with 1/S of the cell's power
** times the emission at its wavelength. Here such a photon takes S lanes
** (shoot.c fills one run entry per sibling) with the same random key, so
** they leave in one direction and make the same choices on grey surfaces:
** the same S records. Only past a dispersive interior do they differ:
** the scalar siblings collapse to sibling 0 with S times its power, the
** lanes go on at their own wavelengths with 1/S each; both have the
** expectation of a photon of each wavelength alone, the lanes with less
** colour noise and S records instead of one. A coloured filter (a pair
** with one, wf_sibling_lanes()) gives a flat light's photons S lanes
** too, each with 1/S of the power: until a filter makes the path
** chromatic the lanes go together and sibling 0 alone stores the white
** record, with S times its power (struct wf_run's 'white'); from there
** each lane stores its own, its power times the filter's transmittance
** at its wavelength (a 1 nm table, as the index). Where a roulette
** depends on lambda (a coloured filter that also mirrors, p/(p + q)) the
** scalar siblings take it once with the siblings' mean probability and
** each lane with its own: either is right at every wavelength.
**
** CONVEX OBJECTS. A box, a linear prism of one convex polygon, a capped
** cylinder and an intersection of such shapes, planes and spheres is the
** intersection of half-spaces, balls and infinite cylinders: the
** scene's showcase glass (scenes/prism.pov, lens.pov, gem.pov). Their
** transforms are folded in at build (an affine map takes a plane to a
** plane, a similarity a ball or a cylinder to one), so a lane meets
** them in world space: the ray's span inside one is the latest entry and
** the first exit over its constituents (slabs for the planes, the
** sphere's solve for a ball, the same across the axis for a cylinder),
** each end carrying its constituent's outward normal. The hit is the
** entry, or the exit for a lane inside.
**
** SELF-HITS without an epsilon: a lane remembers the primitive it left.
** A plane is not asked again; a sphere is asked for its far crossing only,
** and only when the lane goes into it (d·(o - c) < 0 at its surface); a
** convex object likewise, its far end only, when the lane's new direction
** goes into it (the lane stores the object's number, or the number plus
** WF_OUT when it goes out: then the object is not asked). The shapes are
** convex, so nothing else of them can be hit there.
**
** DISPATCH. The kernel (wf_kernel.h) is one always-inline body included
** twice: 8 lanes wide, inlined into a function with target("avx2,fma"),
** and 4 lanes wide into a plain one (SSE2 on any x86-64, the compiler's
** 128-bit vectors elsewhere); __builtin_cpu_supports picks. Both do the
** same float operations in the same order per lane (no contraction
** under -std=c11) and pack survivors in order: the same map.
*/
#include "config.h"

#include "photon/wavefront.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "math/transform.h"
#include "spectrum/ior.h"
#include "spectrum/spectrum.h"
#include "util/mem.h"

/* The 32-byte vectors of wf_kernel.h's static inline helpers never cross
** a call (always_inline): the generic build's ABI note does not apply. */
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#define AI static inline __attribute__((always_inline))

/* Per-primitive flags (struct wf_prims.flags). */
enum {
    WF_STORE = 1,    /* collects and is diffuse: a deposit */
    WF_TARGET = 2,   /* the pair's target (a first hit must be it) */
    WF_REFR = 4,     /* refracts: Fresnel roulette, n(lambda) */
    WF_REFL_OK = 8,  /* reflection allowed (the outside reflection) */
    WF_DISP = 16,    /* its interior is dispersive: index from the table */
    WF_TSPEC = 32,   /* a coloured filter: the transmittance (refraction's
                        gain, or q) from the table at the lane's lambda */
};

/* A lane's 'last' past a convex object's number k: it left k outward
** (wf_kernel.h) */
#define WF_OUT 16

/* The kinds of a convex object's constituents (struct wf_prims.hkind) */
enum { WF_HALF_PLANE, WF_HALF_BALL, WF_HALF_CYL };

/* Samples of a dispersive interior's n(lambda) over [380, 780] nm, read
** with linear interpolation: 1 nm steps, where the Cauchy and Sellmeier
** curves' second derivative makes the error < 1e-7. */
#define WF_IOR_N 401

/* Objects a pair's lanes meet: 8 (one permutation of a lane's object
** number reads its surface's tables) */
#define WF_MAX_OBJ 8
/* Half-spaces and balls of the convex objects, all together */
#define WF_MAX_HALF 32

/* One pair's primitives as the kernel reads them. Spheres are numbered
** 0..ns-1, planes ns..ns+np-1, convex objects (boxes, convex linear
** prisms, intersections of those, planes and spheres: each the
** intersection of half-spaces and balls) ns+np..ns+np+nc-1, at most
** WF_MAX_OBJ in all. Every shape is in world space: a transform is
** folded in at build (an affine map takes a plane to a plane, a
** similarity a sphere to a sphere; other transforms are refused). */
struct wf_prims {
    int ns, np, nc;
    float sc[WF_MAX_OBJ][3], sr2[WF_MAX_OBJ];
    float pn[WF_MAX_OBJ][3], pd[WF_MAX_OBJ];
    /* convex object k: constituents cfirst[k] .. + ccount[k] - 1. A
    ** constituent j (hkind) is a half-space hc·x <= hd (hc its unit
    ** outward normal), a ball |x - hc|^2 <= hd, or an infinite cylinder
    ** of axis ha through hc, |(x - hc) - ((x - hc)·ha) ha|^2 <= hd; its
    ** outward normal at p is v - (v·ha) ha, v = (p·hka - hn)·hsc (ha 0
    ** but for a cylinder) */
    int cfirst[WF_MAX_OBJ], ccount[WF_MAX_OBJ];
    int32_t hkind[WF_MAX_HALF];
    float hc[WF_MAX_HALF][3], hd[WF_MAX_HALF];
    float hnx[WF_MAX_HALF], hny[WF_MAX_HALF], hnz[WF_MAX_HALF];
    float hka[WF_MAX_HALF], hsc[WF_MAX_HALF];
    float hax[WF_MAX_HALF], hay[WF_MAX_HALF], haz[WF_MAX_HALF];
    bool any_cyl;              /* a cylinder among them */
    /* the tables a lane reads by its primitive's number: the outward
    ** normal at p is (p·ka - c)·s (sphere: ka 1, c the centre, s 1/r;
    ** plane: ka 0, c minus its normal, s 1) */
    float ncx[8], ncy[8], ncz[8], nka[8], nsc[8];
    int32_t flags[8];
    float transm[8];           /* refraction: the transmittance (grey) */
    float ior[8];              /* refraction: n of a plain interior */
    float pm[8], qm[8];        /* the rest: a mirror's p, a filter's q */
    int max_level;
    bool parallel;             /* no D^2 at the deposit */
    bool any_disp, any_tspec;
    float ior_tab[WF_MAX_OBJ][WF_IOR_N]; /* WF_DISP primitives */
    float tr_tab[WF_MAX_OBJ][WF_IOR_N];  /* WF_TSPEC primitives */
};

struct wf_scene {
    int n;
    struct wf_prims *prims;    /* one per pair */
    struct wf_light *light;    /* one per pair */
    int32_t perm8[256][8];     /* compaction: the set lanes of a mask
                                  first, in order (arrays, not vectors:
                                  calloc aligns to 16 bytes only) */
    int32_t perm4[16][4];      /* the same for 4 lanes */
    bool avx2;
};

/* One thread's lanes. */
#define WF_LANES (WF_RUN_LANES + 8)
struct wf_state {
    float ox[WF_LANES], oy[WF_LANES], oz[WF_LANES];
    float dx[WF_LANES], dy[WF_LANES], dz[WF_LANES];
    float pw[WF_LANES], lam[WF_LANES], depth[WF_LANES], white[WF_LANES];
    uint32_t key[WF_LANES];
    int32_t last[WF_LANES], inside[WF_LANES], chroma[WF_LANES];
};

/* A 32-bit integer hash (the "lowbias32" constants of C. Wellons'
** hash-prospector, bias ~0.17), one body for a scalar (hash1: the seed
** mix) and for the kernels' lanes (hash: the counter-based random
** numbers); 'x' is a uint32_t or a vector of them. */
#define WF_LOWBIAS32(x)                                                   \
    do {                                                                  \
        (x) ^= (x) >> 16;                                                 \
        (x) *= 0x7feb352dU;                                               \
        (x) ^= (x) >> 15;                                                 \
        (x) *= 0x846ca68bU;                                               \
        (x) ^= (x) >> 16;                                                 \
    } while (0)

static uint32_t hash1(uint32_t x);

/* The lanes, 8 and 4 wide (wf_kernel.h). */
#define WF_W 8
#define WF_NAME(x) x##_w8
#include "photon/wf_kernel.h"
#undef WF_W
#undef WF_NAME
#define WF_W 4
#define WF_NAME(x) x##_w4
#include "photon/wf_kernel.h"
#undef WF_W
#undef WF_NAME

/* The seed mix of the lanes' random numbers (WF_LOWBIAS32). */
static uint32_t hash1(uint32_t x)
{
    WF_LOWBIAS32(x);
    return x;
}

#if defined(__x86_64__) || defined(__i386__)
#define WF_X86 1
__attribute__((target("avx2,fma"))) static void
trace_avx2(const struct wf_scene *ws, struct wf_state *S,
           const struct wf_run *run, struct ptrace_out *out)
{
    trace_body_w8(ws, S, run, out);
}

__attribute__((target("avx2,fma"))) static void
fresnel_avx2(const float *cos_i, const float *eta, float *f, float *cos_t,
             int n)
{
    fresnel_body_w8(cos_i, eta, f, cos_t, n);
}
#endif

static void trace_generic(const struct wf_scene *ws, struct wf_state *S,
                          const struct wf_run *run, struct ptrace_out *out)
{
    trace_body_w4(ws, S, run, out);
}

/* Whether the AVX2 kernel runs: the CPU has AVX2 and FMA, and
** IRIS_WAVEFRONT_KERNEL is not "generic" (tests compare the two). */
static bool have_avx2(void)
{
    const char *k = getenv("IRIS_WAVEFRONT_KERNEL");
    if (k && strcmp(k, "generic") == 0)
        return false;
#ifdef WF_X86
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#else
    return false;
#endif
}

void wf_trace(const struct wf_scene *ws, struct wf_state *st,
              const struct wf_run *run, struct ptrace_out *out)
{
#ifdef WF_X86
    if (ws->avx2) {
        trace_avx2(ws, st, run, out);
        return;
    }
#endif
    trace_generic(ws, st, run, out);
}

void wf_fresnel_lanes(const float *cos_i, const float *eta, float *f,
                      float *cos_t, int n)
{
#ifdef WF_X86
    if (have_avx2()) {
        fresnel_avx2(cos_i, eta, f, cos_t, n);
        return;
    }
#endif
    fresnel_body_w4(cos_i, eta, f, cos_t, n);
}

const char *wf_kernel_name(void)
{
    return have_avx2() ? "avx2" : "generic";
}

/* ---- the scenes it takes ---------------------------------------------- */

/* Whether the interior disperses or fades (fade: not in lanes). */
static bool fades(const iris_interior *in)
{
    return in && in->fade_power > 0.0 && fabs(in->fade_distance) > 1e-10;
}

static bool grey3(iris_colour c)
{
    return c.r == c.g && c.g == c.b;
}

/* A constituent of a convex object in world space: a half-space c·x <= d
** (c its unit outward normal), a ball (centre c, radius d), or an
** infinite cylinder (through c along the unit axis a, radius d). */
struct wf_half {
    int kind;
    vec3 c;
    double d;
    vec3 a;
};

/* An object the lanes meet, in world space. */
enum wf_kind { WF_SPHERE, WF_PLANE, WF_CONVEX };
struct wf_obj {
    const iris_object *o;      /* its surface: the leaf (a CSG's first) */
    const iris_object *top;    /* the scene's object */
    enum wf_kind kind;
    bool sphere;               /* kind == WF_SPHERE */
    vec3 c;                    /* sphere centre, or plane's unit normal */
    double r;                  /* radius, or the plane's distance */
    vec3 wn;                   /* plane: the hit normal */
    vec3 lo, hi;               /* sphere, convex: the world box */
    double size;               /* sphere: r; convex: half the box's
                                  diagonal */
    int nh;                    /* convex: its constituents */
    struct wf_half h[WF_MAX_HALF];
};

/* A primitive as the kernel reads it, for pair 'c'; false (and *why)
** when its surface is not one the lanes handle. */

static bool fill_prim(const struct ptrace_combo *c, const struct wf_obj *ob,
                      int k, struct wf_prims *P, struct ptrace_tex_cache *tc,
                      const char **why)
{
    const iris_object *o = ob->o;
    if (o->photon_pass_through) {
        *why = "pass_through object";
        return false;
    }
    const struct ptrace_tex *e = ptrace_tex_get(c, tc, o->texture);
    if (!e || !e->uniform) {
        *why = "patterned texture";
        return false;
    }
    const iris_finish *fin = e->fin;
    bool diffusive = fin && fin->diffuse > 0.0 && e->opacity > 0.0;
    int fl = 0;
    if (o->photon_collect && diffusive)
        fl |= WF_STORE;
    if (o == c->target || ob->top == c->target)
        fl |= WF_TARGET;
    bool refr_allowed = ptrace_allowed(o->photon_refraction,
                                       c->light->photon_refraction);
    bool refl_allowed = ptrace_allowed(o->photon_reflection,
                                       c->light->photon_reflection);
    if (refl_allowed)
        fl |= WF_REFL_OK;
    const iris_interior *in = o->interior;
    float transm = (float)e->transm, p = 0.0f, q = 0.0f, n = 1.0f;
    if (in && e->transm > 0.0 && refr_allowed) {
        fl |= WF_REFR;
        if (fades(in)) {
            *why = "interior fade";
            return false;
        }
        if (ior_is_dispersive(in)) {
            fl |= WF_DISP;
            P->any_disp = true;
            for (int i = 0; i < WF_IOR_N; i++)
                P->ior_tab[k][i] = (float)ior_eval(
                    in, SPEC_LAMBDA_MIN + SPEC_LAMBDA_RANGE * i /
                                              (WF_IOR_N - 1.0));
        }
        n = (float)ior_eval(in, 550.0);
        if (!(n > 0.0f) || !isfinite(n)) {
            *why = "unusable ior";
            return false;
        }
    } else {
        if (!e->no_reflection && refl_allowed) {
            if (fin->reflection_fresnel || fin->reflection_metallic != 0.0 ||
                !grey3(fin->reflection_max) ||
                fin->reflection_max.r != fin->reflection_min.r) {
                *why = "reflection varying with angle or colour";
                return false;
            }
            double r = fin->reflection_max.r;
            p = (float)(r > 1.0 ? 1.0 : r > 0.0 ? r : 0.0);
        }
        if (!in && refr_allowed && e->transm > 0.0)
            q = transm;
    }
    /* A coloured filter where the lanes read it (a refraction's gain, or
    ** q): its transmittance at every lambda, > 0 everywhere, where the
    ** scalar tracer's test of the siblings' mean (> 0) and each lane's
    ** agree (1 nm samples: the upsampled curves' second derivative makes
    ** the interpolation's error < 1e-5) */
    if (!e->transm_grey && refr_allowed && !(e->transm > 0.0)) {
        *why = "a coloured filter opaque at 550 nm";
        return false;
    }
    if (!e->transm_grey && ((fl & WF_REFR) || q > 0.0f)) {
        fl |= WF_TSPEC;
        P->any_tspec = true;
        for (int i = 0; i < WF_IOR_N; i++) {
            double t = ptrace_tex_transm(
                e, SPEC_LAMBDA_MIN + SPEC_LAMBDA_RANGE * i / (WF_IOR_N - 1.0));
            if (!(t > 0.0)) {
                *why = "a coloured filter blocking some wavelength";
                return false;
            }
            P->tr_tab[k][i] = (float)t;
        }
    }
    P->flags[k] = fl;
    P->transm[k] = transm;
    P->ior[k] = n;
    P->pm[k] = p;
    P->qm[k] = q;
    if (ob->kind == WF_CONVEX) {
        /* the lanes carry their constituent's normal (wf_kernel.h) */
        P->nka[k] = 0.0f;
        P->nsc[k] = 1.0f;
    } else if (ob->sphere) {
        P->ncx[k] = (float)ob->c.x;
        P->ncy[k] = (float)ob->c.y;
        P->ncz[k] = (float)ob->c.z;
        P->nka[k] = 1.0f;
        P->nsc[k] = (float)(1.0 / ob->r);
    } else {
        P->ncx[k] = (float)-ob->wn.x;
        P->ncy[k] = (float)-ob->wn.y;
        P->ncz[k] = (float)-ob->wn.z;
        P->nka[k] = 0.0f;
        P->nsc[k] = 1.0f;
    }
    return true;
}

/* Whether box a is apart from box b by more than 'm' along some axis. */
static bool boxes_apart(vec3 alo, vec3 ahi, vec3 blo, vec3 bhi, double m)
{
    return alo.x > bhi.x + m || blo.x > ahi.x + m || alo.y > bhi.y + m ||
           blo.y > ahi.y + m || alo.z > bhi.z + m || blo.z > ahi.z + m;
}

/* Whether the box lies wholly on one side of the plane n·x = d, more than
** 'm' from it (n unit). */
static bool box_beside_plane(vec3 lo, vec3 hi, vec3 n, double d, double m)
{
    double mn = (n.x >= 0 ? n.x * lo.x : n.x * hi.x) +
                (n.y >= 0 ? n.y * lo.y : n.y * hi.y) +
                (n.z >= 0 ? n.z * lo.z : n.z * hi.z);
    double mx = (n.x >= 0 ? n.x * hi.x : n.x * lo.x) +
                (n.y >= 0 ? n.y * hi.y : n.y * lo.y) +
                (n.z >= 0 ? n.z * hi.z : n.z * lo.z);
    return mn > d + m || mx < d - m;
}

/* Whether a refracting sphere or convex object 'a' is clear of 'b' (a
** lane inside it can meet no other surface, so its medium is known: the
** object or none). Spheres exactly; a convex object by its world box,
** which only refuses more. */
static bool clear_of(const struct wf_obj *a, const struct wf_obj *b)
{
    double margin = 1e-4 * a->size;
    if (a->sphere && b->sphere)
        return v3_len(v3_sub(a->c, b->c)) > a->r + b->r + margin;
    if (a->sphere && b->kind == WF_PLANE)
        return fabs(v3_dot(b->c, a->c) - b->r) > a->r + margin;
    if (b->kind == WF_PLANE)
        return box_beside_plane(a->lo, a->hi, b->c, b->r, margin);
    return boxes_apart(a->lo, a->hi, b->lo, b->hi, margin);
}

/* The scale of 'o's transform when it is a similarity (its 3x3 part an
** orthogonal matrix times s > 0, within 1e-9): it takes a sphere to a
** sphere of s times the radius. 1 without a transform, 0 otherwise. */
static double similarity_scale(const iris_object *o)
{
    if (!o->has_transform)
        return 1.0;
    const double(*m)[4] = o->transform.m;
    vec3 col[3];
    for (int j = 0; j < 3; j++)
        col[j] = v3(m[0][j], m[1][j], m[2][j]);
    double s2 = v3_len2(col[0]);
    if (!(s2 > 0.0) || !isfinite(s2))
        return 0.0;
    for (int j = 0; j < 3; j++) {
        if (fabs(v3_len2(col[j]) - s2) > 1e-9 * s2 ||
            fabs(v3_dot(col[j], col[(j + 1) % 3])) > 1e-9 * s2)
            return 0.0;
    }
    return sqrt(s2);
}

/* The world plane of the object-space plane n·x = d of 'o' (n unit): an
** affine map takes it to a plane; *wn its unit normal, the distance
** returned. False when the transform makes it unusable. */
static bool world_plane(const iris_object *o, vec3 n, double d, vec3 *wn,
                        double *wd)
{
    if (!o->has_transform) {
        *wn = n;
        *wd = d;
        return true;
    }
    vec3 p0 = xf_point(&o->transform, v3_scale(n, d));
    vec3 m = xf_normal(&o->transform, n);
    double len = v3_len(m);
    if (!(len > 0.0) || !isfinite(len))
        return false;
    *wn = v3_scale(m, 1.0 / len);
    *wd = v3_dot(*wn, p0);
    return isfinite(*wd);
}

static bool add_half(struct wf_obj *ob, int kind, vec3 c, double d, vec3 a,
                     const char **why)
{
    if (ob->nh >= WF_MAX_HALF) {
        *why = "a convex object of too many faces";
        return false;
    }
    ob->h[ob->nh++] = (struct wf_half){ kind, c, d, a };
    return true;
}

/* The object-space half-space n·x <= d of 'o' added in world space. */
static bool add_plane(struct wf_obj *ob, const iris_object *o, vec3 n,
                      double d, const char **why)
{
    vec3 wn;
    double wd;
    if (!world_plane(o, n, d, &wn, &wd)) {
        *why = "an unusable transform";
        return false;
    }
    return add_half(ob, WF_HALF_PLANE, wn, wd, v3(0, 0, 0), why);
}

/* The walls and caps of a linear prism whose profile is one convex
** polygon (the last point closing it; points (u, v) at (x, z), swept
** along y between the heights: src/geometry/sweep.c). */
static bool add_prism(struct wf_obj *ob, const iris_object *o,
                      const char **why)
{
    const iris_vec2 *q = o->u.prism.points;
    int n = o->u.prism.n_points - 1; /* the polygon's corners */
    if (o->u.prism.spline != IRIS_SPLINE_LINEAR || o->u.prism.sweep != 0 ||
        n < 3 || !q || q[n].u != q[0].u || q[n].v != q[0].v) {
        *why = "a prism other than one closed linear polygon";
        return false;
    }
    double cu = 0.0, cv = 0.0, turn = 0.0;
    for (int i = 0; i < n; i++) {
        cu += q[i].u / n;
        cv += q[i].v / n;
    }
    for (int i = 0; i < n; i++) {
        const iris_vec2 *a = &q[i], *b = &q[i + 1], *c = &q[(i + 2) % n];
        double x = (b->u - a->u) * (c->v - b->v) -
                   (b->v - a->v) * (c->u - b->u);
        /* every corner turning the same way, none straight: convex, and
        ** no point repeated (a second sub-polygon) */
        if (!(x != 0.0) || (turn != 0.0 && (x > 0) != (turn > 0))) {
            *why = "a prism whose polygon is not convex";
            return false;
        }
        turn = x;
        vec3 nn = v3(b->v - a->v, 0.0, -(b->u - a->u));
        double len = v3_len(nn);
        nn = v3_scale(nn, 1.0 / len);
        /* outward: away from the centroid */
        if (nn.x * (cu - a->u) + nn.z * (cv - a->v) > 0.0)
            nn = v3_neg(nn);
        if (!add_plane(ob, o, nn, nn.x * a->u + nn.z * a->v, why))
            return false;
    }
    double h1 = o->u.prism.height1, h2 = o->u.prism.height2;
    double lo = fmin(h1, h2), hi = fmax(h1, h2);
    if (!(hi > lo)) {
        *why = "a flat prism";
        return false;
    }
    return add_plane(ob, o, v3(0, 1, 0), hi, why) &&
           add_plane(ob, o, v3(0, -1, 0), -lo, why);
}

/* Whether two leaves of one convex object show the same surface (the
** lanes read one object's). */
static bool same_surface(const iris_object *a, const iris_object *b)
{
    return a->texture == b->texture && a->interior == b->interior &&
           a->interior_texture == b->interior_texture &&
           a->photon_refraction == b->photon_refraction &&
           a->photon_reflection == b->photon_reflection &&
           a->photon_collect == b->photon_collect &&
           a->photon_pass_through == b->photon_pass_through &&
           a->no_shadow == b->no_shadow;
}

/* Adds the constituents of 'o' (a leaf, or an intersection of them) to
** the convex object 'ob'. */
static bool add_convex(struct wf_obj *ob, const iris_object *o,
                       const char **why)
{
    if (o->n_clipped_by > 0 || o->bounded_by) {
        *why = "clipped_by or bounded_by";
        return false;
    }
    if (o->kind == IRIS_OBJ_INTERSECTION) {
        if (o->inverse) {
            *why = "an inverse intersection";
            return false;
        }
        for (int i = 0; i < o->u.csg.n_children; i++)
            if (!add_convex(ob, o->u.csg.children[i], why))
                return false;
        return true;
    }
    if (!ob->o) {
        ob->o = o;
    } else if (!same_surface(ob->o, o)) {
        *why = "parts of one object with different surfaces";
        return false;
    }
    if (o->inverse && o->kind != IRIS_OBJ_PLANE) {
        *why = "an inverse shape";
        return false;
    }
    switch (o->kind) {
    case IRIS_OBJ_PLANE: {
        vec3 n = v3_norm(o->u.plane.normal);
        if (!(isfinite(n.x) && isfinite(n.y) && isfinite(n.z))) {
            *why = "an unusable plane";
            return false;
        }
        double d = o->u.plane.distance;
        /* POV-Ray's plane is inside below: n·x < d; inverse above */
        if (o->inverse) {
            n = v3_neg(n);
            d = -d;
        }
        return add_plane(ob, o, n, d, why);
    }
    case IRIS_OBJ_SPHERE: {
        double s = similarity_scale(o), r = o->u.sphere.radius * s;
        if (!(r > 0.0) || !isfinite(r)) {
            *why = "a sphere transformed other than by a similarity";
            return false;
        }
        vec3 c = o->has_transform ? xf_point(&o->transform, o->u.sphere.centre)
                                  : o->u.sphere.centre;
        return add_half(ob, WF_HALF_BALL, c, r, v3(0, 0, 0), why);
    }
    case IRIS_OBJ_CYLINDER: {
        /* a capped cylinder: the infinite one and the two caps' planes
        ** (an open one is a tube without an inside: refused) */
        double s = similarity_scale(o), r = o->u.cylinder.radius * s;
        vec3 b = o->u.cylinder.base, c = o->u.cylinder.cap;
        if (o->has_transform) {
            b = xf_point(&o->transform, b);
            c = xf_point(&o->transform, c);
        }
        vec3 ax = v3_sub(c, b);
        double len = v3_len(ax);
        if (o->open || !(r > 0.0) || !isfinite(r) || !(len > 0.0) ||
            !isfinite(len)) {
            *why = "an open or degenerate cylinder, or one transformed "
                   "other than by a similarity";
            return false;
        }
        ax = v3_scale(ax, 1.0 / len);
        return add_half(ob, WF_HALF_CYL, b, r, ax, why) &&
               add_half(ob, WF_HALF_PLANE, ax, v3_dot(ax, c), v3(0, 0, 0),
                        why) &&
               add_half(ob, WF_HALF_PLANE, v3_neg(ax), -v3_dot(ax, b),
                        v3(0, 0, 0), why);
    }
    case IRIS_OBJ_BOX: {
        vec3 a = o->u.box.lo, b = o->u.box.hi;
        vec3 lo = v3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
        vec3 hi = v3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
        if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) {
            *why = "a flat box";
            return false;
        }
        return add_plane(ob, o, v3(1, 0, 0), hi.x, why) &&
               add_plane(ob, o, v3(-1, 0, 0), -lo.x, why) &&
               add_plane(ob, o, v3(0, 1, 0), hi.y, why) &&
               add_plane(ob, o, v3(0, -1, 0), -lo.y, why) &&
               add_plane(ob, o, v3(0, 0, 1), hi.z, why) &&
               add_plane(ob, o, v3(0, 0, -1), -lo.z, why);
    }
    case IRIS_OBJ_PRISM:
        return add_prism(ob, o, why);
    default:
        *why = "a shape the lanes do not intersect";
        return false;
    }
}

/*
** A tighter world box of the convex object 'b' than accel's (which bounds
** a CSG intersection by its parts' boxes: the gem's pavilion facets gave
** one reaching through its floor): the box of the vertices of the
** polyhedron cut by its half-spaces and accel's box's six faces, every
** triple of planes meeting in a point that all of them contain. That
** polyhedron contains the object (its balls and cylinders only cut it
** more), so the box still bounds the object; it is bounded by the six
** faces. Vertices within 1e-9 of the box's size of a face count.
*/
static void tighten_box(struct wf_obj *b)
{
    struct wf_half pl[WF_MAX_HALF + 6];
    int n = 0;
    for (int i = 0; i < b->nh; i++)
        if (b->h[i].kind == WF_HALF_PLANE)
            pl[n++] = b->h[i];
    const double lo[3] = { b->lo.x, b->lo.y, b->lo.z };
    const double hi[3] = { b->hi.x, b->hi.y, b->hi.z };
    for (int a = 0; a < 3; a++) {
        vec3 e = v3(a == 0, a == 1, a == 2);
        pl[n++] = (struct wf_half){ WF_HALF_PLANE, e, hi[a], v3(0, 0, 0) };
        pl[n++] = (struct wf_half){ WF_HALF_PLANE, v3_neg(e), -lo[a],
                                    v3(0, 0, 0) };
    }
    double tol = 1e-9 * (1.0 + v3_len(b->lo) + v3_len(b->hi));
    vec3 vlo = v3(INFINITY, INFINITY, INFINITY), vhi = v3_neg(vlo);
    int nv = 0;
    for (int i = 0; i < n; i++)
        for (int j = i + 1; j < n; j++)
            for (int k = j + 1; k < n; k++) {
                /* Cramer's rule: x = (d_i (nj x nk) + d_j (nk x ni) +
                ** d_k (ni x nj)) / (ni · (nj x nk)) */
                vec3 jk = v3_cross(pl[j].c, pl[k].c);
                double det = v3_dot(pl[i].c, jk);
                if (!(fabs(det) > 1e-12))
                    continue;
                vec3 x = v3_scale(
                    v3_add(v3_add(v3_scale(jk, pl[i].d),
                                  v3_scale(v3_cross(pl[k].c, pl[i].c),
                                           pl[j].d)),
                           v3_scale(v3_cross(pl[i].c, pl[j].c), pl[k].d)),
                    1.0 / det);
                bool in = true;
                for (int m = 0; m < n && in; m++)
                    in = v3_dot(pl[m].c, x) <= pl[m].d + tol;
                if (!in)
                    continue;
                nv++;
                vlo = v3(fmin(vlo.x, x.x), fmin(vlo.y, x.y),
                         fmin(vlo.z, x.z));
                vhi = v3(fmax(vhi.x, x.x), fmax(vhi.y, x.y),
                         fmax(vhi.z, x.z));
            }
    if (nv < 4)
        return; /* degenerate: keep accel's */
    vec3 t = v3(tol, tol, tol);
    b->lo = v3(fmax(b->lo.x, vlo.x - t.x), fmax(b->lo.y, vlo.y - t.y),
               fmax(b->lo.z, vlo.z - t.z));
    b->hi = v3(fmin(b->hi.x, vhi.x + t.x), fmin(b->hi.y, vhi.y + t.y),
               fmin(b->hi.z, vhi.z + t.z));
}

/* The scene's objects in the kernel's order (spheres, planes, convex
** objects), without those photons skip (no_shadow), in world space; n < 0
** when outside the set. */
static int scene_prims(const iris_scene *sc, const struct pmap_world *w,
                       struct wf_obj *ob, int *ns, int *np,
                       const char **why)
{
    int n = 0;
    *ns = *np = 0;
    for (int pass = 0; pass < 3; pass++)
        for (int i = 0; i < sc->n_objects; i++) {
            const iris_object *o = sc->objects[i];
            enum wf_kind kind = o->kind == IRIS_OBJ_SPHERE  ? WF_SPHERE
                                : o->kind == IRIS_OBJ_PLANE ? WF_PLANE
                                                            : WF_CONVEX;
            if ((int)kind != pass || o->no_shadow)
                continue;
            if (n >= WF_MAX_OBJ) {
                *why = "more than 8 objects";
                return -1;
            }
            struct wf_obj *b = &ob[n];
            memset(b, 0, sizeof *b);
            b->o = b->top = o;
            b->kind = kind;
            b->sphere = kind == WF_SPHERE;
            if (kind != WF_CONVEX &&
                (o->n_clipped_by > 0 || o->bounded_by)) {
                *why = "clipped_by or bounded_by";
                return -1;
            }
            if (kind == WF_SPHERE) {
                double s = similarity_scale(o);
                if (s == 0.0 || o->inverse) {
                    *why = "a sphere inverse or transformed other than by "
                           "a similarity";
                    return -1;
                }
                b->r = o->u.sphere.radius * s;
                if (!(b->r > 0.0) || !isfinite(b->r))
                    continue; /* never hit (fastpath.c) */
                b->c = o->has_transform
                           ? xf_point(&o->transform, o->u.sphere.centre)
                           : o->u.sphere.centre;
                vec3 rr = v3(b->r, b->r, b->r);
                b->lo = v3_sub(b->c, rr);
                b->hi = v3_add(b->c, rr);
                b->size = b->r;
                (*ns)++;
            } else if (kind == WF_PLANE) {
                vec3 pn = v3_norm(o->u.plane.normal);
                if (!(isfinite(pn.x) && isfinite(pn.y) && isfinite(pn.z)))
                    continue; /* never hit (fastpath.c) */
                if (!world_plane(o, pn, o->u.plane.distance, &b->c, &b->r)) {
                    *why = "an unusable transform";
                    return -1;
                }
                b->wn = v3_scale(b->c, o->inverse ? -1.0 : 1.0);
                (*np)++;
            } else {
                b->o = NULL;
                if (!add_convex(b, o, why))
                    return -1;
                if (!w->object_bounds(w->ctx, o, &b->lo, &b->hi)) {
                    *why = "a convex object without a box";
                    return -1;
                }
                tighten_box(b);
                b->size = 0.5 * v3_len(v3_sub(b->hi, b->lo));
                if (!(b->size > 0.0) || !isfinite(b->size)) {
                    *why = "a convex object without a box";
                    return -1;
                }
            }
            n++;
        }
    return n;
}

static bool build_pair(const iris_scene *sc, const struct pmap_world *w,
                       const struct ptrace_combo *c,
                       const struct wf_light *L, struct wf_prims *P,
                       const char **why)
{
    if (c->global || c->media.scene || c->n_stack > 0) {
        *why = "global, media, or light inside an object";
        return false;
    }
    if (c->fade_power > 0.0 && fabs(c->fade_distance) > 1e-10) {
        *why = "light fade";
        return false;
    }
    /* the lanes know the scene's top-level objects, and a first hit is
    ** on the target when it is on its top-level object: not so for a
    ** target inside a CSG (targets.c), left to trace.c */
    bool top_level = false;
    for (int i = 0; i < sc->n_objects && !top_level; i++)
        top_level = sc->objects[i] == c->target;
    if (!top_level) {
        *why = "a target inside a CSG";
        return false;
    }
    const iris_light *l = c->light;
    if (L->atten != WF_ATTEN_ONE && l->tightness > 0.0) {
        *why = "light tightness";
        return false;
    }
    struct wf_obj ob[WF_MAX_OBJ];
    int ns, np, n = scene_prims(sc, w, ob, &ns, &np, why);
    if (n < 0)
        return false;
    memset(P, 0, sizeof *P);
    P->ns = ns;
    P->np = np;
    P->nc = n - ns - np;
    P->max_level = c->max_level;
    P->parallel = c->parallel;
    struct ptrace_tex_cache tc;
    memset(&tc, 0, sizeof tc);
    int n_refr = 0, refr_plane = 0, nh = 0;
    for (int k = 0; k < n; k++) {
        if (!fill_prim(c, &ob[k], k, P, &tc, why))
            return false;
        if (ob[k].kind == WF_SPHERE) {
            P->sc[k][0] = (float)ob[k].c.x;
            P->sc[k][1] = (float)ob[k].c.y;
            P->sc[k][2] = (float)ob[k].c.z;
            P->sr2[k] = (float)(ob[k].r * ob[k].r);
        } else if (ob[k].kind == WF_PLANE) {
            P->pn[k - ns][0] = (float)ob[k].c.x;
            P->pn[k - ns][1] = (float)ob[k].c.y;
            P->pn[k - ns][2] = (float)ob[k].c.z;
            P->pd[k - ns] = (float)ob[k].r;
        } else {
            int j = k - ns - np;
            P->cfirst[j] = nh;
            P->ccount[j] = ob[k].nh;
            for (int i = 0; i < ob[k].nh; i++, nh++) {
                const struct wf_half *h = &ob[k].h[i];
                if (nh >= WF_MAX_HALF) {
                    *why = "convex objects of too many faces";
                    return false;
                }
                bool round = h->kind != WF_HALF_PLANE;
                P->hkind[nh] = h->kind;
                P->hc[nh][0] = (float)h->c.x;
                P->hc[nh][1] = (float)h->c.y;
                P->hc[nh][2] = (float)h->c.z;
                /* a ball, a cylinder: the squared radius, as the spheres'
                ** sr2 */
                P->hd[nh] = (float)(round ? h->d * h->d : h->d);
                /* the outward normal (p·ka - n)·s, less its part along
                ** the axis: a ball's (p - c)/r, a cylinder's the same
                ** without the axial part, a half-space's its own */
                P->hnx[nh] = (float)(round ? h->c.x : -h->c.x);
                P->hny[nh] = (float)(round ? h->c.y : -h->c.y);
                P->hnz[nh] = (float)(round ? h->c.z : -h->c.z);
                P->hka[nh] = round ? 1.0f : 0.0f;
                P->hsc[nh] = (float)(round ? 1.0 / h->d : 1.0);
                P->hax[nh] = (float)h->a.x;
                P->hay[nh] = (float)h->a.y;
                P->haz[nh] = (float)h->a.z;
                P->any_cyl |= h->kind == WF_HALF_CYL;
            }
        }
        if (P->flags[k] & WF_REFR) {
            n_refr++;
            refr_plane += ob[k].kind == WF_PLANE;
        }
    }
    /* Float's rounding (6e-8 of a coordinate, of a sphere's radius in
    ** its discriminant) must stay far below the target: every primitive
    ** and the light within 1e4 target sizes (a sphere's radius, half a
    ** convex object's box diagonal) of the origin (a ground sphere of
    ** radius 1e6 under a ball of radius 1 would misplace its hits by
    ** ~0.1: the scalar tracer's double takes such scenes) */
    double reach = v3_len(L->parallel ? L->base : L->origin);
    double target = -1.0;
    for (int k = 0; k < n; k++) {
        if (ob[k].kind == WF_PLANE) {
            reach = fmax(reach, fabs(ob[k].r));
            continue;
        }
        reach = fmax(reach, fmax(v3_len(ob[k].lo), v3_len(ob[k].hi)));
        if (ob[k].top == c->target)
            target = ob[k].size;
    }
    if (!(target > 0.0) || !(reach <= 1e4 * target)) {
        *why = "the scene too large for float against its target";
        return false;
    }
    /* a lane's medium is the refracting object it is in, or none: a
    ** refracting object stays clear of every object a lane can pass
    ** through (refracting, or filtering without an interior). One that
    ** only absorbs or mirrors may cut into it (the gem's tip through its
    ** floor): a lane meeting it inside the glass ends there or mirrors
    ** and stays inside, as the scalar tracer's interior stack keeps it. */
    if (refr_plane && n_refr > 1) {
        *why = "a refracting plane beside other refracting objects";
        return false;
    }
    for (int k = 0; k < n; k++)
        for (int j = 0; j < n && (P->flags[k] & WF_REFR) &&
                        ob[k].kind != WF_PLANE;
             j++)
            if (j != k && ((P->flags[j] & WF_REFR) || P->qm[j] > 0.0f) &&
                !clear_of(&ob[k], &ob[j])) {
                *why = "a refracting object touching another it passes";
                return false;
            }
    return true;
}

struct wf_scene *wf_build(const iris_scene *scene, const struct pmap_world *w,
                          const struct ptrace_combo *const *tc,
                          const struct wf_light *L, int n, const char **why)
{
    const char *dummy;
    if (!why)
        why = &dummy;
    *why = NULL;
    if (!pmap_world_is_scene(w)) {
        *why = "a world other than the scene's geometry";
        return NULL;
    }
    if (n <= 0) {
        *why = "no pairs";
        return NULL;
    }
    struct wf_scene *ws = iris_calloc(1, sizeof *ws);
    if (ws) {
        ws->prims = iris_calloc((size_t)n, sizeof *ws->prims);
        ws->light = iris_calloc((size_t)n, sizeof *ws->light);
    }
    if (!ws || !ws->prims || !ws->light) {
        *why = "out of memory";
        wf_destroy(ws);
        return NULL;
    }
    ws->n = n;
    for (int i = 0; i < n; i++) {
        ws->light[i] = L[i];
        if (!build_pair(scene, w, tc[i], &L[i], &ws->prims[i], why)) {
            wf_destroy(ws);
            return NULL;
        }
    }
    for (unsigned m = 0; m < 256; m++) {
        int k = 0, k4 = 0;
        for (int l = 0; l < 8; l++)
            if (m >> l & 1)
                ws->perm8[m][k++] = l;
        for (int l = 0; l < 8; l++)
            if (!(m >> l & 1))
                ws->perm8[m][k++] = l;
        for (int l = 0; l < 4 && m < 16; l++)
            if (m >> l & 1)
                ws->perm4[m][k4++] = l;
        for (int l = 0; l < 4 && m < 16; l++)
            if (!(m >> l & 1))
                ws->perm4[m][k4++] = l;
    }
    ws->avx2 = have_avx2();
    return ws;
}

bool wf_sibling_lanes(const struct wf_scene *ws, int combo)
{
    return ws->prims[combo].any_tspec;
}

void wf_destroy(struct wf_scene *ws)
{
    if (!ws)
        return;
    iris_free(ws->prims);
    iris_free(ws->light);
    iris_free(ws);
}

struct wf_state *wf_state_new(void)
{
    return iris_calloc(1, sizeof(struct wf_state));
}

void wf_state_free(struct wf_state *st)
{
    iris_free(st);
}
