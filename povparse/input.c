/* SPDX-License-Identifier: MIT */
/*
** input.c: the token stream the grammar reads.
**
** A stack of frames says where tokens come from: the scene file, the
** #include files it opened, and the bodies of macros being called (read
** again from the source text at each call, as POV-Ray does). pp_next()
** runs every directive it meets (directive.c) and expands macro calls, so
** the grammar only ever sees ordinary tokens. Identifier tokens carry a
** copy of their value, because the macro that defined them may end (and
** free its symbol table) before the grammar looks at the value.
*/
#include "config.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "pp.h"
#include "util/mem.h"

#define MAX_FILE_SIZE (512u << 20)

uint32_t pp_add_text(pp_state *ps, const char *name, const char *text,
                     size_t len)
{
    if (len >= MAX_FILE_SIZE)
        pp_error(ps, NULL, "%s: file too large", name);
    if (ps->n_files == ps->cap_files) {
        int cap = ps->cap_files ? ps->cap_files * 2 : 16;
        pp_file *f = iris_realloc(ps->files, (size_t)cap * sizeof *f);
        if (!f)
            pp_nomem(ps);
        ps->files = f;
        ps->cap_files = cap;
    }
    pp_file *f = &ps->files[ps->n_files];
    memset(f, 0, sizeof *f);
    f->path = pp_strdup(ps, name, strlen(name));
    const char *slash = strrchr(name, '/');
    f->dir = slash ? pp_strdup(ps, name, (size_t)(slash - name)) : ".";
    f->text = text;
    f->len = len;
    return (uint32_t)ps->n_files++;
}

/* A lone carriage return ends a line, as in files saved on a classic Mac:
** POV-Ray's text stream reads CR, LF, CR LF and LF CR each as one line
** break. Such a CR becomes LF in place (offsets, and so columns, are
** unchanged), so that a '//' comment ends there and lines are counted;
** a CR next to an LF stays blank space. Without it a whole CR-only file
** was one line, and its first '//' comment hid the rest of the scene. */
static void old_mac_lines(char *s, size_t n)
{
    char prev = 0; /* the previous byte as read (before any change) */
    for (size_t i = 0; i < n; i++) {
        char c = s[i];
        if (c == '\r' && prev != '\n' && (i + 1 == n || s[i + 1] != '\n'))
            s[i] = '\n';
        /* an LF CR pair is one break: the CR after it is blank */
        prev = (c == '\r' && prev == '\n') ? 0 : c;
    }
}

/* Reads a whole file into the scratch arena; NULL if it cannot. */
static char *read_file(pp_state *ps, const char *path, size_t *len)
{
    struct stat st;
    if (stat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return NULL;
    FILE *fp = fopen(path, "rb");
    if (!fp)
        return NULL;
    if ((unsigned long long)st.st_size >= MAX_FILE_SIZE) {
        fclose(fp);
        return NULL;
    }
    size_t n = (size_t)st.st_size;
    char *buf = arena_alloc(ps->S, n + 1);
    if (!buf) {
        fclose(fp);
        pp_nomem(ps);
    }
    size_t got = fread(buf, 1, n, fp);
    fclose(fp);
    buf[got] = 0;
    *len = got;
    old_mac_lines(buf, got);
    return buf;
}

static bool file_ok(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0 && S_ISREG(st.st_mode);
}

/* Finds 'name' along POV-Ray's search path; returns a scratch copy. */
static const char *locate(pp_state *ps, const char *name, uint32_t from)
{
    char buf[4096];
    const char *dirs[64];
    int nd = 0;
    if (name[0] == '/')
        return file_ok(name) ? name : NULL;
    if (from < (uint32_t)ps->n_files)
        dirs[nd++] = ps->files[from].dir;
    if (ps->n_files > 0)
        dirs[nd++] = ps->files[0].dir;
    for (int i = 0; i < ps->opt.n_include_paths && nd < 60; i++)
        dirs[nd++] = ps->opt.include_paths[i];
#ifdef POVRAY_INCLUDE_DIR
    if (!ps->opt.no_system_includes && POVRAY_INCLUDE_DIR[0])
        dirs[nd++] = POVRAY_INCLUDE_DIR;
#endif
    /* POV-Ray also tries the name with .inc added when it has none. */
    const char *base = strrchr(name, '/');
    bool has_ext = strchr(base ? base : name, '.') != NULL;
    for (int pass = 0; pass < (has_ext ? 1 : 2); pass++) {
        for (int i = 0; i < nd; i++) {
            int n = snprintf(buf, sizeof buf, "%s/%s%s", dirs[i], name,
                             pass ? ".inc" : "");
            if (n > 0 && (size_t)n < sizeof buf && file_ok(buf))
                return pp_strdup(ps, buf, (size_t)n);
        }
    }
    return NULL;
}

void pp_push_frame(pp_state *ps, int kind, uint32_t file, uint32_t pos,
                   const pp_token *call)
{
    if (ps->n_frames == ps->cap_frames) {
        int cap = ps->cap_frames ? ps->cap_frames * 2 : 32;
        pp_frame *f = iris_realloc(ps->frames, (size_t)cap * sizeof *f);
        if (!f)
            pp_nomem(ps);
        ps->frames = f;
        ps->cap_frames = cap;
    }
    pp_frame *fr = &ps->frames[ps->n_frames++];
    memset(fr, 0, sizeof *fr);
    fr->kind = kind;
    fr->file = file;
    fr->pos = pos;
    fr->cond_base = ps->n_conds;
    if (call) {
        fr->call_file = call->file;
        fr->call_off = call->off;
    }
    if (kind == FR_INCLUDE || kind == FR_MACRO)
        sym_push_scope(ps);
    fr->scope = ps->n_scopes - 1;
}

void pp_pop_frame(pp_state *ps)
{
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    if (fr->kind == FR_INCLUDE) {
        sym_pop_scope(ps);
        ps->include_depth--;
    } else if (fr->kind == FR_MACRO) {
        /* parameters passed an array element give their value back to
        ** it, unless the macro #undef'd them */
        for (int i = 0; i < fr->n_elem_params; i++) {
            pp_sym *p = fr->elem_params[i];
            const char *name = fr->macro->params[fr->elem_index[i]];
            if (!sym_is_live(ps, p) || strlen(name) != p->name_len ||
                memcmp(name, p->name, p->name_len) != 0)
                continue;
            p = sym_resolve(p);
            if (p && p->val.kind != V_NONE)
                *fr->elem_slots[i] = p->val;
        }
        sym_pop_scope(ps);
        ps->macro_depth--;
    }
    ps->n_frames--;
}

/* #include of a file this parse wrote while writes were refused
** (memfile.c), named relative to the including file or the scene as
** locate() would find it on disk. Its text is taken as it is now: a
** scene may write the file again and include the new text. */
static bool include_written(pp_state *ps, const char *name, uint32_t from,
                            const pp_token *at)
{
    if (!ps->memfiles)
        return false;
    const char *dirs[2] = { NULL, NULL };
    if (from < (uint32_t)ps->n_files)
        dirs[0] = ps->files[from].dir;
    if (ps->n_files > 0)
        dirs[1] = ps->files[0].dir;
    for (int i = 0; i < 2; i++) {
        char buf[4096];
        if (name[0] != '/' && !dirs[i])
            continue;
        if (name[0] == '/')
            snprintf(buf, sizeof buf, "%s", name);
        else
            snprintf(buf, sizeof buf, "%s/%s", dirs[i], name);
        pp_memfile *m = pp_memfile_find(ps, buf);
        if (!m)
            continue;
        int limit = ps->opt.max_include_depth;
        if (ps->include_depth >= limit)
            pp_error(ps, at, "#include nested more than %d deep (does a "
                     "file include itself?)", limit);
        uint32_t f = UINT32_MAX; /* the same text included before */
        for (int k = 0; k < ps->n_files && f == UINT32_MAX; k++)
            if (!strcmp(ps->files[k].path, m->path) &&
                ps->files[k].len == m->len &&
                !memcmp(ps->files[k].text, m->buf, m->len))
                f = (uint32_t)k;
        if (f == UINT32_MAX) {
            char *text = pp_salloc(ps, m->len + 1);
            memcpy(text, m->buf, m->len + 1);
            f = pp_add_text(ps, m->path, text, m->len);
        }
        ps->include_depth++;
        pp_push_frame(ps, FR_INCLUDE, f, 0, at);
        return true;
    }
    return false;
}

void pp_open_file(pp_state *ps, const char *path, bool is_include,
                  const pp_token *at)
{
    uint32_t from = at ? at->file : UINT32_MAX;
    if (is_include && include_written(ps, path, from, at))
        return;
    const char *full = is_include ? locate(ps, path, from) : path;
    if (!full) {
        if (at)
            pp_error(ps, at, "cannot find include file \"%s\"", path);
        pp_error(ps, NULL, "cannot open \"%s\"", path);
    }
    if (at)
        pp_check_read(ps, at, full);
    int limit = ps->opt.max_include_depth;
    if (is_include && ps->include_depth >= limit)
        pp_error(ps, at, "#include nested more than %d deep (does a file "
                 "include itself?)", limit);
    /* Files are read once and kept: macros re-read their bodies. */
    uint32_t f = UINT32_MAX;
    for (int i = 0; i < ps->n_files; i++)
        if (strcmp(ps->files[i].path, full) == 0) {
            f = (uint32_t)i;
            break;
        }
    if (f == UINT32_MAX) {
        size_t len = 0;
        char *text = read_file(ps, full, &len);
        if (!text) {
            if (at)
                pp_error(ps, at, "cannot read \"%s\": %s", full,
                         strerror(errno ? errno : EIO));
            ps->fail_status = IRIS_EIO;
            pp_error(ps, NULL, "cannot read \"%s\": %s", full,
                     strerror(errno ? errno : EIO));
        }
        f = pp_add_text(ps, full, text, len);
    }
    if (is_include)
        ps->include_depth++;
    pp_push_frame(ps, is_include ? FR_INCLUDE : FR_FILE, f, 0, at);
}

/* Reports the innermost #if/#while/... still open when a frame ends. */
/* The end of the file came before the #end of 'c'. Located as POV-Ray
** locates its "End of file reached but #end expected": at the file's
** last token (its last non-blank character here), on the line POV-Ray
** names; the message says which directive is open. */
static _Noreturn void missing_end(pp_state *ps, const pp_cond *c)
{
    static const char *const names[] = { "#if", "#else", "#while", "#for",
                                          "#switch", "#macro" };
    uint32_t file = ps->frames[ps->n_frames - 1].file;
    const pp_file *f = &ps->files[file];
    size_t end = f->len;
    while (end > 0 && (f->text[end - 1] == ' ' || f->text[end - 1] == '\t' ||
                       f->text[end - 1] == '\n' || f->text[end - 1] == '\r'))
        end--;
    pp_token at;
    memset(&at, 0, sizeof at);
    at.file = c->file;
    at.off = c->off;
    iris_loc open = pp_loc(ps, &at);
    pp_error_at(ps, file, (uint32_t)(end > 0 ? end - 1 : 0), 1,
                "end of file reached, but the %s at line %u has no #end",
                names[c->kind], open.line);
}

void pp_raw(pp_state *ps, pp_token *t)
{
    for (;;) {
        pp_frame *fr = &ps->frames[ps->n_frames - 1];
        fr->pos = lex_scan(ps, fr->file, fr->pos, t);
        if (t->kind != T_EOF)
            return;
        if (ps->n_conds > fr->cond_base)
            missing_end(ps, &ps->conds[ps->n_conds - 1]);
        if (fr->kind == FR_MACRO)
            pp_error_at(ps, fr->file, fr->pos, 0, "macro body without #end");
        if (ps->n_frames == 1 || fr->kind == FR_FILE || fr->kind == FR_STRING) {
            if (fr->kind == FR_STRING && ps->n_frames > 1) {
                /* A Declare= prelude: continue with the frame below. */
                pp_pop_frame(ps);
                continue;
            }
            return;
        }
        pp_pop_frame(ps);
    }
}

/* True when the next raw tokens are the #end that closes the macro being
** read: running it only returns to the caller, which is always safe. */
static bool at_macro_end(pp_state *ps)
{
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    if (fr->kind != FR_MACRO || ps->n_conds != fr->cond_base + 1 ||
        ps->conds[ps->n_conds - 1].kind != C_MACRO)
        return false;
    /* the condition of an #if/#while of this body is being read: the
    ** '#end' after '#if (C)' closes that #if, not yet pushed (shapes3.inc's
    ** Round_Conic_Prism: '#if (Border_R = 0 ) #end') */
    if (ps->header_frames == ps->n_frames && ps->header_conds == ps->n_conds)
        return false;
    pp_token t;
    uint32_t p = lex_peek(ps, fr->file, fr->pos, &t);
    if (t.kind != T_HASH)
        return false;
    lex_peek(ps, fr->file, p, &t);
    return t.kind == T_END;
}

bool pp_next_is_directive(pp_state *ps)
{
    if (ps->n_unget > 0)
        return ps->unget[ps->n_unget - 1].kind == T_HASH;
    /* A macro's closing #end does not end the expression being read:
    ** 'M(1) * 2' goes on after the body of M. */
    while (at_macro_end(ps)) {
        ps->n_conds--;
        pp_pop_frame(ps);
    }
    for (int i = ps->n_frames - 1; i >= 0; i--) {
        pp_frame *fr = &ps->frames[i];
        pp_token t;
        lex_peek(ps, fr->file, fr->pos, &t);
        if (t.kind != T_EOF)
            return t.kind == T_HASH;
        if (fr->kind == FR_FILE || fr->kind == FR_MACRO)
            return false;
    }
    return false;
}

void pp_push_cond(pp_state *ps, int kind, const pp_token *at)
{
    if (ps->n_conds == ps->cap_conds) {
        int cap = ps->cap_conds ? ps->cap_conds * 2 : 32;
        if (cap > 1 << 20)
            pp_error(ps, at, "directives nested too deeply");
        pp_cond *c = iris_realloc(ps->conds, (size_t)cap * sizeof *c);
        if (!c)
            pp_nomem(ps);
        ps->conds = c;
        ps->cap_conds = cap;
    }
    pp_cond *c = &ps->conds[ps->n_conds++];
    memset(c, 0, sizeof *c);
    c->kind = kind;
    c->file = at->file;
    c->off = at->off;
}

int pp_skip(pp_state *ps, int mode, const pp_cond *opener)
{
    pp_frame *fr = &ps->frames[ps->n_frames - 1];
    int depth = 0;
    pp_token t;
    ps->n_unget = 0; /* look-ahead tokens belong to the skipped text */
    for (;;) {
        fr->pos = lex_peek(ps, fr->file, fr->pos, &t);
        if (t.kind == T_EOF) {
            if (opener)
                missing_end(ps, opener);
            pp_error(ps, &t, "end of file while looking for #end");
        }
        if (t.kind != T_HASH)
            continue;
        uint32_t save = fr->pos;
        fr->pos = lex_peek(ps, fr->file, fr->pos, &t);
        switch (t.kind) {
        case T_IF: case T_IFDEF: case T_IFNDEF: case T_SWITCH:
        case T_WHILE: case T_FOR: case T_MACRO:
            depth++;
            break;
        case T_END:
            if (depth == 0)
                return T_END;
            depth--;
            break;
        case T_ELSE: case T_ELSEIF:
            if (depth == 0 && mode != SKIP_END)
                return t.kind;
            break;
        case T_CASE: case T_RANGE: case T_BREAK:
            if (depth == 0 && mode == SKIP_SWITCH)
                return t.kind;
            break;
        default:
            fr->pos = save;
            break;
        }
    }
}

/* An array identifier followed by '[' stands for the element A[i]...
** wherever it appears: the indices are read here. */
static void resolve_element(pp_state *ps)
{
    int next;
    if (ps->n_unget > 0) {
        next = ps->unget[ps->n_unget - 1].kind;
    } else {
        if (pp_next_is_directive(ps))
            return;
        pp_token nt;
        pp_frame *fr = &ps->frames[ps->n_frames - 1];
        lex_peek(ps, fr->file, fr->pos, &nt);
        next = nt.kind;
    }
    if (next != T_LBRACKET)
        return;
    pp_token id = ps->tok;
    pp_value v = pp_array_element(ps, &id, id.val.u.arr);
    uint32_t end = ps->tok.off + ps->tok.len;
    ps->elem_file = id.file;
    ps->elem_start = id.off;
    ps->elem_end = ps->tok.file == id.file ? end : id.off;
    ps->tok = id;
    ps->tok.val = v;
    ps->tok.sym = NULL;
    if (ps->tok.file == id.file && end > id.off)
        ps->tok.len = end - id.off;
}

void pp_unget(pp_state *ps)
{
    if (ps->n_unget >= 4)
        pp_error(ps, &ps->tok, "internal error: too many tokens pushed back");
    ps->unget[ps->n_unget++] = ps->tok;
}

void pp_next(pp_state *ps)
{
    pp_poll_interrupt(ps);
    for (;;) {
        if (ps->n_unget > 0) {
            ps->tok = ps->unget[--ps->n_unget];
            /* a macro name read by a look-ahead runs when it is used */
            if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_MACRO &&
                ps->no_expand == 0) {
                pp_token call = ps->tok;
                pp_call_macro(ps, call.val.u.macro, &call);
                continue;
            }
            if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_ARRAY &&
                ps->tok.sym && ps->no_expand == 0)
                resolve_element(ps);
            return;
        }
        pp_raw(ps, &ps->tok);
        if (ps->tok.kind == T_HASH) {
            pp_token hash = ps->tok;
            pp_directive(ps, &hash);
            continue;
        }
        if (ps->tok.kind != T_IDENT)
            return;
        pp_sym *s = sym_resolve(sym_lookup(ps, pp_tok_text(ps, &ps->tok),
                                           ps->tok.len));
        ps->tok.sym = s;
        if (!s) {
            ps->tok.val.kind = V_NONE;
            return;
        }
        ps->tok.val = s->val;
        if (s->val.kind == V_ARRAY && ps->no_expand == 0) {
            resolve_element(ps);
            return;
        }
        if (s->val.kind == V_MACRO && ps->no_expand == 0) {
            pp_token call = ps->tok;
            pp_call_macro(ps, s->val.u.macro, &call);
            continue;
        }
        return;
    }
}

void pp_run_directives(pp_state *ps)
{
    while (ps->n_unget == 0 && pp_next_is_directive(ps)) {
        pp_raw(ps, &ps->tok);
        if (ps->tok.kind != T_HASH) {
            pp_unget(ps);
            return;
        }
        pp_token hash = ps->tok;
        pp_directive(ps, &hash);
    }
}

bool pp_accept_in_list(pp_state *ps, int kind)
{
    pp_run_directives(ps);
    return pp_accept(ps, kind);
}

bool pp_accept(pp_state *ps, int kind)
{
    /* Looking ahead must not run a directive before the current
    ** statement is complete ('#declare A = array[2]' then '#declare
    ** A[0] = 1'): a directive is never the optional token. Except a
    ** comma: one is looked for only between the items of a list that
    ** is not finished, where POV-Ray's Parse_Comma runs the directives
    ** before it ('P #if (I < N) , #end' in a prism's points,
    ** 'max(1 #if (C) , 5 #end)'). */
    if (kind == T_COMMA)
        pp_run_directives(ps);
    if (pp_next_is_directive(ps))
        return false;
    /* and must not call a macro that is only looked at */
    ps->no_expand++;
    pp_next(ps);
    ps->no_expand--;
    if (ps->tok.kind == kind)
        return true;
    pp_unget(ps);
    return false;
}

void pp_expect(pp_state *ps, int kind, const char *what)
{
    pp_next(ps);
    if (ps->tok.kind != kind) {
        char buf[80];
        pp_error(ps, &ps->tok, "expected %s, found %s", what,
                 pp_tok_name(ps, &ps->tok, buf, sizeof buf));
    }
}

const char *pp_tok_text(pp_state *ps, const pp_token *t)
{
    return ps->files[t->file].text + t->off;
}

void pp_skip_block(pp_state *ps)
{
    pp_token open = ps->tok;
    int depth = 1;
    while (depth > 0) {
        pp_next(ps);
        if (ps->tok.kind == T_LBRACE)
            depth++;
        else if (ps->tok.kind == T_RBRACE)
            depth--;
        else if (ps->tok.kind == T_EOF)
            pp_error(ps, &open, "'{' without a matching '}'");
    }
}

void pp_close_files(pp_state *ps)
{
    for (int i = 0; i < ps->n_open_files; i++) {
        if (ps->open_files[i] && ps->open_files[i]->fp) {
            fclose(ps->open_files[i]->fp);
            ps->open_files[i]->fp = NULL;
        }
    }
    ps->n_open_files = 0;
}
