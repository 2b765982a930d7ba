/* SPDX-License-Identifier: MIT */
/*
** mat.c: textures: pigment, normal, finish, texture (layers and maps),
** interior with the iris IOR extensions, material, patterns and their
** modifiers, colour/pigment/normal/texture/slope maps, transforms.
**
** Nodes read from identifiers are shared and never changed: a transform
** applied to a pigment, normal or texture makes a copy with the transform
** composed into every pattern it holds (pp_tex_transform and friends),
** which is how POV-Ray's Transform_Textures behaves.
*/
#include "config.h"

#include <math.h>
#include <string.h>
#include <sys/stat.h>

#include "math/vec3.h"
#include "pp.h"

/* ---- transforms -------------------------------------------------- */

bool pp_transform_item(pp_state *ps, iris_transform *out)
{
    pp_token at = ps->tok;
    switch (at.kind) {
    case T_TRANSLATE:
        xf_translate(out, pp_vector(ps));
        return true;
    case T_ROTATE:
        xf_rotate(out, pp_vector(ps));
        return true;
    case T_SCALE: {
        iris_vec3 s = pp_vector(ps);
        if (s.x == 0 || s.y == 0 || s.z == 0)
            pp_warning(ps, &at, "illegal scale by 0, changed to 1 for that "
                       "axis (as POV-Ray does)");
        xf_scale(out, s);
        return true;
    }
    case T_MATRIX: {
        pp_expect(ps, T_LT, "'<' and 12 matrix values");
        double v[12];
        for (int i = 0; i < 12; i++) {
            if (i)
                pp_expect(ps, T_COMMA, "',' (matrix takes 12 values)");
            bool iv = ps->in_vector;
            ps->in_vector = true;
            v[i] = pp_float(ps);
            ps->in_vector = iv;
        }
        pp_expect(ps, T_GT, "'>'");
        if (!xf_matrix(out, v))
            pp_error(ps, &at, "singular matrix");
        return true;
    }
    case T_TRANSFORM: {
        iris_transform *t = pp_transform_block(ps);
        *out = *t;
        return true;
    }
    default:
        return false;
    }
}

/* transform { [TRANSFORM_ID] [inverse] transforms... } or transform ID */
iris_transform *pp_transform_block(pp_state *ps)
{
    iris_transform *t = pp_alloc(ps, sizeof *t);
    xf_identity(t);
    pp_next(ps);
    if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_TRANSFORM) {
        *t = *ps->tok.val.u.xf;
        return t;
    }
    if (ps->tok.kind != T_LBRACE)
        pp_error(ps, &ps->tok, "expected '{' or a transform identifier");
    pp_token open = ps->tok;
    for (;;) {
        pp_next(ps);
        iris_transform x;
        if (ps->tok.kind == T_RBRACE)
            return t;
        if (ps->tok.kind == T_INVERSE) {
            xf_inverse(t, t);
            continue;
        }
        if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_TRANSFORM) {
            xf_compose(t, t, ps->tok.val.u.xf);
            continue;
        }
        if (!pp_transform_item(ps, &x)) {
            char buf[80];
            pp_error(ps, &ps->tok, "expected a transform in the transform "
                     "block opened at line %u, found %s",
                     (pp_loc(ps, &open)).line,
                     pp_tok_name(ps, &ps->tok, buf, sizeof buf));
        }
        xf_compose(t, t, &x);
    }
}

/* ---- patterns ---------------------------------------------------- */

void pp_pattern_init(iris_pattern *p)
{
    memset(p, 0, sizeof *p);
    xf_identity(&p->transform);
    p->frequency = 1;
    p->brick_size = v3(8, 3, 4.5);
    p->mortar = 0.5;
    p->noise_generator = 0; /* 0 = the global setting */
    p->iterations = 0;
}

/* Inserts a new warp at index 'at' of the pattern's list. */
static iris_warp *insert_warp(pp_state *ps, iris_pattern *p, int at, int kind)
{
    iris_warp *w = pp_alloc(ps, (size_t)(p->n_warps + 1) * sizeof *w);
    if (at)
        memcpy(w, p->warps, (size_t)at * sizeof *w);
    if (p->n_warps > at)
        memcpy(w + at + 1, p->warps + at,
               (size_t)(p->n_warps - at) * sizeof *w);
    p->warps = w;
    p->n_warps++;
    iris_warp *n = &w[at];
    memset(n, 0, sizeof *n);
    n->kind = kind;
    n->octaves = 6;
    n->omega = 0.5;
    n->lambda = 2;
    xf_identity(&n->transform);
    return n;
}

static iris_warp *add_warp(pp_state *ps, iris_pattern *p, int kind)
{
    return insert_warp(ps, p, p->n_warps, kind);
}

/*
** The order of transforms and warps. POV-Ray keeps one list per pattern:
** transforms and warp{} blocks are appended in the order written (runs
** of transforms merge into one), the classic turbulence sits at the
** front, and a point goes through the list from the last entry to the
** first, so the last-written applies first and the classic turbulence
** last (pattern.cpp Transform_Tpattern, warp.cpp Warp_EPoint).
**
** scene.h's form (src/material/pattern.c pat_space): the point goes
** through pattern.transform first, then warps[n-1] .. warps[0], except
** that a TURBULENCE entry at the very end is the classic turbulence and
** goes last. So the parser keeps:
**   - pattern.transform = the transforms written after the last warp{};
**   - warps = the written order, each earlier run of transforms moved
**     into an IRIS_WARP_TRANSFORM entry when a warp{} follows it;
**   - a classic turbulence, if any, as the last entry, and never a warp
**     {turbulence} last (an identity TRANSFORM entry follows it), so
**     that the renderer cannot take one for the other.
*/
static bool has_classic(const iris_pattern *p)
{
    return p->n_warps && p->warps[p->n_warps - 1].kind == IRIS_WARP_TURBULENCE;
}

/* The classic turbulence of a pattern: the last entry, or a new one. */
static iris_warp *classic_turb(pp_state *ps, iris_pattern *p)
{
    if (has_classic(p))
        return &p->warps[p->n_warps - 1];
    return add_warp(ps, p, IRIS_WARP_TURBULENCE);
}

/* An entry of a warp{} block: after the written ones, before the
** classic turbulence. The transforms written so far move into the list
** first, since they apply after this warp (see above). */
static iris_warp *block_warp(pp_state *ps, iris_pattern *p, int kind)
{
    int at = has_classic(p) ? p->n_warps - 1 : p->n_warps;
    if (p->has_transform) {
        iris_warp *t = insert_warp(ps, p, at++, IRIS_WARP_TRANSFORM);
        t->transform = p->transform;
        xf_identity(&p->transform);
        p->has_transform = false;
    }
    return insert_warp(ps, p, at, kind);
}

/* After a warp{} block: a block turbulence must not be the last entry
** ('had_classic': the pattern had a classic turbulence before the
** block, which then stays last). */
static void guard_block_turb(pp_state *ps, iris_pattern *p, bool had_classic)
{
    if (!had_classic && has_classic(p))
        add_warp(ps, p, IRIS_WARP_TRANSFORM);
}

/* POV-Ray's Check_BH_Parameters, after a black hole's repeat or
** turbulence: on each repeated axis the centre is at least the radius
** from the block's edge and the block holds the hole and its jitter. */
static void check_black_hole(pp_state *ps, const pp_token *at, iris_warp *w)
{
    double *c = &w->centre.x, *r = &w->repeat.x;
    const double *u = &w->turbulence.x;
    if (r[0] == 0 && r[1] == 0 && r[2] == 0)
        return;
    for (int i = 0; i < 3; i++) {
        if (!(r[i] > 0))
            continue;
        if (c[i] < w->radius)
            c[i] = w->radius;
        if (r[i] < c[i] + w->radius + u[i]) {
            r[i] = c[i] + w->radius + u[i];
            pp_warning(ps, at, "black hole repeat vector %c too small; "
                       "increased to %g", "XYZ"[i], r[i]);
        }
    }
}

/* warp { turbulence | repeat | black_hole | planar | spherical | ... } */
static void warp_block(pp_state *ps, iris_pattern *p)
{
    pp_expect(ps, T_LBRACE, "'{'");
    iris_warp *w = NULL;
    bool had_classic = has_classic(p);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            guard_block_turb(ps, p, had_classic);
            return;
        case T_TURBULENCE:
            /* after black_hole: the jitter of its repeated centres */
            if (w && w->kind == IRIS_WARP_BLACK_HOLE) {
                w->turbulence = pp_vector(ps);
                check_black_hole(ps, &at, w);
                break;
            }
            w = block_warp(ps, p, IRIS_WARP_TURBULENCE);
            w->turbulence = pp_vector(ps);
            break;
        case T_REPEAT:
            /* after black_hole: the spacing of its copies */
            if (w && w->kind == IRIS_WARP_BLACK_HOLE) {
                w->repeat = pp_vector(ps);
                check_black_hole(ps, &at, w);
                break;
            }
            w = block_warp(ps, p, IRIS_WARP_REPEAT);
            w->repeat = pp_vector(ps);
            break;
        case T_BLACK_HOLE:
            w = block_warp(ps, p, IRIS_WARP_BLACK_HOLE);
            w->centre = pp_vector(ps);
            pp_accept(ps, T_COMMA); /* optional, as everywhere in POV-Ray */
            w->radius = pp_float(ps);
            w->strength = 1;
            w->falloff = 2;
            break;
        case T_PLANAR: case T_SPHERICAL: case T_CYLINDRICAL: case T_TOROIDAL:
            w = block_warp(ps, p, at.kind == T_PLANAR ? IRIS_WARP_PLANAR :
                                at.kind == T_SPHERICAL ? IRIS_WARP_SPHERICAL :
                                at.kind == T_CYLINDRICAL ? IRIS_WARP_CYLINDRICAL
                                                         : IRIS_WARP_TOROIDAL);
            w->orientation = v3(0, 0, 1);
            w->dist_exp = 0;
            if (at.kind == T_PLANAR) {
                pp_next(ps);
                pp_unget(ps);
                if (pp_starts_expr(ps)) {
                    w->orientation = pp_vector(ps);
                    pp_accept(ps, T_COMMA); /* optional: 'planar z 0.5' */
                    w->offset.x = pp_float(ps);
                }
            }
            break;
        /* modifiers of the warp just opened ('w' is NULL before one) */
        case T_OCTAVES: { int v = pp_int(ps); if (w) w->octaves = v; break; }
        case T_OMEGA: { double v = pp_float(ps); if (w) w->omega = v; break; }
        case T_LAMBDA: { double v = pp_float(ps); if (w) w->lambda = v; break; }
        case T_OFFSET: { vec3 v = pp_vector(ps); if (w) w->offset = v; break; }
        case T_FLIP: { vec3 v = pp_vector(ps); if (w) w->flip = v; break; }
        case T_STRENGTH: {
            double v = pp_float(ps);
            if (w)
                w->strength = v;
            break;
        }
        case T_FALLOFF: {
            double v = pp_float(ps);
            if (w)
                w->falloff = v;
            break;
        }
        case T_INVERSE: if (w) w->inverse = 1; break;
        case T_ORIENTATION: {
            vec3 v = pp_vector(ps);
            if (w)
                w->orientation = v;
            break;
        }
        case T_DIST_EXP: {
            double v = pp_float(ps);
            if (w)
                w->dist_exp = v;
            break;
        }
        case T_MAJOR_RADIUS: {
            double v = pp_float(ps);
            if (w)
                w->major_radius = v;
            break;
        }
        case T_TURB_DEPTH: case T_TYPE: pp_float(ps); break;
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                w = block_warp(ps, p, IRIS_WARP_TRANSFORM);
                w->transform = x;
                break;
            }
            pp_unexpected(ps, &at, "warp");
        }
        }
    }
}

/* Looks 'name' up relative to the including file, the scene and the
** include path; NULL when it is nowhere. */
static const char *find_in_path(pp_state *ps, const pp_token *at,
                                const char *name)
{
    char buf[4096];
    struct stat st;
    if (name[0] == '/') {
        if (stat(name, &st) != 0)
            return NULL;
        pp_check_read(ps, at, name);
        return pp_strdup(ps, name, strlen(name));
    }
    const char *dirs[66];
    int nd = 0;
    dirs[nd++] = ps->files[at->file].dir;
    dirs[nd++] = ps->files[0].dir;
    for (int i = 0; i < ps->opt.n_include_paths && nd < 64; i++)
        dirs[nd++] = ps->opt.include_paths[i];
#ifdef POVRAY_INCLUDE_DIR
    if (!ps->opt.no_system_includes && POVRAY_INCLUDE_DIR[0])
        dirs[nd++] = POVRAY_INCLUDE_DIR;
#endif
    for (int i = 0; i < nd; i++) {
        int n = snprintf(buf, sizeof buf, "%s/%s", dirs[i], name);
        if (n > 0 && (size_t)n < sizeof buf && stat(buf, &st) == 0) {
            pp_check_read(ps, at, buf);
            return pp_strdup(ps, buf, (size_t)n);
        }
    }
    return NULL;
}

/* The name as written, when it is found nowhere: it is opened from the
** working directory later, so under the restricted policy it must not
** lead elsewhere either. */
static const char *not_found(pp_state *ps, const pp_token *at,
                             const char *name)
{
    struct stat st;
    if (stat(name, &st) == 0)
        pp_check_read(ps, at, name);
    pp_warning(ps, at, "file \"%s\" not found", name);
    return pp_strdup(ps, name, strlen(name));
}

/* Resolves an image or font file as POV-Ray does: relative to the
** including file, the scene and the include path. Keeps the name as
** written (with a warning) when it cannot be found. */
const char *pp_find_file(pp_state *ps, const pp_token *at, const char *name)
{
    const char *found = find_in_path(ps, at, name);
    return found ? found : not_found(ps, at, name);
}

/* The same, trying the file type's extensions as POV-Ray's FindFile
** (backendscenedata.cpp) does: a name that already ends in one of them
** is tried as written first, else last, after name+ext for each. */
/* Searches for 'name' and name+ext for each of the NULL-ended 'exts' in
** POV-Ray's order (FindFile, backendscenedata.cpp): a name that already
** ends in one of them is tried as written first, else last. NULL when
** the file is found nowhere. */
static const char *search_ext(pp_state *ps, const pp_token *at,
                              const char *name, const char *const *exts)
{
    size_t len = strlen(name);
    bool exact_first = false;
    for (int i = 0; exts && exts[i]; i++) {
        size_t el = strlen(exts[i]);
        if (len >= el && strcmp(name + len - el, exts[i]) == 0)
            exact_first = true;
    }
    const char *found = exact_first ? find_in_path(ps, at, name) : NULL;
    for (int i = 0; exts && exts[i] && !found; i++) {
        char *with = pp_salloc(ps, len + strlen(exts[i]) + 1);
        memcpy(with, name, len);
        strcpy(with + len, exts[i]);
        found = find_in_path(ps, at, with);
    }
    if (!found && !exact_first)
        found = find_in_path(ps, at, name);
    return found;
}

const char *pp_require_file(pp_state *ps, const pp_token *at,
                            const char *name, const char *const *exts,
                            const char *what)
{
    const char *found = search_ext(ps, at, name, exts);
    if (!found)
        pp_error(ps, at, "cannot find %s \"%s\" (looked beside the scene "
                 "and in the library paths)", what, name);
    return found;
}

static bool is_image_type(int k)
{
    return k == T_GIF || k == T_TGA || k == T_IFF || k == T_PPM ||
           k == T_PGM || k == T_PNG || k == T_JPEG || k == T_TIFF ||
           k == T_SYS || k == T_EXR || k == T_HDR || k == T_BMP;
}

/* Reads [type] "file" of an image_map/bump_map/height_field. */
/* function W, H { body }: the image POV-Ray makes of a function
** (Make_Pattern_Image): pixel (j, i) of row i from the top is the
** function at (j / (W - 1), i / (H - 1), 0), a float function as grey, a
** pigment function as its colour with alpha 1 - transmit, each stored in
** 16 bits (0..1; the rounding is below 1e-5 and not copied). The
** function token is current. */
static void function_image(pp_state *ps, iris_image_ref *img)
{
    pp_token at = ps->tok;
    double fw = pp_float(ps);
    pp_accept(ps, T_COMMA);
    double fh = pp_float(ps);
    int w = (int)(fw + 0.5), h = (int)(fh + 0.5);
    if (!(fw + 0.5 >= 2) || !(fh + 0.5 >= 2) || fw > 16384 || fh > 16384)
        pp_error(ps, &at, "a function image needs 2 to 16384 pixels a side, "
                 "not %g x %g", fw, fh);
    iris_fn *fn = pp_function(ps);
    float *px = pp_alloc(ps, (size_t)w * (size_t)h * 4 * sizeof *px);
    for (int i = 0; i < h; i++) {
        for (int j = 0; j < w; j++) {
            double p[3] = { (double)j / (w - 1), (double)i / (h - 1), 0 };
            float *o = px + 4 * ((size_t)i * (size_t)w + (size_t)j);
            double c[5] = { 0, 0, 0, 0, 0 };
            if (fn->n_results == 5 && fn->n_code == 1 &&
                fn->code[0].op == IRIS_FN_PATTERN && fn->code[0].pigment) {
                iris_fn_insn one = fn->code[0];
                iris_fn f1 = *fn;
                f1.code = &one;
                f1.n_results = 1;
                for (int k = 0; k < 5; k++) {
                    one.arg = k;
                    c[k] = iris_fn_eval(&f1, p, 3);
                }
            } else {
                c[0] = c[1] = c[2] = iris_fn_eval(fn, p, 3);
            }
            for (int k = 0; k < 3; k++)
                o[k] = (float)fmin(fmax(c[k], 0.0), 1.0);
            o[3] = (float)fmin(fmax(1.0 - c[4], 0.0), 1.0);
        }
    }
    char name[64];
    snprintf(name, sizeof name, "function image %dx%d #%d", w, h,
             ps->n_function_images++);
    img->path = pp_strdup(ps, name, strlen(name));
    img->pixels = px;
    img->pixels_w = w;
    img->pixels_h = h;
}

const char *const *pp_image_exts(int kind)
{
    /* POV-Ray 3.7's gPOV_File_Extensions (fileutil.cpp) */
#define EXTS(n, ...) static const char *const n[] = { __VA_ARGS__, NULL }
    EXTS(tga, ".tga", ".TGA");
    EXTS(png, ".png", ".PNG");
    EXTS(ppm, ".ppm", ".PPM");
    EXTS(pgm, ".pgm", ".PGM");
    EXTS(gif, ".gif", ".GIF");
    EXTS(iff, ".iff", ".IFF");
    EXTS(jpeg, ".jpg", ".JPG", ".jpeg", ".JPEG");
    EXTS(tiff, ".tif", ".TIF", ".tiff", ".TIFF");
    EXTS(bmp, ".bmp", ".BMP");
    EXTS(exr, ".exr", ".EXR");
    EXTS(hdr, ".hdr", ".HDR");
#undef EXTS
    switch (kind) {
    case T_TGA: return tga;
    case T_PNG: return png;
    case T_PPM: return ppm;
    case T_PGM: return pgm;
    case T_GIF: return gif;
    case T_IFF: return iff;
    case T_JPEG: return jpeg;
    case T_TIFF: return tiff;
    case T_BMP: return bmp;
    case T_EXR: return exr;
    case T_HDR: return hdr;
    default: return NULL;
    }
}

static iris_image_ref *image_file(pp_state *ps)
{
    iris_image_ref *img = pp_alloc(ps, sizeof *img);
    img->as_stored = pp_image_as_stored(ps);
    pp_next(ps);
    /* the type's extensions are tried too: 'png "linux"' reads
    ** linux.png, as POV-Ray's FindFile does */
    const char *const *exts = pp_image_exts(ps->tok.kind);
    if (is_image_type(ps->tok.kind))
        pp_next(ps);
    if (ps->tok.kind == T_FUNCTION) {
        function_image(ps, img);
        return img;
    }
    pp_unget(ps);
    pp_token at = ps->tok;
    const char *name = pp_string(ps);
    img->path = pp_require_file(ps, &at, name, exts, "image file");
    return img;
}

/* image_map { [type] "file" [map_type n] [once] [interpolate n]
**             [filter all f|n f] [transmit all f|n f] [use_alpha] ... } */
static iris_image_ref *image_block(pp_state *ps, double *bump_size)
{
    pp_expect(ps, T_LBRACE, "'{'");
    iris_image_ref *img = image_file(ps);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE: return img;
        case T_MAP_TYPE: img->map_type = pp_int(ps); break;
        case T_ONCE: img->once = true; break;
        case T_INTERPOLATE: img->interpolate = pp_int(ps); break;
        case T_USE_ALPHA: img->use_alpha = true; break;
        case T_USE_COLOR: img->use_index = false; break;
        case T_USE_INDEX: img->use_index = true; break;
        case T_GAMMA:
            /* 'gamma srgb' (POV-Ray's Parse_Gamma): the sRGB curve, which
            ** is how iris_image_read decodes a file without its own
            ** gamma already (0: the file's own) */
            img->gamma = pp_accept(ps, T_SRGB) ? 0 : pp_float(ps);
            break;
        case T_PREMULTIPLIED: pp_bool_opt(ps); break;
        case T_BUMP_SIZE: {
            double b = pp_float(ps);
            if (bump_size)
                *bump_size = b;
            break;
        }
        case T_FILTER: case T_TRANSMIT: {
            double *all = at.kind == T_FILTER ? &img->filter_all
                                              : &img->transmit_all;
            if (pp_accept(ps, T_ALL)) {
                *all = pp_float(ps);
            } else {
                /* POV-Ray rounds the register as (int)(N + 0.01) */
                double reg = pp_float(ps);
                pp_accept(ps, T_COMMA);
                double v = pp_float(ps);
                if (!(reg + 0.01 >= 0.0 && reg + 0.01 < 256.0))
                    pp_error(ps, &at, "%s colour register value out of "
                             "range", at.kind == T_FILTER ? "filter"
                                                           : "transmit");
                struct iris_palette_ft *a =
                    pp_alloc(ps, (size_t)(img->n_palette_ft + 1) * sizeof *a);
                if (img->n_palette_ft)
                    memcpy(a, img->palette_ft,
                           (size_t)img->n_palette_ft * sizeof *a);
                a[img->n_palette_ft].index = (int)(reg + 0.01);
                a[img->n_palette_ft].which = at.kind == T_FILTER ? 0 : 1;
                a[img->n_palette_ft].value = v;
                img->palette_ft = a;
                img->n_palette_ft++;
            }
            break;
        }
        default: {
            pp_unexpected(ps, &at, "image block");
        }
        }
    }
}

/* A .df3 file's 6-byte header against its length: nx*ny*nz voxels of 1,
** 2 or 4 bytes (POV-Ray's Read_Density_File); a located error else. */
static void check_df3(pp_state *ps, const pp_token *at, const char *path)
{
    FILE *f = fopen(path, "rb");
    unsigned char h[6];
    if (!f)
        pp_error(ps, at, "cannot read media density file \"%s\"", path);
    size_t got = fread(h, 1, 6, f);
    long end = fseek(f, 0, SEEK_END) == 0 ? ftell(f) : -1;
    fclose(f);
    if (got != 6 || end < 6)
        pp_error(ps, at, "density file \"%s\" is truncated (no 6-byte "
                 "header)", path);
    long long n = (long long)(h[0] << 8 | h[1]) * (h[2] << 8 | h[3]) *
                  (h[4] << 8 | h[5]);
    long long len = end - 6;
    if (!(n > 0 && (len == n || len == 2 * n || len == 4 * n)))
        pp_error(ps, at, "invalid density file size: \"%s\" holds %lld "
                 "bytes of voxels for %d x %d x %d (1, 2 or 4 bytes each)",
                 path, len, h[0] << 8 | h[1], h[2] << 8 | h[3],
                 h[4] << 8 | h[5]);
}

static bool list_pattern(int kind)
{
    return kind == IRIS_PAT_CHECKER || kind == IRIS_PAT_HEXAGON ||
           kind == IRIS_PAT_BRICK || kind == IRIS_PAT_OBJECT ||
           kind == IRIS_PAT_SQUARE || kind == IRIS_PAT_TRIANGULAR ||
           kind == IRIS_PAT_CUBIC;
}

/* mandel/julia colouring in params[] (src/material/pattern.c fractal):
** interior type, factor; exterior type, factor; [5] = 1: given. These
** are POV-Ray's defaults, interior 0, 1 and exterior 1, 1. */
static void fractal_defaults(iris_pattern *p)
{
    p->params[0] = 0;
    p->params[1] = 1;
    p->params[2] = 1;
    p->params[3] = 1;
    p->params[4] = 0;
    p->params[5] = 1;
}

/* ITERATIONS of mandel, julia and magnet: an int; above
** IRIS_PATTERN_MAX_ITERATIONS a located warning, as the renderer stops
** each evaluation there (POV-Ray has no limit; 'mandel 1e9' takes
** seconds per point). */
static int fractal_iterations(pp_state *ps)
{
    pp_next(ps);
    pp_token at = ps->tok;
    pp_unget(ps);
    int n = pp_int(ps);
    if (n > IRIS_PATTERN_MAX_ITERATIONS)
        pp_warning(ps, &at, "%d iterations: each point of the pattern "
                   "stops after %d (the colours keep %d)",
                   n, IRIS_PATTERN_MAX_ITERATIONS, n);
    return n;
}

/* [, [LO] [, [HI]]] after a slope or altitude vector (POV-Ray's
** Parse_Comma and Allow_Float: each number may be left out): into r[0],
** r[1], which stay 0 when absent. */
static void slope_range(pp_state *ps, double *r)
{
    for (int i = 0; i < 2; i++) {
        pp_accept(ps, T_COMMA); /* optional too: 'slope { y 0.2 0.8 }' */
        if (pp_float_follows(ps))
            r[i] = pp_float(ps);
    }
}

/* Parses a pattern keyword and its own parameters into 'p'; false when
** the current token is no pattern. */
static bool pattern_kind(pp_state *ps, iris_pattern *p)
{
    pp_token at = ps->tok;
    int k = at.kind;
    switch (k) {
    case T_AGATE: p->kind = IRIS_PAT_AGATE; p->params[0] = 1.0; break;
    case T_AVERAGE: p->kind = IRIS_PAT_AVERAGE; break;
    case T_BOXED: p->kind = IRIS_PAT_BOXED; break;
    case T_BOZO: p->kind = IRIS_PAT_BOZO; break;
    case T_BRICK: p->kind = IRIS_PAT_BRICK; break;
    case T_BUMPS: p->kind = IRIS_PAT_BUMPS; break;
    case T_CELLS: p->kind = IRIS_PAT_CELLS; break;
    case T_CHECKER: p->kind = IRIS_PAT_CHECKER; break;
    case T_CRACKLE:
        p->kind = IRIS_PAT_CRACKLE;
        p->params[0] = -1; p->params[1] = 1; p->params[2] = 0; /* form */
        p->params[3] = 2;  /* metric */
        p->params[4] = 0;  /* offset */
        p->params[5] = 0;  /* solid */
        break;
    case T_CYLINDRICAL: p->kind = IRIS_PAT_CYLINDRICAL; break;
    case T_DENTS: p->kind = IRIS_PAT_DENTS; break;
    case T_FACETS:
        /* POV-Ray's defaults: size 0.1, coords 0, metric 2 */
        p->kind = IRIS_PAT_FACETS;
        p->params[0] = 0.1;
        p->params[1] = 0;
        p->params[3] = 2;
        break;
    case T_GRADIENT:
        /* POV-Ray normalises the vector (Parse_Pattern's VNormalizeEq):
        ** gradient x+y has stripes 1/sqrt(2) apart, not 1/2 */
        p->kind = IRIS_PAT_GRADIENT;
        p->vector = pp_vector(ps);
        if (v3_len2(p->vector) > 0)
            p->vector = v3_norm(p->vector);
        break;
    case T_GRANITE: p->kind = IRIS_PAT_GRANITE; break;
    case T_HEXAGON: p->kind = IRIS_PAT_HEXAGON; break;
    case T_JULIA:
        p->kind = IRIS_PAT_JULIA;
        p->complex_c = pp_vector2(ps);
        pp_accept(ps, T_COMMA);
        p->iterations = fractal_iterations(ps);
        fractal_defaults(p);
        break;
    case T_LEOPARD: p->kind = IRIS_PAT_LEOPARD; break;
    case T_MAGNET: {
        /* magnet N mandel ITER | magnet N julia <u, v>, ITER: a mandel or
        ** julia pattern with the magnet type (1 or 2) in params[7] */
        pp_token mt = ps->tok;
        int type = pp_int(ps);
        if (type != 1 && type != 2)
            pp_error(ps, &mt, "magnet type must be 1 or 2");
        pp_next(ps);
        if (ps->tok.kind == T_JULIA) {
            p->kind = IRIS_PAT_JULIA;
            p->complex_c = pp_vector2(ps);
            pp_accept(ps, T_COMMA);
        } else if (ps->tok.kind == T_MANDEL) {
            p->kind = IRIS_PAT_MANDEL;
        } else {
            pp_error(ps, &ps->tok, "expected mandel or julia after magnet");
        }
        p->iterations = fractal_iterations(ps);
        fractal_defaults(p);
        p->params[7] = type;
        break;
    }
    case T_MANDEL:
        p->kind = IRIS_PAT_MANDEL;
        p->iterations = fractal_iterations(ps);
        fractal_defaults(p);
        break;
    case T_MARBLE: p->kind = IRIS_PAT_MARBLE; p->wave = IRIS_WAVE_TRIANGLE; break;
    case T_ONION: p->kind = IRIS_PAT_ONION; break;
    case T_PLANAR: p->kind = IRIS_PAT_PLANAR; break;
    case T_QUILTED: p->kind = IRIS_PAT_QUILTED; p->params[0] = 1; p->params[1] = 1; break;
    case T_RADIAL: p->kind = IRIS_PAT_RADIAL; break;
    case T_RIPPLES: p->kind = IRIS_PAT_RIPPLES; break;
    case T_SPHERICAL: p->kind = IRIS_PAT_SPHERICAL; break;
    /* POV-Ray's spirals default to triangle_wave (parstxtr.cpp sets
    ** kWaveType_Triangle with the arms); a later *_wave overrides it. */
    case T_SPIRAL1:
        p->kind = IRIS_PAT_SPIRAL1;
        p->params[0] = pp_float(ps);
        p->wave = IRIS_WAVE_TRIANGLE;
        break;
    case T_SPIRAL2:
        p->kind = IRIS_PAT_SPIRAL2;
        p->params[0] = pp_float(ps);
        p->wave = IRIS_WAVE_TRIANGLE;
        break;
    case T_SPOTTED: p->kind = IRIS_PAT_SPOTTED; break;
    case T_WAVES: p->kind = IRIS_PAT_WAVES; break;
    case T_WOOD: p->kind = IRIS_PAT_WOOD; p->wave = IRIS_WAVE_TRIANGLE; break;
    case T_WRINKLES: p->kind = IRIS_PAT_WRINKLES; break;
    case T_SQUARE: p->kind = IRIS_PAT_SQUARE; break;
    case T_TRIANGULAR: p->kind = IRIS_PAT_TRIANGULAR; break;
    case T_CUBIC: p->kind = IRIS_PAT_CUBIC; break;
    case T_TILING:
        p->kind = IRIS_PAT_TILING;
        p->params[0] = pp_float(ps);
        /* POV-Ray truncates, then refuses what is not one of its 27 */
        if (!(p->params[0] >= 1.0 && p->params[0] < 28.0))
            pp_error(ps, &at, "tiling number must be between 1 and 27");
        break;
    case T_PAVEMENT:
        /* src/material has no pavement: it evaluates to 0 (said once) */
        pp_warn_once(ps, &at, at.kind, "pavement");
        p->kind = IRIS_PAT_PAVEMENT;
        p->params[0] = 3;
        p->params[1] = 1;
        break;
    case T_SLOPE: {
        /* slope VECTOR
        ** | slope { [point_at] VECTOR [, [LO] [, [HI]]]
        **           [altitude VECTOR [, [LO] [, [HI]]]] }
        ** params: slope lo, hi (0..1), altitude lo, hi, the altitude
        ** vector (params[4..6]), point_at (params[7] != 0). */
        p->kind = IRIS_PAT_SLOPE;
        bool brace = pp_accept(ps, T_LBRACE);
        if (brace && pp_accept(ps, T_POINT_AT))
            p->params[7] = 1;
        p->vector = pp_vector(ps);
        if (brace) {
            slope_range(ps, &p->params[0]);
            if (pp_accept(ps, T_ALTITUDE)) {
                if (p->params[7] != 0)
                    pp_error(ps, &ps->tok, "'altitude' cannot be used with "
                             "'point_at' in a slope pattern");
                iris_vec3 a = pp_vector(ps);
                p->params[4] = a.x;
                p->params[5] = a.y;
                p->params[6] = a.z;
                slope_range(ps, &p->params[2]);
            }
            pp_expect(ps, T_RBRACE, "'}'");
        }
        if (p->params[7] == 0 && v3_len2(p->vector) == 0 &&
            p->params[4] == 0 && p->params[5] == 0 && p->params[6] == 0)
            pp_error(ps, &at, "slope: zero length for both slope and "
                     "altitude vectors");
        break;
    }
    case T_FUNCTION:
        p->kind = IRIS_PAT_FUNCTION;
        p->fn = pp_function(ps);
        break;
    case T_IDENT:
        if (at.val.kind != V_FUNCTION)
            return false;
        /* pattern given by a function identifier: 'pigment { F ... }'
        ** is not valid; only 'function { F(x,y,z) }' is */
        return false;
    case T_IMAGE_MAP:
        p->kind = IRIS_PAT_IMAGE_MAP;
        p->image = image_block(ps, NULL);
        break;
    case T_IMAGE_PATTERN:
        p->kind = IRIS_PAT_IMAGE_PATTERN;
        p->image = image_block(ps, NULL);
        break;
    case T_OBJECT: {
        p->kind = IRIS_PAT_OBJECT;
        pp_expect(ps, T_LBRACE, "'{'");
        pp_next(ps);
        if (ps->tok.kind == T_IDENT && ps->tok.val.kind == V_OBJECT) {
            p->object = ps->tok.val.u.obj;
        } else {
            pp_unget(ps);
            p->object = pp_object(ps);
            if (!p->object)
                pp_error(ps, &ps->tok, "expected an object");
        }
        /* transforms after the object move it (Parse_Bound_Clip):
        ** object { Logo scale 0.5 translate x } */
        for (;;) {
            pp_next(ps);
            iris_transform x;
            if (!pp_transform_item(ps, &x)) {
                pp_unget(ps);
                break;
            }
            iris_object *c = pp_object_copy(ps, p->object);
            pp_object_transform(ps, c, &x);
            p->object = c;
        }
        /* the list items and the '}' follow (see close_object_pattern) */
        break;
    }
    case T_PIGMENT_PATTERN: {
        /* A pigment used as a pattern: its grey level at the point
        ** (POV-Ray 3.7 PigmentPattern::EvaluateRaw), evaluated by src/fn
        ** as a function pattern. */
        iris_pigment *pg = pp_pigment(ps, NULL);
        p->kind = IRIS_PAT_FUNCTION;
        p->fn = pp_pigment_grey_fn(ps, pg);
        break;
    }
    case T_DENSITY_FILE: {
        /* density_file df3 "file" [interpolate n]: the voxels are read
        ** by the renderer (src/image/df3.c); here the file must exist and
        ** its length must fit its header, as POV-Ray reads it while
        ** parsing ("Cannot read media density file", "Invalid density
        ** file size"). */
        pp_next(ps);
        if (ps->tok.kind != T_DF3)
            pp_unexpected(ps, &ps->tok, "density_file (expected df3)");
        pp_next(ps);
        pp_token ft = ps->tok;
        pp_unget(ps);
        const char *name = pp_string(ps);
        iris_image_ref *ref = pp_alloc(ps, sizeof *ref);
        ref->path = pp_require_file(ps, &ft, name, NULL, "density file");
        check_df3(ps, &ft, ref->path);
        if (pp_accept(ps, T_INTERPOLATE))
            ref->interpolate = pp_int(ps);
        p->kind = IRIS_PAT_DENSITY_FILE;
        p->image = ref;
        break;
    }
    default:
        return false;
    }
    return true;
}

/* object { OBJ item, item }: the items sit inside the braces. */
static void close_object_pattern(pp_state *ps, const iris_pattern *p)
{
    if (p->kind == IRIS_PAT_OBJECT)
        pp_expect(ps, T_RBRACE, "'}' to close the object pattern");
}

/* Pattern modifiers common to pigments, normals and textures. */
static bool pattern_mod(pp_state *ps, iris_pattern *p)
{
    pp_token at = ps->tok;
    switch (at.kind) {
    case T_TURBULENCE: classic_turb(ps, p)->turbulence = pp_vector(ps); return true;
    case T_OCTAVES: classic_turb(ps, p)->octaves = pp_int(ps); return true;
    case T_OMEGA: classic_turb(ps, p)->omega = pp_float(ps); return true;
    case T_LAMBDA: classic_turb(ps, p)->lambda = pp_float(ps); return true;
    case T_WARP: warp_block(ps, p); return true;
    case T_FREQUENCY: p->frequency = pp_float(ps); return true;
    case T_INTERPOLATE:
        /* density_file's interpolation (POV-Ray accepts it as a pattern
        ** modifier) */
        if (p->kind != IRIS_PAT_DENSITY_FILE || !p->image)
            return false;
        p->image->interpolate = pp_int(ps);
        return true;
    case T_PHASE: p->phase = pp_float(ps); return true;
    case T_RAMP_WAVE: p->wave = IRIS_WAVE_RAMP; return true;
    case T_SINE_WAVE: p->wave = IRIS_WAVE_SINE; return true;
    case T_TRIANGLE_WAVE: p->wave = IRIS_WAVE_TRIANGLE; return true;
    case T_SCALLOP_WAVE: p->wave = IRIS_WAVE_SCALLOP; return true;
    case T_CUBIC_WAVE: p->wave = IRIS_WAVE_CUBIC; return true;
    case T_POLY_WAVE:
        p->wave = IRIS_WAVE_POLY;
        p->wave_exponent = 1;
        pp_next(ps);
        pp_unget(ps);
        if (pp_starts_expr(ps) && ps->tok.kind != T_LT)
            p->wave_exponent = pp_float(ps);
        return true;
    case T_NOISE_GENERATOR: p->noise_generator = pp_int(ps); return true;
    /* POV-Ray's Parse_Pattern takes it in any pattern; only a normal's
    ** (read before this) and a texture's have an effect */
    case T_NO_BUMP_SCALE: pp_bool_opt(ps); return true;
    case T_AGATE_TURB: p->params[0] = pp_float(ps); return true;
    case T_BRICK_SIZE: p->brick_size = pp_vector(ps); return true;
    case T_MORTAR: p->mortar = pp_float(ps); return true;
    case T_FORM: {
        iris_vec3 f = pp_vector(ps);
        if (p->kind == IRIS_PAT_PAVEMENT) {
            p->params[3] = f.x;
        } else {
            p->params[0] = f.x; p->params[1] = f.y; p->params[2] = f.z;
        }
        return true;
    }
    case T_METRIC:
        /* POV-Ray reads a vector and keeps its x: 'metric <1,1,1>' */
        p->params[3] = pp_vector(ps).x;
        return true;
    case T_OFFSET: p->params[4] = pp_float(ps); return true;
    case T_SOLID: p->params[5] = 1; return true;
    case T_CONTROL0: p->params[0] = pp_float(ps); return true;
    case T_CONTROL1: p->params[1] = pp_float(ps); return true;
    case T_EXPONENT: p->params[6] = pp_float(ps); return true;
    case T_EXTERIOR: case T_INTERIOR: {
        if (p->kind != IRIS_PAT_MANDEL && p->kind != IRIS_PAT_JULIA &&
            p->kind != IRIS_PAT_PAVEMENT)
            return false;
        int type = pp_int(ps);
        double factor = 1;
        /* POV-Ray: 'exterior 1, 0.5' or 'exterior 1 0.5' (Parse_Comma) */
        if (pp_accept(ps, T_COMMA) || pp_float_follows(ps))
            factor = pp_float(ps);
        if (p->kind == IRIS_PAT_PAVEMENT)
            return true;
        /* the fractal colouring (POV-Ray: exterior 0-8, interior 0-6) */
        bool ext = at.kind == T_EXTERIOR;
        if (type < 0 || type > (ext ? 8 : 6))
            pp_error(ps, &at, "%s type must be 0 to %d",
                     ext ? "exterior" : "interior", ext ? 8 : 6);
        p->params[ext ? 2 : 0] = type;
        p->params[ext ? 3 : 1] = factor;
        p->params[5] = 1;
        return true;
    }
    case T_COORDS: p->params[1] = pp_float(ps); return true;
    case T_SIZE: p->params[0] = pp_float(ps); return true;
    case T_NUMBER_OF_SIDES: p->params[0] = pp_float(ps); return true;
    case T_NUMBER_OF_TILES: p->params[1] = pp_float(ps); return true;
    case T_PATTERN: p->params[2] = pp_float(ps); return true;
    case T_ORIENTATION: p->vector = pp_vector(ps); return true;
    case T_DIST_EXP: p->params[6] = pp_float(ps); return true;
    case T_UV_MAPPING:
        p->uv_mapping = true;
        return true;
    case T_PRECOMPUTE:
        pp_warn_once(ps, &at, at.kind, lex_keyword_name(at.kind));
        pp_float(ps);
        return true;
    default: {
        iris_transform x;
        if (pp_transform_item(ps, &x)) {
            xf_compose(&p->transform, &p->transform, &x);
            p->has_transform = true;
            return true;
        }
        return false;
    }
    }
}

/* ---- maps -------------------------------------------------------- */

static int cmp_entry(const void *a, const void *b)
{
    double x = ((const iris_map_entry *)a)->value;
    double y = ((const iris_map_entry *)b)->value;
    return x < y ? -1 : x > y;
}

static iris_pigment *pigment_body(pp_state *ps, const iris_pigment *base,
                                  int end);
static void default_map(pp_state *ps, iris_pigment *p);
static iris_normal *normal_body(pp_state *ps, const iris_normal *base,
                                int end);
static iris_texture *texture_body(pp_state *ps, int end);

/* x_map { [value item] ... } or x_map { MAP_ID }. The current token is
** the map keyword. */
pp_map *pp_map_block(pp_state *ps, int kind)
{
    pp_expect(ps, T_LBRACE, "'{'");
    pp_enter(ps, &ps->tok);
    pp_map *m = pp_salloc(ps, sizeof *m);
    m->kind = kind;
    int cap = 0;
    iris_map_entry *e = NULL;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_RBRACE)
            break;
        if (at.kind == T_IDENT && at.val.kind == kind) {
            *m = *at.val.u.map;
            cap = m->n;
            e = m->e;
            continue;
        }
        if (at.kind != T_LBRACKET) {
            char buf[80];
            pp_error(ps, &at, "expected '[' or a map identifier in %s, found "
                     "%s", pp_kind_name(kind),
                     pp_tok_name(ps, &at, buf, sizeof buf));
        }
        if (m->n + 2 > cap) {
            int nc = cap ? cap * 2 : 8;
            if (nc > 256)
                nc = cap + 2 > 256 ? cap + 2 : 256;
            iris_map_entry *ne = pp_alloc(ps, (size_t)nc * sizeof *ne);
            if (m->n)
                memcpy(ne, e, (size_t)m->n * sizeof *ne);
            e = ne;
            cap = nc;
        }
        if (m->n >= 256)
            pp_error(ps, &at, "a map has at most 256 entries");
        iris_map_entry *en = &e[m->n];
        memset(en, 0, sizeof *en);
        /* average's pigment_map may leave out the weight (1) */
        pp_next(ps);
        bool has_value = pp_starts_expr(ps) && !(ps->tok.kind == T_IDENT &&
                                                  !(ps->tok.val.kind == V_FLOAT));
        pp_unget(ps);
        en->value = has_value || kind == V_COLOUR_MAP ? pp_float(ps) : 1.0;
        switch (kind) {
        case V_COLOUR_MAP: {
            /* [v color C] or the old [v1, v2 color C1 color C2]; the comma
            ** after the value is optional */
            pp_accept(ps, T_COMMA);
            pp_next(ps);
            bool second = ps->tok.kind == T_NUMBER ||
                          (ps->tok.kind == T_IDENT &&
                           ps->tok.val.kind == V_FLOAT);
            pp_unget(ps);
            if (second) {
                double v2 = pp_float(ps);
                en->colour = pp_colour(ps);
                iris_map_entry *e2 = &e[m->n + 1];
                memset(e2, 0, sizeof *e2);
                e2->value = v2;
                pp_accept(ps, T_COMMA);
                e2->colour = pp_colour(ps);
                m->n++;
            } else {
                en->colour = pp_colour(ps);
            }
            pp_expect(ps, T_RBRACKET, "']'");
            break;
        }
        case V_PIGMENT_MAP:
            pp_accept(ps, T_COMMA);
            en->pigment = pigment_body(ps, NULL, T_RBRACKET);
            break;
        case V_NORMAL_MAP:
            pp_accept(ps, T_COMMA);
            en->normal = normal_body(ps, NULL, T_RBRACKET);
            break;
        case V_TEXTURE_MAP:
            pp_accept(ps, T_COMMA);
            en->texture = texture_body(ps, T_RBRACKET);
            break;
        case V_SLOPE_MAP: {
            pp_accept(ps, T_COMMA);
            double v[4];
            pp_vector4(ps, v);
            en->slope = v[0] == 0 && v[1] == 0 ? 0 : v[0];
            en->height = v[0];
            en->slope = v[1];
            pp_expect(ps, T_RBRACKET, "']'");
            break;
        }
        default:
            pp_skip_block(ps);
            break;
        }
        m->n++;
    }
    pp_leave(ps);
    m->e = e;
    if (m->n > 1) {
        /* stable insertion sort: equal values keep their order */
        for (int i = 1; i < m->n; i++) {
            iris_map_entry x = e[i];
            int j = i;
            while (j > 0 && cmp_entry(&e[j - 1], &x) > 0) {
                e[j] = e[j - 1];
                j--;
            }
            e[j] = x;
        }
    }
    return m;
}

/* ---- copies with transforms ------------------------------------- */

static void pattern_xf(iris_pattern *p, const iris_transform *xf)
{
    xf_compose(&p->transform, &p->transform, xf);
    p->has_transform = true;
}

/*
** POV-Ray evaluates a map's entries at the map pattern's transformed
** point, so they see every transform of the map pattern, also those
** written before the map ('gradient y scale 10 texture_map {...}'). The
** entries here carry the map's transforms instead (those written after
** the map reach them through pp_*_transform); this gives '*out' the
** transforms the map pattern has so far, pattern to world, in the order
** pat_warp_world undoes them. False when there are none.
*/
static bool map_xf_so_far(const iris_pattern *p, iris_transform *out)
{
    bool any = false;
    xf_identity(out);
    for (int i = 0; i < p->n_warps; i++)
        if (p->warps[i].kind == IRIS_WARP_TRANSFORM) {
            xf_compose(out, out, &p->warps[i].transform);
            any = true;
        }
    if (p->has_transform) {
        xf_compose(out, out, &p->transform);
        any = true;
    }
    return any;
}

/* The map entries 'e' given the map pattern's transforms so far: a copy
** when there are any ('e' may be a declared map's, shared). 'kind' is
** the map's (V_PIGMENT_MAP, V_NORMAL_MAP, V_TEXTURE_MAP; others have
** nothing to transform). */
static iris_map_entry *entries_in_map_space(pp_state *ps,
                                            const iris_pattern *p,
                                            iris_map_entry *e, int n,
                                            int kind)
{
    iris_transform xf;
    if (n <= 0 || !map_xf_so_far(p, &xf) ||
        (kind != V_PIGMENT_MAP && kind != V_NORMAL_MAP &&
         kind != V_TEXTURE_MAP))
        return e;
    iris_map_entry *c = pp_alloc(ps, (size_t)n * sizeof *c);
    memcpy(c, e, (size_t)n * sizeof *c);
    for (int i = 0; i < n; i++) {
        if (kind == V_PIGMENT_MAP)
            c[i].pigment = pp_pig_transform(ps, c[i].pigment, &xf);
        else if (kind == V_NORMAL_MAP)
            c[i].normal = pp_nor_transform(ps, c[i].normal, &xf);
        else
            c[i].texture = pp_tex_transform(ps, c[i].texture, &xf);
    }
    return c;
}

/* A copy of pigment 'p' transformed by 'xf'. A uv-mapped pigment lives
** in the surface's uv space, which no transform from outside it (the
** texture's, the object's) moves: only its 'own' transforms, written in
** its body, reach it (POV-Ray's UV_MAP_PATTERN ignores the others). */
/* Whether the pigments under 'p' (its pigment entries, theirs, ...) may
** share one entry transform: none evaluates at the surface's uv point
** (which no outer transform moves) or reads the world point itself
** (slope's point_at). Read from the entries' flags (maptree.c), not by
** a walk: a map of maps sharing one map is a tree far larger than its
** memory. */
static bool entries_shareable(const iris_pigment *p)
{
    return !p->n_entries || !p->is_pigment_map ||
           !pp_pig_entries_pointwise(p);
}

static iris_pigment *pig_xf(pp_state *ps, const iris_pigment *p,
                            const iris_transform *xf, bool own);

/* 'p' with its entry transform given to copies of its entries, as the
** parser did before the entries were shared: for the uv-mapped, which
** the transform must reach in pattern space. */
static iris_pigment *pig_flat(pp_state *ps, const iris_pigment *p)
{
    if (!p || !p->entry_xf)
        return (iris_pigment *)p;
    iris_pigment *n = pp_alloc(ps, sizeof *n);
    *n = *p;
    n->entry_xf = NULL;
    n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
    memcpy(n->entries, p->entries, (size_t)n->n_entries * sizeof *n->entries);
    for (int i = 0; i < n->n_entries; i++)
        n->entries[i].pigment = pig_xf(ps, p->entries[i].pigment,
                                       p->entry_xf, true);
    return n;
}

static iris_pigment *pig_xf(pp_state *ps, const iris_pigment *p,
                            const iris_transform *xf, bool own)
{
    if (!p || (p->pattern.uv_mapping && !own))
        return (iris_pigment *)p;
    iris_pigment *n = pp_alloc(ps, sizeof *n);
    *n = *p;
    pattern_xf(&n->pattern, xf);
    /*
    ** The entries, often a deep tree shared by many pigments (a declared
    ** pigment_map used by every object), stay shared: the transform is
    ** kept beside them, composed after the one they have. Copying the
    ** tree per transform made memory grow with the copies (mscharrer's
    ** tree_of_squares_v4: 63 pigments x 5 transforms x 32768 boxes).
    */
    if (n->n_entries && n->is_pigment_map && !p->pattern.uv_mapping &&
        entries_shareable(p)) {
        iris_transform *x = pp_alloc(ps, sizeof *x);
        if (p->entry_xf)
            xf_compose(x, p->entry_xf, xf);
        else
            *x = *xf;
        n->entry_xf = x;
        return n;
    }
    if (n->entry_xf) {
        p = pig_flat(ps, p);
        *n = *p;
        pattern_xf(&n->pattern, xf);
    }
    if (n->n_entries && n->is_pigment_map) {
        n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
        memcpy(n->entries, p->entries, (size_t)n->n_entries * sizeof *n->entries);
        for (int i = 0; i < n->n_entries; i++)
            n->entries[i].pigment = pig_xf(ps, n->entries[i].pigment, xf, own);
    }
    return n;
}

iris_pigment *pp_pig_transform(pp_state *ps, const iris_pigment *p,
                               const iris_transform *xf)
{
    return pig_xf(ps, p, xf, false);
}

/* entries_shareable for normals: a normal_map's entries (not a
** slope_map's, which hold numbers). */
static bool nor_entries_shareable(const iris_normal *p)
{
    return !p->n_entries || p->is_slope_map || !pp_nor_entries_pointwise(p);
}

static iris_normal *nor_xf(pp_state *ps, const iris_normal *p,
                           const iris_transform *xf, bool own);

/* pig_flat for normals. */
static iris_normal *nor_flat(pp_state *ps, const iris_normal *p)
{
    if (!p || !p->entry_xf)
        return (iris_normal *)p;
    iris_normal *n = pp_alloc(ps, sizeof *n);
    *n = *p;
    n->entry_xf = NULL;
    n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
    memcpy(n->entries, p->entries, (size_t)n->n_entries * sizeof *n->entries);
    for (int i = 0; i < n->n_entries; i++)
        n->entries[i].normal = nor_xf(ps, p->entries[i].normal,
                                      p->entry_xf, true);
    return n;
}

/* pig_xf for normals: a normal_map's entries stay shared too, the
** transform kept beside them (normal.c's perturb() moves the point and
** the normal by it around them, as the pushed transform would). */
static iris_normal *nor_xf(pp_state *ps, const iris_normal *p,
                           const iris_transform *xf, bool own)
{
    if (!p || (p->pattern.uv_mapping && !own))
        return (iris_normal *)p;
    iris_normal *n = pp_alloc(ps, sizeof *n);
    *n = *p;
    pattern_xf(&n->pattern, xf);
    if (n->n_entries && !n->is_slope_map && !p->pattern.uv_mapping &&
        nor_entries_shareable(p)) {
        iris_transform *x = pp_alloc(ps, sizeof *x);
        if (p->entry_xf)
            xf_compose(x, p->entry_xf, xf);
        else
            *x = *xf;
        n->entry_xf = x;
        return n;
    }
    if (n->entry_xf) {
        p = nor_flat(ps, p);
        *n = *p;
        pattern_xf(&n->pattern, xf);
    }
    if (n->n_entries && !n->is_slope_map) {
        n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
        memcpy(n->entries, p->entries, (size_t)n->n_entries * sizeof *n->entries);
        for (int i = 0; i < n->n_entries; i++)
            n->entries[i].normal = nor_xf(ps, n->entries[i].normal, xf, own);
    }
    return n;
}

iris_normal *pp_nor_transform(pp_state *ps, const iris_normal *p,
                              const iris_transform *xf)
{
    return nor_xf(ps, p, xf, false);
}

iris_texture *pp_tex_transform(pp_state *ps, const iris_texture *t,
                               const iris_transform *xf)
{
    if (!t)
        return NULL;
    iris_texture *n = pp_alloc(ps, sizeof *n);
    *n = *t;
    n->pigment = pp_pig_transform(ps, t->pigment, xf);
    n->normal = pp_nor_transform(ps, t->normal, xf);
    /* a transform between the map's pattern and its texture_map applies
    ** to the pattern (the entries, parsed later, do not get it) */
    /* (a uv-mapped one lives in uv space, which they do not move) */
    bool map_xf = !t->map_pattern.uv_mapping;
    if (t->map_pattern.kind != IRIS_PAT_NONE && !t->n_entries && map_xf)
        pattern_xf(&n->map_pattern, xf);
    if (t->n_entries) {
        if (map_xf)
            pattern_xf(&n->map_pattern, xf);
        n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
        memcpy(n->entries, t->entries, (size_t)n->n_entries * sizeof *n->entries);
        for (int i = 0; i < n->n_entries; i++)
            n->entries[i].texture = pp_tex_transform(ps, t->entries[i].texture, xf);
    }
    n->next = pp_tex_transform(ps, t->next, xf);
    return n;
}

/* ---- pigments ---------------------------------------------------- */

iris_pigment *pp_pigment_new(pp_state *ps, const pp_token *at)
{
    iris_pigment *p = pp_alloc(ps, sizeof *p);
    p->loc = pp_loc(ps, at);
    pp_pattern_init(&p->pattern);
    return p;
}

/* Copies 'm' into the entries of a pigment. */
static void set_pigment_map(pp_state *ps, iris_pigment *p, const pp_map *m,
                            const pp_token *at)
{
    if (m->kind != V_COLOUR_MAP && m->kind != V_PIGMENT_MAP)
        pp_error(ps, at, "a pigment takes a colour_map or pigment_map, not "
                 "a %s", pp_kind_name(m->kind));
    p->n_entries = m->n;
    p->entries = entries_in_map_space(ps, &p->pattern, m->e, m->n, m->kind);
    p->entry_xf = NULL;
    p->is_pigment_map = m->kind == V_PIGMENT_MAP;
}

/* The items after a list pattern (checker A B, hexagon A B C, ...). */
static void pigment_list(pp_state *ps, iris_pigment *p, int max)
{
    iris_map_entry *e = pp_alloc(ps, (size_t)max * sizeof *e);
    int n = 0;
    bool pigments = false;
    /* Directives between the entries run as they come, as in POV-Ray,
    ** whose tokenizer executes them: 'brick #end #if (C) rgb 1, rgb 0' */
    while (n < max) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_COMMA && n > 0) {
            pp_next(ps);
            at = ps->tok;
        }
        if (at.kind == T_PIGMENT) {
            e[n].pigment = pp_pigment(ps, NULL);
            e[n].value = n;
            pigments = true;
            n++;
        } else if (at.kind == T_IDENT && at.val.kind == V_PIGMENT) {
            e[n].pigment = at.val.u.pig;
            e[n].value = n;
            pigments = true;
            n++;
        } else if (at.kind == T_COLOR || at.kind == T_RGB ||
                   at.kind == T_RGBF || at.kind == T_RGBT ||
                   at.kind == T_RGBFT || at.kind == T_SRGB ||
                   at.kind == T_SRGBF || at.kind == T_SRGBT ||
                   at.kind == T_SRGBFT ||
                   (at.kind == T_IDENT && (at.val.kind == V_COLOUR ||
                                           at.val.kind == V_VECTOR ||
                                           at.val.kind == V_FLOAT))) {
            pp_unget(ps);
            e[n].colour = pp_colour(ps);
            e[n].value = n;
            n++;
        } else {
            pp_unget(ps);
            break;
        }
        /* POV-Ray's Parse_Blend_List takes an optional ',' after every
        ** entry, the last one too: 'brick rgb 1, rgb 0,' */
        pp_accept(ps, T_COMMA);
    }
    if (n == 0)
        return;
    /* Fewer entries than the pattern has (checker with one colour):
    ** POV-Ray's Parse_Blend_List fills the rest, colours from the
    ** pattern's default map, pigments with copies of the default
    ** texture's pigment (black unless #default says otherwise). iris
    ** repeated the last entry. */
    if (n < max) {
        iris_pigment defaults = *p;
        defaults.n_entries = 0;
        default_map(ps, &defaults);
        const iris_texture *dt = pp_default_texture(ps);
        for (int i = n; i < max; i++) {
            e[i].value = i;
            if (pigments)
                e[i].pigment = dt && dt->pigment ? dt->pigment
                                                 : pp_pigment_new(ps, &ps->tok);
            else if (i < defaults.n_entries)
                e[i].colour = defaults.entries[i].colour;
        }
        n = max;
    }
    if (pigments) {
        /* mixed lists: wrap colours as solid pigments */
        for (int i = 0; i < n; i++)
            if (!e[i].pigment) {
                e[i].pigment = pp_pigment_new(ps, &ps->tok);
                e[i].pigment->colour = e[i].colour;
            }
    }
    p->n_entries = n;
    p->entries = e;
    p->is_pigment_map = pigments;
    p->entry_xf = NULL;
}

static iris_pigment *pigment_body(pp_state *ps, const iris_pigment *base,
                                  int end)
{
    pp_next(ps);
    pp_token open = ps->tok;
    pp_unget(ps);
    iris_pigment *p = pp_alloc(ps, sizeof *p);
    if (base)
        *p = *base;
    else
        *p = *pp_pigment_new(ps, &open);
    p->loc = pp_loc(ps, &open);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        int k = at.kind;
        if (k == end) {
            default_map(ps, p);
            pp_pig_map_tree(ps, p, &open);
            return p;
        }
        if (k == T_EOF)
            pp_error(ps, &open, "pigment without its closing '%s'",
                     end == T_RBRACE ? "}" : "]");
        if (k == T_IDENT && (at.val.kind == V_PIGMENT ||
                             (ps->in_density && at.val.kind == V_DENSITY))) {
            *p = *at.val.u.pig;
            continue;
        }
        if (k == T_IDENT && (at.val.kind == V_COLOUR_MAP ||
                             at.val.kind == V_PIGMENT_MAP ||
                             (ps->in_density &&
                              at.val.kind == V_DENSITY_MAP))) {
            set_pigment_map(ps, p, at.val.u.map, &at);
            continue;
        }
        if (k == T_COLOR_MAP || k == T_PIGMENT_MAP ||
            (k == T_DENSITY_MAP && ps->in_density)) {
            pp_map *m = pp_map_block(ps, k == T_COLOR_MAP ? V_COLOUR_MAP
                                                          : V_PIGMENT_MAP);
            set_pigment_map(ps, p, m, &at);
            continue;
        }
        if (k == T_QUICK_COLOR) {
            p->quick_colour = pp_colour(ps);
            continue;
        }
        if (k == T_IDENT && at.val.kind == V_FUNCTION) {
            pp_error(ps, &at, "a function pattern is written 'function { "
                     "F(x,y,z) }'");
        }
        if (pp_starts_expr(ps) || k == T_COLOR || k == T_RGB ||
            k == T_RGBF || k == T_RGBT || k == T_RGBFT || k == T_SRGB ||
            k == T_SRGBF || k == T_SRGBT || k == T_SRGBFT) {
            pp_unget(ps);
            p->pattern.kind = IRIS_PAT_NONE;
            p->n_entries = 0;
            p->colour = pp_colour(ps);
            continue;
        }
        if (k == T_TRANSFORM || k == T_TRANSLATE || k == T_ROTATE ||
            k == T_SCALE || k == T_MATRIX) {
            iris_transform x;
            pp_transform_item(ps, &x);
            p = pig_xf(ps, p, &x, true);
            continue;
        }
        int old_kind = p->pattern.kind;
        iris_pattern np = p->pattern;
        if (pattern_kind(ps, &np)) {
            /* a new pattern keeps the transforms and turbulence given so
            ** far only when the pigment was an identifier; POV-Ray resets
            ** the pattern type and keeps the modifiers */
            p->pattern.kind = np.kind;
            p->pattern.vector = np.vector;
            p->pattern.fn = np.fn;
            p->pattern.image = np.image;
            p->pattern.object = np.object;
            p->pattern.complex_c = np.complex_c;
            p->pattern.iterations = np.iterations;
            p->pattern.wave = np.wave;
            memcpy(p->pattern.params, np.params, sizeof np.params);
            (void)old_kind;
            if (list_pattern(p->pattern.kind)) {
                int max = p->pattern.kind == IRIS_PAT_HEXAGON ? 3 :
                          p->pattern.kind == IRIS_PAT_SQUARE ? 4 :
                          p->pattern.kind == IRIS_PAT_TRIANGULAR ||
                          p->pattern.kind == IRIS_PAT_CUBIC ? 6 : 2;
                pigment_list(ps, p, max);
                close_object_pattern(ps, &p->pattern);
            }
            continue;
        }
        if (pattern_mod(ps, &p->pattern))
            continue;
        {
            pp_unexpected(ps, &at, "pigment");
        }
    }
}

/* POV-Ray 3.7's colour maps for patterns given without one
** (texture/pigment.cpp: Gray, Bozo, Wood, Mandel, Agate, Radial, Marble,
** Brick, Hex/Check and Cubic/Square/Triangular default maps). */
struct default_map {
    int n;
    double v[6];
    float c[6][3];
};
static const struct default_map gray_map = { 2, { 0, 1 },
    { { 0, 0, 0 }, { 1, 1, 1 } } };
static const struct default_map bozo_map = { 6, { .4, .4, .6, .6, .8, .8 },
    { { 1, 1, 1 }, { 0, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, 1 },
      { 1, 0, 0 } } };
static const struct default_map wood_map = { 2, { .6, .6 },
    { { .666f, .312f, .2f }, { .4f, .1333f, .066f } } };
static const struct default_map mandel_map = { 5,
    { .001, .001, .012, .015, .1 },
    { { 0, 0, 0 }, { 0, 1, 1 }, { 1, 1, 0 }, { 1, 0, 1 }, { 0, 1, 1 } } };
static const struct default_map agate_map = { 6, { 0, .5, .5, .6, .6, 1 },
    { { 1, 1, 1 }, { .95f, .75f, .5f }, { .9f, .7f, .5f }, { .9f, .7f, .4f },
      { 1, .7f, .4f }, { .6f, .3f, 0 } } };
static const struct default_map radial_map = { 4, { 0, .333, .666, 1 },
    { { 0, 1, 1 }, { 1, 1, 0 }, { 1, 0, 1 }, { 0, 1, 1 } } };
static const struct default_map marble_map = { 3, { 0, .9, .9 },
    { { .9f, .8f, .8f }, { .9f, .08f, .08f }, { 0, 0, 0 } } };
static const struct default_map brick_map = { 2, { 0, 1 },
    { { .5f, .5f, .5f }, { .6f, .15f, .15f } } };
static const struct default_map hex_map = { 3, { 0, 1, 2 },
    { { 0, 0, 1 }, { 0, 1, 0 }, { 1, 0, 0 } } };
static const struct default_map cubic_map = { 6, { 0, 1, 1, 1, 1, 2 },
    { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 }, { 0, 1, 1 },
      { 1, 0, 1 } } };

/* Gives a pattern pigment without a map POV-Ray's default map. */
static void default_map(pp_state *ps, iris_pigment *p)
{
    const struct default_map *m = &gray_map;
    int n = -1;
    switch (p->pattern.kind) {
    case IRIS_PAT_NONE: case IRIS_PAT_IMAGE_MAP: case IRIS_PAT_AVERAGE:
        return;
    case IRIS_PAT_BOZO: m = &bozo_map; break;
    case IRIS_PAT_BRICK: m = &brick_map; break;
    case IRIS_PAT_WOOD: m = &wood_map; break;
    case IRIS_PAT_MANDEL: /* magnet mandel (params[7]) has the grey map */
        if (p->pattern.params[7] == 0)
            m = &mandel_map;
        break;
    case IRIS_PAT_RADIAL: m = &radial_map; break;
    case IRIS_PAT_AGATE: m = &agate_map; break;
    case IRIS_PAT_MARBLE: m = &marble_map; break;
    case IRIS_PAT_HEXAGON: m = &hex_map; break;
    case IRIS_PAT_SQUARE: m = &cubic_map; n = 4; break;
    case IRIS_PAT_TRIANGULAR: case IRIS_PAT_CUBIC: m = &cubic_map; break;
    case IRIS_PAT_CHECKER: case IRIS_PAT_OBJECT: m = &hex_map; n = 2; break;
    default: break;
    }
    if (p->n_entries)
        return;
    if (n < 0)
        n = m->n;
    iris_map_entry *e = pp_alloc(ps, (size_t)n * sizeof *e);
    for (int i = 0; i < n; i++) {
        e[i].value = m->v[i];
        e[i].colour.r = m->c[i][0];
        e[i].colour.g = m->c[i][1];
        e[i].colour.b = m->c[i][2];
    }
    p->entries = e;
    p->n_entries = n;
    p->is_pigment_map = false;
}

iris_pigment *pp_pigment(pp_state *ps, const iris_pigment *base)
{
    pp_expect(ps, T_LBRACE, "'{' after pigment");
    pp_enter(ps, &ps->tok);
    iris_pigment *p = pigment_body(ps, base, T_RBRACE);
    pp_leave(ps);
    return p;
}

/* A media density is a pigment whose map may be a density_map (its
** entries are densities as a pigment_map's are pigments); media.c. */
iris_pigment *pp_density_block(pp_state *ps, const iris_pigment *base)
{
    pp_expect(ps, T_LBRACE, "'{' after density");
    pp_enter(ps, &ps->tok);
    ps->in_density++;
    iris_pigment *p = pigment_body(ps, base, T_RBRACE);
    ps->in_density--;
    pp_leave(ps);
    return p;
}

/* ---- normals ----------------------------------------------------- */

static bool normal_pattern_takes_amount(int kind)
{
    return kind != IRIS_PAT_NONE;
}

static iris_normal *normal_body(pp_state *ps, const iris_normal *base,
                                int end)
{
    pp_next(ps);
    pp_token open = ps->tok;
    pp_unget(ps);
    iris_normal *n = pp_alloc(ps, sizeof *n);
    /* A normal starts as a copy of the #default normal, wherever it is
    ** written: a texture, a normal_map entry, a checker's list, a
    ** #declare (POV-Ray 3.7 Parse_Tnormal, Parse_BlendMapData). So a
    ** #default bump_size reaches them all. */
    if (!base && ps->default_tex && ps->default_tex->normal)
        base = ps->default_tex->normal;
    if (base) {
        *n = *base;
    } else {
        pp_pattern_init(&n->pattern);
        n->amount = 0.5;
        n->accuracy = 0.02;
    }
    n->loc = pp_loc(ps, &open);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        int k = at.kind;
        if (k == end) {
            pp_nor_map_tree(ps, n, &open);
            return n;
        }
        if (k == T_EOF)
            pp_error(ps, &open, "normal without its closing bracket");
        if (k == T_IDENT && at.val.kind == V_NORMAL) {
            *n = *at.val.u.nor;
            continue;
        }
        if (k == T_IDENT && (at.val.kind == V_NORMAL_MAP ||
                             at.val.kind == V_SLOPE_MAP)) {
            n->n_entries = at.val.u.map->n;
            n->entries = entries_in_map_space(ps, &n->pattern,
                                              at.val.u.map->e,
                                              at.val.u.map->n, at.val.kind);
            n->is_slope_map = at.val.kind == V_SLOPE_MAP;
            n->entry_xf = NULL;
            continue;
        }
        if (k == T_NORMAL_MAP || k == T_SLOPE_MAP) {
            pp_map *m = pp_map_block(ps, k == T_NORMAL_MAP ? V_NORMAL_MAP
                                                           : V_SLOPE_MAP);
            n->n_entries = m->n;
            n->entries = entries_in_map_space(ps, &n->pattern, m->e, m->n,
                                              m->kind);
            n->is_slope_map = k == T_SLOPE_MAP;
            n->entry_xf = NULL;
            continue;
        }
        if (k == T_BUMP_SIZE) {
            n->amount = pp_float(ps);
            continue;
        }
        if (k == T_ACCURACY) {
            n->accuracy = pp_float(ps);
            continue;
        }
        if (k == T_NO_BUMP_SCALE) {
            n->no_bump_scale = pp_bool_opt(ps);
            continue;
        }
        if (k == T_BUMP_MAP) {
            n->pattern.kind = IRIS_PAT_IMAGE_MAP;
            n->bump_map = image_block(ps, &n->amount);
            continue;
        }
        if (k == T_TRANSFORM || k == T_TRANSLATE || k == T_ROTATE ||
            k == T_SCALE || k == T_MATRIX) {
            iris_transform x;
            pp_transform_item(ps, &x);
            n = nor_xf(ps, n, &x, true);
            continue;
        }
        iris_pattern np = n->pattern;
        if (pattern_kind(ps, &np)) {
            iris_pattern keep = n->pattern;
            n->pattern = np;
            n->pattern.transform = keep.transform;
            n->pattern.has_transform = keep.has_transform;
            n->pattern.n_warps = keep.n_warps;
            n->pattern.warps = keep.warps;
            if (list_pattern(np.kind)) {
                /* checker 0.5 or checker normal{..}, normal{..} */
                int max = np.kind == IRIS_PAT_HEXAGON ? 3 :
                          np.kind == IRIS_PAT_SQUARE ? 4 :
                          np.kind == IRIS_PAT_TRIANGULAR ||
                          np.kind == IRIS_PAT_CUBIC ? 6 : 2;
                iris_map_entry *e = pp_alloc(ps, (size_t)max * sizeof *e);
                int cnt = 0;
                while (cnt < max) {
                    pp_next(ps);
                    if (ps->tok.kind == T_COMMA && cnt > 0)
                        pp_next(ps);
                    if (ps->tok.kind == T_NORMAL) {
                        e[cnt].normal = pp_normal(ps, NULL);
                    } else if (ps->tok.kind == T_IDENT &&
                               ps->tok.val.kind == V_NORMAL) {
                        e[cnt].normal = ps->tok.val.u.nor;
                    } else {
                        pp_unget(ps);
                        break;
                    }
                    e[cnt].value = cnt;
                    cnt++;
                    /* a ',' after the last entry too (Parse_Blend_List) */
                    pp_accept(ps, T_COMMA);
                }
                close_object_pattern(ps, &np);
                if (cnt) {
                    n->n_entries = cnt;
                    n->entries = e;
                    n->entry_xf = NULL;
                    continue;
                }
            }
            if (normal_pattern_takes_amount(np.kind) &&
                !pp_next_is_directive(ps)) {
                pp_accept(ps, T_COMMA);
                pp_next(ps);
                bool amt = pp_starts_expr(ps) && ps->tok.kind != T_IDENT;
                amt = amt || (ps->tok.kind == T_IDENT &&
                              ps->tok.val.kind == V_FLOAT);
                pp_unget(ps);
                if (amt)
                    n->amount = pp_float(ps);
            }
            continue;
        }
        if (pattern_mod(ps, &n->pattern))
            continue;
        {
            pp_unexpected(ps, &at, "normal");
        }
    }
}

iris_normal *pp_normal(pp_state *ps, const iris_normal *base)
{
    pp_expect(ps, T_LBRACE, "'{' after normal");
    pp_enter(ps, &ps->tok);
    iris_normal *n = normal_body(ps, base, T_RBRACE);
    pp_leave(ps);
    return n;
}

/* ---- finish ------------------------------------------------------ */

/* reflection { [min,] max [fresnel] [falloff f] [exponent f] [metallic f] } */
static void reflection_block(pp_state *ps, iris_finish *f)
{
    iris_colour c1 = pp_colour(ps);
    f->reflection_min = f->reflection_max = c1;
    bool two = false;
    bool comma = pp_accept(ps, T_COMMA);
    pp_next(ps);
    bool more = pp_starts_expr(ps) || ps->tok.kind == T_COLOR ||
                ps->tok.kind == T_RGB || ps->tok.kind == T_SRGB;
    pp_unget(ps);
    if (comma || more) {
        f->reflection_max = pp_colour(ps);
        two = true;
    }
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            if (f->reflection_fresnel && !two)
                memset(&f->reflection_min, 0, sizeof f->reflection_min);
            return;
        case T_FRESNEL: f->reflection_fresnel = pp_bool_opt(ps); break;
        case T_FALLOFF: f->reflection_falloff = pp_float(ps); break;
        case T_EXPONENT: f->reflection_exponent = pp_float(ps); break;
        case T_METALLIC: {
            f->reflection_metallic = 1;
            pp_next(ps);
            pp_unget(ps);
            if (pp_starts_expr(ps))
                f->reflection_metallic = pp_float(ps);
            break;
        }
        default: {
            pp_unexpected(ps, &at, "reflection");
        }
        }
    }
}

/* An optional float after a keyword (metallic [f]). */
static bool opt_float(pp_state *ps, double *out)
{
    if (pp_next_is_directive(ps))
        return false;
    pp_next(ps);
    bool yes = pp_starts_expr(ps) && ps->tok.kind != T_LT;
    pp_unget(ps);
    if (yes)
        *out = pp_float(ps);
    return yes;
}

iris_finish *pp_finish(pp_state *ps, const iris_finish *base)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after finish");
    iris_finish *f = pp_alloc(ps, sizeof *f);
    if (base)
        *f = *base;
    else
        iris_finish_defaults(f);
    f->loc = pp_loc(ps, &open);
    bool diffuse_albedo = false, phong_albedo = false, spec_albedo = false;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            /* albedo forms, from the final brilliance/phong_size/roughness */
            /* POV-Ray scales the back side too, and keeps the values as
            ** written for radiosity and subsurface (RawDiffuse); a
            ** finish copied from one with albedo keeps that one's
            ** scaled values as its own raw ones */
            f->albedo_scale = 0;
            if (diffuse_albedo) {
                f->albedo_scale = (f->brilliance + 1) / 2;
                f->diffuse *= f->albedo_scale;
                f->diffuse_back *= f->albedo_scale;
            }
            if (phong_albedo)
                f->phong *= (f->phong_size + 1) / 2;
            if (spec_albedo && f->roughness > 0) {
                double r = 1 / f->roughness;
                f->specular *= (r + 2) / (4 * (2 - pow(2, -r / 2)));
            }
            return f;
        case T_IDENT:
            if (at.val.kind == V_FINISH) {
                *f = *at.val.u.fin;
                break;
            }
            goto bad;
        case T_AMBIENT: f->ambient = pp_colour(ps); break;
        case T_EMISSION: f->emission = pp_colour(ps); break;
        case T_DIFFUSE:
            diffuse_albedo = pp_accept(ps, T_ALBEDO);
            f->diffuse = pp_float(ps);
            /* POV-Ray: optional comma, then an optional float: 'diffuse
            ** 0.6 0.3' sets the back side as 'diffuse 0.6, 0.3' does. */
            if (pp_accept(ps, T_COMMA))
                f->diffuse_back = pp_float(ps);
            else
                opt_float(ps, &f->diffuse_back);
            break;
        case T_BRILLIANCE: f->brilliance = pp_float(ps); break;
        case T_PHONG:
            phong_albedo = pp_accept(ps, T_ALBEDO);
            f->phong = pp_float(ps);
            break;
        case T_PHONG_SIZE: f->phong_size = pp_float(ps); break;
        case T_SPECULAR:
            spec_albedo = pp_accept(ps, T_ALBEDO);
            f->specular = pp_float(ps);
            break;
        case T_ROUGHNESS: {
            double r = pp_float(ps);
            if (r < 0)
                pp_error(ps, &at, "roughness must be >= 0");
            /* POV-Ray 3.7 keeps 1/roughness as the highlight's exponent
            ** and leaves a 0 uninverted with the warning "Zero roughness
            ** used.": an exponent of 0, a flat highlight wherever the
            ** half vector faces the surface. An infinite roughness gives
            ** that exponent (1/r) here and in the albedo form above. */
            if (r == 0) {
                pp_warning(ps, &at, "Zero roughness used.");
                r = INFINITY;
            }
            f->roughness = r;
            break;
        }
        case T_METALLIC:
            f->metallic = 1;
            opt_float(ps, &f->metallic);
            break;
        case T_REFLECTION:
            if (pp_accept(ps, T_LBRACE)) {
                reflection_block(ps, f);
            } else {
                /* the old form: reflection C sets min = max = C */
                f->reflection_min = f->reflection_max = pp_colour(ps);
            }
            break;
        case T_REFLECTION_EXPONENT: f->reflection_exponent = pp_float(ps); break;
        case T_CONSERVE_ENERGY: f->conserve_energy = pp_bool_opt(ps); break;
        case T_CRAND: f->crand = pp_float(ps); break;
        case T_IRID:
            pp_expect(ps, T_LBRACE, "'{'");
            f->irid = pp_float(ps);
            for (;;) {
                pp_next(ps);
                if (ps->tok.kind == T_RBRACE)
                    break;
                if (ps->tok.kind == T_THICKNESS)
                    f->irid_thickness = pp_float(ps);
                else if (ps->tok.kind == T_TURBULENCE)
                    f->irid_turbulence = pp_vector(ps);
                else if (ps->tok.kind != T_COMMA)
                    pp_error(ps, &ps->tok, "expected thickness or turbulence "
                             "in irid");
            }
            break;
        case T_IOR: f->legacy_ior = pp_float(ps); break;
        case T_REFRACTION: f->legacy_refraction = pp_float(ps); break;
        case T_CAUSTICS: case T_FADE_DISTANCE: case T_FADE_POWER:
            pp_float(ps);
            break;
        case T_SUBSURFACE:
            /* subsurface { [translucency C] [anisotropy C] }: the
            ** anisotropy is parsed and unused, as in POV-Ray 3.7 */
            f->subsurface = true;
            pp_expect(ps, T_LBRACE, "'{'");
            for (;;) {
                pp_next(ps);
                if (ps->tok.kind == T_RBRACE)
                    break;
                if (ps->tok.kind == T_TRANSLUCENCY)
                    f->translucency = pp_colour(ps);
                else if (ps->tok.kind == T_ANISOTROPY)
                    (void)pp_colour(ps);
                else
                    pp_error(ps, &ps->tok, "expected translucency or "
                             "anisotropy in subsurface");
            }
            break;
        default:
        bad: {
            pp_unexpected(ps, &at, "finish");
        }
        }
    }
}

/* ---- textures ---------------------------------------------------- */

iris_texture *pp_default_texture(pp_state *ps)
{
    return ps->default_tex;
}

iris_texture *pp_texture_new(pp_state *ps, const pp_token *at)
{
    iris_texture *t = pp_alloc(ps, sizeof *t);
    const iris_texture *d = pp_default_texture(ps);
    *t = *d;
    t->next = NULL;
    t->loc = pp_loc(ps, at);
    pp_pattern_init(&t->map_pattern);
    t->n_entries = 0;
    t->entries = NULL;
    return t;
}

/* A copy of pigment 'p' evaluated at the surface's <u, v, 0>, the
** pigments of its pigment_map too (POV-Ray evaluates a map's entries at
** the map pattern's point, here the uv point). */
static iris_pigment *pig_uv(pp_state *ps, const iris_pigment *p)
{
    if (!p)
        return NULL;
    p = pig_flat(ps, p);
    iris_pigment *n = pp_alloc(ps, sizeof *n);
    *n = *p;
    n->pattern.uv_mapping = true;
    if (n->n_entries && n->is_pigment_map) {
        n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
        memcpy(n->entries, p->entries, (size_t)n->n_entries * sizeof *n->entries);
        for (int i = 0; i < n->n_entries; i++)
            n->entries[i].pigment = pig_uv(ps, p->entries[i].pigment);
        n->map_tree_pointwise = true; /* the entries read the uv point */
    }
    return n;
}

/* pig_uv for normals (and their normal_map). */
static iris_normal *nor_uv(pp_state *ps, const iris_normal *p)
{
    if (!p)
        return NULL;
    p = nor_flat(ps, p);
    iris_normal *n = pp_alloc(ps, sizeof *n);
    *n = *p;
    n->pattern.uv_mapping = true;
    if (n->n_entries && !n->is_slope_map) {
        n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
        memcpy(n->entries, p->entries, (size_t)n->n_entries * sizeof *n->entries);
        for (int i = 0; i < n->n_entries; i++)
            n->entries[i].normal = nor_uv(ps, p->entries[i].normal);
        n->map_tree_pointwise = true; /* the entries read the uv point */
    }
    return n;
}

/* texture { uv_mapping ... }: POV-Ray evaluates the whole texture at
** the surface's <u, v, 0>; here its pigment and normal are marked so
** (the layers of a texture_map are not). */
static iris_texture *uv_texture(pp_state *ps, iris_texture *t)
{
    t->pigment = pig_uv(ps, t->pigment);
    t->normal = nor_uv(ps, t->normal);
    return t;
}

iris_texture *pp_tex_uv_mapped(pp_state *ps, const iris_texture *t)
{
    if (!t)
        return NULL;
    iris_texture *n = pp_alloc(ps, sizeof *n);
    *n = *t;
    uv_texture(ps, n);
    if (n->map_pattern.kind != IRIS_PAT_NONE) {
        n->map_pattern.uv_mapping = true;
        if (n->n_entries) {
            n->entries = pp_alloc(ps, (size_t)n->n_entries * sizeof *n->entries);
            memcpy(n->entries, t->entries,
                   (size_t)n->n_entries * sizeof *n->entries);
            for (int i = 0; i < n->n_entries; i++)
                n->entries[i].texture =
                    pp_tex_uv_mapped(ps, t->entries[i].texture);
        }
    }
    n->next = pp_tex_uv_mapped(ps, t->next);
    return n;
}

/* The items of a texture up to 'end'. */
/*
** material_map { [TYPE] "file" [map_type N] [once] [interpolate N]
**                texture { ... } ... }
** into 't' as an image_map map pattern whose entries are the textures in
** order (src/material/texture.c picks one per texel). Later transforms
** of the texture reach pattern and textures alike (pp_tex_transform).
*/
static void material_map(pp_state *ps, iris_texture *t)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{'");
    iris_image_ref *img = image_file(ps);
    int n = 0, cap = 4;
    iris_map_entry *e = pp_alloc(ps, (size_t)cap * sizeof *e);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            if (n == 0)
                pp_error(ps, &open, "material_map needs at least one "
                         "texture");
            pp_pattern_init(&t->map_pattern);
            t->map_pattern.kind = IRIS_PAT_IMAGE_MAP;
            t->map_pattern.image = img;
            t->n_entries = n;
            t->entries = e;
            return;
        case T_MAP_TYPE: img->map_type = pp_int(ps); break;
        case T_ONCE: img->once = true; break;
        case T_INTERPOLATE: img->interpolate = pp_int(ps); break;
        case T_TEXTURE:
            if (n == cap) {
                iris_map_entry *g = pp_alloc(ps, 2 * (size_t)cap * sizeof *g);
                memcpy(g, e, (size_t)n * sizeof *e);
                e = g;
                cap *= 2;
            }
            e[n].value = n;
            e[n].texture = pp_texture(ps);
            n++;
            break;
        case T_EOF:
            pp_error(ps, &open, "material_map without its closing bracket");
        default:
            pp_unexpected(ps, &at, "material_map");
        }
    }
}

/*
** 'no_bump_scale' on a texture: POV-Ray's Post_Textures hands it to the
** plain texture's normal and to every texture_map entry, wherever in the
** block it stood. Copies: declared textures and normals are shared.
*/
static iris_texture *tex_no_bump_scale(pp_state *ps, const iris_texture *t)
{
    iris_texture *c = pp_alloc(ps, sizeof *c);
    *c = *t;
    if (c->normal) {
        iris_normal *n = pp_alloc(ps, sizeof *n);
        *n = *c->normal;
        n->no_bump_scale = true;
        c->normal = n;
    }
    if (c->n_entries > 0) {
        iris_map_entry *e =
            pp_alloc(ps, (size_t)c->n_entries * sizeof *e);
        for (int i = 0; i < c->n_entries; i++) {
            e[i] = c->entries[i];
            if (e[i].texture)
                e[i].texture = tex_no_bump_scale(ps, e[i].texture);
        }
        c->entries = e;
    }
    return c;
}

static iris_texture *texture_body(pp_state *ps, int end)
{
    pp_next(ps);
    pp_token open = ps->tok;
    pp_unget(ps);
    iris_texture *t = pp_texture_new(ps, &open);
    bool uv = false, no_bump_scale = false;
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        int k = at.kind;
        if (k == end) {
            if (no_bump_scale)
                t = tex_no_bump_scale(ps, t);
            if (uv)
                t = uv_texture(ps, t);
            pp_tex_map_tree(ps, t, &open);
            return t;
        }
        if (k == T_NO_BUMP_SCALE) {
            no_bump_scale = pp_bool_opt(ps) || no_bump_scale;
            continue;
        }
        switch (k) {
        case T_EOF:
            pp_error(ps, &open, "texture without its closing bracket");
        case T_IDENT:
            if (at.val.kind == V_TEXTURE) {
                iris_texture *n = pp_alloc(ps, sizeof *n);
                *n = *at.val.u.tex;
                t = n;
                continue;
            }
            if (at.val.kind == V_TEXTURE_MAP) {
                t->n_entries = at.val.u.map->n;
                t->entries = entries_in_map_space(ps, &t->map_pattern,
                                                  at.val.u.map->e,
                                                  at.val.u.map->n,
                                                  V_TEXTURE_MAP);
                continue;
            }
            /* texture { Jade }: POV-Ray takes a pigment, normal or finish
            ** identifier for that part of a plain texture (a concession
            ** to old scenes that textures.inc's pigments invite) */
            if (at.val.kind == V_PIGMENT) {
                t->pigment = at.val.u.pig;
                continue;
            }
            if (at.val.kind == V_NORMAL) {
                t->normal = at.val.u.nor;
                continue;
            }
            if (at.val.kind == V_FINISH) {
                t->finish = at.val.u.fin;
                continue;
            }
            break;
        case T_PIGMENT:
            t->pigment = pp_pigment(ps, t->pigment);
            continue;
        case T_NORMAL:
            t->normal = pp_normal(ps, t->normal);
            continue;
        case T_FINISH:
            t->finish = pp_finish(ps, t->finish);
            continue;
        case T_TEXTURE_MAP: {
            pp_map *m = pp_map_block(ps, V_TEXTURE_MAP);
            t->n_entries = m->n;
            t->entries = entries_in_map_space(ps, &t->map_pattern, m->e,
                                              m->n, V_TEXTURE_MAP);
            continue;
        }
        case T_TILES: {
            /* the old tiles { texture{} tile2 texture{} }: a checker
            ** whose first tile is checker value 1 and tile2 value 0, as
            ** POV-Ray's Parse_Tiles keeps them (the reverse of
            ** checker's texture order) */
            pp_expect(ps, T_LBRACE, "'{'");
            iris_map_entry *e = pp_alloc(ps, 2 * sizeof *e);
            e[1].value = 1;
            int cnt = 1;
            for (;;) {
                pp_next(ps);
                if (ps->tok.kind == T_RBRACE)
                    break;
                if (ps->tok.kind == T_TILE2) {
                    cnt = 0;
                    continue;
                }
                if (ps->tok.kind != T_TEXTURE)
                    pp_unexpected(ps, &ps->tok, "tiles");
                iris_texture *tt = pp_texture(ps);
                tt->next = e[cnt].texture;
                e[cnt].texture = tt;
            }
            if (!e[1].texture)
                pp_error(ps, &at, "first texture missing from tiles");
            pp_pattern_init(&t->map_pattern);
            t->map_pattern.kind = IRIS_PAT_CHECKER;
            t->n_entries = 2;
            t->entries = e;
            continue;
        }
        case T_UV_MAPPING:
            uv = true;
            continue;
        case T_MATERIAL_MAP:
            material_map(ps, t);
            continue;
        case T_TRANSFORM: case T_TRANSLATE: case T_ROTATE: case T_SCALE:
        case T_MATRIX: {
            iris_transform x;
            pp_transform_item(ps, &x);
            t = pp_tex_transform(ps, t, &x);
            continue;
        }
        default:
            break;
        }
        iris_pattern np = t->map_pattern;
        if (pattern_kind(ps, &np)) {
            t->map_pattern.kind = np.kind;
            t->map_pattern.vector = np.vector;
            t->map_pattern.fn = np.fn;
            t->map_pattern.image = np.image;
            t->map_pattern.object = np.object;
            t->map_pattern.wave = np.wave;
            t->map_pattern.iterations = np.iterations;
            t->map_pattern.complex_c = np.complex_c;
            memcpy(t->map_pattern.params, np.params, sizeof np.params);
            if (list_pattern(np.kind)) {
                int max = np.kind == IRIS_PAT_HEXAGON ? 3 :
                          np.kind == IRIS_PAT_SQUARE ? 4 :
                          np.kind == IRIS_PAT_TRIANGULAR ||
                          np.kind == IRIS_PAT_CUBIC ? 6 : 2;
                iris_map_entry *e = pp_alloc(ps, (size_t)max * sizeof *e);
                int cnt = 0;
                while (cnt < max) {
                    pp_next(ps);
                    if (ps->tok.kind == T_COMMA && cnt > 0)
                        pp_next(ps);
                    if (ps->tok.kind == T_TEXTURE) {
                        e[cnt].texture = pp_texture(ps);
                    } else if (ps->tok.kind == T_IDENT &&
                               ps->tok.val.kind == V_TEXTURE) {
                        e[cnt].texture = ps->tok.val.u.tex;
                    } else {
                        pp_unget(ps);
                        break;
                    }
                    e[cnt].value = cnt;
                    cnt++;
                    /* a ',' after the last entry too (Parse_Blend_List) */
                    pp_accept(ps, T_COMMA);
                }
                /* missing entries are the default texture, as POV-Ray's
                ** Parse_Blend_List fills them (pigment_list) */
                const iris_texture *dt = pp_default_texture(ps);
                if (cnt > 0 && dt)
                    for (; cnt < max; cnt++) {
                        e[cnt].texture = (iris_texture *)dt;
                        e[cnt].value = cnt;
                    }
                t->n_entries = cnt;
                t->entries = e;
                close_object_pattern(ps, &np);
            }
            continue;
        }
        if (t->map_pattern.kind != IRIS_PAT_NONE &&
            pattern_mod(ps, &t->map_pattern))
            continue;
        if (k == T_TURBULENCE || k == T_OCTAVES || k == T_OMEGA ||
            k == T_LAMBDA || k == T_WARP) {
            /* texture-level turbulence applies to its pigment */
            if (t->pigment) {
                iris_pigment *p = pp_alloc(ps, sizeof *p);
                *p = *t->pigment;
                pattern_mod(ps, &p->pattern);
                t->pigment = p;
                continue;
            }
        }
        {
            pp_unexpected(ps, &at, "texture");
        }
    }
}

iris_texture *pp_texture(pp_state *ps)
{
    pp_expect(ps, T_LBRACE, "'{' after texture");
    pp_enter(ps, &ps->tok);
    iris_texture *t = texture_body(ps, T_RBRACE);
    pp_leave(ps);
    return t;
}

/* ---- interior ---------------------------------------------------- */

static bool ident_is(pp_state *ps, const pp_token *t, const char *word)
{
    size_t n = strlen(word);
    return t->kind == T_IDENT && t->len == n &&
           memcmp(pp_tok_text(ps, t), word, n) == 0;
}

/* The iris IOR extensions; false when 'at' is none of them. */
static bool ior_extension(pp_state *ps, iris_interior *in, const pp_token *at)
{
    iris_ior_spec *s = pp_alloc(ps, sizeof *s);
    s->loc = pp_loc(ps, at);
    if (ident_is(ps, at, "glass")) {
        pp_token nt;
        pp_next(ps);
        nt = ps->tok;
        pp_unget(ps);
        const char *name = pp_string(ps);
        if (!name[0])
            pp_error(ps, &nt, "glass needs a catalogue name");
        /* The catalogue is src/spectrum's: the render build looks the
        ** name up and reports an unknown one at this location
        ** (render/check_ior.c), so the parser keeps the name only. */
        s->model = IRIS_IOR_SELLMEIER;
        s->glass_name = pp_strdup(ps, name, strlen(name));
        s->loc = pp_loc(ps, &nt);
    } else if (ident_is(ps, at, "sellmeier")) {
        iris_vec3 b = pp_vector(ps);
        pp_expect(ps, T_COMMA, "','");
        iris_vec3 c = pp_vector(ps);
        s->model = IRIS_IOR_SELLMEIER;
        s->b[0] = b.x; s->b[1] = b.y; s->b[2] = b.z;
        s->c[0] = c.x; s->c[1] = c.y; s->c[2] = c.z;
        if (b.x < 0 || b.y < 0 || b.z < 0 || c.x < 0 || c.y < 0 || c.z < 0)
            pp_error(ps, at, "sellmeier coefficients must be >= 0");
    } else if (ident_is(ps, at, "cauchy")) {
        s->model = IRIS_IOR_CAUCHY;
        s->cauchy_a = pp_float(ps);
        pp_expect(ps, T_COMMA, "','");
        s->cauchy_b = pp_float(ps);
        if (s->cauchy_a < 1)
            pp_error(ps, at, "cauchy A must be >= 1 (it is the index at long "
                     "wavelengths)");
    } else if (ident_is(ps, at, "abbe")) {
        s->model = IRIS_IOR_ABBE;
        s->abbe_nd = pp_float(ps);
        pp_expect(ps, T_COMMA, "','");
        s->abbe_vd = pp_float(ps);
        if (s->abbe_nd < 1 || s->abbe_vd <= 0)
            pp_error(ps, at, "abbe needs n_d >= 1 and V_d > 0");
    } else if (ident_is(ps, at, "ior_decay")) {
        s->model = IRIS_IOR_DECAY;
        s->decay_n1 = pp_float(ps);
        pp_expect(ps, T_COMMA, "','");
        s->decay_n2 = pp_float(ps);
        pp_expect(ps, T_COMMA, "','");
        s->decay_spread = pp_float(ps);
        if (s->decay_spread <= 0)
            pp_error(ps, at, "ior_decay spread must be > 0");
        if (s->decay_n1 < 1 || s->decay_n2 < 1)
            pp_error(ps, at, "ior_decay indices must be >= 1");
    } else {
        return false;
    }
    in->spectral_ior = s;
    return true;
}

iris_interior *pp_interior(pp_state *ps, const iris_interior *base)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after interior");
    iris_interior *in = pp_alloc(ps, sizeof *in);
    if (base)
        *in = *base;
    else
        iris_interior_defaults(in);
    in->loc = pp_loc(ps, &open);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            return in;
        case T_IDENT:
            if (at.val.kind == V_INTERIOR) {
                *in = *at.val.u.inter;
                break;
            }
            if (ior_extension(ps, in, &at))
                break;
            goto bad;
        case T_IOR: in->ior = pp_float(ps); break;
        case T_DISPERSION: in->dispersion = pp_float(ps); break;
        case T_DISPERSION_SAMPLES: {
            double n = pp_float(ps);
            if (!(n >= 2))
                pp_error(ps, &at, "dispersion_samples must be at least 2");
            if (n > 1e6)
                n = 1e6;
            in->dispersion_samples = (int)n;
            break;
        }
        case T_CAUSTICS: in->caustics = pp_float(ps); break;
        case T_FADE_DISTANCE: in->fade_distance = pp_float(ps); break;
        case T_FADE_POWER: in->fade_power = pp_float(ps); break;
        case T_FADE_COLOR: in->fade_colour = pp_colour(ps); break;
        case T_MEDIA:
            pp_interior_add_media(ps, in, pp_media(ps));
            break;
        default:
        bad: {
            pp_unexpected(ps, &at, "interior");
        }
        }
    }
}

/* material { [MATERIAL_ID] texture{} interior{} interior_texture{} ... } */
pp_material *pp_material_block(pp_state *ps)
{
    pp_expect(ps, T_LBRACE, "'{' after material");
    pp_material *m = pp_salloc(ps, sizeof *m);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE:
            return m;
        case T_IDENT:
            if (at.val.kind == V_MATERIAL) {
                *m = *at.val.u.mat;
                break;
            }
            goto bad;
        case T_TEXTURE: {
            iris_texture *t = pp_texture(ps);
            t->next = m->tex;
            m->tex = t;
            break;
        }
        case T_INTERIOR_TEXTURE:
            m->interior_tex = pp_texture(ps);
            break;
        case T_INTERIOR:
            m->inter = pp_interior(ps, m->inter);
            break;
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                m->tex = pp_tex_transform(ps, m->tex, &x);
                m->interior_tex = pp_tex_transform(ps, m->interior_tex, &x);
                break;
            }
        }
        bad: {
            pp_unexpected(ps, &at, "material");
        }
        }
    }
}

/* ---- atmosphere -------------------------------------------------- */

/* fog { [fog_type n] distance d colour C [turbulence ...] [fog_offset]
**       [fog_alt] [up v] [transforms] } */
iris_fog *pp_fog(pp_state *ps)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after fog");
    iris_fog *f = pp_alloc(ps, sizeof *f);
    f->loc = pp_loc(ps, &open);
    f->kind = IRIS_FOG_CONSTANT;
    f->up = v3(0, 1, 0);
    f->octaves = 6;
    f->omega = 0.5;
    f->lambda = 2;
    f->turb_depth = 0.5;
    xf_identity(&f->transform);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE: return f;
        case T_IDENT:
            if (at.val.kind == V_FOG) {
                *f = *at.val.u.fog;
                break;
            }
            pp_unget(ps);
            f->colour = pp_colour(ps);
            break;
        case T_FOG_TYPE: f->kind = pp_int(ps) == 2 ? IRIS_FOG_GROUND
                                                         : IRIS_FOG_CONSTANT; break;
        case T_DISTANCE: f->distance = pp_float(ps); break;
        case T_TURBULENCE: f->turbulence = pp_vector(ps); break;
        case T_TURB_DEPTH: f->turb_depth = pp_float(ps); break;
        case T_OCTAVES: f->octaves = pp_int(ps); break;
        case T_OMEGA: f->omega = pp_float(ps); break;
        case T_LAMBDA: f->lambda = pp_float(ps); break;
        case T_FOG_OFFSET: f->offset = pp_float(ps); break;
        case T_FOG_ALT: f->alt = pp_float(ps); break;
        case T_UP: f->up = pp_vector(ps); break;
        case T_COLOR: case T_RGB: case T_RGBF: case T_RGBT: case T_RGBFT:
        case T_SRGB: case T_SRGBF: case T_SRGBT: case T_SRGBFT:
            pp_unget(ps);
            f->colour = pp_colour(ps);
            break;
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                xf_compose(&f->transform, &f->transform, &x);
                f->has_transform = true;
                break;
            }
            pp_unexpected(ps, &at, "fog");
        }
        }
    }
}

/*
** rainbow { [RAINBOW_IDENTIFIER] [angle A] [width W] [distance D]
**           [jitter J] [direction V] [up V] [arc_angle A] [falloff_angle A]
**           [colour_map {...}] }
** checked and resolved as POV-Ray's Parse_Rainbow (unit, perpendicular
** antisolar, up and right vectors; the colour map as a gradient x pigment;
** the arc and falloff angles halved, in radians), except 'angle' and
** 'width', which stay in degrees as written: pp_rainbow converts them once
** for the scene. A declared rainbow (#declare R = rainbow {...}) is this
** value, so 'rainbow { R }' renders as R's own block would. POV-Ray 3.7
** converts them a second time on the copy (the bow shrinks about 57 times
** towards the antisolar point) and then aborts freeing it (free(): invalid
** pointer); iris keeps the documented meaning.
*/
iris_rainbow *pp_rainbow_block(pp_state *ps)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after rainbow");
    iris_rainbow *r = pp_alloc(ps, sizeof *r);
    r->loc = pp_loc(ps, &open);
    r->distance = 1e7; /* POV-Ray's MAX_DISTANCE */
    r->arc_angle = r->falloff_angle = 180.0;
    r->up = v3(0, 1, 0);
    bool has_arc = false, has_falloff = false;
    for (bool first = true;; first = false) {
        pp_next(ps);
        pp_token at = ps->tok;
        if (at.kind == T_RBRACE)
            break;
        if (first && at.kind == T_IDENT && at.val.kind == V_RAINBOW) {
            *r = *(const iris_rainbow *)at.val.u.ptr;
            r->loc = pp_loc(ps, &open);
            continue;
        }
        switch (at.kind) {
        case T_ANGLE: r->angle = pp_float(ps); break;
        case T_WIDTH: r->width = pp_float(ps); break;
        case T_DISTANCE: r->distance = pp_float(ps); break;
        case T_JITTER: r->jitter = pp_float(ps); break;
        case T_DIRECTION: r->antisolar = pp_vector(ps); break;
        case T_UP: r->up = pp_vector(ps); break;
        case T_ARC_ANGLE: case T_FALLOFF_ANGLE: {
            double a = pp_float(ps);
            if (!(a >= 0.0 && a <= 360.0))
                pp_error(ps, &at, "illegal %s in rainbow (use a value from "
                         "0 to 360 degrees)", at.kind == T_ARC_ANGLE
                         ? "arc angle" : "falloff angle");
            *(at.kind == T_ARC_ANGLE ? &r->arc_angle : &r->falloff_angle) =
                a * M_PI / 360.0;
            *(at.kind == T_ARC_ANGLE ? &has_arc : &has_falloff) = true;
            break;
        }
        case T_COLOR_MAP: {
            pp_map *m = pp_map_block(ps, V_COLOUR_MAP);
            iris_pigment *p = pp_pigment_new(ps, &at);
            p->pattern.kind = IRIS_PAT_GRADIENT;
            p->pattern.vector = v3(1, 0, 0);
            p->n_entries = m->n;
            p->entries = m->e;
            r->pigment = p;
            break;
        }
        case T_EOF:
            pp_error(ps, &open, "rainbow without its closing bracket");
        default:
            pp_unexpected(ps, &at, "rainbow");
        }
    }
    /* Unset angles stay 180 (not halved), as POV-Ray leaves them. */
    if (has_arc && !has_falloff)
        r->falloff_angle = r->arc_angle;
    if (r->arc_angle < r->falloff_angle)
        pp_error(ps, &open, "arc angle is smaller than falloff angle in "
                 "rainbow");
    r->falloff_width = r->arc_angle - r->falloff_angle;
    if (fabs(v3_dot(r->antisolar, r->antisolar)) < 1e-10)
        pp_error(ps, &open, "rainbow's direction vector is zero");
    if (fabs(v3_dot(r->up, r->up)) < 1e-10)
        pp_error(ps, &open, "rainbow's up vector is zero");
    r->antisolar = v3_norm(r->antisolar);
    r->up = v3_norm(r->up);
    if (fabs(1.0 - fabs(v3_dot(r->up, r->antisolar))) < 1e-10)
        pp_error(ps, &open, "rainbow's up and direction vectors are "
                 "co-linear");
    r->right = v3_cross(r->up, r->antisolar);
    r->up = v3_norm(v3_cross(r->antisolar, r->right));
    r->right = v3_norm(r->right);
    return r;
}

/* rainbow {...} in the scene: 'angle' lowered by half the width, both in
** radians, appended to the scene's rainbows. */
void pp_rainbow(pp_state *ps)
{
    iris_rainbow *r = pp_rainbow_block(ps); /* new, a declared one copied */
    r->angle = (r->angle - 0.5 * r->width) * M_PI / 180.0;
    r->width *= M_PI / 180.0;
    iris_scene *sc = ps->scene;
    iris_rainbow **a = pp_alloc(ps, (size_t)(sc->n_rainbows + 1) * sizeof *a);
    if (sc->n_rainbows)
        memcpy(a, sc->rainbows, (size_t)sc->n_rainbows * sizeof *a);
    a[sc->n_rainbows++] = r;
    sc->rainbows = a;
}

/* sky_sphere { [SKY_ID] pigment{}... [emission C] [transforms] } */
iris_sky_sphere *pp_sky_sphere(pp_state *ps, const iris_sky_sphere *b)
{
    pp_token open = ps->tok;
    pp_expect(ps, T_LBRACE, "'{' after sky_sphere");
    iris_sky_sphere *s = pp_alloc(ps, sizeof *s);
    if (b) {
        *s = *b;
    } else {
        s->emission = 1;
        xf_identity(&s->transform);
    }
    s->loc = pp_loc(ps, &open);
    for (;;) {
        pp_next(ps);
        pp_token at = ps->tok;
        switch (at.kind) {
        case T_RBRACE: return s;
        case T_IDENT:
            if (at.val.kind == V_SKY_SPHERE) {
                *s = *at.val.u.sky;
                break;
            }
            goto bad;
        case T_PIGMENT: {
            iris_pigment **np = pp_alloc(ps, (size_t)(s->n_pigments + 1) *
                                                 sizeof *np);
            if (s->n_pigments)
                memcpy(np, s->pigments, (size_t)s->n_pigments * sizeof *np);
            np[s->n_pigments++] = pp_pigment(ps, NULL);
            s->pigments = np;
            break;
        }
        case T_EMISSION: {
            iris_colour c = pp_colour(ps);
            s->emission = (c.r + c.g + c.b) / 3;
            break;
        }
        default: {
            iris_transform x;
            if (pp_transform_item(ps, &x)) {
                xf_compose(&s->transform, &s->transform, &x);
                s->has_transform = true;
                break;
            }
        }
        bad: {
            pp_unexpected(ps, &at, "sky_sphere");
        }
        }
    }
}
