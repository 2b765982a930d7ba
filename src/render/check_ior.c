/* SPDX-License-Identifier: MIT */
/*
** check_ior.c: see check_ior.h. The glass catalogue lives in
** src/spectrum alone (generated from data/), so only the render build
** can tell an unknown glass name: the parser stores the name as written.
** A shared interior is reported once (a small list of those seen).
*/
#include "config.h"

#include "render/check_ior.h"

#include <string.h>

#include "spectrum/ior.h"

#define SEEN_MAX 64

struct check {
    const iris_scene *scene;
    FILE *log;
    const iris_ior_spec *seen[SEEN_MAX];
    int n_seen;
    char *err;
    size_t errlen;
    bool failed;
};

static void report(struct check *c, const iris_ior_spec *s, const char *sev,
                   const char *msg)
{
    const char *file = s->loc.file < (uint32_t)c->scene->n_files
                           ? c->scene->files[s->loc.file] : "";
    char line[1200];
    if (file && file[0])
        snprintf(line, sizeof line, "%s:%u:%u: %s: %s", file,
                 (unsigned)s->loc.line, (unsigned)s->loc.col, sev, msg);
    else
        snprintf(line, sizeof line, "%s: %s", sev, msg);
    if (c->log)
        fprintf(c->log, "%s\n", line);
    if (sev[0] == 'e') {
        /* the located message went to the log; 'err' sums it up */
        if (c->err && c->errlen)
            snprintf(c->err, c->errlen, "%s", c->log ? "the scene names "
                     "an unknown glass (see the error above)" : line);
        c->failed = true;
    }
}

static void walk(struct check *c, const iris_object *o, int depth)
{
    if (!o || depth > 64 || c->failed)
        return;
    const iris_interior *in = o->interior;
    if (in && in->spectral_ior) {
        bool seen = false;
        for (int i = 0; i < c->n_seen && !seen; i++)
            seen = c->seen[i] == in->spectral_ior;
        if (!seen) {
            if (c->n_seen < SEEN_MAX)
                c->seen[c->n_seen++] = in->spectral_ior;
            char msg[1024];
            enum ior_verdict v = ior_check(in, msg, sizeof msg);
            if (v != IOR_FINE)
                report(c, in->spectral_ior,
                       v == IOR_ERROR ? "error" : "warning", msg);
        }
    }
    if (o->kind >= IRIS_OBJ_UNION && o->kind <= IRIS_OBJ_LIGHT_GROUP)
        for (int i = 0; i < o->u.csg.n_children; i++)
            walk(c, o->u.csg.children[i], depth + 1);
}

enum iris_status check_ior(const iris_scene *scene, FILE *log, char *err,
                           size_t errlen)
{
    struct check c;
    memset(&c, 0, sizeof c);
    c.scene = scene;
    c.log = log;
    c.err = err;
    c.errlen = errlen;
    for (int i = 0; scene && i < scene->n_objects && !c.failed; i++)
        walk(&c, scene->objects[i], 0);
    return c.failed ? IRIS_EINVAL : IRIS_OK;
}
