/* SPDX-License-Identifier: MIT */
/*
** fnc.c: the compiler of 'function { ... }' bodies into the stack code of
** fn.h.
**
** The body grammar is the float expression grammar of expr.c; names are
** resolved at compile time: parameters become PARAM, declared floats are
** folded to constants (POV-Ray does the same: a function captures values,
** not variables), other functions become CALL, and internal(N) becomes
** INTERNAL, which passes the caller's arguments through. sum() and prod()
** compile their body as a function of one more parameter (the index);
** pattern and pigment functions become one PATTERN instruction, and a
** call of a pigment function with .red/.gray/... evaluates the pigment
** in place.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "pp.h"

#define MAX_CODE 65536

typedef struct fnc {
    pp_state *ps;
    iris_fn_insn *code;
    int n, cap;
    int depth, max_depth;
    int n_params;
    const char *params[32];
    bool default_params;
} fnc;

static void emit(fnc *c, enum iris_fn_op op, int arg, int nargs, double value,
                 int stack_delta)
{
    if (c->n == c->cap) {
        if (c->cap >= MAX_CODE)
            pp_error(c->ps, &c->ps->tok, "function body too long");
        int nc = c->cap ? c->cap * 2 : 64;
        iris_fn_insn *code = pp_salloc(c->ps, (size_t)nc * sizeof *code);
        if (c->n)
            memcpy(code, c->code, (size_t)c->n * sizeof *code);
        c->code = code;
        c->cap = nc;
    }
    iris_fn_insn *i = &c->code[c->n++];
    memset(i, 0, sizeof *i);
    i->op = op;
    i->arg = arg;
    i->nargs = nargs;
    i->value = value;
    c->depth += stack_delta;
    if (c->depth > c->max_depth)
        c->max_depth = c->depth;
}

static void cexpr(fnc *c);

/* param_index's answer for x/y/z/u/v with no parameter of that
** register: the value 0. */
#define PARAM_ZERO (-2)

/* The index of parameter named by token 't', PARAM_ZERO, or -1. */
static int param_index(fnc *c, const pp_token *t)
{
    pp_state *ps = c->ps;
    if (c->default_params) {
        switch (t->kind) {
        case T_X: case T_U: return 0;
        case T_Y: case T_V: return 1;
        case T_Z: return 2;
        default:
            if (c->n_params <= 3)
                return -1;
            break; /* a sum()/prod() index after x, y, z */
        }
    }
    /* POV-Ray's FNCode keeps x/u, y/v and z in three registers, loaded
    ** from the parameters of those names (the last one wins) and 0
    ** without one, and reads the registers first: in function(u,v) 'x'
    ** is u (meshmaker.inc's mesh_by_2varfunction), in function(x,y) 'u'
    ** is x (p_Lathe), in function(a) 'x' is 0. */
    int reg = t->kind == T_X || t->kind == T_U ? 0 :
              t->kind == T_Y || t->kind == T_V ? 1 :
              t->kind == T_Z ? 2 : -1;
    if (reg >= 0) {
        static const char *const names[3][2] = {
            { "x", "u" }, { "y", "v" }, { "z", "z" } };
        int last = PARAM_ZERO;
        for (int i = 0; i < c->n_params; i++)
            if (!strcmp(c->params[i], names[reg][0]) ||
                !strcmp(c->params[i], names[reg][1]))
                last = i;
        return last;
    }
    if (t->kind != T_IDENT && t->kind < T_KW_FIRST)
        return -1;
    const char *s = pp_tok_text(ps, t);
    for (int i = 0; i < c->n_params; i++)
        if (strlen(c->params[i]) == t->len &&
            memcmp(c->params[i], s, t->len) == 0)
            return i;
    return -1;
}

static int args(fnc *c)
{
    pp_state *ps = c->ps;
    int n = 0;
    pp_expect(ps, T_LPAREN, "'('");
    if (pp_accept(ps, T_RPAREN))
        return 0;
    do {
        cexpr(c);
        n++;
    } while (pp_accept(ps, T_COMMA));
    pp_expect(ps, T_RPAREN, "')'");
    return n;
}

/*
** select '(' expr ',' expr ',' expr [ ',' expr ] ')' ; the current token
** is 'select'. select(a, b, c[, d]) is b for a < 0, else c (three
** arguments), or c for a = 0 and d for a > 0 (four). Only the arm chosen
** is evaluated, as POV-Ray compiles it to branches: users' functions
** (t-o-k's complex functions) call costly functions in every arm.
*/
static void select_arms(fnc *c, const pp_token *at)
{
    pp_state *ps = c->ps;
    pp_expect(ps, T_LPAREN, "'('");
    cexpr(c);
    int br = c->n;
    emit(c, IRIS_FN_BRANCH, 0, 0, 0, -1);
    int d0 = c->depth;
    if (!pp_accept(ps, T_COMMA))
        pp_error(ps, at, "select takes 3 or 4 arguments");
    cexpr(c);                              /* a < 0 */
    int jump1 = c->n;
    emit(c, IRIS_FN_JUMP, 0, 0, 0, 0);
    if (!pp_accept(ps, T_COMMA))
        pp_error(ps, at, "select takes 3 or 4 arguments");
    c->code[br].arg = c->code[br].nargs = c->n;
    c->depth = d0;
    cexpr(c);                              /* a = 0 (and a > 0 of three) */
    if (pp_accept(ps, T_COMMA)) {
        int jump2 = c->n;
        emit(c, IRIS_FN_JUMP, 0, 0, 0, 0);
        c->code[br].nargs = c->n;
        c->depth = d0;
        cexpr(c);                          /* a > 0 */
        c->code[jump2].arg = c->n;
    }
    c->code[jump1].arg = c->n;
    if (pp_accept(ps, T_COMMA))
        pp_error(ps, at, "select takes 3 or 4 arguments");
    pp_expect(ps, T_RPAREN, "')'");
}

/* The arguments internal(N) takes, N = 0..78 (x, y, z and the
** parameters of functions.inc's f_* names): measured with POV-Ray 3.7.0,
** which accepts a call of function { internal(N) } with exactly this many
** and stops on any other count. */
static const unsigned char internal_arity[] = {
    8, 8, 8, 8, 5, 5, 8, 7, 5, 4, 7, 4, 4, 4, 4, 9, 9, 6, 4, 7,   /* 0 */
    6, 9, 4, 4, 13, 10, 10, 4, 4, 9, 4, 6, 7, 6, 9, 4, 4, 7, 4, 9, /* 20 */
    8, 4, 4, 4, 7, 4, 6, 3, 4, 4, 10, 8, 9, 4, 4, 4, 6, 3, 9, 9,  /* 40 */
    7, 4, 8, 7, 9, 4, 7, 10, 5, 3, 5, 6, 4, 4, 5, 9, 3, 3, 4,     /* 60 */
};

int pp_fn_arity(const iris_fn *fn)
{
    if (fn->n_code >= 1 && fn->code[0].op == IRIS_FN_SPLINE)
        return 1;
    if (fn->n_code >= 1 && fn->code[0].op == IRIS_FN_INTERNAL &&
        fn->code[0].nargs == 0 && fn->code[0].arg >= 0 &&
        fn->code[0].arg < (int)sizeof internal_arity)
        return internal_arity[fn->code[0].arg];
    return fn->n_params;
}

static int builtin_of(int k, int *arity)
{
    *arity = 1;
    switch (k) {
    case T_ABS: return IRIS_FB_ABS;
    case T_ACOS: return IRIS_FB_ACOS;
    case T_ACOSH: return IRIS_FB_ACOSH;
    case T_ASIN: return IRIS_FB_ASIN;
    case T_ASINH: return IRIS_FB_ASINH;
    case T_ATAN: return IRIS_FB_ATAN;
    case T_ATANH: return IRIS_FB_ATANH;
    case T_CEIL: return IRIS_FB_CEIL;
    case T_COS: return IRIS_FB_COS;
    case T_COSH: return IRIS_FB_COSH;
    case T_DEGREES: return IRIS_FB_DEGREES;
    case T_EXP: return IRIS_FB_EXP;
    case T_FLOOR: return IRIS_FB_FLOOR;
    case T_INT: return IRIS_FB_INT;
    case T_LN: return IRIS_FB_LN;
    case T_LOG: return IRIS_FB_LOG;
    case T_RADIANS: return IRIS_FB_RADIANS;
    case T_SIN: return IRIS_FB_SIN;
    case T_SINH: return IRIS_FB_SINH;
    case T_SQRT: return IRIS_FB_SQRT;
    case T_SQR: return IRIS_FB_SQR;
    case T_TAN: return IRIS_FB_TAN;
    case T_TANH: return IRIS_FB_TANH;
    case T_ATAN2: *arity = 2; return IRIS_FB_ATAN2;
    case T_DIV: *arity = 2; return IRIS_FB_DIV;
    case T_MOD: *arity = 2; return IRIS_FB_MOD;
    case T_POW: *arity = 2; return IRIS_FB_POW;
    case T_MAX: *arity = -1; return IRIS_FB_MAX;
    case T_MIN: *arity = -1; return IRIS_FB_MIN;
    case T_BITWISE_AND: *arity = -1; return IRIS_FB_BITWISE_AND;
    case T_BITWISE_OR: *arity = -1; return IRIS_FB_BITWISE_OR;
    case T_BITWISE_XOR: *arity = -1; return IRIS_FB_BITWISE_XOR;
    default: return -1;
    }
}

/* The result index that .red, .x, .gray ... (token 't') select of a
** pigment function: 0..4 = r, g, b, f, t; 5 = gray; 6 = hf; -1 for
** anything else. POV-Ray's FNCode::compile_member also takes the names
** 'grey' and 'hf' (MegaPOV's height field value, fn_pigment_component),
** which are no keywords. */
static int component_of(pp_state *ps, const pp_token *t)
{
    if (t->kind == T_IDENT) {
        const char *s = pp_tok_text(ps, t);
        if (t->len == 4 && !memcmp(s, "grey", 4))
            return 5;
        if (t->len == 2 && !memcmp(s, "hf", 2))
            return 6;
        return -1;
    }
    switch (t->kind) {
    case T_RED: case T_X: case T_U: return 0;
    case T_GREEN: case T_Y: case T_V: return 1;
    case T_BLUE: case T_Z: return 2;
    case T_FILTER: case T_T: return 3;
    case T_TRANSMIT: return 4;
    case T_GRAY: return 5;
    default: return -1;
    }
}

static iris_fn *finish_fn(fnc *c, int n_results);

/* sum(i, a, b, body) and prod(i, a, b, body): the body is compiled as a
** function of this one's parameters plus i, which the SUM instruction
** calls for i = a..b. */
static void sum_prod(fnc *c, const pp_token *at)
{
    pp_state *ps = c->ps;
    pp_expect(ps, T_LPAREN, "'('");
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    pp_token name = ps->tok;
    if (name.kind != T_IDENT && name.kind < T_KW_FIRST)
        pp_error(ps, &name, "expected the name of the %s() index",
                 lex_keyword_name(at->kind));
    if (c->n_params >= 32)
        pp_error(ps, &name, "too many function parameters");
    pp_expect(ps, T_COMMA, "','");
    cexpr(c);
    pp_expect(ps, T_COMMA, "','");
    cexpr(c);
    pp_expect(ps, T_COMMA, "','");
    fnc body;
    memset(&body, 0, sizeof body);
    body.ps = ps;
    body.default_params = c->default_params;
    body.n_params = c->n_params + 1;
    memcpy(body.params, c->params, (size_t)c->n_params * sizeof c->params[0]);
    body.params[c->n_params] = pp_strdup(ps, pp_tok_text(ps, &name),
                                         name.len);
    pp_enter(ps, at);
    cexpr(&body);
    pp_leave(ps);
    pp_expect(ps, T_RPAREN, "')'");
    iris_fn *fn = finish_fn(&body, 1);
    emit(c, IRIS_FN_SUM, at->kind == T_PROD, c->n_params, 0, -1);
    c->code[c->n - 1].callee = fn;
}

static void cfactor(fnc *c)
{
    pp_state *ps = c->ps;
    pp_next(ps);
    pp_token at = ps->tok;
    int k = at.kind;
    int pi = param_index(c, &at);
    if (pi >= 0) {
        emit(c, IRIS_FN_PARAM, pi, 0, 0, 1);
        return;
    }
    if (pi == PARAM_ZERO) {
        emit(c, IRIS_FN_CONST, 0, 0, 0, 1);
        return;
    }
    int arity;
    int b = builtin_of(k, &arity);
    if (b >= 0) {
        int n = args(c);
        if (arity > 0 && n != arity)
            pp_error(ps, &at, "%s takes %d argument%s", lex_keyword_name(k),
                     arity, arity > 1 ? "s" : "");
        if (arity < 0 && n < 1)
            pp_error(ps, &at, "%s needs arguments", lex_keyword_name(k));
        emit(c, IRIS_FN_BUILTIN, b, n, 0, 1 - n);
        return;
    }
    switch (k) {
    case T_NUMBER: emit(c, IRIS_FN_CONST, 0, 0, at.num, 1); return;
    case T_PI: emit(c, IRIS_FN_CONST, 0, 0, M_PI, 1); return;
    case T_TAU: emit(c, IRIS_FN_CONST, 0, 0, 2 * M_PI, 1); return;
    case T_TRUE: case T_YES: case T_ON: emit(c, IRIS_FN_CONST, 0, 0, 1, 1); return;
    case T_FALSE: case T_NO: case T_OFF: emit(c, IRIS_FN_CONST, 0, 0, 0, 1); return;
    case T_CLOCK: case T_CLOCK_DELTA: case T_CLOCK_ON: case T_FRAME_NUMBER:
    case T_INITIAL_FRAME: case T_FINAL_FRAME: case T_INITIAL_CLOCK:
    case T_FINAL_CLOCK: case T_IMAGE_WIDTH: case T_IMAGE_HEIGHT:
    case T_VERSION: {
        /* constants of the parse, as in any expression */
        double v = k == T_CLOCK ? ps->opt.clock :
                   k == T_FRAME_NUMBER ? ps->opt.frame_number :
                   k == T_INITIAL_FRAME || k == T_FINAL_FRAME ? 1 :
                   k == T_FINAL_CLOCK ? 1 :
                   k == T_IMAGE_WIDTH ? ps->opt.image_width :
                   k == T_IMAGE_HEIGHT ? ps->opt.image_height :
                   k == T_VERSION ? ps->version : 0;
        emit(c, IRIS_FN_CONST, 0, 0, v, 1);
        return;
    }
    case T_LPAREN:
        pp_enter(ps, &at);
        cexpr(c);
        pp_leave(ps);
        pp_expect(ps, T_RPAREN, "')'");
        return;
    case T_SELECT:
        select_arms(c, &at);
        return;
    case T_INTERNAL: {
        pp_expect(ps, T_LPAREN, "'('");
        int n = pp_int(ps);
        pp_expect(ps, T_RPAREN, "')'");
        emit(c, IRIS_FN_INTERNAL, n, 0, 0, 1);
        return;
    }
    case T_PROD: case T_SUM:
        sum_prod(c, &at);
        return;
    case T_IDENT: {
        pp_value v = at.val;
        if (v.kind == V_FUNCTION) {
            int n = args(c);
            int takes = pp_fn_arity(v.u.fn);
            if (n != takes)
                pp_error(ps, &at, "invalid number of parameters in the call "
                         "of '%.*s': %d supplied, %d required", (int)at.len,
                         pp_tok_text(ps, &at), n, takes);
            emit(c, IRIS_FN_CALL, 0, n, 0, 1 - n);
            c->code[c->n - 1].callee = v.u.fn;
            /* F(x,y,z).red and friends of pigment functions evaluate the
            ** pigment directly; other results are the first one */
            if (!pp_next_is_directive(ps) && pp_accept(ps, T_DOT)) {
                pp_next(ps);
                int comp = component_of(ps, &ps->tok);
                const iris_fn_insn *body = v.u.fn->code;
                int want = body->op == IRIS_FN_SPLINE ? 1 : 3;
                bool inline_op = v.u.fn->n_code == 1 && comp >= 0 &&
                    (body->op == IRIS_FN_SPLINE ||
                     body->op == IRIS_FN_TRANSFORM ||
                     (body->op == IRIS_FN_PATTERN && body->pigment)) &&
                    (comp < v.u.fn->n_results || body->pigment ||
                     (body->op == IRIS_FN_SPLINE && comp >= 5));
                if (inline_op && n == want) {
                    /* the component evaluated in place, at the call's
                    ** arguments (the op pops them) */
                    iris_fn_insn *in = &c->code[c->n - 1];
                    *in = *body;
                    in->arg = comp;
                    in->nargs = n;
                } else if (v.u.fn->n_results == 1) {
                    pp_warn_once(ps, &ps->tok, T_DOT, "'.' after a float "
                                 "function call");
                } else if (comp < 0) {
                    pp_unexpected(ps, &ps->tok, "colour component");
                }
            }
            return;
        }
        if (v.kind == V_FLOAT || v.kind == V_VECTOR || v.kind == V_COLOUR ||
            v.kind == V_ARRAY) {
            /* a captured value; vectors need .x etc. */
            pp_unget(ps);
            pp_value e = pp_factor_value(ps);
            if (e.kind != V_FLOAT)
                pp_error(ps, &at, "a function body needs float values, "
                         "'%.*s' is a vector (use .x, .y, .z)", (int)at.len,
                         pp_tok_text(ps, &at));
            emit(c, IRIS_FN_CONST, 0, 0, e.v[0], 1);
            return;
        }
        if (v.kind == V_NONE)
            pp_error(ps, &at, "undeclared identifier '%.*s' in function",
                     (int)at.len, pp_tok_text(ps, &at));
        pp_error(ps, &at, "a %s cannot be used in a function",
                 pp_kind_name(v.kind));
    }
    default: {
        pp_unexpected(ps, &at, "function");
    }
    }
}

/* The body is not complete before its '}', so the directives met while
** looking for an operator run first, as POV-Ray's Get_Token runs them:
** 'function(x) { x #if (C) * 2 #end }' doubles when C is true. */
static bool op_next(fnc *c, int a, int b, int *got)
{
    pp_state *ps = c->ps;
    pp_run_directives(ps);
    if (pp_next_is_directive(ps))
        return false;
    pp_next(ps);
    int k = ps->tok.kind;
    if (k == a || k == b) {
        *got = k;
        return true;
    }
    pp_unget(ps);
    return false;
}

static void cunary(fnc *c)
{
    pp_state *ps = c->ps;
    pp_next(ps);
    int k = ps->tok.kind;
    pp_enter(ps, &ps->tok);
    if (k == T_MINUS) {
        cunary(c);
        pp_leave(ps);
        emit(c, IRIS_FN_NEG, 0, 0, 0, 0);
        return;
    }
    if (k == T_PLUS) {
        cunary(c);
        pp_leave(ps);
        return;
    }
    if (k == T_BANG) {
        cunary(c);
        pp_leave(ps);
        emit(c, IRIS_FN_NOT, 0, 0, 0, 0);
        return;
    }
    pp_leave(ps);
    pp_unget(ps);
    cfactor(c);
}

static void cmul(fnc *c)
{
    int op;
    cunary(c);
    while (op_next(c, T_STAR, T_SLASH, &op)) {
        cunary(c);
        emit(c, op == T_STAR ? IRIS_FN_MUL : IRIS_FN_DIV, 0, 0, 0, -1);
    }
}

static void cadd(fnc *c)
{
    int op;
    cmul(c);
    while (op_next(c, T_PLUS, T_MINUS, &op)) {
        cmul(c);
        emit(c, op == T_PLUS ? IRIS_FN_ADD : IRIS_FN_SUB, 0, 0, 0, -1);
    }
}

static void ccmp(fnc *c)
{
    pp_state *ps = c->ps;
    cadd(c);
    for (;;) {
        pp_run_directives(ps);
        if (pp_next_is_directive(ps))
            return;
        pp_next(ps);
        enum iris_fn_op op;
        switch (ps->tok.kind) {
        case T_LT: op = IRIS_FN_LT; break;
        case T_LE: op = IRIS_FN_LE; break;
        case T_GT: op = IRIS_FN_GT; break;
        case T_GE: op = IRIS_FN_GE; break;
        case T_EQUALS: op = IRIS_FN_EQ; break;
        case T_NE: op = IRIS_FN_NE; break;
        default:
            pp_unget(ps);
            return;
        }
        cadd(c);
        emit(c, op, 0, 0, 0, -1);
    }
}

static void cand(fnc *c)
{
    int op;
    ccmp(c);
    while (op_next(c, T_AMP, T_AMP, &op)) {
        ccmp(c);
        emit(c, IRIS_FN_AND, 0, 0, 0, -1);
    }
}

static void cor(fnc *c)
{
    int op;
    cand(c);
    while (op_next(c, T_BAR, T_BAR, &op)) {
        cand(c);
        emit(c, IRIS_FN_OR, 0, 0, 0, -1);
    }
}

/* expr: or [ '?' expr ':' expr ] ; the arm not chosen is jumped over,
** as in POV-Ray's compiled functions. */
static void cexpr(fnc *c)
{
    int op;
    cor(c);
    if (op_next(c, T_QUESTION, T_QUESTION, &op)) {
        int br = c->n;
        emit(c, IRIS_FN_BRANCH_ZERO, 0, 0, 0, -1);
        int d0 = c->depth;
        cexpr(c);
        pp_expect(c->ps, T_COLON, "':'");
        int jump = c->n;
        emit(c, IRIS_FN_JUMP, 0, 0, 0, 0);
        c->code[br].arg = c->n;
        c->depth = d0;
        cexpr(c);
        c->code[jump].arg = c->n;
    }
}

static iris_fn *finish_fn(fnc *c, int n_results)
{
    pp_state *ps = c->ps;
    iris_fn *fn = pp_alloc(ps, sizeof *fn);
    fn->n_params = c->n_params;
    fn->param_names = pp_alloc(ps, (size_t)(c->n_params + 1) * sizeof(char *));
    for (int i = 0; i < c->n_params; i++)
        fn->param_names[i] = pp_strdup(ps, c->params[i], strlen(c->params[i]));
    fn->n_code = c->n;
    fn->code = pp_alloc(ps, (size_t)(c->n ? c->n : 1) * sizeof *fn->code);
    if (c->n)
        memcpy(fn->code, c->code, (size_t)c->n * sizeof *fn->code);
    fn->max_stack = c->max_depth;
    fn->n_results = n_results;
    return fn;
}

/*
** src/fn evaluates a function's patterns without the scene, so patterns
** left on the global noise_generator get the one set so far (POV-Ray
** reads global_settings at render time; scenes set it before their
** functions: incdemo/func_gradient.pov). The pigment's map entries are
** stamped too; stamping a shared entry writes the same global value.
*/
static void stamp_noise_generator(pp_state *ps, iris_pigment *pg,
                                  int depth)
{
    if (!pg || depth > 16)
        return;
    int g = ps->scene->settings.noise_generator;
    if (pg->pattern.noise_generator == 0)
        pg->pattern.noise_generator = g;
    for (int i = 0; i < pg->n_entries; i++)
        stamp_noise_generator(ps, pg->entries[i].pigment, depth + 1);
}

static void free_images(void *images) { iris_fn_free_images(images); }

/* A pattern or pigment function that reads an image, a density file or
** an object gets them loaded now (src/fn/fnimages.c), so that it has its
** values while the scene is parsed as well as in the render; the scene
** frees them. */
static void load_images(pp_state *ps, iris_fn *fn)
{
    iris_scene *sc = ps->scene;
    if (!iris_fn_load_images(&fn->code[0], sc->settings.assumed_gamma,
                             pp_effective_version(ps)))
        pp_nomem(ps);
    if (!fn->code[0].images)
        return;
    iris_scene_cleanup *c = pp_alloc(ps, sizeof *c);
    c->free = free_images;
    c->data = (void *)fn->code[0].images;
    /* appended, so that the images go in the order they came */
    iris_scene_cleanup **end = &sc->cleanups;
    while (*end)
        end = &(*end)->next;
    *end = c;
}

/* F(x,y,z) = the grey level of pigment 'pg' at (x,y,z), POV-Ray's
** Greyscale() (0.297 R + 0.589 G + 0.114 B; src/fn's component 5): the
** value of pigment_pattern { pg }. */
iris_fn *pp_pigment_grey_fn(pp_state *ps, iris_pigment *pg)
{
    fnc c;
    memset(&c, 0, sizeof c);
    c.ps = ps;
    c.default_params = true;
    c.n_params = 3;
    c.params[0] = "x";
    c.params[1] = "y";
    c.params[2] = "z";
    stamp_noise_generator(ps, pg, 0);
    emit(&c, IRIS_FN_PATTERN, 5, 0, 0, 1);
    c.code[0].pattern = &pg->pattern;
    c.code[0].pigment = pg;
    iris_fn *fn = finish_fn(&c, 1);
    load_images(ps, fn);
    return fn;
}

/* function [ '(' params ')' ] '{' body '}' ; the current token is
** 'function'. */
iris_fn *pp_function(pp_state *ps)
{
    fnc c;
    memset(&c, 0, sizeof c);
    c.ps = ps;
    pp_token at = ps->tok;
    if (pp_accept(ps, T_LPAREN)) {
        ps->no_expand++;
        for (;;) {
            pp_next(ps);
            if (ps->tok.kind == T_RPAREN)
                break;
            if (ps->tok.kind == T_COMMA)
                continue;
            if (ps->tok.kind != T_IDENT && ps->tok.kind < T_KW_FIRST) {
                ps->no_expand--;
                pp_error(ps, &ps->tok, "expected a parameter name");
            }
            if (c.n_params >= 32) {
                ps->no_expand--;
                pp_error(ps, &ps->tok, "too many function parameters");
            }
            c.params[c.n_params++] = pp_strdup(ps, pp_tok_text(ps, &ps->tok),
                                               ps->tok.len);
        }
        ps->no_expand--;
    } else {
        c.default_params = true;
        c.n_params = 3;
        c.params[0] = "x";
        c.params[1] = "y";
        c.params[2] = "z";
    }
    pp_expect(ps, T_LBRACE, "'{' after function");
    pp_next(ps);
    int k = ps->tok.kind;
    if (k == T_PATTERN || k == T_PIGMENT) {
        /* pattern and pigment functions: src/fn evaluates them with the
        ** pattern code of src/material */
        iris_pigment *pg = pp_pigment(ps, NULL);
        stamp_noise_generator(ps, pg, 0);
        iris_pattern *pat = pp_alloc(ps, sizeof *pat);
        *pat = pg->pattern;
        emit(&c, IRIS_FN_PATTERN, 0, 0, 0, 1);
        c.code[c.n - 1].pattern = pat;
        if (k == T_PIGMENT)
            c.code[c.n - 1].pigment = pg;
        pp_expect(ps, T_RBRACE, "'}'");
        iris_fn *fn = finish_fn(&c, k == T_PIGMENT ? 5 : 1);
        load_images(ps, fn);
        return fn;
    }
    if (k == T_SPLINE) {
        /* a spline function: S(t) is the spline's value; the keys are
        ** copied into the scene arena, where the function lives */
        pp_spline *sp = pp_spline_block(ps);
        iris_fn_spline *fs = pp_alloc(ps, sizeof *fs);
        *fs = pp_spline_view(sp);
        size_t n = (size_t)(sp->n ? sp->n : 1);
        double *t = pp_alloc(ps, n * sizeof *t);
        double (*pv)[5] = pp_alloc(ps, n * sizeof *pv);
        if (sp->n) {
            memcpy(t, sp->t, (size_t)sp->n * sizeof *t);
            memcpy(pv, sp->p, (size_t)sp->n * sizeof *pv);
        }
        fs->t = t;
        fs->p = (const double (*)[5])pv;
        if (sp->coeff) {
            double (*cf)[5] = pp_alloc(ps, n * sizeof *cf);
            memcpy(cf, sp->coeff, (size_t)sp->n * sizeof *cf);
            fs->coeff = (const double (*)[5])cf;
        }
        emit(&c, IRIS_FN_SPLINE, 0, 0, 0, 1);
        c.code[c.n - 1].spline = fs;
        pp_expect(ps, T_RBRACE, "'}'");
        return finish_fn(&c, sp->dim > 1 ? sp->dim : 1);
    }
    if (k == T_TRANSFORM) {
        /* a transform function: F(x,y,z) is the transformed point */
        iris_transform *xf = pp_transform_block(ps);
        emit(&c, IRIS_FN_TRANSFORM, 0, 0, 0, 1);
        c.code[c.n - 1].xform = xf;
        pp_expect(ps, T_RBRACE, "'}'");
        return finish_fn(&c, 3);
    }
    pp_unget(ps);
    cexpr(&c);
    pp_expect(ps, T_RBRACE, "'}' to end the function body");
    (void)at;
    return finish_fn(&c, 1);
}
