/* SPDX-License-Identifier: MIT */
/*
** symtab.c: symbol tables: the global one, one per #include file and one
** per macro call, searched innermost first as POV-Ray does.
**
** Tables are malloc'd and freed when their file or macro ends; symbols are
** recycled through a free list so that a macro called a million times in
** a loop does not grow memory. Values point into the arenas and stay valid.
*/
#include "config.h"

#include <string.h>

#include "pp.h"
#include "util/mem.h"

static unsigned hash_name(const char *s, size_t n)
{
    unsigned h = 2166136261u;
    for (size_t i = 0; i < n; i++)
        h = (h ^ (unsigned char)s[i]) * 16777619u;
    return h;
}

void sym_push_scope(pp_state *ps)
{
    if (ps->n_scopes == ps->cap_scopes) {
        int cap = ps->cap_scopes ? ps->cap_scopes * 2 : 16;
        pp_scope *sc = iris_realloc(ps->scopes, (size_t)cap * sizeof *sc);
        if (!sc)
            pp_nomem(ps);
        ps->scopes = sc;
        ps->cap_scopes = cap;
    }
    pp_scope *sc = &ps->scopes[ps->n_scopes];
    sc->n_buckets = ps->n_scopes == 0 ? 1024 : 16;
    sc->n_syms = 0;
    sc->buckets = iris_calloc(sc->n_buckets, sizeof *sc->buckets);
    if (!sc->buckets)
        pp_nomem(ps);
    ps->n_scopes++;
}

static void free_scope(pp_state *ps, pp_scope *sc)
{
    for (unsigned i = 0; i < sc->n_buckets; i++) {
        pp_sym *s = sc->buckets[i];
        while (s) {
            pp_sym *next = s->next;
            s->next = ps->free_syms;
            ps->free_syms = s;
            s = next;
        }
    }
    iris_free(sc->buckets);
    sc->buckets = NULL;
}

void sym_pop_scope(pp_state *ps)
{
    if (ps->n_scopes <= 1)
        return;
    free_scope(ps, &ps->scopes[--ps->n_scopes]);
}

void sym_free_all(pp_state *ps)
{
    while (ps->n_scopes > 0)
        free_scope(ps, &ps->scopes[--ps->n_scopes]);
    iris_free(ps->scopes);
    ps->scopes = NULL;
    ps->cap_scopes = 0;
}

static pp_sym *find_in(pp_scope *sc, const char *name, size_t len)
{
    pp_sym *s = sc->buckets[hash_name(name, len) & (sc->n_buckets - 1)];
    for (; s; s = s->next)
        if (s->name_len == len && memcmp(s->name, name, len) == 0)
            return s;
    return NULL;
}

pp_sym *sym_lookup(pp_state *ps, const char *name, size_t len)
{
    for (int i = ps->n_scopes - 1; i >= 0; i--) {
        pp_sym *s = find_in(&ps->scopes[i], name, len);
        if (s)
            return s;
    }
    return NULL;
}

pp_sym *sym_resolve(pp_sym *s)
{
    int guard = 0;
    while (s && s->ref && guard++ < 1000)
        s = s->ref;
    return s;
}

bool sym_is_live(pp_state *ps, const pp_sym *s)
{
    for (int i = ps->n_scopes - 1; s && i >= 0; i--)
        if (find_in(&ps->scopes[i], s->name, s->name_len) == s)
            return true;
    return false;
}

/* Doubles the bucket count of 'sc' when it gets crowded. */
static void grow(pp_state *ps, pp_scope *sc)
{
    unsigned n = sc->n_buckets * 2;
    pp_sym **b = iris_calloc(n, sizeof *b);
    if (!b)
        pp_nomem(ps);
    for (unsigned i = 0; i < sc->n_buckets; i++) {
        pp_sym *s = sc->buckets[i];
        while (s) {
            pp_sym *next = s->next;
            unsigned h = hash_name(s->name, s->name_len) & (n - 1);
            s->next = b[h];
            b[h] = s;
            s = next;
        }
    }
    iris_free(sc->buckets);
    sc->buckets = b;
    sc->n_buckets = n;
}

pp_sym *sym_define(pp_state *ps, int scope, const char *name, size_t len)
{
    pp_scope *sc = &ps->scopes[scope];
    pp_sym *s = find_in(sc, name, len);
    if (s)
        return s;
    if (sc->n_syms >= sc->n_buckets)
        grow(ps, sc);
    s = ps->free_syms;
    if (s)
        ps->free_syms = s->next;
    else
        s = pp_salloc(ps, sizeof *s);
    memset(s, 0, sizeof *s);
    if (len < sizeof s->name_buf) {
        memcpy(s->name_buf, name, len);
        s->name_buf[len] = 0;
        s->name = s->name_buf;
    } else {
        s->name = pp_strdup(ps, name, len);
    }
    s->name_len = len;
    unsigned h = hash_name(name, len) & (sc->n_buckets - 1);
    s->next = sc->buckets[h];
    sc->buckets[h] = s;
    sc->n_syms++;
    return s;
}

bool sym_undef(pp_state *ps, const char *name, size_t len)
{
    for (int i = ps->n_scopes - 1; i >= 0; i--) {
        pp_scope *sc = &ps->scopes[i];
        pp_sym **pp = &sc->buckets[hash_name(name, len) & (sc->n_buckets - 1)];
        for (; *pp; pp = &(*pp)->next) {
            pp_sym *s = *pp;
            if (s->name_len == len && memcmp(s->name, name, len) == 0) {
                *pp = s->next;
                s->next = ps->free_syms;
                ps->free_syms = s;
                sc->n_syms--;
                return true;
            }
        }
    }
    return false;
}
