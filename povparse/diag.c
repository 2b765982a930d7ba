/* SPDX-License-Identifier: MIT */
/*
** diag.c: diagnostics as values, and their compiler-style rendering.
**
** A diagnostic is located by file and byte offset; the line and column are
** found from a per-file line map built on first use (jq's locfile). The
** chain of #include files and macro calls that led to the position is
** taken from the input frames at the time of the message. pp_error() is
** the one exit of every parse error: it records the message and longjmps
** to the setjmp in parse.c.
*/
#include "config.h"

#include <limits.h>

#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "pp.h"
#include "util/mem.h"

void iris_diag_list_init(iris_diag_list *list)
{
    memset(list, 0, sizeof *list);
}

void iris_diag_list_fini(iris_diag_list *list)
{
    if (!list)
        return;
    iris_free(list->items);
    memset(list, 0, sizeof *list);
}

void iris_diag_format(const iris_diag *d, FILE *out)
{
    static const char *const sev[] = { "note", "warning", "error" };
    const char *s = (unsigned)d->sev <= IRIS_SEV_ERROR ? sev[d->sev] : "error";
    if (d->line)
        fprintf(out, "%s:%u:%u: %s: %s\n", d->file, d->line, d->col, s,
                d->message);
    else if (d->file[0])
        fprintf(out, "%s: %s: %s\n", d->file, s, d->message);
    else
        fprintf(out, "%s: %s\n", s, d->message);
    if (d->line && d->source_line[0]) {
        fprintf(out, "%5u | %s\n", d->line, d->source_line);
        if (d->col >= 1 && d->col <= strlen(d->source_line) + 1) {
            fprintf(out, "      | %*s^", (int)(d->col - 1), "");
            for (unsigned i = 1; i < d->caret_len && i < 200; i++)
                fputc('~', out);
            fputc('\n', out);
        }
    }
    for (int i = 0; i < d->n_chain && i < 8; i++)
        fprintf(out, "      = %s\n", d->chain[i]);
}

/* Builds the line map of file 'f' on first use. */
static void line_map(pp_state *ps, uint32_t f)
{
    pp_file *pf = &ps->files[f];
    if (pf->line_start)
        return;
    uint32_t n = 1;
    for (size_t i = 0; i < pf->len; i++)
        n += pf->text[i] == '\n';
    uint32_t *ls = arena_array(ps->S, n, sizeof *ls);
    if (!ls)
        return;
    uint32_t k = 0;
    ls[k++] = 0;
    for (size_t i = 0; i < pf->len; i++)
        if (pf->text[i] == '\n')
            ls[k++] = (uint32_t)i + 1;
    pf->line_start = ls;
    pf->n_lines = n;
}

void pp_line_col(pp_state *ps, uint32_t file, uint32_t off, unsigned *line,
                 unsigned *col)
{
    *line = *col = 0;
    if (file >= (uint32_t)ps->n_files)
        return;
    line_map(ps, file);
    pp_file *pf = &ps->files[file];
    if (!pf->line_start) {
        /* no memory for the map (an out-of-memory error is being
        ** reported): count the lines up to 'off' instead */
        unsigned l = 1;
        uint32_t ls = 0;
        for (uint32_t i = 0; i < off && i < pf->len; i++)
            if (pf->text[i] == '\n') {
                l++;
                ls = i + 1;
            }
        *line = l;
        *col = off - ls + 1;
        return;
    }
    uint32_t lo = 0, hi = pf->n_lines - 1;
    while (lo < hi) {
        uint32_t mid = (lo + hi + 1) / 2;
        if (pf->line_start[mid] <= off)
            lo = mid;
        else
            hi = mid - 1;
    }
    *line = lo + 1;
    *col = off - pf->line_start[lo] + 1;
}

iris_loc pp_loc(pp_state *ps, const pp_token *t)
{
    iris_loc l = { 0, 0, 0 };
    if (!t)
        return l;
    unsigned line, col;
    pp_line_col(ps, t->file, t->off, &line, &col);
    /* scene file ids are shifted by one: files[0] is "unknown" */
    l.file = t->file + 1;
    l.line = line;
    l.col = col;
    return l;
}

static void fill_diag(pp_state *ps, iris_diag *d, enum iris_severity sev,
                      uint32_t file, uint32_t off, uint32_t len,
                      const char *fmt, va_list ap)
{
    memset(d, 0, sizeof *d);
    d->sev = sev;
    vsnprintf(d->message, sizeof d->message, fmt, ap);
    if (file < (uint32_t)ps->n_files) {
        pp_file *pf = &ps->files[file];
        snprintf(d->file, sizeof d->file, "%s", pf->path);
        pp_line_col(ps, file, off, &d->line, &d->col);
        if (d->line && pf->line_start) {
            uint32_t s = pf->line_start[d->line - 1];
            size_t k = 0;
            for (uint32_t i = s; i < pf->len && pf->text[i] != '\n' &&
                                 pf->text[i] != '\r' &&
                                 k + 1 < sizeof d->source_line; i++) {
                unsigned char c = (unsigned char)pf->text[i];
                /* One column per byte so that the caret lines up. */
                d->source_line[k++] = (c == '\t' || c < 32) ? ' ' :
                                      c >= 127 ? '?' : (char)c;
            }
            d->source_line[k] = 0;
        }
        d->caret_len = len ? len : 1;
    }
    /* The chain of #include files and macro calls, innermost first. */
    for (int i = ps->n_frames - 1; i >= 1 && d->n_chain < 8; i--) {
        const pp_frame *fr = &ps->frames[i];
        unsigned line, col;
        if (fr->kind != FR_INCLUDE && fr->kind != FR_MACRO)
            continue;
        pp_line_col(ps, fr->call_file, fr->call_off, &line, &col);
        const char *cf = fr->call_file < (uint32_t)ps->n_files
                             ? ps->files[fr->call_file].path : "?";
        if (fr->kind == FR_INCLUDE)
            snprintf(d->chain[d->n_chain++], sizeof d->chain[0],
                     "in file included from %.200s:%u:%u", cf, line, col);
        else
            snprintf(d->chain[d->n_chain++], sizeof d->chain[0],
                     "in macro '%.60s' called at %.150s:%u:%u",
                     fr->macro ? fr->macro->name : "?", cf, line, col);
    }
}

void pp_check_interrupt(pp_state *ps)
{
    if (!ps->opt.interrupt || !*ps->opt.interrupt)
        return;
    ps->fail_status = IRIS_EINTR;
    pp_error(ps, &ps->tok, "interrupted while parsing here");
}

/* Room for the first diagnostics before the parse starts: the one that
** says the memory ran out must not need memory. */
void pp_diags_reserve(pp_state *ps)
{
    iris_diag_list *l = ps->diags;
    if (!l || l->cap >= 16)
        return;
    iris_diag *items = iris_realloc(l->items, 16 * sizeof *items);
    if (items) {
        l->items = items;
        l->cap = 16;
    }
}

static void push_diag(pp_state *ps, const iris_diag *d)
{
    iris_diag_list *l = ps->diags;
    if (!l)
        return;
    if (l->n == l->cap) {
        int cap = l->cap ? l->cap * 2 : 16;
        if (cap > 100000)
            return; /* enough: do not grow without bound */
        iris_diag *items = iris_realloc(l->items, (size_t)cap * sizeof *items);
        if (!items)
            return;
        l->items = items;
        l->cap = cap;
    }
    l->items[l->n++] = *d;
    if (d->sev == IRIS_SEV_ERROR)
        l->n_errors++;
    else if (d->sev == IRIS_SEV_WARNING)
        l->n_warnings++;
}

_Noreturn void pp_error_at(pp_state *ps, uint32_t file, uint32_t off,
                           uint32_t len, const char *fmt, ...)
{
    iris_diag d;
    va_list ap;
    va_start(ap, fmt);
    fill_diag(ps, &d, IRIS_SEV_ERROR, file, off, len, fmt, ap);
    va_end(ap);
    push_diag(ps, &d);
    if (!ps->fail_status)
        ps->fail_status = IRIS_EPARSE;
    longjmp(ps->jb, 1);
}

_Noreturn void pp_error(pp_state *ps, const pp_token *at, const char *fmt,
                        ...)
{
    iris_diag d;
    va_list ap;
    va_start(ap, fmt);
    if (at)
        fill_diag(ps, &d, IRIS_SEV_ERROR, at->file, at->off, at->len, fmt, ap);
    else
        fill_diag(ps, &d, IRIS_SEV_ERROR, UINT32_MAX, 0, 0, fmt, ap);
    va_end(ap);
    push_diag(ps, &d);
    if (!ps->fail_status)
        ps->fail_status = IRIS_EPARSE;
    longjmp(ps->jb, 1);
}

/*
** Warnings kept in the list. Past this many they are only counted: a
** #while that warns on each turn (a stray '#' in its body) would
** otherwise spend its time filling copies of one warning (3 KB each;
** libFuzzer found one that took over 10 s).
*/
#define MAX_KEPT_WARNINGS 1000

void pp_warning(pp_state *ps, const pp_token *at, const char *fmt, ...)
{
    if (ps->diags && ps->diags->n_warnings >= MAX_KEPT_WARNINGS) {
        if (ps->diags->n_warnings < INT_MAX)
            ps->diags->n_warnings++;
        return;
    }
    iris_diag d;
    va_list ap;
    va_start(ap, fmt);
    if (at)
        fill_diag(ps, &d, IRIS_SEV_WARNING, at->file, at->off, at->len, fmt,
                  ap);
    else
        fill_diag(ps, &d, IRIS_SEV_WARNING, UINT32_MAX, 0, 0, fmt, ap);
    va_end(ap);
    push_diag(ps, &d);
    /* Also kept in the scene for callers that only see the scene. */
}

void pp_warn_once(pp_state *ps, const pp_token *at, int kw, const char *what)
{
    if (kw < 0 || kw >= T_NUM_TOKENS || ps->warned[kw])
        return;
    ps->warned[kw] = 1;
    pp_warning(ps, at, "%s is parsed but not rendered", what);
}

_Noreturn void pp_nomem(pp_state *ps)
{
    const pp_token *t = &ps->tok;
    iris_diag d;
    memset(&d, 0, sizeof d);
    d.sev = IRIS_SEV_ERROR;
    snprintf(d.message, sizeof d.message,
             "out of parser memory (limit %zu MiB): the scene is too large "
             "or loops without end", ps->opt.max_memory >> 20);
    if (t->file < (uint32_t)ps->n_files) {
        snprintf(d.file, sizeof d.file, "%s", ps->files[t->file].path);
        pp_line_col(ps, t->file, t->off, &d.line, &d.col);
    }
    push_diag(ps, &d);
    ps->fail_status = IRIS_ENOMEM;
    longjmp(ps->jb, 1);
}

const char *pp_kind_name(int kind)
{
    static const char *const names[V_KIND_COUNT] = {
        "nothing", "float", "vector", "colour", "string", "object",
        "light_source", "texture", "pigment", "normal", "finish",
        "interior", "material", "transform", "camera", "function", "array",
        "colour_map", "pigment_map", "normal_map", "texture_map",
        "slope_map", "density_map", "fog", "sky_sphere", "rainbow",
        "spline", "media", "density", "file", "macro", "texture_list",
        "unsupported item",
    };
    return kind >= 0 && kind < V_KIND_COUNT ? names[kind] : "?";
}

const char *pp_tok_name(pp_state *ps, const pp_token *t, char *buf, size_t n)
{
    switch (t->kind) {
    case T_EOF: return "end of file";
    case T_NUMBER: snprintf(buf, n, "number"); return buf;
    case T_STRING: return "string";
    default: break;
    }
    if (t->file < (uint32_t)ps->n_files && t->len) {
        size_t len = t->len < n - 3 ? t->len : n - 3;
        snprintf(buf, n, "'%.*s'", (int)len, ps->files[t->file].text + t->off);
        return buf;
    }
    return "token";
}

_Noreturn void pp_unexpected(pp_state *ps, const pp_token *at,
                             const char *where)
{
    char buf[80];
    if (at->kind == T_IDENT && at->val.kind == V_NONE)
        pp_error(ps, at, "undeclared identifier '%.*s' in %s", (int)at->len,
                 pp_tok_text(ps, at), where);
    if (at->kind == T_IDENT)
        pp_error(ps, at, "unexpected %s identifier '%.*s' in %s",
                 pp_kind_name(at->val.kind), (int)at->len,
                 pp_tok_text(ps, at), where);
    pp_error(ps, at, "unexpected %s in %s",
             pp_tok_name(ps, at, buf, sizeof buf), where);
}

void pp_enter(pp_state *ps, const pp_token *at)
{
    if (++ps->depth == 1 && at) {
        ps->outer_file = at->file;
        ps->outer_off = at->off;
        ps->outer_len = at->len;
    }
    /* The stack grows down on every platform iris builds for; the
    ** distance from the parse's first frame is the stack in use. Which
    ** limit is met first depends on the build's frame sizes, so both
    ** give the same error at the outermost construct. */
    uintptr_t here = (uintptr_t)__builtin_frame_address(0);
    if (ps->depth > PP_MAX_DEPTH ||
        (ps->stack_base > here && ps->stack_base - here > ps->stack_limit))
        pp_error_at(ps, ps->outer_file, ps->outer_off, ps->outer_len,
                    "nested too deep (the parser allows %d levels, fewer "
                    "when each level uses much of its stack)", PP_MAX_DEPTH);
}
