/* SPDX-License-Identifier: MIT */
/*
** wavefront.c: caustic photons of sphere-and-plane scenes traced eight at
** a time (wavefront.h).
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
** SELF-HITS without an epsilon: a lane remembers the primitive it left.
** A plane is not asked again; a sphere is asked for its far crossing only,
** and only when the lane goes into it (d·(o - c) < 0 at its surface): the
** shapes are convex, so nothing else can be hit there.
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

#include "photon/fastpath.h"
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

/* Samples of a dispersive interior's n(lambda) over [380, 780] nm, read
** with linear interpolation: 1 nm steps, where the Cauchy and Sellmeier
** curves' second derivative makes the error < 1e-7. */
#define WF_IOR_N 401

/* One pair's primitives as the kernel reads them. Spheres are numbered
** 0..ns-1, planes ns..ns+np-1 (at most PFAST_MAX_PRIMS in all). */
struct wf_prims {
    int ns, np;
    float sc[PFAST_MAX_PRIMS][3], sr2[PFAST_MAX_PRIMS];
    float pn[PFAST_MAX_PRIMS][3], pd[PFAST_MAX_PRIMS];
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
    float ior_tab[PFAST_MAX_PRIMS][WF_IOR_N]; /* WF_DISP primitives */
    float tr_tab[PFAST_MAX_PRIMS][WF_IOR_N];  /* WF_TSPEC primitives */
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

/* A 32-bit integer hash (the "lowbias32" constants of C. Wellons'
** hash-prospector): the seed mix of the lanes' random numbers. */
static uint32_t hash1(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
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

/* A primitive as the kernel reads it, for pair 'c'; false (and *why)
** when its surface is not one the lanes handle. */
struct wf_obj {
    const iris_object *o;
    bool sphere;
    vec3 c;                    /* centre or unit normal (object space) */
    double r;                  /* radius or distance */
    vec3 wn;                   /* plane: the hit normal */
};

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
    if (o == c->target)
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
    if (ob->sphere) {
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

/* Whether a refracting sphere 'a' is clear of 'b' (a lane inside it can
** meet no other surface, so its medium is known: the sphere or none). */
static bool clear_of(const struct wf_obj *a, const struct wf_obj *b)
{
    double margin = 1e-4 * a->r;
    if (b->sphere)
        return v3_len(v3_sub(a->c, b->c)) > a->r + b->r + margin;
    return fabs(v3_dot(b->c, a->c) - b->r) > a->r + margin;
}

/* The scene's primitives in the fast path's order (spheres, then planes),
** without those photons skip (no_shadow); n < 0 when outside the set. */
static int scene_prims(const iris_scene *sc, struct wf_obj ob[PFAST_MAX_PRIMS],
                       int *ns, const char **why)
{
    int n = 0;
    *ns = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < sc->n_objects; i++) {
            const iris_object *o = sc->objects[i];
            bool sphere = o->kind == IRIS_OBJ_SPHERE;
            if (sphere != (pass == 0) || o->no_shadow)
                continue;
            if (o->has_transform || (sphere && o->inverse)) {
                *why = "transformed or inverse primitive";
                return -1;
            }
            struct wf_obj w = { o, sphere, v3(0, 0, 0), 0.0, v3(0, 0, 0) };
            if (sphere) {
                w.c = o->u.sphere.centre;
                w.r = o->u.sphere.radius;
                if (!(w.r > 0.0) || !isfinite(w.r))
                    continue;
                (*ns)++;
            } else {
                vec3 pn = v3_norm(o->u.plane.normal);
                if (!(isfinite(pn.x) && isfinite(pn.y) && isfinite(pn.z)))
                    continue; /* never hit (fastpath.c) */
                w.c = pn;
                w.r = o->u.plane.distance;
                w.wn = v3_scale(pn, o->inverse ? -1.0 : 1.0);
            }
            ob[n++] = w;
        }
    return n;
}

static bool build_pair(const iris_scene *sc, const struct ptrace_combo *c,
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
    const iris_light *l = c->light;
    if (L->atten != WF_ATTEN_ONE && l->tightness > 0.0) {
        *why = "light tightness";
        return false;
    }
    struct wf_obj ob[PFAST_MAX_PRIMS];
    int ns, n = scene_prims(sc, ob, &ns, why);
    if (n < 0)
        return false;
    memset(P, 0, sizeof *P);
    P->ns = ns;
    P->np = n - ns;
    P->max_level = c->max_level;
    P->parallel = c->parallel;
    struct ptrace_tex_cache tc;
    memset(&tc, 0, sizeof tc);
    int n_refr = 0, refr_plane = 0;
    for (int k = 0; k < n; k++) {
        if (!fill_prim(c, &ob[k], k, P, &tc, why))
            return false;
        if (ob[k].sphere) {
            P->sc[k][0] = (float)ob[k].c.x;
            P->sc[k][1] = (float)ob[k].c.y;
            P->sc[k][2] = (float)ob[k].c.z;
            P->sr2[k] = (float)(ob[k].r * ob[k].r);
        } else {
            P->pn[k - ns][0] = (float)ob[k].c.x;
            P->pn[k - ns][1] = (float)ob[k].c.y;
            P->pn[k - ns][2] = (float)ob[k].c.z;
            P->pd[k - ns] = (float)ob[k].r;
        }
        if (P->flags[k] & WF_REFR) {
            n_refr++;
            refr_plane += !ob[k].sphere;
        }
    }
    /* Float's rounding (6e-8 of a coordinate, of a sphere's radius in
    ** its discriminant) must stay far below the target: every primitive
    ** and the light within 1e4 target radii of the origin (a ground
    ** sphere of radius 1e6 under a ball of radius 1 would misplace its
    ** hits by ~0.1: the scalar tracer's double takes such scenes) */
    double reach = v3_len(L->parallel ? L->base : L->origin);
    for (int k = 0; k < n; k++)
        reach = fmax(reach, ob[k].sphere ? v3_len(ob[k].c) + ob[k].r
                                         : fabs(ob[k].r));
    const iris_object *t = c->target;
    if (!t || t->kind != IRIS_OBJ_SPHERE ||
        !(reach <= 1e4 * t->u.sphere.radius)) {
        *why = "the scene too large for float against its target";
        return false;
    }
    /* a lane's medium is the refracting sphere it is in, or none */
    if (refr_plane && n_refr > 1) {
        *why = "a refracting plane beside other refracting objects";
        return false;
    }
    for (int k = 0; k < ns; k++)
        for (int j = 0; j < n && (P->flags[k] & WF_REFR); j++)
            if (j != k && !clear_of(&ob[k], &ob[j])) {
                *why = "a refracting sphere touching another object";
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
    if (w->intersect != pfast_intersect || !pfast_plain(w->ctx)) {
        *why = "not the photon fast path's plain scene";
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
        if (!build_pair(scene, tc[i], &L[i], &ws->prims[i], why)) {
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
