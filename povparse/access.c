/* SPDX-License-Identifier: MIT */
/*
** access.c: which files a scene may read and write (issue 7).
**
** With read_policy IRIS_IO_RESTRICTED (the default) a scene reads only
** below its own directory and the library paths: the +L paths and
** POV-Ray's installed include directory. Writes (#fopen write/append)
** need allow_writes and then stay below the scene's directory. Every
** path is resolved with realpath() before the check, so neither ".."
** nor a symbolic link can lead out of an allowed tree; a path that
** cannot be resolved is refused. The allowed roots are resolved once,
** on the first check.
*/
#include "config.h"

#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "pp.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

#define MAX_ROOTS 64

/* Adds the resolved form of 'dir' to the roots; unresolvable ones (a +L
** path that does not exist) allow nothing and are left out. */
static void add_root(pp_state *ps, const char *dir)
{
    char buf[PATH_MAX];
    if (ps->n_io_roots >= MAX_ROOTS || !dir || !dir[0] ||
        !realpath(dir, buf))
        return;
    ps->io_roots[ps->n_io_roots++] = pp_strdup(ps, buf, strlen(buf));
}

static void init_roots(pp_state *ps)
{
    if (ps->io_roots)
        return;
    ps->io_roots = pp_alloc(ps, MAX_ROOTS * sizeof *ps->io_roots);
    /* Root 0 is the scene's directory: the only one writes may use. */
    add_root(ps, ps->n_files > 0 ? ps->files[0].dir : ".");
    if (ps->n_io_roots == 0)
        ps->io_roots[ps->n_io_roots++] = "\x01"; /* matches no path */
    for (int i = 0; i < ps->opt.n_include_paths; i++)
        add_root(ps, ps->opt.include_paths[i]);
#ifdef POVRAY_INCLUDE_DIR
    if (!ps->opt.no_system_includes)
        add_root(ps, POVRAY_INCLUDE_DIR);
#endif
}

/* True when the resolved path 'real' lies below root 'root'. */
static bool below(const char *real, const char *root)
{
    size_t n = strlen(root);
    if (n == 1 && root[0] == '/')
        return real[0] == '/';
    return strncmp(real, root, n) == 0 && (real[n] == '/' || real[n] == 0);
}

static bool below_any(pp_state *ps, const char *real, int n_roots)
{
    for (int i = 0; i < n_roots; i++)
        if (below(real, ps->io_roots[i]))
            return true;
    return false;
}

/* The directory part of 'path' resolved into 'out'; false if it fails. */
static bool resolve_dir(const char *path, char *out)
{
    char dir[PATH_MAX];
    const char *slash = strrchr(path, '/');
    if (!slash) {
        strcpy(dir, ".");
    } else {
        size_t n = (size_t)(slash - path);
        if (n == 0)
            n = 1; /* "/name" */
        if (n >= sizeof dir)
            return false;
        memcpy(dir, path, n);
        dir[n] = 0;
    }
    return realpath(dir, out) != NULL;
}

bool pp_read_allowed(pp_state *ps, const char *path)
{
    if (ps->opt.read_policy == IRIS_IO_UNRESTRICTED)
        return true;
    init_roots(ps);
    char real[PATH_MAX];
    if (!realpath(path, real))
        return false;
    if (below_any(ps, real, ps->n_io_roots))
        return true;
    /* A symbolic link that a library directory holds was put there by
    ** whoever installed the library (Debian links timrom.ttf from the
    ** include directory to the fonts), not by the scene: it is trusted.
    ** Links in the scene's own tree are not. */
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    if (!strcmp(base, "..") || !strcmp(base, "."))
        return false;
    char rdir[PATH_MAX];
    for (int i = 1; i < ps->n_io_roots; i++)
        if (resolve_dir(path, rdir) && below(rdir, ps->io_roots[i]) &&
            !below(rdir, ps->io_roots[0]))
            return true;
    return false;
}

void pp_check_read(pp_state *ps, const pp_token *at, const char *path)
{
    struct stat st;
    /* A file that does not exist is not read: the caller's "cannot
    ** open" says more than a refusal would */
    if (lstat(path, &st) != 0 && errno == ENOENT)
        return;
    if (pp_read_allowed(ps, path))
        return;
    pp_error(ps, at, "reading \"%s\" is refused: it is outside the scene's "
             "directory and the library paths (add its directory with "
             "+L<dir>, or allow any file with --unrestricted-io)", path);
}

/* Resolves a file that may not exist yet: its directory must resolve and
** the name itself must be no symbolic link (it could point anywhere). */
static bool resolve_for_write(const char *path, char *real)
{
    struct stat st;
    if (realpath(path, real))
        return true;
    if (lstat(path, &st) == 0)
        return false; /* exists but does not resolve: a dangling link */
    const char *slash = strrchr(path, '/');
    const char *base = slash ? slash + 1 : path;
    if (!base[0] || !strcmp(base, ".") || !strcmp(base, ".."))
        return false;
    char rdir[PATH_MAX];
    if (!resolve_dir(path, rdir))
        return false;
    int n = snprintf(real, PATH_MAX, "%s/%s",
                     strcmp(rdir, "/") ? rdir : "", base);
    return n > 0 && n < PATH_MAX;
}

bool pp_write_allowed(pp_state *ps, const char *path)
{
    if (!ps->opt.allow_writes)
        return false;
    init_roots(ps);
    char real[PATH_MAX];
    if (!resolve_for_write(path, real))
        return false;
    return below_any(ps, real, 1);
}
