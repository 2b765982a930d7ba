/* SPDX-License-Identifier: MIT */
/*
** trace.c: transport of one photon at one wavelength.
**
** Where POV-Ray's photons are not physical, these are (DESIGN.md):
**  - At a refracting surface POV-Ray spawns both a reflected and a
**    refracted photon at full power (semantics §2.5). Here the photon
**    reflects with the exact unpolarised Fresnel probability F(lambda)
**    and refracts otherwise (Russian roulette), keeping its power: the
**    expected power splits F : 1-F as in nature, with one path.
**  - POV-Ray's dispersion splits a photon into 'dispersion_samples'
**    RGB-tinted bands (§1.6). Here each photon carries one wavelength
**    and bends by n(lambda) from ior_eval(), at every interface.
**  - Pigment filter/transmit is a spectral transmittance
**    f·rho_rgb(lambda) + t (Burns' curve of the filter colour), and
**    interior fade a spectral absorption with POV-Ray's fade laws applied
**    to the fade colour's curve, instead of RGB products.
**  - Mirror reflection of surfaces without an interior (finish
**    reflection) is taken with Russian roulette on the spectral
**    reflectivity.
** White photons: when nothing on a photon's path depends on its wavelength
** (a light of flat emission, no dispersive medium, grey filters, fades and
** mirrors) the same path and power hold at every wavelength, and the photon
** is stored as white (pstore.h): it stands for the whole spectrum, and the
** estimate weighs it by the spectrum's mean instead of by one wavelength's
** RGB weight, so scenes without dispersion get no colour noise.
** Global photons (c->global; global.c, radiosity{}) take the same path
** with Lambertian bounces at diffuse surfaces, by Russian roulette on the
** albedo, and are stored from the second diffuse surface on.
** As in POV-Ray: photons pass through no_shadow objects (they are "shadow
** rays" for this purpose), but NOT through no_image objects, although
** POV-Ray 3.7 lets them pass (photons are launched as primary rays, so
** IsImageRay() is true for them: POV-Ray/povray#373, a bug). The first
** hit must be the target (or a pass_through object); photons are stored
** only after at least one bounce, on collecting surfaces with diffuse > 0.
*/
#include "config.h"

#include "photon/trace.h"

#include <math.h>
#include <string.h>

#include "material/material.h"
#include "spectrum/ior.h"
#include "spectrum/spectrum.h"
#include "util/mem.h"

/* pmap_fresnel(), inlined into the transport (twice per photon through a
** glass ball: the call was 8% of the shooting, perf) */
static inline double fresnel(double cos_i, double eta, double *cos_t)
{
    if (cos_i > 1.0)
        cos_i = 1.0;
    if (!(cos_i >= 0.0))
        cos_i = 0.0;
    double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
    if (sin2_t >= 1.0) {
        *cos_t = 0.0;
        return 1.0; /* total internal reflection */
    }
    double ct = sqrt(1.0 - sin2_t);
    *cos_t = ct;
    double rs = (eta * cos_i - ct) / (eta * cos_i + ct);
    double rp = (cos_i - eta * ct) / (cos_i + eta * ct);
    double f = 0.5 * (rs * rs + rp * rp);
    return f != f ? 1.0 : f;
}

double pmap_fresnel(double cos_i, double eta, double *cos_t)
{
    return fresnel(cos_i, eta, cos_t);
}

static double clamp01(double x)
{
    return x > 1.0 ? 1.0 : (x > 0.0 ? x : 0.0);
}

/* A grey colour upsamples to a flat curve (spectrum.h): no lambda. */
static bool grey(const double rgb[3])
{
    return rgb[0] == rgb[1] && rgb[1] == rgb[2];
}

/* spec_reflectance() without the table lookup for grey colours (Burns'
** three curves sum to 1, so grey g is the flat curve g): most filters,
** fades and mirrors are grey, and the lookup was 5% of the shooting. */
static double reflectance(const double rgb[3], double lambda)
{
    return grey(rgb) ? rgb[0] : spec_reflectance(rgb, lambda);
}

/* What a photon needs of the surface it hits. */
struct psurf {
    double transm;             /* spectral transmittance of the layers */
    double opacity;            /* top layer: 1 - filter - transmit */
    const iris_finish *fin;    /* top layer finish (NULL: none) */
    vec3 n;                    /* top layer normal, facing the photon */
    double refl[3];            /* top layer reflection colour */
    double pigment[3];         /* top layer pigment rgb (global photons'
                                  diffuse albedo) */
    bool reflects;
    bool transm_grey;          /* the transmittance is the same at every
                                  wavelength */
};

/*
** Evaluates the texture at hit 'h' for a photon arriving along 'd' with
** geometric normal 'nf' facing it: through mat_eval_texture() when the
** build has a material context (a texture_map's stacks are chosen by
** Russian roulette on their weights), otherwise from the top layer's solid
** pigment (the unit tests). The transmittance is the product over the
** layers of f·rho_rgb(lambda) + t.
*/
static void eval_surface(const struct ptrace_combo *c, const struct hit *h,
                         vec3 d, vec3 nf, double lambda, rng *r,
                         struct psurf *s)
{
    s->transm = 0.0;
    s->opacity = 1.0;
    s->fin = h->texture ? h->texture->finish : NULL;
    s->n = nf;
    s->reflects = false;
    s->transm_grey = true;
    s->pigment[0] = s->pigment[1] = s->pigment[2] = 0.0;
    double cos_i = -v3_dot(d, nf);
    if (!c->mat) {
        iris_colour col = { 0, 0, 0, 0, 0 };
        if (h->texture && h->texture->pigment)
            col = h->texture->pigment->colour;
        double rgb[3] = { col.r, col.g, col.b };
        double fr = col.f > 0.0 ? col.f * clamp01(reflectance(rgb, lambda))
                                : 0.0;
        s->transm = clamp01(fr + col.t);
        s->transm_grey = grey(rgb) || !(col.f > 0.0);
        s->opacity = 1.0 - col.f - col.t;
        for (int k = 0; k < 3; k++)
            s->pigment[k] = rgb[k];
        if (s->fin) {
            double fo = s->fin->reflection_falloff;
            double fl = fo == 1.0 ? 1.0 - cos_i : pow(1.0 - cos_i, fo);
            s->refl[0] = fl * s->fin->reflection_max.r +
                         (1 - fl) * s->fin->reflection_min.r;
            s->refl[1] = fl * s->fin->reflection_max.g +
                         (1 - fl) * s->fin->reflection_min.g;
            s->refl[2] = fl * s->fin->reflection_max.b +
                         (1 - fl) * s->fin->reflection_min.b;
            s->reflects = s->refl[0] > 0 || s->refl[1] > 0 || s->refl[2] > 0;
        }
        return;
    }
    struct mat_eval ev;
    struct mat_point pt = { h->p, nf, d, h->uv, h->obj, false };
    mat_eval_texture(c->mat, h->texture, &pt, &ev);
    if (ev.n_stacks <= 0)
        return;
    int k = 0;
    if (ev.n_stacks > 1) {
        double u = rng_uniform(r), acc = 0.0;
        for (k = 0; k < ev.n_stacks - 1; k++) {
            acc += ev.stacks[k].weight;
            if (u < acc)
                break;
        }
    }
    const struct mat_stack *st = &ev.stacks[k];
    double t = 1.0;
    for (int i = st->first; i < st->first + st->n; i++) {
        const struct mat_layer *ly = &ev.layers[i];
        if (!ly->valid)
            continue;
        double rgb[3] = { ly->pigment.r, ly->pigment.g, ly->pigment.b };
        t *= clamp01(ly->pigment.f > 0.0
                         ? ly->pigment.f * clamp01(reflectance(rgb, lambda)) +
                               ly->pigment.t
                         : ly->pigment.t);
        if (!grey(rgb) && ly->pigment.f > 0.0)
            s->transm_grey = false;
    }
    s->transm = t;
    if (st->n > 0 && ev.layers[st->first].valid) {
        const struct mat_layer *top = &ev.layers[st->first];
        s->opacity = mat_opacity(c->mat, &top->pigment);
        s->pigment[0] = top->pigment.r;
        s->pigment[1] = top->pigment.g;
        s->pigment[2] = top->pigment.b;
        s->fin = top->finish;
        if (v3_dot(top->n, nf) > 0.0)
            s->n = top->n;
        double w;
        s->reflects = mat_layer_reflectivity(top, -v3_dot(d, s->n), 1.0,
                                             s->refl, &w);
    }
}

/* Spectral transmittance of fade over a segment of length 'd'. */
static double fade_factor(const iris_interior *in, double d, double lambda)
{
    if (!in || !(in->fade_power > 0.0) || !(fabs(in->fade_distance) > 1e-10))
        return 1.0;
    double rgb[3] = { in->fade_colour.r, in->fade_colour.g,
                      in->fade_colour.b };
    double fc = clamp01(reflectance(rgb, lambda));
    if (in->fade_power >= 1000.0)
        return exp(-(1.0 - fc) * d / in->fade_distance);
    return fc + (1.0 - fc) /
                    (1.0 + pow(fabs(d / in->fade_distance), in->fade_power));
}

/* POV-Ray's flag logic for refraction/reflection (semantics §2.5). */
static bool allowed(enum iris_tristate obj, enum iris_tristate light)
{
    return (obj == IRIS_ON && light != IRIS_OFF) ||
           (obj != IRIS_OFF && light == IRIS_ON);
}

#define PTRACE_FIRST_CAP 4096

/* Stores a photon; lambda < 0 marks one whose path and power are the same
** at every wavelength (pstore.h: a white photon). */
static void deposit(struct ptrace_out *out, vec3 p, double power,
                    double lambda, vec3 from)
{
    if (out->n == out->cap) {
        /* a batch's photons mostly deposit once: start there */
        size_t cap = out->cap ? 2 * out->cap : PTRACE_FIRST_CAP;
        struct pstore_raw *ph =
            out->borrowed ? iris_malloc(cap * sizeof *ph)
                          : iris_realloc(out->ph, cap * sizeof *ph);
        if (!ph) {
            out->failed = true;
            return;
        }
        if (out->borrowed && out->n > 0)
            memcpy(ph, out->ph, out->n * sizeof *ph);
        out->borrowed = false;
        out->ph = ph;
        out->cap = cap;
    }
    struct pstore_raw *r = &out->ph[out->n++];
    r->p[0] = (float)p.x;
    r->p[1] = (float)p.y;
    r->p[2] = (float)p.z;
    r->power = (float)power;
    r->lambda = (float)lambda;
    r->dir[0] = (float)from.x;
    r->dir[1] = (float)from.y;
    r->dir[2] = (float)from.z;
}

/* POV-Ray's photon power at a point 'depth' along the path from a light
** (shoot.c): x D^2 (not for parallel lights) and the light's fade. */
static double landing_factor(const struct ptrace_combo *c, double depth)
{
    double f = c->parallel ? 1.0 : depth * depth;
    if (c->fade_power > 0.0 && fabs(c->fade_distance) > 1e-10)
        f *= 2.0 / (1.0 + pow(depth / c->fade_distance, c->fade_power));
    return f;
}

/* A cosine-weighted direction about unit 'n' (Malley's method). */
static vec3 cosine_dir(vec3 n, rng *r)
{
    vec3 a, b;
    v3_basis(n, &a, &b);
    double u = rng_uniform(r), v = rng_uniform(r);
    double rad = sqrt(u), ph = 2.0 * M_PI * v;
    double z = sqrt(fmax(0.0, 1.0 - u));
    return v3_norm(v3_add(v3_scale(n, z),
                          v3_add(v3_scale(a, rad * cos(ph)),
                                 v3_scale(b, rad * sin(ph)))));
}

/*
** Whether the stack entry 'in_stack' is the medium of the surface just hit
** (object 'obj', interior 'interior'). Keyed by the interior, as the eye
** tracer's stack (render/trace.c, interior_key) and POV-Ray's: the
** children of a CSG share their parent's interior, so a photon entering
** the outer cylinder of a glass tube (difference of two cylinders) and
** leaving through the inner one leaves the glass. Keyed by the child hit,
** it stayed "inside" the first child, crossed the hollow at ior 1.5 and
** left the far wall unrefracted (eta 1), and the light through a glass's
** walls went astray. An object without interior{} is keyed by its
** top-level object ('top', 'in_top'): POV-Ray gives a CSG without one a
** single default interior that its children share, so entering one child
** and leaving through another leaves it (the eye tracer does the same).
*/
static bool same_medium(const iris_object *in_stack,
                        const iris_object *in_top, const iris_object *obj,
                        const iris_object *top,
                        const iris_interior *interior)
{
    if (in_stack == obj)
        return true;
    if (interior != NULL)
        return in_stack->interior == interior;
    return in_stack->interior == NULL && top != NULL && in_top == top;
}

/* The index of the medium at the top of the stack (1 = atmosphere). */
static double top_ior(const iris_object *const *stack, int n, double lambda)
{
    return n > 0 ? ior_eval(stack[n - 1]->interior, lambda) : 1.0;
}

void ptrace_photon(const struct pmap_world *w, const struct ptrace_combo *c,
                   vec3 o, vec3 d, double lambda, double power, rng *r,
                   struct ptrace_out *out)
{
    /* the media the photon is in, innermost last, with the top-level
    ** object of each (the start's are top-level objects themselves) */
    const iris_object *stack[PTRACE_MAX_STACK], *tops[PTRACE_MAX_STACK];
    int n_stack = c->n_stack;
    for (int i = 0; i < n_stack; i++)
        stack[i] = tops[i] = c->stack[i];
    double depth = 0.0;
    struct hit h;
    bool chroma = c->chromatic; /* has lambda changed anything yet? */
    /* The first segment leaves the light (no surface): 1e-9 of the
    ** light's position (accel_origin_epsilon; the global offset would be
    ** 10 units with one hidden sphere of radius 1e10). Later ones leave hit h with its own offset h.eps (accel.h),
    ** as the eye tracer does: the global one is 1e-3 in a scene with a
    ** 1e6 sky sphere, thicker than a thin glass wall, and a photon would
    ** skip the wall's far side. A world that sets no h.eps (0) keeps the
    ** global offset. */
    double tmin = accel_origin_epsilon(o, w->epsilon);
    int max_level = c->global ? PTRACE_GLOBAL_MAX_LEVEL : c->max_level;
    int n_diffuse = 0;         /* global: diffuse bounces so far */
    bool landed = false;       /* global: D^2 and fade applied */
    for (int level = 1; level <= max_level && power > 0.0; level++) {
        ray ry = { o, d };
        h.eps = 0.0;
        if (!w->intersect(w->ctx, &ry, tmin, INFINITY, ACCEL_SKIP_NO_SHADOW,
                          &h))
            return;
        tmin = h.eps > 0.0 && h.eps < w->epsilon ? h.eps : w->epsilon;
        depth += h.t;
        /* Absorption in the medium just crossed */
        if (n_stack > 0) {
            const iris_interior *fi = stack[n_stack - 1]->interior;
            power *= fade_factor(fi, h.t, lambda);
            if (fi && fi->fade_power > 0.0 &&
                !(fi->fade_colour.r == fi->fade_colour.g &&
                  fi->fade_colour.g == fi->fade_colour.b))
                chroma = true;
        }
        const iris_object *obj = h.obj;
        /* The first surface must belong to the target */
        if (!c->global && level == 1 && h.top != c->target &&
            obj != c->target && !obj->photon_pass_through)
            return;
        bool entering = v3_dot(d, h.n) < 0.0;
        vec3 nf = entering ? h.n : v3_neg(h.n); /* facing the photon */
        struct psurf sf;
        eval_surface(c, &h, d, nf, lambda, r, &sf);
        const iris_finish *fin = sf.fin;

        /* Global photons: the light's power lands where the photon first
        ** meets a diffuse surface (as a caustic photon's would); stored
        ** from the second diffuse surface on (direct light and caustics
        ** are the light loop's and the caustic map's) */
        bool diffusive = fin && fin->diffuse > 0.0 && sf.opacity > 0.0;
        if (c->global && diffusive) {
            if (!landed)
                power *= landing_factor(c, depth);
            landed = true;
            if (c->max_diffuse > 0 && n_diffuse > c->max_diffuse)
                return; /* past POV-Ray's recursion_limit (global.c) */
            if (n_diffuse > 0) {
                /* the direction field holds the surface normal on the
                ** photon's side: the global estimate is Lambertian and
                ** needs only which surface the photon lit (global.c) */
                deposit(out, h.p, power, chroma ? lambda : -1.0, nf);
                if (out->failed)
                    return;
            }
        }
        /* Store caustic photons (after at least one bounce) */
        if (!c->global && level > 1 && obj->photon_collect && diffusive) {
            double p = power * landing_factor(c, depth);
            deposit(out, h.p, p, chroma ? lambda : -1.0, v3_neg(d));
            if (out->failed)
                return;
        }

        double transm = sf.transm;
        if (obj->photon_pass_through) {
            /* Straight on, filtered; POV-Ray counts the level too */
            power *= transm;
            chroma = chroma || !sf.transm_grey;
            o = h.p;
            continue;
        }
        vec3 n_geom = nf;
        nf = sf.n; /* the perturbed normal bends and mirrors */
        double cos_i = -v3_dot(d, nf);
        bool refl_ok = c->global || allowed(obj->photon_reflection,
                                            c->light->photon_reflection);
        bool refr_ok = (c->global || allowed(obj->photon_refraction,
                                             c->light->photon_refraction)) &&
                       h.interior && transm > 0.0;
        if (c->global && diffusive) {
            /* Lambertian bounce with probability = the albedo at lambda,
            ** POV-Ray's diffuse x pigment x opacity; otherwise the specular
            ** events below, their power divided by the probability of
            ** getting there, so that diffuse and specular light add as in
            ** POV-Ray's finish. About the geometric normal: a perturbed
            ** one would send photons into the surface. */
            double p_d = clamp01(fin->diffuse * sf.opacity *
                                 clamp01(reflectance(sf.pigment, lambda)));
            chroma = chroma || !grey(sf.pigment);
            if (rng_uniform(r) < p_d) {
                n_diffuse++;
                d = cosine_dir(n_geom, r);
                o = h.p;
                continue;
            }
            if (!(p_d < 0.999) || !(refr_ok || (refl_ok && sf.reflects)))
                return;
            power /= 1.0 - p_d;
        }
        double u = rng_uniform(r);
        if (refr_ok) {
            /* Indices on both sides from the interior stack (§1.2) */
            int pos = -1;
            for (int i = n_stack - 1; i >= 0; i--)
                if (same_medium(stack[i], tops[i], obj, h.top,
                                h.interior)) {
                    pos = i;
                    break;
                }
            double n_from, n_to;
            int action; /* 0 push, 1 pop top, 2 remove inner, 3 none */
            if (entering && pos < 0) {
                n_from = top_ior(stack, n_stack, lambda);
                n_to = ior_eval(h.interior, lambda);
                action = 0;
            } else if (pos == n_stack - 1 && pos >= 0) {
                n_from = ior_eval(h.interior, lambda);
                n_to = top_ior(stack, n_stack - 1, lambda);
                action = 1;
            } else if (pos >= 0) {
                n_from = n_to = 1.0; /* leaving an outer overlapping object */
                action = 2;
            } else {
                /* leaving an object we were not known to be inside (the
                ** light sat in it, or a grazing miss): into the top medium */
                n_from = ior_eval(h.interior, lambda);
                n_to = top_ior(stack, n_stack, lambda);
                action = 3;
            }
            double cos_t;
            double eta = n_from / n_to;
            /* n(lambda) decides the path: only dispersive media tie it to
            ** the wavelength */
            if (!c->no_dispersion) {
                chroma = chroma || ior_is_dispersive(h.interior);
                for (int i = 0; i < n_stack && !chroma; i++)
                    chroma = ior_is_dispersive(stack[i]->interior);
            }
            double f = fresnel(cos_i, eta, &cos_t);
            if (u < f) {
                /* Reflection off the outside needs 'reflection on', as
                ** in POV-Ray; inside the object (total or partial
                ** internal reflection) it is part of the refracted light
                ** and always followed (POV-Ray follows TIR only). */
                if (!refl_ok && entering)
                    return;
                d = v3_norm(v3_reflect(d, nf));
            } else {
                d = v3_norm(v3_add(v3_scale(d, eta),
                                   v3_scale(nf, eta * cos_i - cos_t)));
                power *= transm;
                chroma = chroma || !sf.transm_grey;
                if (action == 0 && n_stack < PTRACE_MAX_STACK) {
                    tops[n_stack] = h.top ? h.top : obj;
                    stack[n_stack++] = obj;
                } else if (action == 1) {
                    n_stack--;
                } else if (action == 2) {
                    for (int i = pos; i < n_stack - 1; i++) {
                        stack[i] = stack[i + 1];
                        tops[i] = tops[i + 1];
                    }
                    n_stack--;
                }
            }
        } else if (refl_ok && sf.reflects) {
            /* A mirror: POV-Ray's reflection colour (falloff, metallic),
            ** as a spectral reflectivity taken by Russian roulette */
            double p = clamp01(reflectance(sf.refl, lambda));
            chroma = chroma || !grey(sf.refl);
            if (!(u < p))
                return;
            d = v3_norm(v3_reflect(d, nf));
        } else {
            return;
        }
        o = h.p;
    }
}
