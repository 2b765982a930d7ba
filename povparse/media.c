/* SPDX-License-Identifier: MIT */
/*
** media.c: the media{} block, for an interior{} and for the atmosphere
** (POV-Ray 3.7's Parse_Media, parser_materials.cpp; docs/media.md).
**
** A media's densities are pigments (POV-Ray keeps them as PIGMENTs and
** multiplies their colours): density{} is parsed by mat.c's pigment
** grammar, with density_map in the place of pigment_map. Transforms
** written in a media apply to the densities parsed before them, as
** POV-Ray's Transform_Density does; an object's transforms reach its
** interior's media through pp_interior_transform (obj.c).
*/
#include "config.h"

#include <string.h>

#include "pp.h"

/* Appends 'd' to the densities of 'm' (a new array: a media copied from
** an identifier shares the old one). */
static void add_density(pp_state *ps, iris_media *m, iris_pigment *d)
{
    iris_pigment **a = pp_alloc(ps, (size_t)(m->n_densities + 1) * sizeof *a);
    if (m->n_densities)
        memcpy(a, m->densities, (size_t)m->n_densities * sizeof *a);
    a[m->n_densities++] = d;
    m->densities = a;
}

/* Composes 'xf' into every density of 'm' (copies: densities may be
** shared with a declared media). */
static void transform_densities(pp_state *ps, iris_media *m,
                                const iris_transform *xf)
{
    if (m->n_densities == 0)
        return;
    iris_pigment **a = pp_alloc(ps, (size_t)m->n_densities * sizeof *a);
    for (int i = 0; i < m->n_densities; i++)
        a[i] = pp_pig_transform(ps, m->densities[i], xf);
    m->densities = a;
}

/*
** scattering { TYPE, COLOUR [eccentricity G] [extinction X] }
** The current token is 'scattering'.
*/
static void scattering_block(pp_state *ps, iris_media *m)
{
    pp_expect(ps, T_LBRACE, "'{' after scattering");
    pp_next(ps);
    pp_token type_at = ps->tok;
    pp_unget(ps);
    int type = pp_int(ps);
    if (type < IRIS_SCATTER_ISOTROPIC ||
        type > IRIS_SCATTER_HENYEY_GREENSTEIN) {
        /* POV-Ray warns and then scatters isotropically (the default
        ** case of its phase function) */
        pp_warning(ps, &type_at, "unknown scattering type %d (1 to 5): "
                   "scattered isotropically", type);
    }
    m->scattering_type = type;
    pp_accept(ps, T_COMMA);
    m->scattering = pp_colour(ps);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_ECCENTRICITY:
            if (m->scattering_type != IRIS_SCATTER_HENYEY_GREENSTEIN)
                pp_error(ps, &at, "eccentricity needs scattering type 5 "
                         "(Henyey-Greenstein)");
            m->eccentricity = pp_float(ps);
            if (!(m->eccentricity > -1.0 && m->eccentricity < 1.0))
                pp_error(ps, &at, "eccentricity must lie strictly between "
                         "-1 and 1");
            break;
        case T_EXTINCTION:
            m->sc_ext = pp_float(ps);
            break;
        case T_RBRACE:
            return;
        default:
            pp_unexpected(ps, &at, "scattering");
        }
    }
}

/*
** media { [MEDIA_ID] [method 1|2|3] [intervals N] [samples MIN [, MAX]]
**         [confidence C] [variance V] [ratio R] [jitter J]
**         [aa_level L] [aa_threshold T] [collect [on|off]]
**         [absorption COLOUR] [emission COLOUR] [scattering {...}]
**         [density {...}]... [transforms]... }
** The current token is 'media'.
*/
iris_media *pp_media(pp_state *ps)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after media");
    pp_enter(ps, &open);
    iris_media *m = pp_alloc(ps, sizeof *m);
    iris_media_defaults(m, ps->version);
    m->loc = pp_loc(ps, &open);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            pp_leave(ps);
            return m;
        case T_IDENT:
            if (at.val.kind != V_MEDIA || !at.val.u.ptr)
                pp_unexpected(ps, &at, "media");
            *m = *(const iris_media *)at.val.u.ptr;
            m->loc = pp_loc(ps, &open);
            break;
        case T_METHOD: {
            int v = pp_int(ps);
            if (v < 1 || v > 3)
                pp_error(ps, &at, "media method must be 1, 2 or 3");
            m->method = v;
            break;
        }
        case T_INTERVALS: {
            double v = pp_float(ps);
            if (!(v >= 1))
                pp_error(ps, &at, "media needs at least one interval");
            m->intervals = v > 1e4 ? 10000 : (int)v;
            break;
        }
        case T_SAMPLES: {
            double lo = pp_float(ps), hi = lo;
            /* POV-Ray: Parse_Comma, then Allow_Float: 'samples 5 10' */
            if (pp_accept(ps, T_COMMA) || pp_float_follows(ps))
                hi = pp_float(ps);
            if (!(lo >= 1))
                pp_error(ps, &at, "media needs at least one sample per "
                         "interval");
            if (!(hi >= lo))
                pp_error(ps, &at, "the maximum number of media samples is "
                         "smaller than the minimum");
            /* a sane cap: beyond it no image changes */
            m->min_samples = lo > 1e4 ? 10000 : (int)lo;
            m->max_samples = hi > 1e4 ? 10000 : (int)hi;
            break;
        }
        case T_CONFIDENCE: {
            double v = pp_float(ps);
            if (!(v >= 0.0 && v < 1.0))
                pp_error(ps, &at, "media confidence must be in [0, 1)");
            m->confidence = v;
            break;
        }
        case T_VARIANCE: m->variance = pp_float(ps); break;
        case T_RATIO: m->ratio = pp_float(ps); break;
        case T_JITTER: m->jitter = pp_float(ps); break;
        case T_AA_THRESHOLD: {
            double v = pp_float(ps);
            if (!(v > 0.0))
                pp_error(ps, &at, "media aa_threshold must be greater than "
                         "zero");
            m->aa_threshold = v;
            break;
        }
        case T_AA_LEVEL: {
            double v = pp_float(ps);
            if (!(v >= 1))
                pp_error(ps, &at, "media aa_level must be at least 1");
            /* a cap against a hang: 2^15 samples per pair at most */
            m->aa_level = v > 16 ? 16 : (int)v;
            break;
        }
        case T_COLLECT:
            m->ignore_photons = !pp_bool_opt(ps);
            break;
        case T_ABSORPTION: m->absorption = pp_colour(ps); break;
        case T_EMISSION: m->emission = pp_colour(ps); break;
        case T_SCATTERING: scattering_block(ps, m); break;
        case T_DENSITY:
            add_density(ps, m, pp_density_block(ps, NULL));
            break;
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                transform_densities(ps, m, &x);
                break;
            }
            pp_unexpected(ps, &at, "media");
        }
        }
    }
}

/* Adds 'm' to the media of interior 'in' (a new array, as add_density). */
void pp_interior_add_media(pp_state *ps, iris_interior *in, iris_media *m)
{
    iris_media **a = pp_alloc(ps, (size_t)(in->n_media + 1) * sizeof *a);
    if (in->n_media)
        memcpy(a, in->media, (size_t)in->n_media * sizeof *a);
    a[in->n_media++] = m;
    in->media = a;
    in->has_media = true;
}

/* A copy of 'in' whose media densities have 'xf' composed in (an object's
** transform reaching its interior, POV-Ray's Interior::Transform). An
** interior without media densities is returned as it is. */
iris_interior *pp_interior_transform(pp_state *ps, const iris_interior *in,
                                     const iris_transform *xf)
{
    bool any = false;
    for (int i = 0; in && i < in->n_media; i++)
        any = any || in->media[i]->n_densities > 0;
    if (!any)
        return (iris_interior *)in;
    iris_interior *n = pp_alloc(ps, sizeof *n);
    *n = *in;
    n->media = pp_alloc(ps, (size_t)in->n_media * sizeof *n->media);
    for (int i = 0; i < in->n_media; i++) {
        iris_media *m = pp_alloc(ps, sizeof *m);
        *m = *in->media[i];
        transform_densities(ps, m, xf);
        n->media[i] = m;
    }
    return n;
}

/* Adds an atmospheric media{} to the scene. */
void pp_add_atmosphere_media(pp_state *ps, iris_media *m)
{
    iris_scene *sc = ps->scene;
    iris_media **a = pp_alloc(ps, (size_t)(sc->n_media + 1) * sizeof *a);
    if (sc->n_media)
        memcpy(a, sc->media, (size_t)sc->n_media * sizeof *a);
    a[sc->n_media++] = m;
    sc->media = a;
}
