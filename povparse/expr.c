/* SPDX-License-Identifier: MIT */
/*
** expr.c: float, vector, colour and string expressions, and the right-hand
** side of #declare.
**
** Precedence, lowest first, as POV-Ray's Parse_Express: ?:  |  &
** comparisons (< <= = != >= >)  + -  * /  unary + - !  then factors with
** .x/.red/... suffixes. A float meets a vector by filling every component
** (POV-Ray's promotion); a shorter vector is padded with zeros. Inside
** <...> a bare '>' closes the vector and is not a comparison.
*/
#include "config.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "math/vec3.h"
#include "pp.h"

static pp_value expr_cond(pp_state *ps);
static pp_value expr_add(pp_state *ps);

static pp_value fval(double f)
{
    pp_value v;
    memset(&v, 0, sizeof v);
    v.kind = V_FLOAT;
    v.dim = 1;
    v.v[0] = f;
    return v;
}

static pp_value vval(int dim, double a, double b, double c, double d)
{
    pp_value v;
    memset(&v, 0, sizeof v);
    v.kind = V_VECTOR;
    v.dim = dim;
    v.v[0] = a; v.v[1] = b; v.v[2] = c; v.v[3] = d;
    return v;
}

static pp_value sval(const char *s)
{
    pp_value v;
    memset(&v, 0, sizeof v);
    v.kind = V_STRING;
    v.u.str = s;
    return v;
}

static bool numeric(const pp_value *v)
{
    return v->kind == V_FLOAT || v->kind == V_VECTOR || v->kind == V_COLOUR;
}

void pp_value_promote(pp_value *v, int dim)
{
    if (v->dim >= dim)
        return;
    v->leftover = false;
    if (v->dim == 1)
        for (int i = 1; i < dim; i++)
            v->v[i] = v->v[0];
    else
        for (int i = v->dim; i < dim; i++)
            v->v[i] = 0;
    v->dim = dim;
    if (v->kind == V_FLOAT)
        v->kind = dim == 5 ? V_COLOUR : V_VECTOR;
}

static void need_numeric(pp_state *ps, const pp_token *at, const pp_value *v)
{
    if (!numeric(v))
        pp_error(ps, at, "expected a numeric expression, found a %s",
                 pp_kind_name(v->kind));
}

/* Numbers that go into the scene (or steer a directive) must be finite:
** an overflow such as 1e308 * 1e308 would reach the renderer as inf or
** NaN (issue 7). #declare keeps any value; only its use is checked. */
static void need_finite(pp_state *ps, const pp_token *at, const pp_value *v)
{
    for (int i = 0; i < v->dim && i < 5; i++)
        if (!isfinite(v->v[i]))
            pp_error(ps, at, "the expression is not a finite number (%g): "
                     "an overflow or an undefined operation", v->v[i]);
}

/*
** True when the next token is a directive that only closes the running
** #if branch: #else or #elseif of an #if being run, or the #end of an
** #if/#else. Such a directive computes nothing, so running it before
** the expression is complete is safe, and POV-Ray does so: a macro whose
** body is '#if (c) A[i] #else ... #end' can be followed by '* 2' in the
** caller (arrays.inc's Rand_Array_Item in advanced/isocacti). The same
** holds for a #switch's control flow: #break (to the #end of the switch
** or loop it leaves), and, in a running #switch clause, #case/#range/#else
** falling through and the switch's #end: a macro returning a value from a
** clause, 'M(x) + 1' or concat(M(x), ...), goes on after the #switch as in
** POV-Ray. Any other directive (#declare, a loop's #end, ...) still ends
** the expression.
*/
static bool next_directive_closes_if(pp_state *ps)
{
    if (ps->n_unget > 0 || ps->n_frames == 0 ||
        (ps->n_frames == ps->header_frames &&
         ps->n_conds == ps->header_conds))
        return false;
    pp_frame *cur = &ps->frames[ps->n_frames - 1];
    if (ps->n_conds <= cur->cond_base)
        return false;
    int inner = ps->conds[ps->n_conds - 1].kind;
    pp_token t, kw;
    uint32_t pos = lex_peek(ps, cur->file, cur->pos, &t);
    if (t.kind != T_HASH)
        return false;
    lex_peek(ps, cur->file, pos, &kw);
    switch (kw.kind) {
    case T_ELSEIF:
        return inner == C_IF;
    case T_ELSE:
        return inner == C_IF || inner == C_SWITCH;
    case T_CASE: case T_RANGE:
        return inner == C_SWITCH;
    case T_BREAK:
        return inner == C_IF || inner == C_ELSE || inner == C_SWITCH;
    case T_END:
        return inner == C_IF || inner == C_ELSE || inner == C_SWITCH;
    default:
        return false;
    }
}

/* pp_next_is_directive(), except for the directives that only close an
** #if branch (next_directive_closes_if): the expression goes on past
** them. */
static bool expression_ends(pp_state *ps)
{
    while (pp_next_is_directive(ps)) {
        if (!next_directive_closes_if(ps))
            return true;
        /* run that one directive, nothing after it */
        pp_token hash;
        pp_raw(ps, &hash);
        pp_directive(ps, &hash);
    }
    return false;
}

/* Reads the next operator token, or nothing when the next token is a
** directive (which must not run before the expression is complete). */
static int peek_op(pp_state *ps)
{
    if (expression_ends(ps))
        return T_EOF;
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    int k = ps->tok.kind;
    pp_unget(ps);
    return k;
}

/* One component of a binary operator: arithmetic (+ - * /), a relation
** (POV-Ray's Parse_Rel_Term: 1 or 0; equality within POV-Ray's absolute
** EPSILON, 1e-10, also for '<=' and '>='; '<' and '>' exact) or '&' / '|'
** (Parse_Logical). */
static double component(pp_state *ps, const pp_token *at, int op,
                        double x, double y)
{
    bool same = !pp_true(x - y);
    switch (op) {
    case T_PLUS: return x + y;
    case T_MINUS: return x - y;
    case T_STAR: return x * y;
    case T_SLASH:
        /* POV-Ray's Parse_Term: a divisor of exactly 0 gives HUGE_VAL
        ** (+inf, whatever the dividend) and a warning, not an error:
        ** '#declare Speed = D / clock;' parses at clock 0. The value is
        ** refused only where it goes into the scene (need_finite). */
        if (y == 0) {
            pp_warning(ps, at, "divide by zero");
            return HUGE_VAL;
        }
        return x / y;
    case T_LT: return x < y;
    case T_LE: return x <= y || same;
    case T_EQUALS: return same;
    case T_NE: return !same;
    case T_GE: return x >= y || same;
    case T_GT: return x > y;
    case T_AMP: return pp_true(x) && pp_true(y);
    default: return pp_true(x) || pp_true(y); /* T_BAR */
    }
}

/* A binary operator component by component: the operands are promoted to
** the longer one (a float fills every component, a shorter vector gets
** zeros), so '(<1,2,3> = <1,2,4>)' is <1,1,0>; the result is a colour if
** either operand is one. */
static void binop(pp_state *ps, const pp_token *at, pp_value *a,
                  const pp_value *bb, int op)
{
    pp_value b = *bb;
    need_numeric(ps, at, a);
    need_numeric(ps, at, &b);
    int dim = a->dim > b.dim ? a->dim : b.dim;
    bool colour = a->kind == V_COLOUR || b.kind == V_COLOUR;
    pp_value_promote(a, dim);
    pp_value_promote(&b, dim);
    for (int i = 0; i < dim; i++)
        a->v[i] = component(ps, at, op, a->v[i], b.v[i]);
    a->dim = dim;
    a->kind = dim == 1 ? V_FLOAT : colour ? V_COLOUR : V_VECTOR;
}

/* ---- built-in functions ----------------------------------------- */

static void lparen(pp_state *ps) { pp_expect(ps, T_LPAREN, "'('"); }
static void rparen(pp_state *ps) { pp_expect(ps, T_RPAREN, "')'"); }
/* Between a built-in function's arguments: POV-Ray's Parse_Comma, which
** takes a comma if there is one ('vrotate(<1,0,0> <0,90,0>)' is valid;
** only min/max insist on theirs). */
static void comma(pp_state *ps) { pp_accept(ps, T_COMMA); }

/* A float argument that may be infinite or NaN (min, max). */
static double any_float(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    pp_value v = expr_add(ps);
    need_numeric(ps, &at, &v);
    if (v.dim != 1)
        pp_error(ps, &at, "expected a float, found a %d-component vector",
                 v.dim);
    return v.v[0];
}

static double arg1(pp_state *ps)
{
    lparen(ps);
    double a = pp_float(ps);
    rparen(ps);
    return a;
}

static void arg2(pp_state *ps, double *a, double *b)
{
    lparen(ps);
    *a = pp_float(ps);
    comma(ps);
    *b = pp_float(ps);
    rparen(ps);
}

/* A domain check: POV-Ray stops with an error, and so do we. */
static double checked(pp_state *ps, const pp_token *at, double r,
                      const char *fn)
{
    if (!isfinite(r))
        pp_error(ps, at, "%s: argument out of range", fn);
    return r;
}

/* acos() and asin() of a number outside [-1, 1]: POV-Ray warns
** "Domain error" and takes the nearest end (acos(1.0000000001) of a dot
** product of unit vectors is 0, not an error). */
static double domain_clamp(pp_state *ps, const pp_token *at, double x,
                           const char *fn)
{
    if (x > 1 || x < -1) {
        pp_warning(ps, at, "domain error in %s(%g): %g used", fn, x,
                   x > 1 ? 1.0 : -1.0);
        return x > 1 ? 1 : -1;
    }
    return x;
}

/* rand(): POV-Ray 3.7's generator, so that scenes built from random
** numbers come out the same (randomsequence.cpp POV_rand): a 32-bit
** linear congruential step s = s * 1812433253 + 12345 (mod 2^32), and
** the value s / (2^32 - 1), in [0, 1]. */
static double pov_rand(uint64_t *state)
{
    uint32_t s = (uint32_t)*state * 1812433253u + 12345u;
    *state = s;
    return (double)s / 4294967295.0;
}

/* seed(): the stream starts at (unsigned int)(int)x, as POV-Ray's
** stream_seed; a float outside the int range gives INT_MIN, what x86's
** conversion gives there. */
static uint64_t pov_seed(double x)
{
    int32_t i = x > -2147483649.0 && x < 2147483648.0 ? (int32_t)x
                                                      : INT32_MIN;
    return (uint32_t)i;
}

static const char *fmt_float(pp_state *ps, double f, int len, int prec)
{
    char buf[512];
    bool zero = len < 0;
    int w = len < 0 ? -len : len;
    if (w > 200)
        w = 200;
    if (prec > 100)
        prec = 100;
    if (prec < 0)
        prec = 6;
    if (zero)
        snprintf(buf, sizeof buf, "%0*.*f", w, prec, f);
    else
        snprintf(buf, sizeof buf, "%*.*f", w, prec, f);
    /* POV-Ray's Parse_Str formats into 256 bytes and, when %f fills
    ** them (a number of 255 digits or more: 1e255), formats with %g
    ** and the same width and precision: str(1e304, 0, 0) is "1e+304" */
    if (strlen(buf) >= 255) {
        if (zero)
            snprintf(buf, sizeof buf, "%0*.*g", w, prec, f);
        else
            snprintf(buf, sizeof buf, "%*.*g", w, prec, f);
    }
    return pp_strdup(ps, buf, strlen(buf));
}

static const iris_object *object_arg(pp_state *ps)
{
    lparen(ps);
    pp_next(ps);
    const iris_object *o = NULL;
    if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_OBJECT) {
        o = ps->tok.val.u.obj;
    } else {
        pp_unget(ps);
        o = pp_object(ps);
        if (!o)
            pp_error(ps, &ps->tok, "expected an object");
    }
    rparen(ps);
    return o;
}

/* The object argument of trace() and inside(): an object identifier
** (POV-Ray accepts nothing else). */
static const iris_object *object_ident(pp_state *ps)
{
    pp_next(ps);
    if (ps->tok.kind != T_IDENT || ps->tok.val.kind != V_OBJECT)
        pp_error(ps, &ps->tok, "object identifier expected");
    return ps->tok.val.u.obj;
}

/* The geometry callbacks, or a located error naming what needs them. */
static const iris_geometry_queries *need_geometry(pp_state *ps,
                                                  const pp_token *at,
                                                  const char *what)
{
    const iris_geometry_queries *g = ps->opt.geometry;
    if (!g || (what[0] == 't' ? !g->trace : !g->inside))
        pp_error(ps, at, "%s() needs the renderer (no geometry queries were "
                 "given to the parser)", what);
    return g;
}

/* trace(OBJECT_ID, A, B [, VECTOR_ID]): the first hit of the ray from A
** along B with the object, <0,0,0> on a miss; the optional identifier
** receives the surface normal there, <0,0,0> on a miss (POV-Ray 3.7,
** parser_expressions.cpp Parse_Trace). */
static pp_value trace_call(pp_state *ps, const pp_token *at)
{
    const iris_geometry_queries *g = need_geometry(ps, at, "trace");
    lparen(ps);
    const iris_object *o = object_ident(ps);
    comma(ps);
    vec3 org = pp_vector(ps);
    comma(ps);
    vec3 dir = pp_vector(ps);
    vec3 p = v3(0, 0, 0), n = v3(0, 0, 0);
    double len = v3_len(dir);
    if (len > 0 && isfinite(len) &&
        !g->trace(g->user, ps->scene, pp_query_object(ps, o), org,
                  v3_scale(dir, 1 / len), &p, &n)) {
        p = v3(0, 0, 0);
        n = v3(0, 0, 0);
    }
    if (pp_accept(ps, T_COMMA)) {
        pp_next(ps);
        pp_token name = ps->tok;
        if (name.kind != T_IDENT)
            pp_error(ps, &name, "expected a vector identifier for the "
                     "normal in trace()");
        const char *text = pp_tok_text(ps, &name);
        pp_sym *s = sym_lookup(ps, text, name.len);
        if (!s)
            s = sym_define(ps, 0, text, name.len);
        s = sym_resolve(s);
        s->val = vval(3, n.x, n.y, n.z, 0);
    }
    rparen(ps);
    return vval(3, p.x, p.y, p.z, 0);
}

/* inside(OBJECT_ID, POINT): 1 when the point is inside the object. */
static pp_value inside_call(pp_state *ps, const pp_token *at)
{
    const iris_geometry_queries *g = need_geometry(ps, at, "inside");
    lparen(ps);
    const iris_object *o = object_ident(ps);
    comma(ps);
    vec3 p = pp_vector(ps);
    rparen(ps);
    return fval(g->inside(g->user, ps->scene, pp_query_object(ps, o), p)
                    ? 1 : 0);
}

/* A spline's value at 't' (POV-Ray's definitions, src/fn/spline.c). */
static pp_value spline_eval(const pp_spline *s, double t)
{
    pp_value v;
    memset(&v, 0, sizeof v);
    v.kind = s->dim <= 1 ? V_FLOAT : V_VECTOR;
    v.dim = s->dim < 1 ? 1 : s->dim;
    iris_fn_spline view = pp_spline_view(s);
    iris_fn_spline_eval(&view, t, v.v);
    return v;
}

/* Parses the components after a colour keyword, POV-Ray's Parse_Colour:
** rgb/rgbf/rgbt/rgbft/srgb... once, then red/green/blue/filter/transmit
** and colour identifiers. The current token is the first keyword. */
static pp_value colour_body(pp_state *ps)
{
    pp_value c;
    memset(&c, 0, sizeof c);
    c.kind = V_COLOUR;
    c.dim = 5;
    bool started = false;
    for (;;) {
        int k = ps->tok.kind;
        pp_token at = ps->tok;
        int terms = 0;
        bool srgb = false;
        switch (k) {
        case T_COLOR:
            if (started) {
                pp_unget(ps);
                return c;
            }
            break;
        case T_RED: c.v[0] = pp_float(ps); started = true; break;
        case T_GREEN: c.v[1] = pp_float(ps); started = true; break;
        case T_BLUE: c.v[2] = pp_float(ps); started = true; break;
        case T_FILTER: c.v[3] = pp_float(ps); started = true; break;
        case T_TRANSMIT: c.v[4] = pp_float(ps); started = true; break;
        case T_ALPHA:
            /* POV-Ray 3.1's colour component: 3.7 warns "Keyword ALPHA
            ** discontinued. Use FILTER instead." and reads it as filter */
            pp_warning(ps, &at, "'alpha' is discontinued: read as 'filter'");
            c.v[3] = pp_float(ps);
            started = true;
            break;
        case T_SRGB: srgb = true; terms = 3; break;
        case T_SRGBF: srgb = true; terms = 4; break;
        case T_SRGBT: srgb = true; terms = -4; break;
        case T_SRGBFT: srgb = true; terms = 5; break;
        case T_RGB: terms = 3; break;
        case T_RGBF: terms = 4; break;
        case T_RGBT: terms = -4; break;
        case T_RGBFT: terms = 5; break;
        default:
            if (started || !pp_starts_expr(ps)) {
                pp_unget(ps);
                return c;
            }
            pp_unget(ps);
            {
                pp_value e = expr_cond(ps);
                need_numeric(ps, &at, &e);
                if (e.dim == 1) {
                    /* POV-Ray promotes a float to all five components:
                    ** 'color 0.8' filters and transmits 0.8 */
                    for (int i = 0; i < 5; i++)
                        c.v[i] = e.v[0];
                } else {
                    for (int i = 0; i < e.dim && i < 5; i++)
                        c.v[i] = e.v[i];
                }
            }
            started = true;
            break;
        }
        if (terms != 0) {
            if (started) {
                pp_unget(ps);
                return c;
            }
            pp_value e = expr_cond(ps);
            need_numeric(ps, &at, &e);
            int n = terms < 0 ? -terms : terms;
            if (e.dim == 1) {
                for (int i = 0; i < n; i++)
                    c.v[i] = e.v[0];
            } else {
                /* POV-Ray's Parse_Colour takes every term the expression
                ** has, with a warning: 'rgb <0.1, 0.1, 0.1, 1>' filters
                ** (2-complex's domino floor) */
                if (e.dim != n)
                    pp_warning(ps, &at, "suspicious expression after %s: "
                               "%d components, not %d", lex_keyword_name(k),
                               e.dim, n);
                for (int i = 0; i < e.dim && i < 5; i++)
                    c.v[i] = e.v[i];
            }
            if (terms == -4) {
                c.v[4] = c.v[3];
                c.v[3] = 0;
            }
            if (srgb)
                for (int i = 0; i < 3; i++)
                    c.v[i] = pp_srgb_to_working(ps, &at, c.v[i]);
            started = true;
        }
        if (expression_ends(ps))
            return c;
        pp_next(ps);
    }
}

static bool is_colour_kw(int k)
{
    return k == T_COLOR || k == T_RGB || k == T_RGBF || k == T_RGBT ||
           k == T_RGBFT || k == T_SRGB || k == T_SRGBF || k == T_SRGBT ||
           k == T_SRGBFT || k == T_RED || k == T_GREEN || k == T_BLUE ||
           k == T_FILTER || k == T_TRANSMIT;
}

bool pp_is_colour_keyword(int kind)
{
    return is_colour_kw(kind);
}

bool pp_starts_expr(pp_state *ps)
{
    int k = ps->tok.kind;
    switch (k) {
    case T_NUMBER: case T_LPAREN: case T_LT: case T_MINUS: case T_PLUS:
    case T_BANG: case T_STRING:
        return true;
    case T_IDENT:
        return numeric(&ps->tok.val) || ps->tok.val.kind == V_STRING ||
               ps->tok.val.kind == V_FUNCTION || ps->tok.val.kind == V_SPLINE ||
               ps->tok.val.kind == V_ARRAY;
    case T_X: case T_Y: case T_Z: case T_T: case T_U: case T_V: case T_PI:
    case T_TAU: case T_TRUE: case T_FALSE: case T_YES: case T_NO: case T_ON:
    case T_OFF: case T_CLOCK: case T_CLOCK_DELTA: case T_CLOCK_ON:
    case T_FRAME_NUMBER: case T_INITIAL_FRAME: case T_FINAL_FRAME:
    case T_INITIAL_CLOCK: case T_FINAL_CLOCK: case T_IMAGE_WIDTH:
    case T_IMAGE_HEIGHT: case T_VERSION:
    case T_ABS: case T_ACOS: case T_ACOSH: case T_ASIN: case T_ASINH:
    case T_ATAN: case T_ATANH: case T_ATAN2: case T_CEIL: case T_COS:
    case T_COSH: case T_DEGREES: case T_RADIANS: case T_DIV: case T_EXP:
    case T_FLOOR: case T_INT: case T_LN: case T_LOG: case T_MAX: case T_MIN:
    case T_MOD: case T_POW: case T_SQRT: case T_SQR: case T_TAN: case T_TANH:
    case T_SIN: case T_SINH: case T_SELECT: case T_VLENGTH: case T_VDOT:
    case T_VNORMALIZE: case T_VCROSS: case T_VROTATE: case T_VAXIS_ROTATE:
    case T_VTURBULENCE: case T_RAND: case T_SEED: case T_DEFINED:
    case T_DIMENSIONS: case T_DIMENSION_SIZE: case T_STRLEN: case T_VAL:
    case T_ASC: case T_STRCMP: case T_FILE_EXISTS: case T_MIN_EXTENT:
    case T_MAX_EXTENT: case T_BITWISE_AND: case T_BITWISE_OR:
    case T_BITWISE_XOR: case T_STR: case T_CONCAT: case T_CHR:
    case T_SUBSTR: case T_STRUPR: case T_STRLWR: case T_VSTR: case T_INSIDE:
    case T_TRACE: case T_DATETIME: case T_NOW:
        return true;
    default:
        return is_colour_kw(k);
    }
}

bool pp_float_follows(pp_state *ps)
{
    if (pp_next_is_directive(ps))
        return false;
    pp_next(ps);
    bool yes = pp_starts_expr(ps) && ps->tok.kind != T_LT &&
               ps->tok.kind != T_STRING;
    pp_unget(ps);
    return yes;
}

/* Whether this parse wrote 'name' (at 'full' beside the file asking, or
** in the scene's directory, where writes go) while writes were refused
** (memfile.c). Out of factor(), whose frame every level of parentheses
** pays for. */
static __attribute__((noinline)) bool written(pp_state *ps,
                                              const char *full,
                                              const char *name)
{
    if (!ps->memfiles)
        return false;
    if (pp_memfile_find(ps, full))
        return true;
    char scene[4096];
    snprintf(scene, sizeof scene, "%s/%s",
             ps->n_files > 0 ? ps->files[0].dir : ".", name);
    return name[0] != '/' && pp_memfile_find(ps, scene);
}

/* Reads the indices of an array reference; the '[' is next. */
pp_value pp_array_element(pp_state *ps, const pp_token *at, pp_array *arr)
{
again:;
    long idx = 0;
    for (int d = 0; d < arr->ndim; d++) {
        pp_expect(ps, T_LBRACKET, "'['");
        pp_token it = ps->tok;
        double f = pp_float(ps);
        pp_expect(ps, T_RBRACKET, "']'");
        if (!(f >= 0) || !(f < arr->dims[d]))
            pp_error(ps, &it, "array index %g out of range [0, %d]", f,
                     arr->dims[d] - 1);
        idx = idx * arr->dims[d] + (long)f;
    }
    pp_value v = arr->items[idx];
    if (v.kind == V_NONE)
        pp_error(ps, at, "array element used before it was given a value");
    ps->elem_slot = &arr->items[idx];
    /* an array held in an array: A[i][j] goes on into it */
    if (v.kind == V_ARRAY && pp_accept(ps, T_LBRACKET)) {
        pp_unget(ps);
        arr = v.u.arr;
        goto again;
    }
    return v;
}

/* Calls function 'fn' with '(' args ')' at the next tokens. */
static pp_value call_fn(pp_state *ps, const iris_fn *fn)
{
    double args[64];
    int n = 0;
    /* exactly as many arguments as the function takes, commas optional
    ** (POV-Ray: one too many stops at its ',', one too few at the ')') */
    int want = pp_fn_arity(fn);
    lparen(ps);
    for (int i = 0; i < want; i++) {
        if (i > 0)
            comma(ps);
        double a = pp_float(ps);
        if (n < 64)
            args[n++] = a;
    }
    rparen(ps);
    if (fn->n_results > 1) {
        pp_value v;
        memset(&v, 0, sizeof v);
        v.kind = fn->n_results == 5 ? V_COLOUR : V_VECTOR;
        v.dim = fn->n_results;
        /* A pigment, spline or transform function: its result, one
        ** component at a time */
        const iris_fn_insn *body = fn->code;
        if (fn->n_code == 1 && (body->op == IRIS_FN_SPLINE ||
                                body->op == IRIS_FN_TRANSFORM ||
                                (body->op == IRIS_FN_PATTERN &&
                                 body->pigment))) {
            for (int k = 0; k < fn->n_results && k < 5; k++) {
                iris_fn_insn in = fn->code[0];
                in.arg = k;
                in.nargs = 0;
                iris_fn one = { fn->n_params, NULL, 1, &in, 1, 1 };
                v.v[k] = iris_fn_eval(&one, args, n);
            }
        }
        return v;
    }
    return fval(iris_fn_eval(fn, args, n));
}

/* A string expression factor: literal, identifier or string function. */
/* paren_rest: expr_cond ')' -- after the '(' at 'open'. Inside
** parentheses '<' compares again, even within a vector's components. */
static pp_value paren_rest(pp_state *ps, const pp_token *open)
{
    bool iv = ps->in_vector;
    ps->in_vector = false;
    pp_enter(ps, open);
    pp_value v = expr_cond(ps);
    pp_leave(ps);
    ps->in_vector = iv;
    rparen(ps);
    return v;
}

static pp_value factor(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    int k = at.kind;
    double a, b;
    switch (k) {
    case T_NUMBER: return fval(at.num);
    case T_STRING: return sval(at.str);
    case T_LPAREN:
        return paren_rest(ps, &at);
    case T_LT: {
        /* POV-Ray reads each component as a float (no comparisons) and
        ** the commas between them are optional */
        pp_value v;
        memset(&v, 0, sizeof v);
        int n = 0;
        pp_enter(ps, &at);
        for (;;) {
            pp_token ct = ps->tok;
            pp_value c = expr_add(ps);
            if (c.kind != V_FLOAT)
                pp_error(ps, &ct, "vector components must be floats");
            if (n >= 5)
                pp_error(ps, &at, "a vector has at most 5 components");
            v.v[n++] = c.v[0];
            pp_next(ps);
            if (ps->tok.kind == T_COMMA)
                pp_next(ps);
            if (ps->tok.kind == T_GT)
                break;
            pp_unget(ps);
        }
        pp_leave(ps);
        if (n < 2)
            pp_error(ps, &at, "a vector needs at least 2 components");
        v.kind = V_VECTOR;
        v.dim = n;
        return v;
    }
    case T_IDENT: {
        pp_value v = at.val;
        switch (v.kind) {
        case V_NONE:
            pp_error(ps, &at, "undeclared identifier '%.*s'", (int)at.len,
                     pp_tok_text(ps, &at));
        case V_FLOAT: case V_VECTOR: case V_COLOUR: case V_STRING:
            return v;
        case V_ARRAY:
            if (!pp_accept(ps, T_LBRACKET))
                pp_error(ps, &at, "array '%.*s' used without an index",
                         (int)at.len, pp_tok_text(ps, &at));
            pp_unget(ps);
            return pp_array_element(ps, &at, v.u.arr);
        case V_FUNCTION:
            return call_fn(ps, v.u.fn);
        case V_SPLINE: {
            /* S(t [, spline_type]): with a type, POV-Ray's
            ** Parse_Spline_Call evaluates a copy of S of that type */
            lparen(ps);
            double t = pp_float(ps);
            const pp_spline *s = v.u.spline;
            if (pp_accept(ps, T_COMMA)) {
                pp_next(ps);
                int ty;
                switch (ps->tok.kind) {
                case T_LINEAR_SPLINE: ty = IRIS_FN_SPLINE_LINEAR; break;
                case T_QUADRATIC_SPLINE: ty = IRIS_FN_SPLINE_QUADRATIC; break;
                case T_CUBIC_SPLINE: ty = IRIS_FN_SPLINE_CUBIC; break;
                case T_NATURAL_SPLINE: ty = IRIS_FN_SPLINE_NATURAL; break;
                default: {
                    char buf[80];
                    pp_error(ps, &ps->tok, "expected linear_spline, "
                             "quadratic_spline, cubic_spline or "
                             "natural_spline, found %s",
                             pp_tok_name(ps, &ps->tok, buf, sizeof buf));
                }
                }
                pp_spline *c = pp_salloc(ps, sizeof *c);
                *c = *s;
                c->type = ty;
                pp_spline_finish(ps, c);
                s = c;
            }
            rparen(ps);
            return spline_eval(s, t);
        }
        default:
            pp_error(ps, &at, "expected a numeric expression, but '%.*s' is "
                     "a %s", (int)at.len, pp_tok_text(ps, &at),
                     pp_kind_name(v.kind));
        }
    }
    case T_X: return vval(3, 1, 0, 0, 0);
    case T_Y: return vval(3, 0, 1, 0, 0);
    case T_Z: return vval(3, 0, 0, 1, 0);
    case T_T: return vval(4, 0, 0, 0, 1);
    case T_U: return vval(2, 1, 0, 0, 0);
    case T_V: return vval(2, 0, 1, 0, 0);
    case T_PI: return fval(M_PI);
    case T_TAU: return fval(2 * M_PI);
    case T_TRUE: case T_YES: case T_ON: return fval(1);
    case T_FALSE: case T_NO: case T_OFF: return fval(0);
    case T_CLOCK: return fval(ps->opt.clock);
    case T_CLOCK_DELTA: return fval(0);
    /* POV-Ray 3.7 sets clock_on when +K is given; iris cannot tell +K0
    ** from no +K, so a zero clock reads as off. */
    case T_CLOCK_ON: return fval(ps->opt.clock != 0);
    case T_FRAME_NUMBER: return fval(ps->opt.frame_number);
    /* A still image, with or without +K, reads initial_frame = final_frame
    ** = 0 and initial_clock = final_clock = 0 in POV-Ray 3.7 (checked with
    ** povray 3.7.0 and #debug; tests/parse/cases/user_scenes2.pov). */
    case T_INITIAL_FRAME: case T_FINAL_FRAME: return fval(0);
    case T_INITIAL_CLOCK: return fval(0);
    case T_FINAL_CLOCK: return fval(0);
    case T_IMAGE_WIDTH: return fval(ps->opt.image_width);
    case T_IMAGE_HEIGHT: return fval(ps->opt.image_height);
    case T_VERSION: return fval(ps->version);
    case T_NOW: return fval(0);
    case T_ABS: return fval(fabs(arg1(ps)));
    case T_ACOS:
        a = domain_clamp(ps, &at, arg1(ps), "acos");
        return fval(checked(ps, &at, acos(a), "acos"));
    case T_ACOSH: return fval(checked(ps, &at, acosh(arg1(ps)), "acosh"));
    case T_ASIN:
        a = domain_clamp(ps, &at, arg1(ps), "asin");
        return fval(checked(ps, &at, asin(a), "asin"));
    case T_ASINH: return fval(asinh(arg1(ps)));
    case T_ATAN: return fval(atan(arg1(ps)));
    case T_ATANH: return fval(checked(ps, &at, atanh(arg1(ps)), "atanh"));
    case T_ATAN2:
        arg2(ps, &a, &b);
        /* POV-Ray: "Domain error in atan2!" when both are within its
        ** EPSILON (1e-10) of zero */
        if (!pp_true(a) && !pp_true(b))
            pp_error(ps, &at, "atan2(%g, %g): domain error (both within 1e-10 "
                     "of 0)", a, b);
        return fval(atan2(a, b));
    case T_CEIL: return fval(ceil(arg1(ps)));
    case T_COS: return fval(cos(arg1(ps)));
    case T_COSH: return fval(cosh(arg1(ps)));
    case T_DEGREES: return fval(arg1(ps) * 180 / M_PI);
    case T_RADIANS: return fval(arg1(ps) * M_PI / 180);
    case T_DIV:
        arg2(ps, &a, &b);
        if (b == 0)
            pp_error(ps, &at, "div: division by zero");
        return fval(trunc(a / b) + 0.0); /* POV-Ray's (int) cast: no -0 */
    case T_MOD:
        arg2(ps, &a, &b);
        if (b == 0)
            pp_error(ps, &at, "mod: division by zero");
        return fval(fmod(a, b));
    case T_EXP: return fval(checked(ps, &at, exp(arg1(ps)), "exp"));
    case T_FLOOR: return fval(floor(arg1(ps)));
    /* POV-Ray: (DBL)(int)x, so int(-0.5) is 0, not -0 */
    case T_INT: return fval(trunc(arg1(ps)) + 0.0);
    case T_LN: return fval(checked(ps, &at, log(arg1(ps)), "ln"));
    case T_LOG: return fval(checked(ps, &at, log10(arg1(ps)), "log"));
    case T_SQRT: return fval(checked(ps, &at, sqrt(arg1(ps)), "sqrt"));
    case T_SQR: a = arg1(ps); return fval(a * a);
    case T_SIN: return fval(sin(arg1(ps)));
    case T_SINH: return fval(sinh(arg1(ps)));
    case T_TAN: return fval(tan(arg1(ps)));
    case T_TANH: return fval(tanh(arg1(ps)));
    case T_POW:
        arg2(ps, &a, &b);
        if (a == 0 && b == 0) /* POV-Ray: "Domain error." */
            pp_error(ps, &at, "pow(0, 0): domain error");
        return fval(checked(ps, &at, pow(a, b), "pow"));
    case T_BITWISE_AND: case T_BITWISE_OR: case T_BITWISE_XOR: {
        lparen(ps);
        long r = pp_clamp_long(pp_float(ps));
        while (pp_accept(ps, T_COMMA)) {
            long x = pp_clamp_long(pp_float(ps));
            r = k == T_BITWISE_AND ? (r & x) : k == T_BITWISE_OR ? (r | x)
                                                                 : (r ^ x);
        }
        rparen(ps);
        return fval((double)r);
    }
    case T_MAX: case T_MIN: {
        /* the arguments may be infinite (POV-Ray's x / 0 is HUGE_VAL):
        ** min(1 / 0, 4) is 4 there; only the result must be finite
        ** where it is used */
        lparen(ps);
        double r = any_float(ps);
        while (pp_accept(ps, T_COMMA)) {
            double x = any_float(ps);
            r = k == T_MAX ? fmax(r, x) : fmin(r, x);
        }
        rparen(ps);
        return fval(r);
    }
    case T_SELECT: {
        lparen(ps);
        double s = pp_float(ps);
        comma(ps);
        pp_value x = expr_cond(ps);
        comma(ps);
        pp_value y = expr_cond(ps);
        pp_value z = y;
        bool four = pp_accept(ps, T_COMMA);
        if (four)
            z = expr_cond(ps);
        rparen(ps);
        if (s < 0)
            return x;
        if (four && s == 0)
            return y;
        return four ? z : y;
    }
    case T_VLENGTH: {
        lparen(ps);
        iris_vec3 p = pp_vector(ps);
        rparen(ps);
        return fval(v3_len(p));
    }
    case T_VDOT: {
        lparen(ps);
        iris_vec3 p = pp_vector(ps);
        comma(ps);
        iris_vec3 q = pp_vector(ps);
        rparen(ps);
        return fval(v3_dot(p, q));
    }
    case T_VNORMALIZE: {
        lparen(ps);
        iris_vec3 p = pp_vector(ps);
        rparen(ps);
        /* POV-Ray only warns ("Possible Parse Error") and yields <0,0,0>:
        ** math.inc's VRotation, used by transforms.inc's Reorient_Trans,
        ** normalizes a zero cross product for parallel vectors. */
        if (v3_len(p) == 0)
            pp_warning(ps, &at, "vnormalize: zero-length vector (result <0,0,0>)");
        else
            p = v3_norm(p);
        return vval(3, p.x, p.y, p.z, 0);
    }
    case T_VCROSS: {
        lparen(ps);
        iris_vec3 p = pp_vector(ps);
        comma(ps);
        iris_vec3 q = pp_vector(ps);
        rparen(ps);
        p = v3_cross(p, q);
        return vval(3, p.x, p.y, p.z, 0);
    }
    case T_VROTATE: {
        lparen(ps);
        iris_vec3 p = pp_vector(ps);
        comma(ps);
        iris_vec3 r = pp_vector(ps);
        rparen(ps);
        iris_transform xf;
        xf_rotate(&xf, r);
        p = xf_point(&xf, p);
        return vval(3, p.x, p.y, p.z, 0);
    }
    case T_VAXIS_ROTATE: {
        lparen(ps);
        iris_vec3 p = pp_vector(ps);
        comma(ps);
        iris_vec3 ax = pp_vector(ps);
        comma(ps);
        double ang = pp_float(ps);
        rparen(ps);
        if (v3_len(ax) == 0)
            pp_error(ps, &at, "vaxis_rotate: zero-length axis");
        iris_transform xf;
        xf_axis_rotate(&xf, ax, ang);
        p = xf_point(&xf, p);
        return vval(3, p.x, p.y, p.z, 0);
    }
    case T_VTURBULENCE: {
        /* vturbulence(lambda, omega, octaves, <p>): the core's noise */
        lparen(ps);
        double lambda = pp_float(ps);
        comma(ps);
        double omega = pp_float(ps);
        comma(ps);
        double oct = pp_float(ps);
        comma(ps);
        iris_vec3 p = pp_vector(ps);
        pp_accept(ps, T_COMMA);
        rparen(ps);
        double in[3] = { p.x, p.y, p.z }, d[3];
        iris_fn_vturbulence(lambda, omega, oct, in, d);
        return vval(3, d[0], d[1], d[2], 0);
    }
    case T_SEED: {
        double s = arg1(ps);
        if (ps->n_rng == ps->cap_rng) {
            int cap = ps->cap_rng ? ps->cap_rng * 2 : 8;
            uint64_t *r = pp_salloc(ps, (size_t)cap * sizeof *r);
            if (ps->n_rng)
                memcpy(r, ps->rng, (size_t)ps->n_rng * sizeof *r);
            ps->rng = r;
            ps->cap_rng = cap;
        }
        ps->rng[ps->n_rng] = pov_seed(s);
        return fval(ps->n_rng++);
    }
    case T_RAND: {
        double s = arg1(ps);
        int i = s >= 0 && s < 1e9 ? (int)s : -1;
        if (i < 0 || i >= ps->n_rng)
            pp_error(ps, &at, "rand: %g is not a stream made by seed()", s);
        return fval(pov_rand(&ps->rng[i]));
    }
    case T_DEFINED:
        return fval(pp_is_defined(ps));
    case T_DIMENSIONS: case T_DIMENSION_SIZE: {
        lparen(ps);
        pp_next(ps);
        if (ps->tok.kind != T_IDENT || ps->tok.val.kind != V_ARRAY)
            pp_error(ps, &ps->tok, "expected an array identifier");
        pp_array *arr = ps->tok.val.u.arr;
        double r = arr->ndim;
        if (k == T_DIMENSION_SIZE) {
            comma(ps);
            pp_token dt = ps->tok;
            int d = pp_int(ps);
            if (d < 1 || d > arr->ndim)
                pp_error(ps, &dt, "dimension %d out of range [1, %d]", d,
                         arr->ndim);
            r = arr->dims[d - 1];
        }
        rparen(ps);
        return fval(r);
    }
    case T_STRLEN: {
        lparen(ps);
        const char *s = pp_string(ps);
        rparen(ps);
        return fval((double)strlen(s));
    }
    case T_VAL: {
        lparen(ps);
        const char *s = pp_string(ps);
        rparen(ps);
        return fval(strtod(s, NULL));
    }
    case T_ASC: {
        lparen(ps);
        const char *s = pp_string(ps);
        rparen(ps);
        return fval((unsigned char)s[0]);
    }
    case T_STRCMP: {
        lparen(ps);
        const char *s = pp_string(ps);
        comma(ps);
        const char *t = pp_string(ps);
        rparen(ps);
        /* POV-Ray's UCS2_strcmp: the difference of the first two
        ** characters that differ (strcmp("abc", "ab") is 99, 'c' - 0) */
        const unsigned char *p = (const unsigned char *)s;
        const unsigned char *q = (const unsigned char *)t;
        while (*p && *p == *q) {
            p++;
            q++;
        }
        return fval((double)((int)*p - (int)*q));
    }
    case T_FILE_EXISTS: {
        lparen(ps);
        const char *s = pp_string(ps);
        rparen(ps);
        struct stat st;
        char full[4096];
        if (s[0] != '/')
            snprintf(full, sizeof full, "%s/%s", ps->files[at.file].dir, s);
        else
            snprintf(full, sizeof full, "%s", s);
        /* A file the scene may not read does not exist for it; one it
        ** wrote while writes were refused does. */
        if (written(ps, full, s))
            return fval(1);
        return fval(stat(full, &st) == 0 && pp_read_allowed(ps, full));
    }
    case T_MIN_EXTENT: case T_MAX_EXTENT: {
        const iris_object *o = object_arg(ps);
        vec3 lo, hi;
        const iris_geometry_queries *g = ps->opt.geometry;
        if (!pp_object_bounds(o, &lo, &hi) && g && g->bounds &&
            !g->bounds(g->user, ps->scene, pp_query_object(ps, o), &lo, &hi)) {
            lo = v3(-1e10, -1e10, -1e10); /* unbounded: POV-Ray's box */
            hi = v3(1e10, 1e10, 1e10);
        }
        vec3 r = k == T_MIN_EXTENT ? lo : hi;
        return vval(3, r.x, r.y, r.z, 0);
    }
    case T_TRACE: return trace_call(ps, &at);
    case T_INSIDE: return inside_call(ps, &at);
    case T_STR: {
        lparen(ps);
        double f = pp_float(ps);
        comma(ps);
        int len = pp_int(ps);
        comma(ps);
        int prec = pp_int(ps);
        rparen(ps);
        return sval(fmt_float(ps, f, len, prec));
    }
    case T_VSTR: {
        lparen(ps);
        int n = pp_int(ps);
        comma(ps);
        pp_value v = expr_cond(ps);
        comma(ps);
        const char *sep = pp_string(ps);
        comma(ps);
        int len = pp_int(ps);
        comma(ps);
        int prec = pp_int(ps);
        rparen(ps);
        need_numeric(ps, &at, &v);
        /* POV-Ray prints 2 to 5 components, and a float as its first
        ** with zeros after it (Parse_Unknown_Vector does not promote) */
        if (n < 2)
            n = 2;
        if (n > 5)
            n = 5;
        if (v.kind == V_FLOAT) {
            for (int i = 1; i < 5; i++)
                v.v[i] = 0;
            v.kind = V_VECTOR;
            v.dim = n;
        }
        pp_value_promote(&v, n);
        char *buf = pp_salloc(ps, 2048);
        size_t used = 0;
        for (int i = 0; i < n; i++) {
            const char *s = fmt_float(ps, v.v[i], len, prec);
            used += (size_t)snprintf(buf + used, 2048 - used, "%s%s",
                                     i ? sep : "", s);
            if (used >= 2048)
                break;
        }
        return sval(pp_strdup(ps, buf, strlen(buf)));
    }
    case T_CONCAT: {
        /* concat(S {[,] S}): POV-Ray's Parse_Concat reads strings until
        ** ')', the commas between them optional (Parse_Comma), so a
        ** macro's "b" followed by a fall-through #case's "c" is "bc" */
        lparen(ps);
        size_t cap = 256, len = 0;
        char *buf = pp_salloc(ps, cap);
        for (bool first = true; first || !pp_accept_in_list(ps, T_RPAREN);
             first = false) {
            if (!first)
                comma(ps);
            const char *s = pp_string(ps);
            size_t n = strlen(s);
            if (len + n + 1 > cap) {
                while (len + n + 1 > cap)
                    cap *= 2;
                if (cap > (1u << 24))
                    pp_error(ps, &at, "string longer than 16 MiB");
                char *nb = pp_salloc(ps, cap);
                memcpy(nb, buf, len);
                buf = nb;
            }
            memcpy(buf + len, s, n);
            len += n;
            buf[len] = 0;
        }
        return sval(buf);
    }
    case T_CHR: {
        double cv = arg1(ps);
        /* POV-Ray: "Value N cannot be used in chr(...)" outside 0..65535
        ** (a UCS-2 character; iris keeps 1..255 and a blank otherwise) */
        if (!(cv > -1 && cv < 65536))
            pp_error(ps, &at, "chr(%g): the value must be in 0..65535", cv);
        int c = cv >= 0 && cv < 256 ? (int)cv : 0;
        char ch[2] = { (char)(c > 0 && c < 256 ? c : ' '), 0 };
        return sval(pp_strdup(ps, ch, 1));
    }
    case T_SUBSTR: {
        lparen(ps);
        const char *s = pp_string(ps);
        comma(ps);
        int p = pp_int(ps);
        comma(ps);
        int n = pp_int(ps);
        rparen(ps);
        int len = (int)strlen(s);
        if (p < 1 || n < 0 || p - 1 + n > len)
            pp_error(ps, &at, "substr: position %d, length %d outside the "
                     "string of length %d", p, n, len);
        return sval(pp_strdup(ps, s + p - 1, (size_t)n));
    }
    case T_STRUPR: case T_STRLWR: {
        lparen(ps);
        const char *s = pp_string(ps);
        rparen(ps);
        char *r = pp_strdup(ps, s, strlen(s));
        for (char *p = r; *p; p++)
            *p = (char)(k == T_STRUPR ? toupper((unsigned char)*p)
                                      : tolower((unsigned char)*p));
        return sval(r);
    }
    case T_DATETIME: {
        /* datetime(days [, format]): 'days' counts from 2000-01-01 00:00
        ** UTC (POV-Ray's 'now' scale: 10957 days after the Unix epoch),
        ** rounded to the second, formatted by strftime in UTC; the default
        ** format is POV-Ray's "%Y-%m-%d %H:%M:%SZ". */
        lparen(ps);
        double days = pp_float(ps);
        const char *fmt = "%Y-%m-%d %H:%M:%SZ";
        pp_token ft = at;
        comma(ps); /* optional, as POV-Ray's Parse_Comma */
        if (!pp_accept(ps, T_RPAREN)) {
            pp_next(ps);
            ft = ps->tok;
            pp_unget(ps);
            fmt = pp_string(ps);
            if (!*fmt)
                pp_error(ps, &ft, "datetime: empty format string");
            rparen(ps);
        }
        double secs = floor((days + 10957.0) * 86400.0 + 0.5);
        if (!(fabs(secs) < 1e15))
            pp_error(ps, &at, "datetime: time out of range");
        time_t stamp = (time_t)secs;
        struct tm tmv;
        char buf[201];
        size_t n = 0;
        if (gmtime_r(&stamp, &tmv)) {
            /* the format is the scene's, as POV-Ray's datetime takes it */
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wformat-nonliteral"
            n = strftime(buf, sizeof buf, fmt, &tmv);
#pragma GCC diagnostic pop
        }
        buf[n] = 0; /* POV-Ray: an empty string when it does not fit */
        return sval(pp_strdup(ps, buf, n));
    }
    default:
        if (is_colour_kw(k))
            return colour_body(ps);
        {
            char buf[80];
            pp_error(ps, &at, "expected a numeric expression, found %s",
                     pp_tok_name(ps, &at, buf, sizeof buf));
        }
    }
}

/*
** factor [ '.' component ]
** POV-Ray's period operator (Parse_Num_Factor) takes one component and
** leaves the others where they were: the value is a float whose
** 'leftover' components a vector parameter still reads. Only one period
** follows a factor, and on a float only the components its Terms hold
** exist: 'F.y' is refused where a float is read (POV-Ray: "Bad operands
** for period operator"), taken as F where a vector is.
*/
static pp_value postfix(pp_state *ps)
{
    int terms = ps->dot_terms > 1 ? ps->dot_terms : 1;
    ps->dot_terms = 1; /* what the factor reads inside is its own */
    pp_value v = factor(ps);
    ps->dot_terms = terms;
    if (peek_op(ps) != T_DOT)
        return v;
    pp_next(ps);
    pp_token dot = ps->tok;
    pp_next(ps);
    int i;
    switch (ps->tok.kind) {
    case T_X: case T_U: case T_RED: i = 0; break;
    case T_Y: case T_V: case T_GREEN: i = 1; break;
    case T_Z: case T_BLUE: i = 2; break;
    case T_T: case T_FILTER: i = 3; break;
    case T_TRANSMIT: i = 4; break;
    case T_GRAY: {
        need_numeric(ps, &dot, &v);
        pp_value_promote(&v, 3);
        return fval(0.297 * v.v[0] + 0.589 * v.v[1] + 0.114 * v.v[2]);
    }
    default:
        pp_error(ps, &ps->tok, "expected x, y, z, t, u, v or a colour "
                 "component after '.'");
    }
    need_numeric(ps, &dot, &v);
    int have = v.dim > 1 ? v.dim : v.leftover ? 1 : terms;
    if (i >= have) {
        if (v.dim > 1)
            pp_error(ps, &dot, "bad operand for '.': the value has %d "
                     "components", v.dim);
        pp_error(ps, &dot, "bad operand for '.': a float has no '.%s' "
                 "where a float is read (only .x, or .u, .red)",
                 lex_keyword_name(ps->tok.kind));
    }
    if (v.dim > 1) {
        double c = v.v[i];
        pp_value_promote(&v, 5);
        v.v[0] = c;
        v.kind = V_FLOAT;
        v.dim = 1;
        v.leftover = true;
    }
    /* a float's .x (or, in a vector, .y ...) is the float itself */
    return v;
}

static pp_value unary(pp_state *ps)
{
    pp_next(ps);
    int k = ps->tok.kind;
    pp_token at = ps->tok;
    if (k == T_MINUS || k == T_PLUS || k == T_BANG) {
        pp_enter(ps, &at);
        pp_value v = unary(ps);
        pp_leave(ps);
        need_numeric(ps, &at, &v);
        for (int i = 0; i < v.dim; i++) {
            if (k == T_MINUS)
                v.v[i] = -v.v[i];
            else if (k == T_BANG)
                v.v[i] = !pp_true(v.v[i]);
        }
        return v;
    }
    pp_unget(ps);
    return postfix(ps);
}

/* POV-Ray's Terms after a left operand read where 'ctx' were asked
** for: a vector's components, 1 after a period, else the float filled
** all 'ctx' (the right operand is read with as many). */
static int operand_terms(const pp_value *a, int ctx)
{
    if (a->leftover)
        return 1;
    return a->dim > ctx ? a->dim : ctx;
}

static pp_value expr_mul(pp_state *ps)
{
    int ctx = ps->dot_terms;
    pp_value a = unary(ps);
    for (;;) {
        int op = peek_op(ps);
        if (op != T_STAR && op != T_SLASH)
            break;
        pp_next(ps);
        pp_token at = ps->tok;
        ps->dot_terms = operand_terms(&a, ctx);
        pp_value b = unary(ps);
        ps->dot_terms = ctx;
        binop(ps, &at, &a, &b, op);
    }
    return a;
}

static pp_value expr_add(pp_state *ps)
{
    int ctx = ps->dot_terms;
    pp_value a = expr_mul(ps);
    for (;;) {
        int op = peek_op(ps);
        if (op != T_PLUS && op != T_MINUS)
            break;
        pp_next(ps);
        pp_token at = ps->tok;
        ps->dot_terms = operand_terms(&a, ctx);
        pp_value b = expr_mul(ps);
        ps->dot_terms = ctx;
        binop(ps, &at, &a, &b, op);
    }
    return a;
}

/* rel_term: sum { ('<' | '<=' | '=' | '!=' | '>=' | '>') sum } */
static pp_value expr_cmp(pp_state *ps)
{
    pp_value a = expr_add(ps);
    for (;;) {
        int op = peek_op(ps);
        if (op != T_LT && op != T_LE && op != T_EQUALS && op != T_NE &&
            op != T_GE && op != T_GT)
            return a;
        if ((op == T_LT || op == T_GT) && ps->in_vector)
            return a;
        pp_next(ps);
        pp_token at = ps->tok;
        int ctx = ps->dot_terms;
        ps->dot_terms = a.kind == V_STRING ? 1 : operand_terms(&a, ctx);
        pp_value b = expr_add(ps);
        ps->dot_terms = ctx;
        if (a.kind == V_STRING && b.kind == V_STRING) {
            /* POV-Ray compares strings as strcmp does */
            int c = strcmp(a.u.str, b.u.str);
            a = fval(op == T_LT ? c < 0 : op == T_LE ? c <= 0 :
                     op == T_EQUALS ? c == 0 : op == T_NE ? c != 0 :
                     op == T_GE ? c >= 0 : c > 0);
            continue;
        }
        binop(ps, &at, &a, &b, op);
    }
}

/* logical: rel_term { ('&' | '|') rel_term }
** '&' and '|' have one precedence and group from the left, as in
** POV-Ray's Parse_Logical: '1 | 0 & 0' is (1 | 0) & 0, 0. */
static pp_value expr_logical(pp_state *ps)
{
    pp_value a = expr_cmp(ps);
    for (;;) {
        int op = peek_op(ps);
        if (op != T_AMP && op != T_BAR)
            return a;
        pp_next(ps);
        pp_token at = ps->tok;
        pp_value b = expr_cmp(ps);
        binop(ps, &at, &a, &b, op);
    }
}

static pp_value expr_cond(pp_state *ps)
{
    pp_value c = expr_logical(ps);
    if (peek_op(ps) != T_QUESTION)
        return c;
    pp_next(ps);
    pp_token at = ps->tok;
    need_numeric(ps, &at, &c);
    /* POV-Ray's Parse_Express refuses a vector condition */
    if (c.dim != 1)
        pp_error(ps, &at, "the condition of '?:' must be a float, "
                 "found a %d-component vector", c.dim);
    pp_value a = expr_cond(ps);
    pp_expect(ps, T_COLON, "':'");
    pp_value b = expr_cond(ps);
    return pp_true(c.v[0]) ? a : b;
}

pp_value pp_expr(pp_state *ps)
{
    return expr_cond(ps);
}

pp_value pp_expr_sum(pp_state *ps)
{
    return expr_add(ps);
}

/* The value 'v' read at 'at' as a finite float, or an error there. */
static double finite_float(pp_state *ps, const pp_token *at, pp_value *v)
{
    need_numeric(ps, at, v);
    if (v->dim != 1)
        pp_error(ps, at, "expected a float, found a %d-component vector",
                 v->dim);
    need_finite(ps, at, v);
    return v->v[0];
}

double pp_paren_float(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    if (at.kind != T_LPAREN) {
        char buf[80];
        pp_error(ps, &at, "expected '(', found %s",
                 pp_tok_name(ps, &at, buf, sizeof buf));
    }
    pp_value v = paren_rest(ps, &at);
    return finite_float(ps, &at, &v);
}

double pp_float(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    pp_value v = expr_add(ps);
    return finite_float(ps, &at, &v);
}

static iris_vec3 vector_value(pp_state *ps, double bound);

iris_vec3 pp_vector(pp_state *ps)
{
    return vector_value(ps, 0);
}

iris_vec3 pp_vector_clamped(pp_state *ps, double bound)
{
    return vector_value(ps, bound);
}

/* A vector; with 'bound' > 0 an infinite component becomes +-bound (a
** NaN is still refused). */
static iris_vec3 vector_value(pp_state *ps, double bound)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    int ctx = ps->dot_terms;
    ps->dot_terms = 3;
    pp_value v = expr_add(ps);
    ps->dot_terms = ctx;
    need_numeric(ps, &at, &v);
    /* Parse_Vector reads the three components as the expression left
    ** them: 'vlength(V.x)' and 'scale S.y' see V's and S's other ones */
    if (v.dim == 1 && v.leftover)
        v.dim = 3;
    pp_value_promote(&v, 3);
    for (int i = 0; bound > 0 && i < 3; i++)
        if (isinf(v.v[i]))
            v.v[i] = v.v[i] > 0 ? bound : -bound;
    need_finite(ps, &at, &v);
    iris_vec3 r = { v.v[0], v.v[1], v.v[2] };
    return r;
}

iris_vec2 pp_vector2(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    int ctx = ps->dot_terms;
    ps->dot_terms = 2;
    pp_value v = expr_add(ps);
    ps->dot_terms = ctx;
    need_numeric(ps, &at, &v);
    pp_value_promote(&v, 2);
    need_finite(ps, &at, &v);
    iris_vec2 r = { v.v[0], v.v[1] };
    return r;
}

void pp_vector4(pp_state *ps, double out[4])
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    int ctx = ps->dot_terms;
    ps->dot_terms = 4;
    pp_value v = expr_add(ps);
    ps->dot_terms = ctx;
    need_numeric(ps, &at, &v);
    pp_value_promote(&v, 4);
    need_finite(ps, &at, &v);
    for (int i = 0; i < 4; i++)
        out[i] = v.v[i];
}

iris_colour pp_value_colour(const pp_value *v)
{
    iris_colour c = { 0, 0, 0, 0, 0 };
    if (v->dim == 1) {
        c.r = c.g = c.b = v->v[0];
        return c;
    }
    c.r = v->v[0];
    c.g = v->v[1];
    c.b = v->dim > 2 ? v->v[2] : 0;
    c.f = v->dim > 3 ? v->v[3] : 0;
    c.t = v->dim > 4 ? v->v[4] : 0;
    return c;
}

iris_colour pp_colour(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    if (!is_colour_kw(at.kind) && !pp_starts_expr(ps)) {
        char buf[80];
        pp_error(ps, &at, "expected a colour, found %s",
                 pp_tok_name(ps, &at, buf, sizeof buf));
    }
    pp_value v = colour_body(ps);
    need_numeric(ps, &at, &v);
    need_finite(ps, &at, &v);
    return pp_value_colour(&v);
}

const char *pp_string(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    pp_value v = expr_add(ps);
    if (v.kind != V_STRING)
        pp_error(ps, &at, "expected a string, found a %s",
                 pp_kind_name(v.kind));
    return v.u.str;
}

bool pp_bool_opt(pp_state *ps)
{
    if (pp_next_is_directive(ps))
        return true;
    pp_next(ps);
    bool isbool = ps->tok.kind == T_NUMBER || ps->tok.kind == T_TRUE ||
                  ps->tok.kind == T_FALSE || ps->tok.kind == T_ON ||
                  ps->tok.kind == T_OFF || ps->tok.kind == T_YES ||
                  ps->tok.kind == T_NO || ps->tok.kind == T_LPAREN ||
                  ps->tok.kind == T_BANG ||
                  (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_FLOAT);
    pp_unget(ps);
    if (!isbool)
        return true;
    return pp_float(ps) != 0;
}

double pp_full_float(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    pp_value v = expr_cond(ps);
    need_numeric(ps, &at, &v);
    need_finite(ps, &at, &v);
    return v.v[0];
}

pp_value pp_string_rvalue(pp_state *ps)
{
    /* No look-ahead after a string: 'S = "a"' then a macro call on the
    ** next line must not run before S is assigned (POV-Ray's strings
    ** have no operators). */
    return factor(ps);
}

pp_value pp_factor_value(pp_state *ps)
{
    return postfix(ps);
}

int pp_int(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    double v = pp_float(ps);
    if (!(fabs(v) < 2147483647.0))
        pp_error(ps, &at, "value %g out of the integer range", v);
    return (int)v;
}

long pp_clamp_long(double v)
{
    if (!(v > -9.0e15))
        return v > 0 ? (long)9.0e15 : (long)-9.0e15;
    if (v > 9.0e15)
        return (long)9.0e15;
    return (long)v;
}
