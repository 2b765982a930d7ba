/* SPDX-License-Identifier: MIT */
/*
** rvalue.c: what may follow '#declare X =': any kind of value (numbers,
** strings, objects, textures, arrays, splines, functions, maps, ...), as
** POV-Ray's Parse_RValue. Arrays and splines are built here.
*/
#include "config.h"

#include <string.h>

#include "pp.h"

#define MAX_ARRAY_ELEMS (1L << 24)

/* POV-Ray's identifier type of an array element: float, uv (2), vector,
** 4-D vector and colour (5 components) apart, a light source an object.
** -1 for the kinds whose POV-Ray type iris does not tell apart; those
** are not checked. */
static int array_type(const pp_value *v)
{
    switch (v->kind) {
    case V_FLOAT: return 1;
    case V_VECTOR: return v->dim == 5 ? 5 : v->dim;
    case V_COLOUR: return 5;
    case V_STRING: return 6;
    case V_OBJECT: case V_LIGHT: return 7;
    case V_ARRAY: return 8;
    default: return -1;
    }
}

void pp_array_store(pp_state *ps, pp_array *arr, pp_value *slot,
                    const pp_value *v, const pp_token *at)
{
    static const char *const one[] = {
        "", "a float", "a 2-D vector", "a vector", "a 4-D vector",
        "a colour", "a string", "an object", "an array" };
    static const char *const many[] = {
        "", "floats", "2-D vectors", "vectors", "4-D vectors", "colours",
        "strings", "objects", "arrays" };
    int t = array_type(v);
    if (t > 0) {
        if (arr->elem_type > 0 && arr->elem_type != t)
            pp_error(ps, at, "cannot store %s in an array of %s (POV-Ray "
                     "keeps one type per array)", one[t],
                     many[arr->elem_type]);
        arr->elem_type = t;
    }
    *slot = *v;
}

/* One element of an array initialiser: nested braces per dimension. */
static void array_init(pp_state *ps, pp_array *arr, int d, long base)
{
    pp_expect(ps, T_LBRACE, "'{'");
    pp_enter(ps, &ps->tok);
    long stride = 1;
    for (int k = d + 1; k < arr->ndim; k++)
        stride *= arr->dims[k];
    for (int i = 0; i < arr->dims[d]; i++) {
        if (i > 0)
            pp_accept(ps, T_COMMA); /* optional, as in POV-Ray */
        if (d + 1 < arr->ndim) {
            array_init(ps, arr, d + 1, base + i * stride);
        } else {
            /* elements may be written without commas: a '<' after an
            ** element starts the next one, it is no comparison */
            bool iv = ps->in_vector;
            ps->in_vector = true;
            pp_next(ps);
            pp_token at = ps->tok;
            pp_unget(ps);
            pp_value v = pp_rvalue(ps);
            ps->in_vector = iv;
            /* an array named in the initialiser is copied, as POV-Ray
            ** copies an identifier's value */
            if (v.kind == V_ARRAY)
                v.u.arr = pp_array_copy(ps, v.u.arr);
            pp_array_store(ps, arr, &arr->items[base + i], &v, &at);
        }
    }
    pp_accept(ps, T_COMMA);
    pp_expect(ps, T_RBRACE, "'}' (the initialiser has more elements than "
              "the array)");
    pp_leave(ps);
}

pp_array *pp_array_copy(pp_state *ps, const pp_array *arr)
{
    pp_array *c = pp_salloc(ps, sizeof *c);
    *c = *arr;
    c->items = pp_salloc(ps, (size_t)arr->n * sizeof *c->items);
    for (long i = 0; i < arr->n; i++) {
        c->items[i] = arr->items[i];
        if (c->items[i].kind == V_ARRAY)
            c->items[i].u.arr = pp_array_copy(ps, arr->items[i].u.arr);
    }
    return c;
}

/* array '[' n ']' ... [ '{' initialiser '}' ] */
static pp_array *array_value(pp_state *ps, const pp_token *at)
{
    pp_array *arr = pp_salloc(ps, sizeof *arr);
    long n = 1;
    while (pp_accept(ps, T_LBRACKET)) {
        pp_token dt = ps->tok;
        double f = pp_float(ps);
        pp_expect(ps, T_RBRACKET, "']'");
        if (arr->ndim >= 5)
            pp_error(ps, &dt, "arrays have at most 5 dimensions");
        if (!(f >= 1) || f > MAX_ARRAY_ELEMS)
            pp_error(ps, &dt, "array size %g out of range [1, %ld]", f,
                     MAX_ARRAY_ELEMS);
        arr->dims[arr->ndim++] = (int)f;
        n *= (long)f;
        if (n > MAX_ARRAY_ELEMS)
            pp_error(ps, &dt, "array of more than %ld elements",
                     MAX_ARRAY_ELEMS);
    }
    if (arr->ndim == 0)
        pp_error(ps, at, "array needs a size: array[N]");
    arr->n = n;
    arr->items = pp_salloc(ps, (size_t)n * sizeof *arr->items);
    if (!pp_next_is_directive(ps)) {
        pp_next(ps);
        pp_unget(ps);
        if (ps->tok.kind == T_LBRACE)
            array_init(ps, arr, 0, 0);
    }
    return arr;
}

iris_fn_spline pp_spline_view(const pp_spline *s)
{
    iris_fn_spline v = { s->type, s->n, s->dim, s->t,
                         (const double (*)[5])s->p,
                         (const double (*)[5])s->coeff };
    return v;
}

/* A natural spline's coefficients, once its keys are final. */
void pp_spline_finish(pp_state *ps, pp_spline *s)
{
    s->coeff = NULL;
    if (s->type != IRIS_FN_SPLINE_NATURAL || s->n < 3)
        return;
    s->coeff = pp_salloc(ps, (size_t)s->n * sizeof *s->coeff);
    iris_fn_spline v = pp_spline_view(s);
    if (!iris_fn_spline_coeffs(&v, s->coeff))
        pp_nomem(ps);
}

/* spline { [type] t, <v> [,] ... } */
pp_spline *pp_spline_block(pp_state *ps)
{
    pp_expect(ps, T_LBRACE, "'{'");
    pp_spline *s = pp_salloc(ps, sizeof *s);
    int cap = 0;
    /* POV-Ray reads every key's value into one five-component buffer
    ** and stores all five: a float key is promoted to <v, v> and the
    ** components a key does not give keep the previous key's (in the
    ** order written). spline { 0, <1,2,3>, 1, 5 } gives <5,5,3> at 1. */
    double last[5] = { 0, 0, 0, 0, 0 };
    for (;;) {
        pp_next(ps);
        switch (ps->tok.kind) {
        case T_LINEAR_SPLINE: s->type = 0; continue;
        case T_QUADRATIC_SPLINE: s->type = 1; continue;
        case T_CUBIC_SPLINE: s->type = 2; continue;
        case T_NATURAL_SPLINE: s->type = 3; continue;
        case T_RBRACE:
            pp_spline_finish(ps, s);
            return s;
        case T_IDENT:
            if (ps->tok.val.kind == V_SPLINE) {
                /* a copy: keys added here must not change the original */
                const pp_spline *o = ps->tok.val.u.spline;
                *s = *o;
                s->t = pp_salloc(ps, (size_t)(o->n ? o->n : 1) * sizeof *s->t);
                s->p = pp_salloc(ps, (size_t)(o->n ? o->n : 1) * sizeof *s->p);
                if (o->n) {
                    memcpy(s->t, o->t, (size_t)o->n * sizeof *s->t);
                    memcpy(s->p, o->p, (size_t)o->n * sizeof *s->p);
                }
                cap = o->n;
                continue;
            }
            break;
        default:
            break;
        }
        pp_unget(ps);
        double t = pp_float(ps);
        pp_accept(ps, T_COMMA);
        /* no colour keyword: POV-Ray's Parse_Spline refuses one there
        ** ("Expected 'numeric expression', color keyword found") */
        pp_next(ps);
        if (pp_is_colour_keyword(ps->tok.kind)) {
            char buf[80];
            pp_error(ps, &ps->tok, "a spline key's value is a float or a "
                     "vector, found %s (write <r, g, b> without it)",
                     pp_tok_name(ps, &ps->tok, buf, sizeof buf));
        }
        pp_unget(ps);
        pp_value v = pp_expr(ps);
        pp_accept(ps, T_COMMA);
        if (v.dim <= 1) {
            v.v[1] = v.v[0];
            v.dim = 2;
        }
        for (int k = 0; k < v.dim && k < 5; k++)
            last[k] = v.v[k];
        if (s->n == cap) {
            int nc = cap ? cap * 2 : 16;
            double *nt = pp_salloc(ps, (size_t)nc * sizeof *nt);
            double (*np)[5] = pp_salloc(ps, (size_t)nc * sizeof *np);
            if (s->n) {
                memcpy(nt, s->t, (size_t)s->n * sizeof *nt);
                memcpy(np, s->p, (size_t)s->n * sizeof *np);
            }
            s->t = nt;
            s->p = np;
            cap = nc;
        }
        /* A key at an existing t replaces it (POV-Ray's
        ** Insert_Spline_Entry); keys are kept sorted by t. */
        int lo = 0, hi = s->n;   /* the first key with t[j] >= t */
        while (lo < hi) {
            int mid = lo + (hi - lo) / 2;
            if (s->t[mid] < t)
                lo = mid + 1;
            else
                hi = mid;
        }
        int same = lo < s->n && s->t[lo] == t ? lo : -1;
        if (same >= 0) {
            memcpy(s->p[same], last, sizeof s->p[same]);
            if (v.dim > s->dim)
                s->dim = v.dim;
            continue;
        }
        int i = s->n;
        while (i > 0 && s->t[i - 1] > t) {
            s->t[i] = s->t[i - 1];
            memcpy(s->p[i], s->p[i - 1], sizeof s->p[i]);
            i--;
        }
        s->t[i] = t;
        memcpy(s->p[i], last, sizeof s->p[i]);
        if (v.dim > s->dim)
            s->dim = v.dim;
        s->n++;
    }
}

static pp_value make(int kind, void *p)
{
    pp_value v;
    memset(&v, 0, sizeof v);
    v.kind = kind;
    v.u.ptr = p;
    return v;
}

pp_value pp_rvalue(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    switch (at.kind) {
    case T_TEXTURE: {
        /* consecutive textures make a layered texture, the last on top */
        iris_texture *t = pp_texture(ps);
        while (!pp_next_is_directive(ps) && pp_accept(ps, T_TEXTURE)) {
            iris_texture *top = pp_texture(ps);
            iris_texture *last = top;
            while (last->next)
                last = last->next;
            last->next = t;
            t = top;
        }
        return make(V_TEXTURE, t);
    }
    case T_PIGMENT: return make(V_PIGMENT, pp_pigment(ps, NULL));
    case T_NORMAL: return make(V_NORMAL, pp_normal(ps, NULL));
    case T_FINISH: {
        /* a declared finish starts from the #default finish, as POV-Ray's
        ** Parse_RValue copies the default texture's (incdemo/shapes.pov:
        ** #default { finish { ambient 0 } } then #declare F = finish {..}) */
        const iris_texture *d = pp_default_texture(ps);
        return make(V_FINISH, pp_finish(ps, d ? d->finish : NULL));
    }
    case T_INTERIOR: return make(V_INTERIOR, pp_interior(ps, NULL));
    case T_MATERIAL: return make(V_MATERIAL, pp_material_block(ps));
    case T_TRANSFORM: return make(V_TRANSFORM, pp_transform_block(ps));
    case T_CAMERA: return make(V_CAMERA, pp_camera(ps, NULL));
    case T_LIGHT_SOURCE: return make(V_LIGHT, pp_light(ps));
    case T_FOG: return make(V_FOG, pp_fog(ps));
    case T_SKY_SPHERE: return make(V_SKY_SPHERE, pp_sky_sphere(ps, NULL));
    case T_FUNCTION: return make(V_FUNCTION, pp_function(ps));
    case T_SPLINE: return make(V_SPLINE, pp_spline_block(ps));
    case T_ARRAY: return make(V_ARRAY, array_value(ps, &at));
    case T_COLOR_MAP: return make(V_COLOUR_MAP, pp_map_block(ps, V_COLOUR_MAP));
    case T_PIGMENT_MAP:
        return make(V_PIGMENT_MAP, pp_map_block(ps, V_PIGMENT_MAP));
    case T_NORMAL_MAP:
        return make(V_NORMAL_MAP, pp_map_block(ps, V_NORMAL_MAP));
    case T_TEXTURE_MAP:
        return make(V_TEXTURE_MAP, pp_map_block(ps, V_TEXTURE_MAP));
    case T_SLOPE_MAP: return make(V_SLOPE_MAP, pp_map_block(ps, V_SLOPE_MAP));
    case T_MEDIA: return make(V_MEDIA, pp_media(ps));
    case T_DENSITY: return make(V_DENSITY, pp_density_block(ps, NULL));
    case T_DENSITY_MAP: {
        ps->in_density++;
        pp_map *m = pp_map_block(ps, V_PIGMENT_MAP);
        ps->in_density--;
        return make(V_DENSITY_MAP, m);
    }
    case T_RAINBOW: return make(V_RAINBOW, pp_rainbow_block(ps));
    case T_PHOTONS: case T_RADIOSITY: {
        pp_warn_once(ps, &at, at.kind, lex_keyword_name(at.kind));
        pp_expect(ps, T_LBRACE, "'{'");
        pp_skip_block(ps);
        return make(V_UNSUPPORTED, NULL);
    }
    case T_IDENT: {
        int k = at.val.kind;
        if (k == V_NONE)
            pp_error(ps, &at, "undeclared identifier '%.*s'", (int)at.len,
                     pp_tok_text(ps, &at));
        bool callable = k == V_FUNCTION || k == V_SPLINE || k == V_ARRAY;
        if (callable && !pp_next_is_directive(ps)) {
            /* only a look at the next token: a macro called right after
            ** (the value ended its own macro's body: '#declare G = A
            ** #end' then 'M(G)') runs once this value is stored */
            ps->no_expand++;
            pp_next(ps);
            ps->no_expand--;
            int nk = ps->tok.kind;
            pp_unget(ps);
            ps->tok = at;
            if (nk == T_LPAREN || nk == T_LBRACKET)
                callable = false; /* a call or an element: an expression */
            else
                return at.val;
        } else if (callable) {
            return at.val;
        }
        if (k == V_STRING) {
            pp_unget(ps);
            return pp_string_rvalue(ps);
        }
        if (!callable && k != V_FLOAT && k != V_VECTOR && k != V_COLOUR &&
            k != V_STRING && k != V_FUNCTION && k != V_SPLINE &&
            k != V_ARRAY) {
            /* objects are copied on use, so sharing is safe */
            return at.val;
        }
        break;
    }
    case T_STRING: case T_STR: case T_CONCAT: case T_CHR: case T_SUBSTR:
    case T_STRUPR: case T_STRLWR: case T_VSTR: case T_DATETIME:
        pp_unget(ps);
        return pp_string_rvalue(ps);
    default:
        break;
    }
    pp_unget(ps);
    if (pp_starts_object(ps)) {
        iris_object *o = pp_object(ps);
        return make(V_OBJECT, o);
    }
    /* a declared or passed float is a float (Parse_RValue keeps
    ** Express[0]): a period's leftover components end here */
    pp_value v = pp_expr_sum(ps);
    v.leftover = false;
    return v;
}
