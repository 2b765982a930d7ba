/* SPDX-License-Identifier: MIT */
/*
** memfile.c: the files a scene writes while writes are refused.
**
** Scenes write data and read it back in the same parse: a loop #writes
** points and a later #while (defined(F)) #read loop builds objects from
** them, or a macro writes a mesh to an include file that the scene then
** #includes. POV-Ray writes to disk by default; iris refuses writes
** unless --allow-writes is given (docs/numerics.md), and a refused write
** used to lose the data, so the read that follows failed. Here the text
** is kept in memory under the name #fopen gave it, and #fopen read,
** #include and file_exists() look there first, so such a scene parses as
** in POV-Ray and nothing reaches the disk.
*/
#include "config.h"
#include <string.h>
#include "pp.h"

/* 'path' without "./" segments and repeated '/': the same file named
** "./a.txt" by one directive and "a.txt" relative to "." by another. */
static const char *normalise(pp_state *ps, const char *path)
{
    size_t n = strlen(path);
    char *out = pp_salloc(ps, n + 1);
    size_t o = 0;
    const char *p = path;
    if (*p == '/')
        out[o++] = *p++;
    while (*p) {
        const char *e = strchr(p, '/');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len > 0 && !(len == 1 && p[0] == '.')) {
            if (o > 0 && out[o - 1] != '/')
                out[o++] = '/';
            memcpy(out + o, p, len);
            o += len;
        }
        p += len;
        if (*p == '/')
            p++;
    }
    out[o] = 0;
    return out;
}

pp_memfile *pp_memfile_find(pp_state *ps, const char *path)
{
    const char *key = normalise(ps, path);
    for (pp_memfile *m = ps->memfiles; m; m = m->next)
        if (!strcmp(m->path, key))
            return m;
    return NULL;
}

/* #fopen ... write starts the file empty; append keeps what this parse
** wrote to it before (a file on disk is not read: it may be stale). */
pp_memfile *pp_memfile_open(pp_state *ps, const char *path, bool append)
{
    pp_memfile *m = pp_memfile_find(ps, path);
    if (!m) {
        m = pp_salloc(ps, sizeof *m);
        memset(m, 0, sizeof *m);
        m->path = normalise(ps, path);
        m->next = ps->memfiles;
        ps->memfiles = m;
    }
    if (!append || !m->buf) {
        m->cap = 256;
        m->buf = pp_salloc(ps, m->cap);
        m->len = 0;
        m->buf[0] = 0;
    }
    return m;
}

void pp_memfile_write(pp_state *ps, pp_memfile *m, const char *s, size_t n)
{
    if (m->len + n + 1 > m->cap) {
        /* The scratch arena frees nothing before the end: doubling keeps
        ** the old copies below the size of the final one. */
        size_t cap = m->cap * 2;
        while (cap < m->len + n + 1)
            cap *= 2;
        char *buf = pp_salloc(ps, cap);
        memcpy(buf, m->buf, m->len);
        m->buf = buf;
        m->cap = cap;
    }
    memcpy(m->buf + m->len, s, n);
    m->len += n;
    m->buf[m->len] = 0;
}
