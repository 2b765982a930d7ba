/* SPDX-License-Identifier: MIT */
/*
** parse.c: the entry points iris_parse_file() and iris_parse_string(),
** the single setjmp every parse error returns to, and the memory helpers.
**
** The scene and everything it points to live in the scene arena; symbol
** values, arrays, macro records and file texts live in a scratch arena
** freed when the parse ends, on success and on error alike. Both arenas
** carry a byte limit (opts->max_memory), so no input can grow memory
** without bound.
*/
#include "config.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>

#include "pp.h"
#include "pp_test.h"
#include "util/mem.h"

void *pp_alloc(pp_state *ps, size_t n)
{
    void *p = arena_alloc(ps->A, n ? n : 1);
    if (!p)
        pp_nomem(ps);
    return p;
}

void *pp_salloc(pp_state *ps, size_t n)
{
    void *p = arena_alloc(ps->S, n ? n : 1);
    if (!p)
        pp_nomem(ps);
    return p;
}

char *pp_strdup(pp_state *ps, const char *s, size_t n)
{
    char *p = arena_strndup(ps->A, s, n);
    if (!p)
        pp_nomem(ps);
    return p;
}

/* The default texture: black pigment, default finish, no normal. */
static void make_defaults(pp_state *ps)
{
    iris_texture *t = pp_alloc(ps, sizeof *t);
    iris_pigment *p = pp_alloc(ps, sizeof *p);
    iris_finish *f = pp_alloc(ps, sizeof *f);
    pp_pattern_init(&p->pattern);
    iris_finish_defaults(f);
    pp_pattern_init(&t->map_pattern);
    t->pigment = p;
    t->finish = f;
    ps->default_tex = t;
    ps->default_pigment = p;
    ps->default_finish = f;
}

static void define_float(pp_state *ps, const char *name, double v)
{
    pp_sym *s = sym_define(ps, 0, name, strlen(name));
    s->val.kind = V_FLOAT;
    s->val.dim = 1;
    s->val.v[0] = v;
}

/* Declare=Name=Value options become a prelude read before the scene. */
static void push_declares(pp_state *ps)
{
    for (int i = ps->opt.n_declares - 1; i >= 0; i--) {
        const iris_declare *d = &ps->opt.declares[i];
        if (!d->name || !d->value)
            continue;
        size_t n = strlen(d->name) + strlen(d->value) + 32;
        char *text = pp_salloc(ps, n);
        snprintf(text, n, "#declare %s = %s;\n", d->name, d->value);
        char name[300];
        snprintf(name, sizeof name, "<Declare=%.200s>", d->name);
        uint32_t f = pp_add_text(ps, name, text, strlen(text));
        pp_push_frame(ps, FR_STRING, f, 0, NULL);
    }
}

static void fill_files(pp_state *ps)
{
    iris_scene *sc = ps->scene;
    sc->n_files = ps->n_files + 1;
    sc->files = pp_alloc(ps, (size_t)sc->n_files * sizeof *sc->files);
    sc->files[0] = "";
    for (int i = 0; i < ps->n_files; i++)
        sc->files[i + 1] = pp_strdup(ps, ps->files[i].path,
                                     strlen(ps->files[i].path));
}

static void release(pp_state *ps)
{
    pp_close_files(ps);
    sym_free_all(ps);
    iris_free(ps->frames);
    iris_free(ps->conds);
    iris_free(ps->files);
    arena_destroy(ps->S);
}

/* The C stack the grammar may use: half the stack size limit (the
** parser may run on a thread whose stack is the default, which Linux
** takes from the same limit), at most 4 MiB, at least 256 KiB.
** AddressSanitizer's frames are about three times larger (a level of
** parentheses takes ~22 KiB against ~7.6 KiB, measured), so a sanitised
** build allows three times the stack: the same depth parses (about 550
** levels of parentheses) and its tests raise the stack size limit to
** make room (tests/robust.mk). */
#if defined(__SANITIZE_ADDRESS__)
#define PP_STACK_CAP ((size_t)12 << 20)
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define PP_STACK_CAP ((size_t)12 << 20)
#endif
#endif
#ifndef PP_STACK_CAP
#define PP_STACK_CAP ((size_t)4 << 20)
#endif
static size_t stack_limit(void)
{
    size_t lim = PP_STACK_CAP;
    struct rlimit rl;
    if (getrlimit(RLIMIT_STACK, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY &&
        rl.rlim_cur / 2 < lim)
        lim = (size_t)(rl.rlim_cur / 2);
    return lim < ((size_t)256 << 10) ? (size_t)256 << 10 : lim;
}

/* Under an address-space limit (ulimit -v) malloc fails long before a
** 2 GiB parser limit is reached, where no diagnostic can be made: each of
** the two arenas then gets at most a third of the limit, so the located
** "out of parser memory" comes first and the rest is left for the
** program, its libraries and the render. */
static size_t address_space_cap(size_t limit)
{
    struct rlimit rl;
    if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY &&
        rl.rlim_cur / 3 < limit)
        limit = (size_t)(rl.rlim_cur / 3);
    return limit;
}

static enum iris_status run(const char *name, const char *text, size_t len,
                            const iris_parse_options *opts,
                            iris_scene **out, iris_diag_list *diags,
                            const char *probe, pp_test_result *res)
{
    *out = NULL;
    pp_state *ps = iris_calloc(1, sizeof *ps);
    if (!ps)
        return IRIS_ENOMEM;
    if (opts)
        ps->opt = *opts;
    /* POV-Ray has no loop limit; 1e6 iterations of one loop take about a
    ** second here, so an endless loop ends soon with a located error,
    ** and a scene that needs more says so (--max-loop-iterations). */
    if (ps->opt.max_while_iterations <= 0)
        ps->opt.max_while_iterations = 1000000;
    if (ps->opt.max_include_depth <= 0)
        ps->opt.max_include_depth = 64;
    if (ps->opt.max_macro_depth <= 0)
        ps->opt.max_macro_depth = 256;
    if (ps->opt.max_memory == 0)
        ps->opt.max_memory = (size_t)2 << 30;
    ps->opt.max_memory = address_space_cap(ps->opt.max_memory);
    if (ps->opt.image_width <= 0)
        ps->opt.image_width = 800;
    if (ps->opt.image_height <= 0)
        ps->opt.image_height = 600;
    ps->diags = diags;
    pp_diags_reserve(ps);
    ps->stack_base = (uintptr_t)__builtin_frame_address(0);
    ps->stack_limit = stack_limit();
    ps->A = arena_create(ps->opt.max_memory);
    ps->S = arena_create(ps->opt.max_memory);
    if (!ps->A || !ps->S) {
        arena_destroy(ps->A);
        arena_destroy(ps->S);
        iris_free(ps);
        return IRIS_ENOMEM;
    }
    if (setjmp(ps->jb)) {
        enum iris_status st = ps->fail_status ? ps->fail_status : IRIS_EPARSE;
        release(ps);
        /* what the scene holds outside its arena (a function's images) */
        for (iris_scene_cleanup *c = ps->scene ? ps->scene->cleanups : NULL;
             c; c = c->next)
            c->free(c->data);
        arena_destroy(ps->A);
        iris_free(ps);
        return st;
    }
    iris_scene *sc = pp_alloc(ps, sizeof *sc);
    ps->scene = sc;
    sc->arena = ps->A;
    sc->version = 3.7;
    ps->version = 3.7;
    iris_camera_defaults(&sc->camera);
    iris_global_defaults(&sc->settings);
    sc->background.t = 1;
    sc->image_width = ps->opt.image_width;
    sc->image_height = ps->opt.image_height;
    ps->warned = pp_salloc(ps, T_NUM_TOKENS);
    lex_init_keywords(ps);
    sym_push_scope(ps);
    define_float(ps, "iris_version", 0.1);
    make_defaults(ps);

    if (text) {
        char *copy = pp_salloc(ps, len + 1);
        memcpy(copy, text, len);
        copy[len] = 0;
        uint32_t f = pp_add_text(ps, name, copy, len);
        pp_push_frame(ps, FR_FILE, f, 0, NULL);
    } else {
        ps->fail_status = IRIS_EIO;
        pp_open_file(ps, name, false, NULL);
        ps->fail_status = 0;
    }
    push_declares(ps);
    pp_scene_items(ps);
    /* A scene in which no #version ran (none of its own, none in an
    ** include file: colors.inc and most others set one and restore
    ** 'version', 3.7, at their end) renders as POV-Ray 3.7 renders it:
    ** with EffectiveLanguageVersion() 3.62 (the end of its Parser::Parse:
    ** no gamma correction without assumed_gamma, 3.6's layered-texture
    ** opacity and sky; src/render reads scene->version). */
    sc->version = pp_effective_version(ps);
    /* and POV-Ray sets it again from the version the scene ends with
    ** (Parser::Parse): a 3.1 scene whose include files switch to 3.5
    ** and back renders textures.inc's Jade with generator 1 */
    if (!ps->noise_explicit)
        sc->settings.noise_generator = pp_version_noise(ps->version);
    if (ps->n_conds > 0) {
        pp_cond *c = &ps->conds[ps->n_conds - 1];
        pp_error_at(ps, c->file, c->off, 1, "directive without #end");
    }
    fill_files(ps);
    if (probe && res) {
        pp_sym *s = sym_resolve(sym_lookup(ps, probe, strlen(probe)));
        memset(res, 0, sizeof *res);
        if (s) {
            res->kind = s->val.kind;
            res->dim = s->val.dim;
            memcpy(res->v, s->val.v, sizeof res->v);
            if (s->val.kind == V_STRING)
                snprintf(res->str, sizeof res->str, "%s", s->val.u.str);
            if (s->val.kind == V_ARRAY) {
                res->dim = s->val.u.arr->ndim;
                res->n = s->val.u.arr->n;
            }
        }
    }
    release(ps);
    iris_free(ps);
    *out = sc;
    return IRIS_OK;
}

enum iris_status iris_parse_file(const char *path,
                                 const iris_parse_options *opts,
                                 iris_scene **out, iris_diag_list *diags)
{
    if (!path || !out) {
        if (out)
            *out = NULL;
        return IRIS_EINVAL;
    }
    return run(path, NULL, 0, opts, out, diags, NULL, NULL);
}

enum iris_status iris_parse_string(const char *name, const char *text,
                                   size_t len,
                                   const iris_parse_options *opts,
                                   iris_scene **out, iris_diag_list *diags)
{
    if (!text || !out) {
        if (out)
            *out = NULL;
        return IRIS_EINVAL;
    }
    return run(name ? name : "<string>", text, len, opts, out, diags, NULL,
               NULL);
}

enum iris_status pp_test_value(const char *sdl, const char *name,
                               const iris_parse_options *opts,
                               pp_test_result *res, iris_diag_list *diags)
{
    iris_scene *scene = NULL;
    enum iris_status st = run("<test>", sdl, strlen(sdl), opts, &scene,
                              diags, name, res);
    iris_scene_destroy(scene);
    return st;
}
