/* SPDX-License-Identifier: MIT */
/*
** trace.c: transport of one photon at one wavelength (or three siblings).
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
**    reflectivity; a filtering surface without an interior passes the
**    photon straight on (POV-Ray's default interior, ior 1), weighted by
**    its transmittance (the mirror branch below).
**  - Media (pmedia.c): extinction on every segment, media photons.
** White photons: when nothing on a photon's path depends on its wavelength
** (a light of flat emission, no dispersive medium, grey filters, fades and
** mirrors) the same path and power hold at every wavelength, and the photon
** is stored as white (pstore.h): it stands for the whole spectrum, and the
** estimate weighs it by the spectrum's mean instead of by one wavelength's
** RGB weight, so scenes without dispersion get no colour noise.
** Sibling wavelengths (trace.h, ptrace_sibs; issue 5): a photon
** carries three wavelengths along one path (media: pmedia.c), a spectral
** roulette weighs each by its own probability over their mean, a spectral
** transmittance multiplies each by its own, and a chromatic path stores
** one record per sibling; a dispersive interior collapses them to one
** (sib_collapse).
** Global photons (c->global; global.c, radiosity{}) take the same path
** with Lambertian bounces at diffuse surfaces, by Russian roulette on the
** albedo, and are stored from the second diffuse surface on.
** As in POV-Ray: photons pass through no_shadow objects (they are "shadow
** rays" for this purpose), but NOT through no_image objects, although
** POV-Ray 3.7 lets them pass (photons are launched as primary rays, so
** IsImageRay() is true for them: POV-Ray/povray#373, a bug). The first
** surface hit that is not pass_through must be in the target
** (ptrace_in_target); photons are stored only on surfaces met after it
** (and in media beyond it), on collecting surfaces with diffuse > 0.
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
    double transm_sib[PTRACE_SIBS]; /* !transm_grey: the transmittance at
                                  each sibling's wavelength (eval_surface) */
};

/* The spectral transmittance f·rho_rgb(lambda) + t of one layer of pigment
** 'c'; '*grey_out' is cleared when it depends on lambda. */
static double layer_transm(const iris_colour *c, double lambda,
                           bool *grey_out)
{
    double rgb[3] = { c->r, c->g, c->b };
    if (!grey(rgb) && c->f > 0.0)
        *grey_out = false;
    return clamp01(c->f > 0.0 ? c->f * clamp01(reflectance(rgb, lambda)) +
                                    c->t
                              : c->t);
}

/* Without a material context (the unit tests, tools/photon_bench -m 0),
** the reflection colour of finish s->fin (NULL: none)
** with its falloff. */
static void plain_reflection(vec3 d, vec3 nf, struct psurf *s)
{
    if (!s->fin)
        return;
    double cos_i = -v3_dot(d, nf);
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

/* Whether finish 'f' reflects nothing at any angle: its reflection
** colours are black (mat_layer_reflectivity()'s first test; the falloff
** blend of two zeros is zero). */
static bool finish_no_reflection(const iris_finish *f)
{
    return f->reflection_max.r == 0 && f->reflection_max.g == 0 &&
           f->reflection_max.b == 0 && f->reflection_min.r == 0 &&
           f->reflection_min.g == 0 && f->reflection_min.b == 0;
}

/* Whether texture 't' gives the same layers at every point: at most
** PTRACE_TEX_LAYERS layers, each a solid pigment (or none), no normal{},
** no texture_map or material_map (quick_colour is the context's choice,
** the same at every point too). */
static bool texture_uniform(const iris_texture *t)
{
    int n = 0;
    for (; t; t = t->next, n++)
        if (n >= PTRACE_TEX_LAYERS || t->map_pattern.kind != IRIS_PAT_NONE ||
            t->normal ||
            (t->pigment && t->pigment->pattern.kind != IRIS_PAT_NONE))
            return false;
    return n > 0;
}

/*
** The cache slot of texture 'tex' (not NULL), filled on first use with
** what the general evaluation in eval_surface() gives at any point and
** normal 'nf': mat_eval_texture()'s layers with a context, else the
** top layer's pigment. For a uniform texture these do not depend on the
** point, so the cache gives the same numbers to the bit.
*/
static const struct ptrace_tex *tex_lookup(const struct ptrace_combo *c,
                                           struct ptrace_tex_cache *tc,
                                           const iris_texture *tex, vec3 nf)
{
    for (int i = 0; i < PTRACE_TEX_SLOTS; i++)
        if (tc->slot[i].key == tex)
            return &tc->slot[i];
    struct ptrace_tex *e = &tc->slot[tc->next];
    tc->next = (tc->next + 1) % PTRACE_TEX_SLOTS;
    memset(e, 0, sizeof *e);
    e->key = tex;
    e->uniform = texture_uniform(tex);
    if (!e->uniform)
        return e;
    e->transm_grey = true;
    if (!c->mat) {
        const iris_colour black = { 0, 0, 0, 0, 0 };
        e->n_layers = 1;
        e->pigment[0] = tex->pigment ? tex->pigment->colour : black;
        e->fin = tex->finish;
        e->opacity = 1.0 - e->pigment[0].f - e->pigment[0].t;
        e->no_reflection = !e->fin || finish_no_reflection(e->fin);
    } else {
        struct mat_eval ev;
        struct mat_point pt = { v3(0, 0, 0), nf, v3_neg(nf), { 0, 0 },
                                NULL, false };
        mat_eval_texture(c->mat, tex, &pt, &ev);
        bool ok = ev.n_stacks == 1 && ev.stacks[0].first == 0 &&
                  ev.stacks[0].n == ev.n_layers && ev.n_layers > 0 &&
                  ev.n_layers <= PTRACE_TEX_LAYERS;
        for (int i = 0; ok && i < ev.n_layers; i++)
            ok = ev.layers[i].valid;
        if (!ok) {
            e->uniform = false;
            return e;
        }
        e->n_layers = ev.n_layers;
        for (int i = 0; i < ev.n_layers; i++)
            e->pigment[i] = ev.layers[i].pigment;
        e->fin = ev.layers[0].finish;
        e->opacity = mat_opacity(c->mat, &e->pigment[0]);
        e->no_reflection = finish_no_reflection(e->fin);
    }
    /* the product in eval_surface()'s order; when no layer depends on
    ** lambda any lambda gives these bits */
    e->transm = 1.0;
    for (int i = 0; i < e->n_layers; i++)
        e->transm *= layer_transm(&e->pigment[i], 550.0, &e->transm_grey);
    return e;
}

double ptrace_tex_transm(const struct ptrace_tex *e, double lambda)
{
    bool grey_out = true;
    double t = 1.0;
    for (int i = 0; i < e->n_layers; i++)
        t *= layer_transm(&e->pigment[i], lambda, &grey_out);
    return t;
}

const struct ptrace_tex *ptrace_tex_get(const struct ptrace_combo *c,
                                        struct ptrace_tex_cache *tc,
                                        const iris_texture *tex)
{
    /* a uniform texture's slot does not depend on the normal */
    return tex ? tex_lookup(c, tc, tex, v3(0, 1, 0)) : NULL;
}

static double fresnel_n(const iris_object *const *stack,
                        const iris_object *const *tops, int n_stack,
                        const struct hit *h, double lambda);

/* The interior stack fresnel_n() reads. */
struct fres_query {
    const iris_object *const *stack, *const *tops;
    int n_stack;
};

/* The n for mat_layer_reflectivity() with finish 'f' at hit 'h': only a
** 'fresnel' reflection reads it, so the index lookups and the stack walk
** are not paid at every hit (they were 4% of a photon's instructions). */
static double reflect_n(const iris_finish *f, const struct fres_query *q,
                        const struct hit *h, double lambda)
{
    return f->reflection_fresnel
               ? fresnel_n(q->stack, q->tops, q->n_stack, h, lambda)
               : 1.0;
}

/*
** Evaluates the texture at hit 'h' for a photon arriving along 'd' with
** geometric normal 'nf' facing it: through mat_eval_texture() when the
** build has a material context (a texture_map's stacks are chosen by
** Russian roulette on their weights), otherwise from the top layer's solid
** pigment (the unit tests). The transmittance is the product over the
** layers of f·rho_rgb(lambda) + t. A texture of one colour everywhere is
** taken from the batch's cache 'tc' (when not NULL): the same numbers.
*/
static void eval_surface(const struct ptrace_combo *c, const struct hit *h,
                         vec3 d, vec3 nf, const struct ptrace_sibs *sb,
                         const struct fres_query *fq, rng *r,
                         struct ptrace_tex_cache *tc, struct psurf *s)
{
    double lambda = sb->lambda[0];
    s->n = nf;
    s->reflects = false;
    s->transm_grey = true;
    const struct ptrace_tex *e =
        tc && h->texture &&
                (h->obj->kind != IRIS_OBJ_BLOB || /* no call per hit */
                 !mat_texture_blended(h->obj))
            ? tex_lookup(c, tc, h->texture, nf)
            : NULL;
    if (e && e->uniform) {
        /* every other field is set from the cache below: the defaults
        ** further down are the other paths' */
        tc->hits++;
        s->transm = e->transm;
        if (!e->transm_grey) {
            s->transm = 1.0;
            for (int i = 0; i < e->n_layers; i++)
                s->transm *= layer_transm(&e->pigment[i], lambda,
                                          &s->transm_grey);
            for (int j = 1; j < sb->n && !s->transm_grey; j++) {
                bool g = true;
                s->transm_sib[j] = 1.0;
                for (int i = 0; i < e->n_layers; i++)
                    s->transm_sib[j] *= layer_transm(
                        &e->pigment[i], sb->lambda[j], &g);
            }
        }
        s->opacity = e->opacity;
        s->pigment[0] = e->pigment[0].r;
        s->pigment[1] = e->pigment[0].g;
        s->pigment[2] = e->pigment[0].b;
        s->fin = e->fin;
        if (e->no_reflection) {
            s->refl[0] = s->refl[1] = s->refl[2] = 0.0;
        } else if (!c->mat) {
            plain_reflection(d, nf, s);
        } else {
            /* the top layer as mat_eval_texture() gives it: normal nf */
            struct mat_layer top = { .pigment = e->pigment[0],
                                     .finish = e->fin, .n = nf,
                                     .valid = true };
            double w;
            s->reflects = mat_layer_reflectivity(
                &top, -v3_dot(d, s->n), reflect_n(e->fin, fq, h, lambda),
                s->refl, &w);
        }
        return;
    }
    s->transm = 0.0;
    s->opacity = 1.0;
    s->fin = h->texture ? h->texture->finish : NULL;
    s->pigment[0] = s->pigment[1] = s->pigment[2] = 0.0;
    if (!c->mat) {
        iris_colour col = { 0, 0, 0, 0, 0 };
        if (h->texture && h->texture->pigment)
            col = h->texture->pigment->colour;
        s->transm = layer_transm(&col, lambda, &s->transm_grey);
        for (int j = 1; j < sb->n && !s->transm_grey; j++) {
            bool g = true;
            s->transm_sib[j] = layer_transm(&col, sb->lambda[j], &g);
        }
        s->opacity = 1.0 - col.f - col.t;
        s->pigment[0] = col.r;
        s->pigment[1] = col.g;
        s->pigment[2] = col.b;
        plain_reflection(d, nf, s);
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
    for (int i = st->first; i < st->first + st->n; i++)
        if (ev.layers[i].valid)
            t *= layer_transm(&ev.layers[i].pigment, lambda, &s->transm_grey);
    s->transm = t;
    for (int j = 1; j < sb->n && !s->transm_grey; j++) {
        bool g = true;
        s->transm_sib[j] = 1.0;
        for (int i = st->first; i < st->first + st->n; i++)
            if (ev.layers[i].valid)
                s->transm_sib[j] *= layer_transm(&ev.layers[i].pigment,
                                                 sb->lambda[j], &g);
    }
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
        s->reflects = mat_layer_reflectivity(top, -v3_dot(d, s->n),
                                             reflect_n(top->finish, fq, h,
                                                       lambda),
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
bool ptrace_allowed(enum iris_tristate obj, enum iris_tristate light)
{
    return (obj == IRIS_ON && light != IRIS_OFF) ||
           (obj != IRIS_OFF && light == IRIS_ON);
}

/* Whether a photon of combo 'c' may reflect off / refract through 'obj'
** (global photons: always). */
static inline bool refl_allowed(const struct ptrace_combo *c,
                                const iris_object *obj)
{
    return c->global ||
           ptrace_allowed(obj->photon_reflection,
                          c->light->photon_reflection);
}

static inline bool refr_allowed(const struct ptrace_combo *c,
                                const iris_object *obj)
{
    return c->global ||
           ptrace_allowed(obj->photon_refraction,
                          c->light->photon_refraction);
}

_Static_assert(PTRACE_SIBS <= 3, "deposit_sibs sums equal powers as p * n");

#define PTRACE_FIRST_CAP 4096

/* Appends one raw record to 'out' with its wavelength field already
** encoded (trace.h); a borrowed slice is copied out when full, never
** reallocated. */
void ptrace_out_push(struct ptrace_out *out, vec3 p, double power,
                     float lambda_field, vec3 from)
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
    r->lambda = lambda_field;
    r->dir[0] = (float)from.x;
    r->dir[1] = (float)from.y;
    r->dir[2] = (float)from.z;
}

/* Stores a photon; lambda < 0 marks one whose path and power are the same
** at every wavelength (pstore.h: a white photon). */
static void deposit(struct ptrace_out *out, vec3 p, double power,
                    double lambda, vec3 from)
{
    ptrace_out_push(out, p, power, (float)lambda, from);
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

/* One photon's last index: ior_eval() of one interior at the photon's one
** wavelength is the same number every time, and a photon through a ball
** asks for the ball's index entering and again leaving. */
struct ior_memo {
    const iris_interior *in; /* NULL: empty (ior_eval(NULL) is 1 anyway) */
    double n;
};

static double memo_ior(struct ior_memo *m, const iris_interior *in,
                       double lambda)
{
    if (!in)
        return 1.0;
    if (in != m->in) {
        m->in = in;
        m->n = ior_eval(in, lambda);
    }
    return m->n;
}

/* top_ior() through the photon's memo */
static double memo_top_ior(struct ior_memo *m,
                           const iris_object *const *stack, int n,
                           double lambda)
{
    return n > 0 ? memo_ior(m, stack[n - 1]->interior, lambda) : 1.0;
}

/*
** The n = n_t/n_i of `reflection { ... fresnel }` at a surface of
** interior 'in' (NULL: 1), POV-Ray's ComputeRelativeIOR as the eye
** tracer's relative_ior (render/trace.c) and POV-Ray's photon tracer use
** it: the object's index over the medium the photon is in, or, leaving
** it, the atmosphere's (or the innermost medium's) over the object's.
** With n = 1 an opaque glazed surface (interior ior 1.5, fresnel
** reflection) reflected no photons at all (tests/optics, check 15).
*/
static double fresnel_n(const iris_object *const *stack,
                        const iris_object *const *tops, int n_stack,
                        const struct hit *h, double lambda)
{
    if (!h->interior)
        return 1.0;
    double n = ior_eval(h->interior, lambda);
    for (int i = n_stack - 1; i >= 0; i--)
        if (same_medium(stack[i], tops[i], h->obj, h->top, h->interior))
            return n_stack == 1 ? 1.0 / n
                                : top_ior(stack, n_stack, lambda) / n;
    return n / top_ior(stack, n_stack, lambda);
}

/*
** Keeps sibling 0 alone with the power of all (x n), where the path is
** about to depend on lambda (a dispersive interior). Unbiased: every
** choice so far was the same for all siblings and each sibling's power is
** the expectation for its wavelength alone times 1/n (trace.h), so each
** sibling's marginal is right; sibling 0's wavelength u is uniform on its
** own (shoot.c), so keeping it with n times its power keeps the expected
** power at every wavelength. Sibling 0 rather than one drawn uniformly
** (also unbiased): it is the lattice value of the photon's cell, which
** spreads neighbouring cells over the spectrum (the dispersed caustic's
** colour noise, shoot.c), a drawn one would scramble that and take a
** draw. Its surface evaluation at lambda[0] stays valid.
*/
static void sib_collapse(struct ptrace_sibs *s)
{
    s->power[0] *= (double)s->n;
    s->n = 1;
}

/* Gives every sibling its own power (an 'equal' set keeps the common one
** in power[0] only). */
static void sib_split(struct ptrace_sibs *s)
{
    if (s->equal) {
        for (int j = 1; j < s->n; j++)
            s->power[j] = s->power[0];
        s->equal = false;
    }
}

/* Multiplies every sibling's power by 'f' (the same at every lambda). */
static void sib_scale(struct ptrace_sibs *s, double f)
{
    if (s->equal) {
        s->power[0] *= f;
        return;
    }
    for (int j = 0; j < s->n; j++)
        s->power[j] *= f;
}

/* The siblings' mean transmittance at surface 'sf' (sf->transm with one
** sibling or a grey one: the same number). */
static double sib_transm(const struct psurf *sf, const struct ptrace_sibs *s)
{
    if (sf->transm_grey || s->n == 1)
        return sf->transm;
    double t = sf->transm;
    for (int j = 1; j < s->n; j++)
        t += sf->transm_sib[j];
    return t / s->n;
}

/* Multiplies each sibling's power by the transmittance of surface 'sf' at
** its own wavelength: the expected power of a photon of that wavelength
** through a coloured filter, no roulette. */
static void sib_filter(struct ptrace_sibs *s, const struct psurf *sf)
{
    if (sf->transm_grey || s->n == 1) {
        sib_scale(s, sf->transm);
        return;
    }
    sib_split(s);
    s->power[0] *= sf->transm;
    for (int j = 1; j < s->n; j++)
        s->power[j] *= sf->transm_sib[j];
}

static bool sib_alive(const struct ptrace_sibs *s)
{
    if (s->equal)
        return s->power[0] > 0.0;
    for (int j = 0; j < s->n; j++)
        if (s->power[j] > 0.0)
            return true;
    return false;
}

/* Whether the surface of 'obj' (interior 'in') meets a dispersive medium:
** its own interior or one the photon is in (the refraction's test). */
static bool meets_dispersion(const iris_interior *in,
                             const iris_object *const *stack, int n_stack)
{
    if (ior_is_dispersive(in))
        return true;
    for (int i = 0; i < n_stack; i++)
        if (ior_is_dispersive(stack[i]->interior))
            return true;
    return false;
}

/* Stores the siblings at 'p': one white record (their summed power) when
** nothing on the path depended on lambda, else one record per sibling
** with power > 0 at its own wavelength. */
static void deposit_sibs(struct ptrace_out *out, vec3 p,
                         const struct ptrace_sibs *s, double factor,
                         bool chroma, vec3 from)
{
    if (!chroma) {
        double sum = s->power[0];
        if (s->equal) {
            /* p·n is the sum p + p + p to the bit (p + p is exact, then
            ** one rounding of 3p either way; PTRACE_SIBS <= 3) */
            sum *= s->n;
        } else {
            for (int j = 1; j < s->n; j++)
                sum += s->power[j];
        }
        deposit(out, p, sum * factor, -1.0, from);
        return;
    }
    for (int j = 0; j < s->n && !out->failed; j++) {
        double pj = s->equal ? s->power[0] : s->power[j];
        if (pj > 0.0)
            deposit(out, p, pj * factor, s->lambda[j], from);
    }
}

void ptrace_photon(const struct pmap_world *w, const struct ptrace_combo *c,
                   vec3 o, vec3 d, double lambda, double power, rng *r,
                   struct ptrace_out *out)
{
    struct ptrace_sibs s = { 1, true, { lambda }, { power } };
    ptrace_photon_sibs(w, c, o, d, &s, r, out);
}

void ptrace_photon_sibs(const struct pmap_world *w,
                        const struct ptrace_combo *c, vec3 o, vec3 d,
                        struct ptrace_sibs *s, rng *r,
                        struct ptrace_out *out)
{
    /* global photons take one wavelength (the diffuse bounces read
    ** one); the shooter gives them one. Media carry siblings (pmedia.c) */
    if (s->n > 1 && c->global)
        sib_collapse(s);
    double lambda = s->lambda[0]; /* the one that decides eval_surface() */
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
    /* a caustic photon has met its target: the first surface it hit that
    ** is not pass_through (POV-Ray's passThruPrev). Until then every hit
    ** must be the target or pass_through, and nothing is stored, also in
    ** media (before, a photon through a pass_through cloud that missed
    ** the target was stored on the floor beyond, as caustic light) */
    bool met = c->global;
    bool landed = false;       /* global: D^2 and fade applied */
    struct ior_memo im = { NULL, 1.0 };
    for (int level = 1; level <= max_level && sib_alive(s); level++) {
        ray ry = { o, d };
        h.eps = 0.0;
        if (!w->intersect(w->ctx, &ry, tmin, INFINITY, ACCEL_SKIP_NO_SHADOW,
                          &h))
            return;
        tmin = h.eps > 0.0 && h.eps < w->epsilon ? h.eps : w->epsilon;
        /* Media on the segment just crossed: extinction, media photons
        ** (pmedia.h; nothing when the scene has no media) */
        if (c->media.scene)
            pmedia_segment(c, stack, n_stack, o, d, h.t, depth,
                           met ? level : 1, s,
                           &chroma, r, out);
        depth += h.t;
        /* Absorption in the medium just crossed */
        if (n_stack > 0) {
            const iris_interior *fi = stack[n_stack - 1]->interior;
            bool tinted = fi && fi->fade_power > 0.0 &&
                          !(fi->fade_colour.r == fi->fade_colour.g &&
                            fi->fade_colour.g == fi->fade_colour.b);
            if (tinted && s->n > 1) {
                sib_split(s);
                for (int j = 0; j < s->n; j++)
                    s->power[j] *= fade_factor(fi, h.t, s->lambda[j]);
            } else {
                sib_scale(s, fade_factor(fi, h.t, lambda));
            }
            chroma = chroma || tinted;
        }
        const iris_object *obj = h.obj;
        /* The first surface must belong to the target */
        if (!met && !obj->photon_pass_through &&
            !ptrace_in_target(c, obj, h.top))
            return;
        /* stored here only when the target was met before this hit */
        bool stores = met && !c->global;
        met = met || !obj->photon_pass_through;
        bool entering = v3_dot(d, h.n) < 0.0;
        vec3 nf = entering ? h.n : v3_neg(h.n); /* facing the photon */
        /* a dispersive medium on either side: n(lambda) decides the path
        ** (and a fresnel reflection's strength) from here on */
        if (!c->no_dispersion && s->n > 1 &&
            meets_dispersion(h.interior, stack, n_stack))
            sib_collapse(s);
        struct psurf sf;
        struct fres_query fq = { stack, tops, n_stack };
        eval_surface(c, &h, d, nf, s, &fq, r, out->tex, &sf);
        const iris_finish *fin = sf.fin;

        /* Global photons: the light's power lands where the photon first
        ** meets a diffuse surface (as a caustic photon's would); stored
        ** from the second diffuse surface on (direct light and caustics
        ** are the light loop's and the caustic map's) */
        bool diffusive = fin && fin->diffuse > 0.0 && sf.opacity > 0.0;
        if (c->global && diffusive) {
            if (!landed)
                s->power[0] *= landing_factor(c, depth);
            landed = true;
            if (c->max_diffuse > 0 && n_diffuse > c->max_diffuse)
                return; /* past POV-Ray's recursion_limit (global.c) */
            if (n_diffuse > 0) {
                /* the direction field holds the surface normal on the
                ** photon's side: the global estimate is Lambertian and
                ** needs only which surface the photon lit (global.c) */
                deposit(out, h.p, s->power[0], chroma ? lambda : -1.0, nf);
                if (out->failed)
                    return;
            }
        }
        /* Store caustic photons (after at least one bounce) */
        if (stores && obj->photon_collect && diffusive) {
            deposit_sibs(out, h.p, s, landing_factor(c, depth), chroma,
                         v3_neg(d));
            if (out->failed)
                return;
        }

        /* the siblings' mean: > 0 when any of them passes */
        double transm = sib_transm(&sf, s);
        if (obj->photon_pass_through) {
            /* Straight on, filtered; POV-Ray counts the level too */
            sib_filter(s, &sf);
            chroma = chroma || !sf.transm_grey;
            o = h.p;
            continue;
        }
        vec3 n_geom = nf;
        nf = sf.n; /* the perturbed normal bends and mirrors */
        double cos_i = -v3_dot(d, nf);
        /* the flags are read where a branch needs them (a diffuse floor
        ** that ends the photon needs neither) */
        bool refr_ok = h.interior && transm > 0.0 &&
                       refr_allowed(c, obj);
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
            if (!(p_d < 0.999) || !(refr_ok || sf.reflects))
                return;
            s->power[0] /= 1.0 - p_d;
        }
        /* The event's draw is taken on the two branches that use it, not
        ** before a photon that ends here (a diffuse floor): the stream is
        ** the photon's own (seeded per photon, shoot.c, global.c), so the
        ** maps are unchanged. */
        if (refr_ok) {
            double u = rng_uniform(r);
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
                n_from = memo_top_ior(&im, stack, n_stack, lambda);
                n_to = memo_ior(&im, h.interior, lambda);
                action = 0;
            } else if (pos == n_stack - 1 && pos >= 0) {
                n_from = memo_ior(&im, h.interior, lambda);
                n_to = memo_top_ior(&im, stack, n_stack - 1, lambda);
                action = 1;
            } else if (pos >= 0) {
                n_from = n_to = 1.0; /* leaving an outer overlapping object */
                action = 2;
            } else {
                /* leaving an object we were not known to be inside (the
                ** light sat in it, or a grazing miss): into the top medium */
                n_from = memo_ior(&im, h.interior, lambda);
                n_to = memo_top_ior(&im, stack, n_stack, lambda);
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
                if (entering && !refl_allowed(c, obj))
                    return;
                d = v3_norm(v3_reflect(d, nf));
            } else {
                d = v3_norm(v3_add(v3_scale(d, eta),
                                   v3_scale(nf, eta * cos_i - cos_t)));
                sib_filter(s, &sf);
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
        } else if ((sf.reflects && refl_allowed(c, obj)) ||
                   (!h.interior && transm > 0.0 && refr_allowed(c, obj))) {
            bool refl_ok = sf.reflects && refl_allowed(c, obj);
            bool refr_flag = !h.interior && refr_allowed(c, obj);
            double u = rng_uniform(r);
            /* A mirror: POV-Ray's reflection colour (falloff, metallic),
            ** as a spectral reflectivity p, taken by Russian roulette; a
            ** filtering surface without an interior (POV-Ray gives it a
            ** default one, ior 1) passes the photon straight on with its
            ** spectral transmittance q as a weight, as refraction does
            ** (a roulette on q(lambda) would tint the surviving photons:
            ** 4% colour noise under a yellow filter). Both (optics.pov's
            ** colour-splitting mirrors): reflection with probability
            ** p/(p+q), passage otherwise, the power times p + q (1 for a
            ** colour and its complement: Burns' curves sum to 1); a
            ** choice independent of lambda (1/2, weights 2p, 2q) lost
            ** 3/4 of the photons behind two such faces: 5% colour
            ** errors, tests/unit/test_pfilter.c. POV-Ray spawns both at
            ** full power. */
            /* Siblings (ptrace_photon_sibs): the roulette takes the means
            ** P and Q of the siblings' p_j and q_j: reflection with
            ** probability P/(P+Q), each sibling's power times
            ** p_j (P+Q)/P, passage otherwise, times q_j (P+Q)/Q; the
            ** expectation of sibling j is p_j + q_j, as above. One
            ** sibling, or grey p and q, give the rule above exactly. */
            double q = refr_flag ? transm : 0.0;
            bool spectral_q = q > 0.0 && !sf.transm_grey && s->n > 1;
            double p = refl_ok ? clamp01(reflectance(sf.refl, lambda))
                               : 0.0;
            double pj[PTRACE_SIBS] = { p };
            bool spectral = s->n > 1 && refl_ok && !grey(sf.refl);
            if (spectral) {
                for (int j = 1; j < s->n; j++) {
                    pj[j] = clamp01(reflectance(sf.refl, s->lambda[j]));
                    p += pj[j];
                }
                p /= s->n;
            }
            chroma = chroma || (p > 0.0 && !grey(sf.refl)) ||
                     (q > 0.0 && !sf.transm_grey);
            if (spectral || spectral_q)
                sib_split(s);
            if (q <= 0.0) {
                if (!(u < p))
                    return;
                if (spectral)
                    for (int j = 0; j < s->n; j++)
                        s->power[j] *= pj[j] / p;
                d = v3_norm(v3_reflect(d, nf));
            } else if (p <= 0.0) {
                sib_filter(s, &sf);
            } else {
                bool mirror = u * (p + q) < p;
                if (spectral && mirror) {
                    for (int j = 0; j < s->n; j++)
                        s->power[j] *= pj[j] * (p + q) / p;
                } else if (spectral_q && !mirror) {
                    s->power[0] *= sf.transm * (p + q) / q;
                    for (int j = 1; j < s->n; j++)
                        s->power[j] *= sf.transm_sib[j] * (p + q) / q;
                } else {
                    sib_scale(s, p + q);
                }
                if (mirror)
                    d = v3_norm(v3_reflect(d, nf));
            }
        } else {
            return;
        }
        o = h.p;
    }
}
