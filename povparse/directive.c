/* SPDX-License-Identifier: MIT */
/*
** directive.c: the language directives (#declare, #if, #while, #macro,
** #include, #fopen, ...), run by input.c when it meets a '#'.
**
** Control flow is POV-Ray's: a false #if branch is skipped by raw
** scanning; a #while loop remembers where its condition starts and jumps
** back there at its #end; a macro call pushes a frame that reads the body
** from the source, and the body's #end pops it.
*/
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "pp.h"

/* Reads an identifier token without expanding macros. */
static void ident(pp_state *ps, const char *what)
{
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    int k = ps->tok.kind;
    if (k != T_IDENT) {
        char buf[80];
        if (k > T_KW_FIRST)
            pp_error(ps, &ps->tok, "%s is a reserved word and cannot be %s",
                     pp_tok_name(ps, &ps->tok, buf, sizeof buf), what);
        pp_error(ps, &ps->tok, "expected an identifier for %s, found %s",
                 what, pp_tok_name(ps, &ps->tok, buf, sizeof buf));
    }
}

/* 'read' (a float reader) among a directive's own parameters (pp.h's
** header_frames). */
static double in_header(pp_state *ps, double (*read)(pp_state *))
{
    int frames = ps->header_frames, conds = ps->header_conds;
    ps->header_frames = ps->n_frames;
    ps->header_conds = ps->n_conds;
    double v = read(ps);
    ps->header_frames = frames;
    ps->header_conds = conds;
    return v;
}

/* A float among a directive's own parameters. */
static double header_float(pp_state *ps)
{
    return in_header(ps, pp_float);
}

/* Parses '(' float ')' as the condition of #if/#while/#switch. */
static double cond_value(pp_state *ps)
{
    /* POV-Ray's Parse_Cond_Param reads '(' float ')' and no more: '#if
    ** (A < B)' compares inside the parentheses, a '<' after them starts
    ** a vector, and in 'x #if (C) * 2 #end' the '* 2' is the #if's body,
    ** not part of its condition */
    return in_header(ps, pp_paren_float);
}

/* The condition of #if, #elseif or #while: true when further than
** POV-Ray's EPSILON from zero, as POV-Ray tests it ('#if (1e-11)' is
** false). */
static bool cond_true(pp_state *ps)
{
    return pp_true(cond_value(ps));
}

/* Assigns 'v' to array element [..] of 'arr'; reads the indices. */
static pp_value *array_slot(pp_state *ps, pp_array *arr)
{
    long idx = 0;
    for (int d = 0; d < arr->ndim; d++) {
        pp_expect(ps, T_LBRACKET, "'['");
        pp_token at = ps->tok;
        double f = pp_float(ps);
        pp_expect(ps, T_RBRACKET, "']'");
        if (!(f >= 0) || !(f < arr->dims[d]))
            pp_error(ps, &at, "array index %g out of range [0, %d]", f,
                     arr->dims[d] - 1);
        idx = idx * arr->dims[d] + (long)f;
    }
    return &arr->items[idx];
}

/*
** undef: '#undef' IDENT { '[' float ']' }
** An element of an array becomes uninitialised again, as POV-Ray's
** Remove_Symbol does for an array element: users #undef a function held
** in an array before declaring another there (t-o-k's complex-function
** library). The '[' is looked for only when no directive follows, so
** that '#undef A' then '#declare A = ...' on the next line runs in order.
*/
static void do_undef(pp_state *ps)
{
    ident(ps, "undefined");
    pp_token name = ps->tok;
    const char *text = pp_tok_text(ps, &name);
    pp_sym *s = sym_resolve(sym_lookup(ps, text, name.len));
    if (s && s->val.kind == V_ARRAY && !pp_next_is_directive(ps) &&
        pp_accept(ps, T_LBRACKET)) {
        pp_unget(ps);
        pp_value *slot = array_slot(ps, s->val.u.arr);
        while (slot->kind == V_ARRAY && !pp_next_is_directive(ps) &&
               pp_accept(ps, T_LBRACKET)) {
            pp_unget(ps);
            slot = array_slot(ps, slot->u.arr);
        }
        memset(slot, 0, sizeof *slot); /* kind V_NONE */
        return;
    }
    sym_undef(ps, text, name.len);
}

/* #declare / #local Name [index...] = rvalue [;] */
static void do_declare(pp_state *ps, bool local)
{
    /* #declare deprecated [once] "message" Name = ... */
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    if (ps->tok.kind == T_DEPRECATED) {
        pp_accept(ps, T_ONCE);
        pp_string(ps);
    } else {
        pp_unget(ps);
    }
    ident(ps, "declared");
    pp_token name = ps->tok;
    const char *text = pp_tok_text(ps, &name);
    pp_value *slot = NULL;
    pp_array *slot_arr = NULL;
    pp_sym *target = NULL;
    if (pp_accept(ps, T_LBRACKET)) {
        pp_unget(ps);
        pp_sym *s = sym_resolve(sym_lookup(ps, text, name.len));
        if (!s || s->val.kind != V_ARRAY)
            pp_error(ps, &name, "'%.*s' is not an array", (int)name.len,
                     text);
        slot_arr = s->val.u.arr;
        slot = array_slot(ps, slot_arr);
        /* an element of an array held in an array: A[i][j] = ... */
        while (slot->kind == V_ARRAY && pp_accept(ps, T_LBRACKET)) {
            pp_unget(ps);
            slot_arr = slot->u.arr;
            slot = array_slot(ps, slot_arr);
        }
    }
    if (!slot) {
        /* POV-Ray's Parse_Declare refuses a name that is a function or a
        ** macro where it is seen, even for a #local that would make a new
        ** one (colors.inc's CH2RGB '#local G' after '#declare G =
        ** function ...'): "Redeclaring functions is not allowed" */
        pp_sym *cur = sym_resolve(sym_lookup(ps, text, name.len));
        if (cur && cur->val.kind == V_FUNCTION)
            pp_error(ps, &name, "'%.*s' is a function: it cannot be "
                     "redeclared (#undef it first, as POV-Ray requires)",
                     (int)name.len, text);
        if (cur && cur->val.kind == V_MACRO)
            pp_error(ps, &name, "'%.*s' is a macro: #declare and #local "
                     "cannot redefine it (#undef it first, as POV-Ray "
                     "requires)", (int)name.len, text);
    }
    pp_expect(ps, T_EQUALS, "'='");
    /* #local writes to the table current at the '#local' (POV-Ray's
    ** old_table_index): a macro called by the value may still be open
    ** when the value is complete */
    int scope = ps->n_scopes - 1;
    /* #declare finds its name before the value is read (POV-Ray looks
    ** the identifier up first): a macro whose last line declares a
    ** by-reference parameter ends while the value is completed, and the
    ** write must still reach the caller's variable */
    pp_sym *before = slot || local
                         ? NULL : sym_resolve(sym_lookup(ps, text, name.len));
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    bool named_array = ps->tok.kind == T_IDENT && ps->tok.val.kind == V_ARRAY;
    pp_unget(ps);
    pp_value v = pp_rvalue(ps);
    /* POV-Ray 3.5 and later require the ';' after a float, vector or
    ** colour; POV-Ray stops at the token found instead, or, when that is
    ** a directive in the same file or macro body (even the macro's
    ** closing #end), at the value's last token (ps->tok: the expression
    ** ended without reading on) */
    bool strict = (v.kind == V_FLOAT || v.kind == V_VECTOR ||
                   v.kind == V_COLOUR) && ps->version >= 3.5;
    static const char no_semi[] = "a #declare or #local of a float, vector "
        "or colour needs a ';' after the value (#version 3.5 and later)";
    if (strict && ps->n_unget == 0) {
        pp_frame *fr = &ps->frames[ps->n_frames - 1];
        pp_token t;
        lex_peek(ps, fr->file, fr->pos, &t);
        if (t.kind == T_HASH)
            pp_error(ps, &ps->tok, no_semi);
    }
    pp_next_is_directive(ps); /* returns from macros that just ended */
    /* '#declare B = A' makes B a copy of the array A, as in POV-Ray:
    ** writing B[i] leaves A as it was (a new array is not copied) */
    if (v.kind == V_ARRAY && named_array)
        v.u.arr = pp_array_copy(ps, v.u.arr);
    if (scope > ps->n_scopes - 1)
        scope = ps->n_scopes - 1;
    if (slot) {
        if (slot->kind != V_NONE && slot->kind != v.kind &&
            !((slot->kind == V_FLOAT || slot->kind == V_VECTOR ||
               slot->kind == V_COLOUR) &&
              (v.kind == V_FLOAT || v.kind == V_VECTOR || v.kind == V_COLOUR)))
            pp_error(ps, &name, "cannot store a %s in an array of %s",
                     pp_kind_name(v.kind), pp_kind_name(slot->kind));
        pp_array_store(ps, slot_arr, slot, &v, &name);
    } else {
        if (local) {
            target = sym_define(ps, scope, text, name.len);
        } else {
            /* #declare writes where the name already lives (this is how a
            ** macro's by-reference parameters return values), else in the
            ** global table. */
            target = sym_lookup(ps, text, name.len);
            if (before && before != sym_resolve(target) &&
                sym_is_live(ps, before))
                target = before;
            if (!target)
                target = sym_define(ps, 0, text, name.len);
        }
        target = sym_resolve(target);
        target->val = v;
    }
    /* (a directive after a value that ended a file or macro may still be
    ** followed by the ';': strings.inc's Parse_String includes the value) */
    if (!pp_next_is_directive(ps)) {
        pp_next(ps);
        if (ps->tok.kind != T_SEMI) {
            if (strict)
                pp_error(ps, &ps->tok, no_semi);
            pp_unget(ps);
        } else if (v.kind == V_FLOAT || v.kind == V_VECTOR ||
                   v.kind == V_COLOUR) {
            /* POV-Ray's Parse_Declare allows one more ';' after the one
            ** a float, vector or colour requires: meshmaker.inc's
            ** FindPoint() ends its value with ';' and the caller writes
            ** '#local P = FindPoint(su, sv);' (pp_accept runs the
            ** macro's #end first) */
            pp_accept(ps, T_SEMI);
        }
    }
}

/* Starts an #if-like branch: runs it when 'cond', else skips to the
** #else/#elseif that applies. */
static void branch(pp_state *ps, const pp_token *at, bool cond)
{
    pp_push_cond(ps, C_IF, at);
    if (cond)
        return;
    for (;;) {
        pp_cond opener = ps->conds[ps->n_conds - 1];
        int k = pp_skip(ps, SKIP_IF, &opener);
        if (k == T_END) {
            ps->n_conds--;
            return;
        }
        if (k == T_ELSE) {
            ps->conds[ps->n_conds - 1].kind = C_ELSE;
            return;
        }
        /* #elseif (cond) */
        if (cond_true(ps))
            return;
    }
}

/* #ifdef / #ifndef ( identifier [index] ) */
bool pp_is_defined(pp_state *ps)
{
    pp_expect(ps, T_LPAREN, "'('");
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    bool def;
    if (ps->tok.kind != T_IDENT) {
        /* POV-Ray 3.7 (checked with #ifdef on every reserved word): the
        ** predefined identifiers of the animation and image size are
        ** defined, every other reserved word (pi, x, clock, version...)
        ** is not */
        switch (ps->tok.kind) {
        case T_CLOCK_DELTA: case T_FINAL_CLOCK: case T_FINAL_FRAME:
        case T_FRAME_NUMBER: case T_IMAGE_HEIGHT: case T_IMAGE_WIDTH:
        case T_INITIAL_CLOCK: case T_INITIAL_FRAME:
            def = true;
            break;
        default:
            def = false;
            break;
        }
    } else {
        pp_sym *s = sym_resolve(sym_lookup(ps, pp_tok_text(ps, &ps->tok),
                                           ps->tok.len));
        def = s && s->val.kind != V_NONE;
        if (s && s->val.kind == V_ARRAY && pp_accept(ps, T_LBRACKET)) {
            pp_unget(ps);
            def = array_slot(ps, s->val.u.arr)->kind != V_NONE;
        }
    }
    pp_expect(ps, T_RPAREN, "')'");
    return def;
}

/* #switch (value) ... #case (v) ... #range (lo, hi) ... #else ... #end */
static void switch_seek(pp_state *ps)
{
    for (;;) {
        pp_cond opener = ps->conds[ps->n_conds - 1];
        int k = pp_skip(ps, SKIP_SWITCH, &opener);
        pp_cond *c = &ps->conds[ps->n_conds - 1];
        if (k == T_END) {
            ps->n_conds--;
            return;
        }
        if (k == T_ELSE) {
            c->matched = true;
            return;
        }
        if (k == T_BREAK)
            continue;
        if (k == T_CASE) {
            pp_expect(ps, T_LPAREN, "'('");
            double v = header_float(ps);
            pp_expect(ps, T_RPAREN, "')'");
            if (fabs(v - c->switch_val) < 1e-10) {
                c->matched = true;
                return;
            }
        } else if (k == T_RANGE) {
            pp_expect(ps, T_LPAREN, "'('");
            double lo = header_float(ps);
            pp_expect(ps, T_COMMA, "','");
            double hi = header_float(ps);
            pp_expect(ps, T_RPAREN, "')'");
            if (c->switch_val >= lo && c->switch_val <= hi) {
                c->matched = true;
                return;
            }
        }
    }
}

/* Leaves the innermost #switch/#while/#for at #break. */
static void do_break(pp_state *ps, const pp_token *at)
{
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    int levels = 0;
    for (int i = ps->n_conds - 1; i >= fr->cond_base; i--) {
        int k = ps->conds[i].kind;
        if (k == C_SWITCH || k == C_WHILE || k == C_FOR) {
            pp_cond opener = ps->conds[i];
            for (int j = 0; j <= levels; j++)
                pp_skip(ps, SKIP_END, &opener);
            ps->n_conds = i;
            return;
        }
        if (k != C_IF && k != C_ELSE)
            break;
        levels++;
    }
    pp_error(ps, at, "#break outside #switch, #while or #for");
}

/* The #end of the innermost open directive. */
static void do_end(pp_state *ps, const pp_token *at)
{
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    if (ps->n_conds <= fr->cond_base)
        pp_error(ps, at, "#end without #if, #while, #switch or #macro");
    pp_cond *c = &ps->conds[ps->n_conds - 1];
    switch (c->kind) {
    case C_IF: case C_ELSE: case C_SWITCH:
        ps->n_conds--;
        return;
    case C_WHILE: {
        long limit = ps->opt.max_while_iterations;
        pp_check_interrupt(ps);
        if (++c->iterations > limit)
            pp_error_at(ps, c->file, c->off, 6, "#while loop ran more than "
                        "%ld times (raise the limit with "
                        "--max-loop-iterations=N)", limit);
        fr->pos = c->cond_pos;
        ps->n_unget = 0;
        if (cond_true(ps))
            return;
        pp_cond opener = *c;
        pp_skip(ps, SKIP_END, &opener);
        ps->n_conds--;
        return;
    }
    case C_FOR: {
        long limit = ps->opt.max_while_iterations;
        pp_check_interrupt(ps);
        if (++c->iterations > limit)
            pp_error_at(ps, c->file, c->off, 4, "#for loop ran more than "
                        "%ld times (raise the limit with "
                        "--max-loop-iterations=N)", limit);
        pp_sym *s = sym_resolve(c->for_sym);
        double v = (s->val.kind == V_FLOAT ? s->val.v[0] : 0) + c->for_step;
        /* incremented before the test, as POV-Ray: after '#for (K, 0, 3)'
        ** K is 4 */
        s->val.kind = V_FLOAT;
        s->val.dim = 1;
        s->val.v[0] = v;
        if (c->for_step > 0 ? v <= c->for_end + 1e-10 * fabs(c->for_end)
                            : v >= c->for_end - 1e-10 * fabs(c->for_end)) {
            fr->pos = c->loop_pos;
            ps->n_unget = 0;
            return;
        }
        ps->n_conds--;
        return;
    }
    case C_MACRO:
        ps->n_conds--;
        pp_pop_frame(ps);
        return;
    default:
        break;
    }
}

/* The array element a macro argument is, when the argument is nothing but
** Name[i]... ('first' is its first token; the ',' or ')' after it is
** read): POV-Ray passes it by reference, as it does an identifier. */
static pp_value *element_argument(pp_state *ps, const pp_token *first)
{
    if (first->kind != T_IDENT || first->val.kind != V_ARRAY ||
        !ps->elem_slot || ps->elem_file != first->file ||
        ps->elem_start != first->off || ps->tok.file != first->file ||
        ps->tok.off < ps->elem_end)
        return NULL;
    /* only blanks between the last ']' and the ',' or ')' */
    const char *text = ps->files[first->file].text;
    for (uint32_t i = ps->elem_end; i < ps->tok.off; i++)
        if (text[i] != ' ' && text[i] != '\t' && text[i] != '\n' &&
            text[i] != '\r')
            return NULL;
    return ps->elem_slot;
}

void pp_call_macro(pp_state *ps, const pp_macro *m, const pp_token *call)
{
    if (ps->macro_depth >= ps->opt.max_macro_depth)
        pp_error(ps, call, "macro '%s' nested more than %d deep (endless "
                 "recursion?)", m->name, ps->opt.max_macro_depth);
    pp_expect(ps, T_LPAREN, "'(' after the macro name");
    pp_value *vals = NULL;
    pp_sym **refs = NULL;
    pp_value **slots = NULL;
    int n_slots = 0;
    if (m->n_params) {
        vals = pp_salloc(ps, (size_t)m->n_params * sizeof *vals);
        refs = pp_salloc(ps, (size_t)m->n_params * sizeof *refs);
        slots = pp_salloc(ps, (size_t)m->n_params * sizeof *slots);
    }
    int n = 0;
    if (!pp_accept(ps, T_RPAREN)) {
        for (;;) {
            if (n == m->n_params && n > 0 && ps->tok.kind == T_COMMA) {
                /* POV-Ray's Invoke_Macro reads an optional comma after
                ** every argument, the last too: 'M(1, 2,)' (shapes3.inc's
                ** Rounded_Tube template, meshmaker's SweepSpline) */
                ps->no_expand++;
                pp_next(ps);
                ps->no_expand--;
                if (ps->tok.kind == T_RPAREN)
                    break;
                pp_error(ps, &ps->tok, "too many parameters in the call of "
                         "macro '%s' (it takes %d)", m->name, m->n_params);
            }
            if (n >= m->n_params && n > 0 && ps->tok.kind != T_COMMA) {
                /* the last argument ended before an operator it does not
                ** take: 'M(1 < 2)' (POV-Ray: "Expected ')'") */
                int k = ps->tok.kind;
                bool cmp = k == T_LT || k == T_GT || k == T_LE ||
                           k == T_GE || k == T_EQUALS || k == T_NE ||
                           k == T_AMP || k == T_BAR || k == T_QUESTION;
                char buf[80];
                pp_error(ps, &ps->tok, "expected ')' after the argument%s "
                         "of macro '%s', found %s%s", n > 1 ? "s" : "",
                         m->name, pp_tok_name(ps, &ps->tok, buf, sizeof buf),
                         cmp ? " (a comparison or a logical operator in an "
                               "argument needs parentheses)" : "");
            }
            if (n >= m->n_params)
                pp_error(ps, &ps->tok, "too many parameters in the call of "
                         "macro '%s' (it takes %d)", m->name, m->n_params);
            /* A lone identifier is passed by reference. */
            ps->no_expand++;
            pp_next(ps);
            ps->no_expand--;
            /* as POV-Ray: a macro cannot declare its caller's new
            ** variable through a parameter, and an argument that starts
            ** with an undeclared name is refused with the same words */
            if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_NONE)
                pp_error(ps, &ps->tok, "cannot pass the uninitialized "
                         "identifier '%.*s' as a macro parameter (declare "
                         "it first)", (int)ps->tok.len,
                         pp_tok_text(ps, &ps->tok));
            if (ps->tok.kind == T_IDENT && ps->tok.val.kind != V_MACRO) {
                pp_token id = ps->tok;
                pp_next(ps);
                if (ps->tok.kind == T_COMMA || ps->tok.kind == T_RPAREN) {
                    refs[n] = id.sym;
                    vals[n] = id.val;
                    n++;
                    if (ps->tok.kind == T_RPAREN)
                        break;
                    continue;
                }
                pp_unget(ps);
                ps->tok = id;
            }
            pp_token first = ps->tok;
            pp_unget(ps);
            ps->elem_slot = NULL;
            slots[n] = NULL;
            vals[n++] = pp_rvalue(ps);
            pp_next(ps);
            if (ps->tok.kind == T_COMMA || ps->tok.kind == T_RPAREN)
                slots[n - 1] = element_argument(ps, &first);
            n_slots += slots[n - 1] != NULL;
            if (ps->tok.kind == T_RPAREN)
                break;
            if (ps->tok.kind != T_COMMA) {
                if (ps->tok.kind == T_EOF || ps->tok.kind == T_RBRACE ||
                    ps->tok.kind == T_SEMI) {
                    char buf[80];
                    pp_error(ps, &ps->tok, "expected ',' or ')' in the call "
                             "of macro '%s', found %s", m->name,
                             pp_tok_name(ps, &ps->tok, buf, sizeof buf));
                }
                pp_unget(ps); /* POV-Ray's commas are optional */
            }
        }
    }
    if (n != m->n_params)
        pp_error(ps, call, "macro '%s' takes %d parameters, %d given",
                 m->name, m->n_params, n);
    ps->macro_depth++;
    pp_push_frame(ps, FR_MACRO, m->file, m->body_off, call);
    ps->frames[ps->n_frames - 1].macro = m;
    int scope = ps->n_scopes - 1;
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    if (n_slots > 0) {
        fr->elem_params = pp_salloc(ps, (size_t)n_slots * sizeof(pp_sym *));
        fr->elem_slots = pp_salloc(ps, (size_t)n_slots * sizeof(pp_value *));
        fr->elem_index = pp_salloc(ps, (size_t)n_slots * sizeof(int));
    }
    for (int i = 0; i < n; i++) {
        pp_sym *s = sym_define(ps, scope, m->params[i], strlen(m->params[i]));
        if (refs[i])
            s->ref = refs[i];
        else
            s->val = vals[i];
        if (slots[i]) {
            fr->elem_params[fr->n_elem_params] = s;
            fr->elem_index[fr->n_elem_params] = i;
            fr->elem_slots[fr->n_elem_params++] = slots[i];
        }
    }
    pp_token at = *call;
    pp_push_cond(ps, C_MACRO, &at);
    ps->frames[ps->n_frames - 1].cond_base = ps->n_conds - 1;
}

/* #macro Name ( params ) body #end */
static void do_macro(pp_state *ps, const pp_token *at)
{
    ident(ps, "a macro name");
    pp_token name = ps->tok;
    pp_macro *m = pp_salloc(ps, sizeof *m);
    m->name = pp_strdup(ps, pp_tok_text(ps, &name), name.len);
    pp_expect(ps, T_LPAREN, "'('");
    const char *params[64];
    ps->no_expand++;
    pp_next(ps);
    while (ps->tok.kind != T_RPAREN) {
        if (ps->tok.kind != T_IDENT) {
            ps->no_expand--;
            pp_error(ps, &ps->tok, "expected a parameter name");
        }
        if (m->n_params >= 64) {
            ps->no_expand--;
            pp_error(ps, &ps->tok, "too many macro parameters (max 64)");
        }
        params[m->n_params++] = pp_strdup(ps, pp_tok_text(ps, &ps->tok),
                                          ps->tok.len);
        pp_next(ps);
        if (ps->tok.kind == T_COMMA)
            pp_next(ps);
    }
    ps->no_expand--;
    m->params = pp_salloc(ps, (size_t)(m->n_params + 1) * sizeof *m->params);
    memcpy(m->params, params, (size_t)m->n_params * sizeof *params);
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    m->file = fr->file;
    m->body_off = fr->pos;
    m->def_off = at->off;
    pp_cond opener;
    memset(&opener, 0, sizeof opener);
    opener.kind = C_MACRO;
    opener.file = at->file;
    opener.off = at->off;
    pp_skip(ps, SKIP_END, &opener);
    pp_sym *s = sym_define(ps, 0, pp_tok_text(ps, &name), name.len);
    s->ref = NULL;
    s->val.kind = V_MACRO;
    s->val.u.macro = m;
}

/* #for (Identifier, Start, End [, Step]) */
static void do_for(pp_state *ps, const pp_token *at)
{
    pp_expect(ps, T_LPAREN, "'('");
    ident(ps, "the loop variable");
    pp_token name = ps->tok;
    pp_expect(ps, T_COMMA, "','");
    double start = header_float(ps);
    pp_expect(ps, T_COMMA, "','");
    double end = header_float(ps);
    double step = 1;
    if (pp_accept(ps, T_COMMA))
        step = header_float(ps);
    pp_expect(ps, T_RPAREN, "')'");
    if (step == 0)
        pp_error(ps, at, "#for step must not be 0");
    /* POV-Ray's Parse_For_Param: the variable is the current scope's
    ** (a macro's or include file's, as #local), made there when only an
    ** outer scope has the name; a global I is left alone by a macro's or
    ** an include file's '#for (I, ...)' */
    pp_sym *s = sym_define(ps, ps->n_scopes - 1, pp_tok_text(ps, &name),
                           name.len);
    s = sym_resolve(s);
    s->val.kind = V_FLOAT;
    s->val.dim = 1;
    s->val.v[0] = start;
    pp_push_cond(ps, C_FOR, at);
    pp_cond *c = &ps->conds[ps->n_conds - 1];
    c->for_sym = s;
    c->for_end = end;
    c->for_step = step;
    c->loop_pos = ps->frames[ps->n_frames - 1].pos;
    ps->n_unget = 0;
    if (step > 0 ? start > end : start < end) {
        pp_cond opener = *c;
        pp_skip(ps, SKIP_END, &opener);
        ps->n_conds--;
    }
}

/* The file #fopen opens. POV-Ray writes relative to its working
** directory, the scene's for iris, also when a macro of a library file
** (makegrass.inc) does the writing; it reads from there or along the
** library path, here the directory of the file naming it (first, as
** before) or the scene's. */
static void fopen_path(pp_state *ps, const pp_token *name, const char *path,
                       bool write, char *full, size_t size)
{
    if (path[0] == '/' || ps->n_files == 0) {
        snprintf(full, size, "%s", path);
        return;
    }
    snprintf(full, size, "%s/%s", ps->files[name->file].dir, path);
    if (write || name->file == 0)
        snprintf(full, size, "%s/%s", ps->files[0].dir, path);
    else if (!pp_memfile_find(ps, full) && access(full, F_OK) != 0) {
        char scene[4096];
        snprintf(scene, sizeof scene, "%s/%s", ps->files[0].dir, path);
        if (pp_memfile_find(ps, scene) || access(scene, F_OK) == 0)
            snprintf(full, size, "%s", scene);
    }
}

/* Takes a slot among the open files: closed ones leave theirs, so that a
** scene may open files one after another without limit. */
static void add_open_file(pp_state *ps, const pp_token *at, pp_fileh *fh)
{
    int n = 0;
    for (int i = 0; i < ps->n_open_files; i++)
        if (ps->open_files[i]->fp || ps->open_files[i]->mem)
            ps->open_files[n++] = ps->open_files[i];
    ps->n_open_files = n;
    if (n >= 32)
        pp_error(ps, at, "too many open files (32 at once)");
    ps->open_files[ps->n_open_files++] = fh;
}

/* #fopen Name "file" read|write|append */
static void do_fopen(pp_state *ps)
{
    ident(ps, "a file identifier");
    pp_token name = ps->tok;
    pp_next(ps);
    pp_token path_tok = ps->tok;
    pp_unget(ps);
    const char *path = pp_string(ps);
    pp_token mode = ps->tok;
    pp_next(ps);
    mode = ps->tok;
    bool write = mode.kind == T_WRITE || mode.kind == T_APPEND;
    if (!write && mode.kind != T_READ)
        pp_error(ps, &mode, "expected read, write or append");
    pp_fileh *fh = pp_salloc(ps, sizeof *fh);
    memset(fh, 0, sizeof *fh);
    fh->write = write;
    fh->path = path;
    char full[4096];
    fopen_path(ps, &name, path, write, full, sizeof full);
    pp_memfile *mem = write ? NULL : pp_memfile_find(ps, full);
    if (write && !ps->opt.allow_writes) {
        if (!pp_memfile_find(ps, full)) /* once a file, not once a loop */
            pp_warning(ps, &mode, "#fopen for writing refused (writes are "
                       "not allowed); output to \"%s\" is kept in memory "
                       "for this parse only", path);
        fh->mem = pp_memfile_open(ps, full, mode.kind == T_APPEND);
        add_open_file(ps, &name, fh);
    } else if (mem) {
        /* what this parse wrote (and could not put on disk) */
        if (mem->len > 0) {
            fh->fp = fmemopen(mem->buf, mem->len, "r");
            if (!fh->fp)
                pp_error(ps, &mode, "cannot open \"%s\"", full);
            add_open_file(ps, &name, fh);
        }
    } else {
        if (write && !pp_write_allowed(ps, full))
            pp_error(ps, &path_tok, "writing \"%s\" is refused: scenes may "
                     "write only inside their own directory", path);
        if (!write)
            pp_check_read(ps, &path_tok, full);
        fh->fp = fopen(full, mode.kind == T_READ ? "r" :
                             mode.kind == T_WRITE ? "w" : "a");
        if (!fh->fp)
            pp_error(ps, &mode, "cannot open \"%s\"", full);
        add_open_file(ps, &name, fh);
    }
    pp_sym *s = sym_define(ps, 0, pp_tok_text(ps, &name), name.len);
    s->val.kind = V_FILE;
    s->val.u.fh = fh;
}

static pp_fileh *file_ident(pp_state *ps)
{
    ident(ps, "a file identifier");
    if (ps->tok.val.kind != V_FILE)
        pp_error(ps, &ps->tok, "not a file opened by #fopen");
    return ps->tok.val.u.fh;
}

/* After an item: POV-Ray's Parse_Read_Value reads the next token and
** keeps it only if it is a comma; when that token is the end of the file,
** the item still counts but the file is at its end (the #read then skips
** the remaining variables and undefines the file identifier). So a last
** line without a trailing comma ends a #while (defined(F)) loop at once. */
static bool item_ends_file(FILE *fp)
{
    int c;
    do {
        c = fgetc(fp);
    } while (c == ' ' || c == '\t' || c == '\n' || c == '\r');
    if (c == EOF)
        return true;
    if (c != ',')
        ungetc(c, fp);
    return false;
}

/* Reads one comma-separated item (number, vector or string) from 'fp'. */
static bool read_item(pp_state *ps, FILE *fp, pp_value *v)
{
    int c;
    do {
        c = fgetc(fp);
    } while (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == ',');
    if (c == EOF)
        return false;
    memset(v, 0, sizeof *v);
    if (c == '"') {
        char buf[4096];
        size_t n = 0;
        while ((c = fgetc(fp)) != EOF && c != '"')
            if (n + 1 < sizeof buf)
                buf[n++] = (char)c;
        v->kind = V_STRING;
        v->u.str = pp_strdup(ps, buf, n);
        return true;
    }
    if (c == '<') {
        int d = 0;
        v->kind = V_VECTOR;
        while (d < 5 && fscanf(fp, " %lf ,", &v->v[d]) == 1)
            d++;
        while ((c = fgetc(fp)) != EOF && c != '>')
            ;
        v->dim = d < 2 ? 2 : d;
        return true;
    }
    ungetc(c, fp);
    v->kind = V_FLOAT;
    v->dim = 1;
    return fscanf(fp, "%lf", &v->v[0]) == 1;
}

/* #read (File, Var1, Var2, ...) */
static void do_read(pp_state *ps)
{
    pp_expect(ps, T_LPAREN, "'('");
    pp_fileh *fh = file_ident(ps);
    pp_token file = ps->tok;
    if (fh->write)
        pp_error(ps, &file, "cannot #read a file opened for writing");
    bool at_end = false;
    while (pp_accept(ps, T_COMMA)) {
        ident(ps, "a variable to read into");
        pp_token name = ps->tok;
        pp_value v;
        if (at_end)
            continue;
        if (fh->fp && read_item(ps, fh->fp, &v)) {
            pp_sym *s = sym_lookup(ps, pp_tok_text(ps, &name), name.len);
            if (!s)
                s = sym_define(ps, 0, pp_tok_text(ps, &name), name.len);
            sym_resolve(s)->val = v;
            at_end = item_ends_file(fh->fp);
        } else {
            at_end = true; /* this variable and the rest keep their values */
        }
    }
    pp_expect(ps, T_RPAREN, "')'");
    /* POV-Ray closes a file whose end a #read met and undefines its
    ** identifier: scenes loop with #while (defined(File)). */
    if (at_end) {
        if (fh->fp)
            fclose(fh->fp);
        fh->fp = NULL;
        sym_undef(ps, pp_tok_text(ps, &file), file.len);
    }
}

/* Sends text to the file on disk or to the copy kept in memory. */
static void put(pp_state *ps, pp_fileh *fh, const char *s)
{
    if (fh->fp)
        fputs(s, fh->fp);
    else if (fh->mem)
        pp_memfile_write(ps, fh->mem, s, strlen(s));
}

/* Writes value 'v' as POV-Ray's #write does. */
static void write_value(pp_state *ps, pp_fileh *fh, const pp_value *v)
{
    char buf[64];
    if (v->kind == V_STRING) {
        put(ps, fh, v->u.str);
    } else if (v->kind == V_FLOAT) {
        snprintf(buf, sizeof buf, "%g", v->v[0]);
        put(ps, fh, buf);
    } else if (v->kind == V_VECTOR || v->kind == V_COLOUR) {
        put(ps, fh, "<");
        for (int i = 0; i < v->dim; i++) {
            snprintf(buf, sizeof buf, i ? ",%g" : "%g", v->v[i]);
            put(ps, fh, buf);
        }
        put(ps, fh, ">");
    }
}

/* #write (File, items...) */
static void do_write(pp_state *ps)
{
    pp_expect(ps, T_LPAREN, "'('");
    pp_fileh *fh = file_ident(ps);
    pp_token file = ps->tok;
    if (!fh->write)
        pp_error(ps, &file, "cannot #write a file opened for reading");
    for (;;) {
        pp_accept(ps, T_COMMA); /* optional */
        if (pp_accept(ps, T_RPAREN))
            return;
        pp_value v = pp_expr(ps);
        write_value(ps, fh, &v);
    }
}

/* #debug / #warning / #error / #render / #statistics "text" */
static void do_message(pp_state *ps, int kind, const pp_token *at)
{
    const char *s = pp_string(ps);
    if (kind == T_ERROR)
        pp_error(ps, at, "#error: %s", s);
    if (kind == T_WARNING) {
        pp_warning(ps, at, "#warning: %s", s);
        return;
    }
    if (ps->opt.quiet_debug)
        return;
    /* POV-Ray 3.7's message streams end a line at '\r' too: "a\rb" comes
    ** out as two lines, "\r\n" as two line breaks (measured with
    ** povray 3.7.0.10; the mesh macros' progress lines use '\r'). */
    FILE *out = ps->opt.debug_stream ? ps->opt.debug_stream : stderr;
    for (; *s; s++)
        fputc(*s == '\r' ? '\n' : *s, out);
}

/* #default { texture | pigment | finish | normal } */
void pp_default_block(pp_state *ps)
{
    pp_expect(ps, T_LBRACE, "'{'");
    for (;;) {
        pp_next(ps);
        iris_texture *t = pp_alloc(ps, sizeof *t);
        *t = *pp_default_texture(ps);
        switch (ps->tok.kind) {
        case T_TEXTURE: {
            iris_texture *nt = pp_texture(ps);
            ps->default_tex = nt;
            if (nt->finish)
                ps->default_finish = nt->finish;
            if (nt->pigment)
                ps->default_pigment = nt->pigment;
            continue;
        }
        case T_PIGMENT:
            t->pigment = pp_pigment(ps, t->pigment);
            ps->default_pigment = t->pigment;
            ps->default_tex = t;
            continue;
        case T_FINISH:
            t->finish = pp_finish(ps, t->finish);
            ps->default_finish = t->finish;
            ps->default_tex = t;
            continue;
        case T_NORMAL:
            t->normal = pp_normal(ps, t->normal);
            ps->default_tex = t;
            continue;
        case T_RBRACE:
            return;
        case T_RADIOSITY: {
            double imp = pp_radiosity_block(ps);
            if (imp > 0.0)
                ps->scene->settings.rad_default_importance = imp;
            continue;
        }
        default: {
            char buf[80];
            pp_error(ps, &ps->tok, "expected texture, pigment, finish or "
                     "normal in #default, found %s",
                     pp_tok_name(ps, &ps->tok, buf, sizeof buf));
        }
        }
    }
}

static void run_directive(pp_state *ps, pp_token kw, pp_token at,
                          const pp_token *hash);

void pp_directive(pp_state *ps, const pp_token *hash)
{
    pp_token kw;
    pp_raw(ps, &kw);
    pp_token at = kw;
    at.off = hash->off;
    at.len = kw.off + kw.len - hash->off;
    if (kw.file != hash->file)
        at = kw;
    run_directive(ps, kw, at, hash);
}

/* 'declare', 'include' and 'version' written without their '#' among a
** scene's items: POV-Ray's Parse_Frame runs them, with a warning (old
** scenes, POV-Ray 2's syntax). */
bool pp_bare_directive(pp_state *ps, const pp_token *kw)
{
    if (kw->kind != T_DECLARE && kw->kind != T_INCLUDE &&
        kw->kind != T_VERSION)
        return false;
    pp_warning(ps, kw, "should have '#' before '%s'",
               lex_keyword_name(kw->kind));
    run_directive(ps, *kw, *kw, kw);
    return true;
}

static void run_directive(pp_state *ps, pp_token kw, pp_token at,
                          const pp_token *hash)
{
    switch (kw.kind) {
    case T_DECLARE: do_declare(ps, false); return;
    case T_LOCAL: do_declare(ps, true); return;
    case T_UNDEF:
        do_undef(ps);
        return;
    case T_IF:
        branch(ps, &at, cond_true(ps));
        return;
    case T_IFDEF:
        branch(ps, &at, pp_is_defined(ps));
        return;
    case T_IFNDEF:
        branch(ps, &at, !pp_is_defined(ps));
        return;
    case T_ELSE: case T_ELSEIF: {
        pp_frame *fr = &ps->frames[ps->n_frames - 1];
        if (ps->n_conds > fr->cond_base) {
            pp_cond *c = &ps->conds[ps->n_conds - 1];
            if (c->kind == C_SWITCH && kw.kind == T_ELSE)
                return; /* falling through into the default clause */
            if (c->kind == C_IF) {
                pp_cond opener = *c;
                pp_skip(ps, SKIP_END, &opener);
                ps->n_conds--;
                return;
            }
        }
        pp_error(ps, &at, "%s without #if", kw.kind == T_ELSE ? "#else"
                                                              : "#elseif");
    }
    case T_END:
        do_end(ps, &at);
        return;
    case T_WHILE: {
        uint32_t cond_pos = ps->frames[ps->n_frames - 1].pos;
        bool run = cond_true(ps);
        pp_push_cond(ps, C_WHILE, &at);
        ps->conds[ps->n_conds - 1].cond_pos = cond_pos;
        if (!run) {
            pp_cond opener = ps->conds[ps->n_conds - 1];
            pp_skip(ps, SKIP_END, &opener);
            ps->n_conds--;
        }
        return;
    }
    case T_FOR: do_for(ps, &at); return;
    case T_SWITCH: {
        double v = cond_value(ps);
        pp_push_cond(ps, C_SWITCH, &at);
        ps->conds[ps->n_conds - 1].switch_val = v;
        switch_seek(ps);
        return;
    }
    case T_CASE: case T_RANGE: {
        pp_frame *fr = &ps->frames[ps->n_frames - 1];
        if (ps->n_conds <= fr->cond_base ||
            ps->conds[ps->n_conds - 1].kind != C_SWITCH)
            pp_error(ps, &at, "#case or #range outside #switch");
        /* Inside a matched clause without #break: POV-Ray falls through;
        ** the label's value is read and ignored. */
        pp_expect(ps, T_LPAREN, "'('");
        header_float(ps);
        if (kw.kind == T_RANGE) {
            pp_expect(ps, T_COMMA, "','");
            header_float(ps);
        }
        pp_expect(ps, T_RPAREN, "')'");
        return;
    }
    case T_BREAK: do_break(ps, &at); return;
    case T_MACRO: do_macro(ps, &at); return;
    case T_INCLUDE: {
        /* a single string factor: no look-ahead into the text that
        ** follows, which may be the end of this very file */
        pp_next(ps);
        pp_token st = ps->tok;
        pp_unget(ps);
        pp_value nv = pp_string_rvalue(ps);
        if (nv.kind != V_STRING)
            pp_error(ps, &st, "#include needs a file name string");
        const char *name = nv.u.str;
        /* Tokens read ahead after the name belong after the #include:
        ** read them again once the included file is done. */
        pp_frame *fr = &ps->frames[ps->n_frames - 1];
        if (ps->n_unget > 0 && ps->unget[0].file == fr->file) {
            uint32_t pos = ps->unget[0].off;
            for (int i = 1; i < ps->n_unget; i++)
                if (ps->unget[i].off < pos)
                    pos = ps->unget[i].off;
            fr->pos = pos;
            ps->n_unget = 0;
        }
        pp_open_file(ps, name, true, &at);
        return;
    }
    case T_VERSION: {
        double v = pp_float(ps);
        ps->version = v;
        ps->scene->version = v;
        ps->version_set = true;
        /* POV-Ray's #version picks the default noise generator: 1, the
        ** original Perlin noise, before 3.5 (tokenize.cpp) */
        if (!ps->noise_explicit)
            ps->scene->settings.noise_generator = pp_version_noise(v);
        if (!pp_next_is_directive(ps))
            pp_accept(ps, T_SEMI);
        return;
    }
    case T_DEFAULT: pp_default_block(ps); return;
    case T_DEBUG: case T_WARNING: case T_ERROR: case T_RENDER:
    case T_STATISTICS:
        do_message(ps, kw.kind, &at);
        return;
    case T_FOPEN: do_fopen(ps); return;
    case T_FCLOSE: {
        /* A name that is no open file is accepted, as POV-Ray does: a
        ** #read at the end of a file has closed and undefined it. */
        ident(ps, "a file identifier");
        if (ps->tok.val.kind != V_FILE)
            return;
        pp_fileh *fh = ps->tok.val.u.fh;
        if (fh->fp) {
            fclose(fh->fp);
            fh->fp = NULL;
        }
        fh->mem = NULL;
        sym_undef(ps, pp_tok_text(ps, &ps->tok), ps->tok.len);
        return;
    }
    case T_READ: do_read(ps); return;
    case T_WRITE: do_write(ps); return;
    default: {
        char buf[80];
        if (kw.kind < T_KW_FIRST && kw.kind != T_IDENT && kw.kind != T_EOF &&
            kw.file == ps->frames[ps->n_frames - 1].file) {
            /* POV-Ray ignores a '#' before punctuation; read it again */
            pp_warning(ps, hash, "stray '#' ignored");
            ps->frames[ps->n_frames - 1].pos = kw.off;
            return;
        }
        pp_error(ps, &at, "unknown directive #%s",
                 pp_tok_name(ps, &kw, buf, sizeof buf));
    }
    }
}
