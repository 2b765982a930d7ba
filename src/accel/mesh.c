/* SPDX-License-Identifier: MIT */
/*
** mesh.c: triangle leaves (mesh, mesh2, triangle, smooth_triangle,
** height_field, bicubic_patch) as Embree triangle geometry.
**
** Vertices are transformed to world space once and stored as floats for
** Embree. Embree only proposes candidates: an intersection filter
** recomputes every candidate in double precision from those same float
** vertices (Moller-Trumbore) and decides against the query's double tmin
** and best t. The surface is therefore the float mesh, but distances and
** self-intersection decisions are exact to double rounding, which is what
** lets accel_epsilon() be as small as 1e-9 of the scene. Degenerate
** triangles (area below 1e-12 of the longest edge squared, or non-finite)
** are dropped at build time.
*/
#include "config.h"

#include "accel/node.h"

#include <math.h>
#include <string.h>

#include "iris/fn.h"
#include "image/heights.h"
#include "iris/image.h"
#include "math/transform.h"
#include "util/mem.h"

struct amesh {
    int n_verts, n_tris;
    float *verts;                  /* 3 floats per vertex + 1 of padding */
    unsigned *idx;                 /* 3 per triangle */
    vec3 *cn;                      /* 3 unit corner normals per triangle */
    iris_vec2 *cuv;                /* 3 corner uvs per triangle */
    const iris_texture **tex;      /* per triangle, NULL = the object's */
    RTCGeometry geom;
    RTCScene priv;
    vec3 inside_dir;               /* world, unit; zero = no inside */
    int hf_w, hf_h;                /* height field grid, object space */
    double *hf;
    vec3 *hf_vn;                   /* smooth height field: POV-Ray's unit
                                      normal per grid vertex (object space
                                      while building, then world) */
};

bool amesh_kind(enum iris_object_kind kind)
{
    return kind == IRIS_OBJ_TRIANGLE || kind == IRIS_OBJ_MESH ||
           kind == IRIS_OBJ_HEIGHT_FIELD || kind == IRIS_OBJ_BICUBIC_PATCH;
}

void amesh_free(struct amesh *m)
{
    if (!m)
        return;
    if (m->priv)
        rtcReleaseScene(m->priv);
    if (m->geom)
        rtcReleaseGeometry(m->geom);
    iris_free(m->verts);
    iris_free(m->idx);
    iris_free(m->cn);
    iris_free(m->cuv);
    iris_free(m->tex);
    iris_free(m->hf);
    iris_free(m->hf_vn);
    iris_free(m);
}

static vec3 vert(const struct amesh *m, unsigned i)
{
    const float *f = m->verts + 3 * (size_t)i;
    return v3(f[0], f[1], f[2]);
}

/*
** The crossing of world ray o + t·d with triangle 'prim', in double
** precision. Barycentrics are clamped into the triangle: Embree already
** decided that the ray meets it, and the recomputation may differ from its
** float answer by rounding only.
*/
static bool tri_hit(const struct anode *n, unsigned prim, vec3 o, vec3 d,
                    struct ahit *h)
{
    const struct amesh *m = n->mesh;
    if (prim >= (unsigned)m->n_tris)
        return false;
    const unsigned *ix = m->idx + 3 * (size_t)prim;
    vec3 p0 = vert(m, ix[0]), p1 = vert(m, ix[1]), p2 = vert(m, ix[2]);
    vec3 e1 = v3_sub(p1, p0), e2 = v3_sub(p2, p0);
    vec3 pv = v3_cross(d, e2);
    double det = v3_dot(e1, pv);
    if (det == 0 || !isfinite(det))
        return false;
    double inv = 1.0 / det;
    vec3 tv = v3_sub(o, p0);
    double u = v3_dot(tv, pv) * inv;
    vec3 qv = v3_cross(tv, e1);
    double v = v3_dot(d, qv) * inv;
    double t = v3_dot(e2, qv) * inv;
    if (!isfinite(t))
        return false;
    u = fmax(0, fmin(1, u));
    v = fmax(0, fmin(1 - u, v));
    double w = 1 - u - v;

    vec3 ng = v3_norm(v3_cross(e1, e2));
    vec3 sn = ng;
    if (m->hf_vn) {
        /* A smooth height field's normal as POV-Ray's HField::Normal
        ** takes it: bilinear in the cell between its four corner
        ** normals, not across the triangle */
        vec3 p = v3_madd(o, d, t);
        if (n->obj->has_transform)
            p = xf_inv_point(&n->obj->transform, p);
        int gw = m->hf_w, gh = m->hf_h;
        double gx = fmax(0, fmin(1, p.x)) * (gw - 1);
        double gz = fmax(0, fmin(1, p.z)) * (gh - 1);
        int px = (int)fmin(gx, gw - 2), pz = (int)fmin(gz, gh - 2);
        double x = gx - px, z = gz - pz;
        const vec3 *c0 = m->hf_vn + (size_t)pz * gw + px, *c1 = c0 + gw;
        vec3 r0 = v3_add(v3_scale(c0[0], 1 - x), v3_scale(c0[1], x));
        vec3 r1 = v3_add(v3_scale(c1[0], 1 - x), v3_scale(c1[1], x));
        vec3 bl = v3_add(v3_scale(r0, 1 - z), v3_scale(r1, z));
        if (v3_len2(bl) > 0 && isfinite(v3_len2(bl))) {
            sn = v3_norm(bl);
            if (v3_dot(ng, sn) < 0)
                ng = v3_neg(ng);
        }
    } else if (m->cn) {
        const vec3 *c = m->cn + 3 * (size_t)prim;
        vec3 s = v3_add(v3_add(v3_scale(c[0], w), v3_scale(c[1], u)),
                        v3_scale(c[2], v));
        if (v3_len2(s) > 0 && isfinite(v3_len2(s))) {
            sn = v3_norm(s);
            /* A smooth triangle faces the way its normals say */
            if (v3_dot(ng, sn) < 0)
                ng = v3_neg(ng);
        }
    }
    if (n->inverted) {
        ng = v3_neg(ng);
        sn = v3_neg(sn);
    }
    h->t = t;
    h->n = ng;
    h->sn = sn;
    h->uv.u = h->uv.v = 0;
    if (m->cuv) {
        const iris_vec2 *c = m->cuv + 3 * (size_t)prim;
        h->uv.u = w * c[0].u + u * c[1].u + v * c[2].u;
        h->uv.v = w * c[0].v + u * c[1].v + v * c[2].v;
    }
    h->leaf = n;
    h->texture = m->tex ? m->tex[prim] : NULL;
    return true;
}

/* Embree's intersection filter: decides every candidate in double. */
static void filter(const struct RTCFilterFunctionNArguments *args)
{
    if (args->N != 1 || !args->valid[0])
        return;
    struct qctx *q = (struct qctx *)args->context;
    const struct anode *n = args->geometryUserPtr;
    unsigned prim = ((const unsigned *)args->hit)[5]; /* RTCHit.primID */
    struct ahit h;
    if (!tri_hit(n, prim, q->o, q->d, &h) || !(h.t > q->tmin) ||
        !(h.t < q->tmax) || (q->mode == Q_NEAREST && (n->skip & q->skip))) {
        args->valid[0] = 0;
        return;
    }
    if (q->mode == Q_ALL) {
        ahit_push(q->all, &h);
        args->valid[0] = 0; /* keep going: every crossing is wanted */
        return;
    }
    q->best = h;
    q->tmax = h.t;
    q->found = true;
}

void qctx_embree_ray(const struct qctx *q, struct RTCRayHit *rh)
{
    memset(rh, 0, sizeof *rh);
    rh->ray.org_x = (float)q->o.x;
    rh->ray.org_y = (float)q->o.y;
    rh->ray.org_z = (float)q->o.z;
    rh->ray.dir_x = (float)q->d.x;
    rh->ray.dir_y = (float)q->d.y;
    rh->ray.dir_z = (float)q->d.z;
    /* Embree works in float: open its window a little on both sides and
    ** let the double-precision callbacks decide (half of tmin, and 1e-6
    ** relative beyond tmax, are far wider than float rounding) */
    /* fmax(0, 0.5 tmin) without libm's call: NaN and -0 give +0 too */
    double tnear = 0.5 * q->tmin;
    rh->ray.tnear = tnear > 0 ? (float)tnear : 0.0f;
    rh->ray.tfar = isfinite(q->tmax) && q->tmax < 1e37
                       ? (float)(q->tmax * (1 + 1e-6)) + 1e-30f
                       : INFINITY;
    rh->ray.mask = 0xffffffffu;
    rh->ray.flags = 0;
    rh->hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.primID = RTC_INVALID_GEOMETRY_ID;
    rh->hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

void amesh_hits(const struct anode *n, vec3 o, vec3 d, double tmin,
                double tmax, struct ahit_list *out)
{
    const struct amesh *m = n->mesh;
    if (!m->priv) {
        /* No scene of its own (not expected): test every triangle */
        for (int i = 0; i < m->n_tris; i++) {
            struct ahit h;
            const unsigned *ix = m->idx + 3 * (size_t)i;
            vec3 p0 = vert(m, ix[0]), p1 = vert(m, ix[1]), p2 = vert(m, ix[2]);
            vec3 e1 = v3_sub(p1, p0), e2 = v3_sub(p2, p0);
            vec3 pv = v3_cross(d, e2);
            double det = v3_dot(e1, pv);
            if (det == 0)
                continue;
            vec3 tv = v3_sub(o, p0);
            double u = v3_dot(tv, pv) / det;
            double v = v3_dot(d, v3_cross(tv, e1)) / det;
            if (u < 0 || v < 0 || u + v > 1)
                continue;
            if (tri_hit(n, (unsigned)i, o, d, &h) && h.t > tmin && h.t < tmax)
                ahit_push(out, &h);
        }
        return;
    }
    struct qctx q;
    memset(&q, 0, sizeof q);
    rtcInitIntersectContext(&q.ec);
    q.mode = Q_ALL;
    q.o = o;
    q.d = d;
    q.tmin = tmin;
    q.tmax = tmax;
    q.all = out;
    struct RTCRayHit rh;
    qctx_embree_ray(&q, &rh);
    rtcIntersect1(m->priv, &q.ec, &rh);
}

/* Height of the triangulated height field at object-space (x, z). */
static bool hf_height(const struct amesh *m, double x, double z, double *h)
{
    if (!(x >= 0 && x <= 1 && z >= 0 && z <= 1))
        return false;
    double gx = x * (m->hf_w - 1), gz = z * (m->hf_h - 1);
    int i = (int)fmin(gx, m->hf_w - 2), j = (int)fmin(gz, m->hf_h - 2);
    double fx = gx - i, fz = gz - j;
    const double *H = m->hf;
    double h00 = H[j * m->hf_w + i], h10 = H[j * m->hf_w + i + 1];
    double h01 = H[(j + 1) * m->hf_w + i], h11 = H[(j + 1) * m->hf_w + i + 1];
    /* The same diagonal split as the triangles */
    if (fx + fz <= 1)
        *h = h00 + fx * (h10 - h00) + fz * (h01 - h00);
    else
        *h = h11 + (1 - fx) * (h01 - h11) + (1 - fz) * (h10 - h11);
    return true;
}

bool amesh_inside(const struct anode *n, vec3 p)
{
    const struct amesh *m = n->mesh;
    if (!m)
        return false; /* a mesh left without usable triangles */
    if (m->hf) {
        /* POV-Ray: inside is below the surface, over the unit square */
        vec3 lp = n->obj->has_transform
                      ? xf_inv_point(&n->obj->transform, p) : p;
        double h;
        /* ... and under the water level (heightfield.cpp's Inside: y
        ** below the box's floor is inside); not below y = 0, where
        ** objects/csg/hfclip.pov shows POV-Ray's clipped column end */
        return hf_height(m, lp.x, lp.z, &h) && lp.y >= 0 &&
               lp.y < fmax(h, n->obj->u.height_field.water_level);
    }
    if (v3_len2(m->inside_dir) == 0)
        return false; /* POV-Ray: a mesh without inside_vector has none */
    /* Even-odd count of crossings along inside_vector */
    struct ahit_list l;
    ahit_list_init(&l);
    amesh_hits(n, p, m->inside_dir, 0, INFINITY, &l);
    bool in = l.n & 1;
    ahit_list_fini(&l);
    return in;
}

bool amesh_bounds(const struct anode *n, vec3 *lo, vec3 *hi)
{
    const struct amesh *m = n->mesh;
    if (m->n_tris == 0)
        return false;
    *lo = *hi = vert(m, m->idx[0]);
    for (int i = 0; i < 3 * m->n_tris; i++) {
        vec3 p = vert(m, m->idx[i]);
        *lo = v3_min(*lo, p);
        *hi = v3_max(*hi, p);
    }
    return true;
}

/* ---------------------------------------------------------------- */
/* Building                                                           */
/* ---------------------------------------------------------------- */

/* Triangles in object space, before the world transform. */
struct tri_src {
    int nv, nt;
    const vec3 *v;                 /* nv vertices */
    vec3 *vbuf;                    /* owned vertex storage, if any */
    int32_t *ix;                   /* 3 per triangle */
    vec3 *cn;                      /* 3 per triangle, or NULL */
    iris_vec2 *cuv;                /* 3 per triangle, or NULL */
    const iris_texture **tex;      /* per triangle, or NULL */
};

static void tri_src_free(struct tri_src *s)
{
    iris_free(s->vbuf);
    iris_free(s->ix);
    iris_free(s->cn);
    iris_free(s->cuv);
    iris_free(s->tex);
}

static const char *src_triangle(const iris_object *o, struct tri_src *s)
{
    s->nv = 3;
    s->nt = 1;
    s->v = o->u.triangle.p;
    s->ix = iris_malloc(3 * sizeof *s->ix);
    if (!s->ix)
        return "out of memory";
    for (int k = 0; k < 3; k++)
        s->ix[k] = k;
    if (o->u.triangle.smooth) {
        s->cn = iris_malloc(3 * sizeof *s->cn);
        if (!s->cn)
            return "out of memory";
        memcpy(s->cn, o->u.triangle.n, 3 * sizeof *s->cn);
    }
    if (o->u.triangle.has_uv) {
        s->cuv = iris_malloc(3 * sizeof *s->cuv);
        if (!s->cuv)
            return "out of memory";
        memcpy(s->cuv, o->u.triangle.uv, 3 * sizeof *s->cuv);
    }
    return NULL;
}

static const char *src_mesh(const iris_object *o, struct tri_src *s)
{
    const iris_mesh_data *md = &o->u.mesh;
    if (md->n_triangles <= 0 || md->n_vertices <= 0 || !md->vertices ||
        !md->tri_vertices)
        return "mesh has no triangles";
    s->nv = md->n_vertices;
    s->nt = md->n_triangles;
    s->v = md->vertices;
    size_t n3 = 3 * (size_t)s->nt;
    s->ix = iris_malloc(n3 * sizeof *s->ix);
    if (!s->ix)
        return "out of memory";
    memcpy(s->ix, md->tri_vertices, n3 * sizeof *s->ix);
    /* Normals: per corner through normal indices, else per vertex */
    const int32_t *ni = md->tri_normals;
    if (md->normals && md->n_normals > 0 &&
        (ni || md->n_normals == md->n_vertices)) {
        s->cn = iris_malloc(n3 * sizeof *s->cn);
        if (!s->cn)
            return "out of memory";
        for (size_t k = 0; k < n3; k++) {
            int32_t j = ni ? ni[k] : md->tri_vertices[k];
            s->cn[k] = j >= 0 && j < md->n_normals ? md->normals[j]
                                                   : v3(0, 0, 0);
        }
    }
    const int32_t *ui = md->tri_uvs;
    if (md->uvs && md->n_uvs > 0 && (ui || md->n_uvs == md->n_vertices)) {
        s->cuv = iris_malloc(n3 * sizeof *s->cuv);
        if (!s->cuv)
            return "out of memory";
        for (size_t k = 0; k < n3; k++) {
            int32_t j = ui ? ui[k] : md->tri_vertices[k];
            iris_vec2 z = { 0, 0 };
            s->cuv[k] = j >= 0 && j < md->n_uvs ? md->uvs[j] : z;
        }
    }
    if (md->tri_texture && md->textures && md->n_textures > 0) {
        s->tex = iris_malloc((size_t)s->nt * sizeof *s->tex);
        if (!s->tex)
            return "out of memory";
        for (int i = 0; i < s->nt; i++) {
            int32_t j = md->tri_texture[i];
            s->tex[i] = j >= 0 && j < md->n_textures ? md->textures[j] : NULL;
        }
    }
    return NULL;
}

/*
** A function value as a height, the way POV-Ray 3.7 stores it: in a
** 16-bit grey image, as unsigned short(float(v) * 65535), read back as
** HF_VAL(grey * 65535) over 65536 units (image.cpp GrayImage,
** imageutil.cpp image_height_at). The conversion does not clamp: on the
** x86 POV-Ray runs on it truncates to 32 bits and keeps the low 16, so a
** value of -0.1 becomes a height of 0.9 and 1.2 one of 0.2; scenes show
** those wrapped plates, and iris draws them too.
*/
static double hf_gray16(double v)
{
    float s = (float)v * 65535.0f;
    int32_t k = isfinite(s) && fabsf(s) < 2147483520.0f ? (int32_t)s
                                                          : INT32_MIN;
    uint16_t px = (uint16_t)((uint32_t)k & 0xffffu);
    float grey = (float)px / 65535.0f;
    return (double)(uint16_t)(grey * 65535.0f) / 65536.0;
}

/* Heights of the grid, 0..1, row j along z, column i along x. */
static const char *hf_grid(const iris_object *o, struct amesh *m)
{
    int w, h;
    if (o->u.height_field.fn) {
        w = o->u.height_field.fn_res_x;
        h = o->u.height_field.fn_res_y;
        if (w < 2 || h < 2 || (double)w * h > 64e6)
            return "height_field function resolution is out of range";
        m->hf = iris_malloc((size_t)w * h * sizeof *m->hf);
        if (!m->hf)
            return "out of memory";
        /* POV-Ray fills image row r with F(x, r/(h-1), 0) and, as for
        ** image files, makes row r the grid row z = h-1-r (heightfield.cpp),
        ** so the function's y runs against z: z = 1 - y. */
        for (int j = 0; j < h; j++)
            for (int i = 0; i < w; i++) {
                double args[3] = { (double)i / (w - 1),
                                   (double)(h - 1 - j) / (h - 1), 0 };
                m->hf[j * w + i] =
                    hf_gray16(iris_fn_eval(o->u.height_field.fn, args, 3));
            }
    } else if (o->u.height_field.image && o->u.height_field.image->path) {
        double *px;
        char err[256];
        /* POV-Ray's heights: palette indices, grey, or red and green as
        ** the high and low byte (image/heights.h) */
        if (iris_image_read_heights(o->u.height_field.image->path, &px, &w,
                                    &h, err, sizeof err) != IRIS_OK)
            return "height_field image cannot be read";
        if (w < 2 || h < 2) {
            iris_free(px);
            return "height_field image is smaller than 2x2";
        }
        m->hf = iris_malloc((size_t)w * h * sizeof *m->hf);
        if (!m->hf) {
            iris_free(px);
            return "out of memory";
        }
        /* Row 0 (top of the image) is z = 1. */
        for (int j = 0; j < h; j++)
            for (int i = 0; i < w; i++)
                m->hf[j * w + i] = px[(size_t)(h - 1 - j) * w + i];
        iris_free(px);
    } else {
        return "height_field has no image or function";
    }
    m->hf_w = w;
    m->hf_h = h;
    return NULL;
}

/* One of the four triangles POV-Ray fans around a grid vertex
** (heightfield.cpp add_single_normal), in its raw units: x and z grid
** steps, y 16-bit height values; its unit normal, turned up, is added. */
static int hf_fan(const struct amesh *m, int x0, int z0, int x1, int z1,
                  int x2, int z2, vec3 *sum)
{
    int w = m->hf_w, h = m->hf_h;
    if (x0 < 0 || z0 < 0 || x1 < 0 || z1 < 0 || x2 < 0 || z2 < 0 ||
        x0 >= w || z0 >= h || x1 >= w || z1 >= h || x2 >= w || z2 >= h)
        return 0;
    vec3 v0 = v3(x0, m->hf[z0 * w + x0] * 65536.0, z0);
    vec3 v1 = v3(x1, m->hf[z1 * w + x1] * 65536.0, z1);
    vec3 v2 = v3(x2, m->hf[z2 * w + x2] * 65536.0, z2);
    vec3 nt = v3_cross(v3_sub(v2, v0), v3_sub(v1, v0));
    if (!(v3_len2(nt) > 0))
        return 0;
    nt = v3_norm(nt);
    if (nt.y < 0)
        nt = v3_neg(nt);
    *sum = v3_add(*sum, nt);
    return 1;
}

/*
** A smooth height field's normal at grid vertex (i, j) as POV-Ray
** computes it (smooth_height_field): the sum of the unit normals of the
** four triangles fanned around it in raw units, normalised and stored as
** shorts (32767 N), then taken to the unit square (the raw-to-unit
** scaling's inverse transpose: x (w-1), y 65536, z (h-1)).
*/
static vec3 hf_pov_normal(const struct amesh *m, int i, int j)
{
    vec3 sum = v3(0, 0, 0);
    hf_fan(m, i, j, i + 1, j, i, j + 1, &sum);
    hf_fan(m, i, j, i, j + 1, i - 1, j, &sum);
    hf_fan(m, i, j, i - 1, j, i, j - 1, &sum);
    hf_fan(m, i, j, i, j - 1, i + 1, j, &sum);
    if (!(v3_len2(sum) > 0))
        return v3(0, 1, 0);
    sum = v3_norm(sum);
    vec3 q = v3((short)(32767 * sum.x), (short)(32767 * sum.y),
                (short)(32767 * sum.z));
    return v3(q.x * (m->hf_w - 1), q.y * 65536.0, q.z * (m->hf_h - 1));
}

/* A height_field's triangles as they are built: the grid's vertices
** first, then the points where water_level cuts edges; with 'smooth', one
** normal per vertex. */
struct hf_build {
    vec3 *v, *vn;
    int nv, cap_v;
    int32_t *ix;
    int nt, cap_t;
};

static bool hf_grow(void **p, int *cap, int need, size_t size)
{
    if (need <= *cap)
        return true;
    int c = *cap > 0 ? *cap : 1024;
    while (c < need) {
        if (c > INT32_MAX / 2)
            return false;
        c *= 2;
    }
    void *q = iris_realloc(*p, (size_t)c * size);
    if (!q)
        return false;
    *p = q;
    *cap = c;
    return true;
}

/* The point where the level y = 'wl' cuts edge a-b (one end below it,
** one at or above it), its normal interpolated the same way. Both
** triangles of a shared edge compute it from the same ordered ends, so
** the cut surface has no cracks. */
static int hf_cut(struct hf_build *b, int va, int vb, double wl)
{
    if (va > vb) {
        int t = va;
        va = vb;
        vb = t;
    }
    int old_cap = b->cap_v;
    if (!hf_grow((void **)&b->v, &b->cap_v, b->nv + 1, sizeof *b->v))
        return -1;
    if (b->vn && b->cap_v != old_cap) {
        void *q = iris_realloc(b->vn, (size_t)b->cap_v * sizeof *b->vn);
        if (!q)
            return -1;
        b->vn = q;
    }
    vec3 pa = b->v[va], pb = b->v[vb];
    double t = (wl - pa.y) / (pb.y - pa.y);
    vec3 p = v3_add(pa, v3_scale(v3_sub(pb, pa), t));
    p.y = wl;
    b->v[b->nv] = p;
    if (b->vn)
        b->vn[b->nv] = v3_add(b->vn[va],
                              v3_scale(v3_sub(b->vn[vb], b->vn[va]), t));
    return b->nv++;
}

static bool hf_tri(struct hf_build *b, int a, int c, int d)
{
    if (!hf_grow((void **)&b->ix, &b->cap_t, 3 * (b->nt + 1), sizeof *b->ix))
        return false;
    b->ix[3 * b->nt] = a;
    b->ix[3 * b->nt + 1] = c;
    b->ix[3 * b->nt + 2] = d;
    b->nt++;
    return true;
}

/*
** Triangle t[0..2] of the grid, cut at water_level 'wl'. POV-Ray clips
** the ray to the height field's box, whose floor is the water level
** (heightfield.cpp: bounding_corner1[Y] = 65536 * water_level), so the
** surface below the level is not there and a triangle crossing it ends
** at the level; there is no lid. Keeping the part at or above the level
** (Sutherland-Hodgman against one plane) leaves 0 to 4 corners.
*/
static bool hf_clip_tri(struct hf_build *b, const int t[3], double wl)
{
    int poly[4], n = 0;
    for (int k = 0; k < 3; k++) {
        int p = t[k], q = t[(k + 1) % 3];
        bool pin = b->v[p].y >= wl, qin = b->v[q].y >= wl;
        if (pin)
            poly[n++] = p;
        if (pin != qin) {
            int c = hf_cut(b, p, q, wl);
            if (c < 0)
                return false;
            poly[n++] = c;
        }
    }
    for (int k = 1; k + 1 < n; k++)
        if (!hf_tri(b, poly[0], poly[k], poly[k + 1]))
            return false;
    return true;
}

static const char *src_height_field(const iris_object *o, struct amesh *m,
                                    struct tri_src *s)
{
    const char *why = hf_grid(o, m);
    if (why)
        return why;
    int w = m->hf_w, h = m->hf_h;
    struct hf_build b = { 0 };
    b.nv = w * h;
    b.cap_v = b.nv;
    b.v = iris_malloc((size_t)b.nv * sizeof *b.v);
    b.cap_t = (w - 1) * (h - 1) * 6;
    b.ix = iris_malloc((size_t)b.cap_t * sizeof *b.ix);
    bool smooth = o->u.height_field.smooth;
    if (smooth)
        b.vn = iris_malloc((size_t)b.nv * sizeof *b.vn);
    s->vbuf = b.v;
    s->ix = b.ix;
    if (!b.v || !b.ix || (smooth && !b.vn)) {
        iris_free(b.vn);
        return "out of memory";
    }
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            b.v[j * w + i] = v3((double)i / (w - 1), m->hf[j * w + i],
                                (double)j / (h - 1));
            if (smooth)
                b.vn[j * w + i] = hf_pov_normal(m, i, j);
        }
    double wl = o->u.height_field.water_level;
    bool ok = true;
    for (int j = 0; ok && j + 1 < h; j++)
        for (int i = 0; ok && i + 1 < w; i++) {
            int a = j * w + i, bb = a + 1, c = a + w, d = c + 1;
            /* POV-Ray's split: the diagonal from (i+1, j) to (i, j+1) */
            int t1[3] = { a, bb, c }, t2[3] = { bb, d, c };
            if (wl > 0)
                ok = hf_clip_tri(&b, t1, wl) && hf_clip_tri(&b, t2, wl);
            else
                ok = hf_tri(&b, a, bb, c) && hf_tri(&b, bb, d, c);
        }
    /* hf_cut and hf_tri may have moved the buffers */
    s->vbuf = b.v;
    s->v = b.v;
    s->ix = b.ix;
    s->nv = b.nv;
    s->nt = b.nt;
    if (!ok) {
        iris_free(b.vn);
        return "out of memory";
    }
    if (smooth && b.nt > 0) {
        s->cn = iris_malloc(3 * (size_t)b.nt * sizeof *s->cn);
        if (!s->cn) {
            iris_free(b.vn);
            return "out of memory";
        }
        for (int k = 0; k < 3 * b.nt; k++)
            s->cn[k] = b.vn[b.ix[k]];
        /* the grid's own normals, for the bilinear shading normal */
        m->hf_vn = iris_realloc(b.vn, (size_t)w * h * sizeof *m->hf_vn);
        return m->hf_vn ? NULL : "out of memory";
    }
    iris_free(b.vn);
    return NULL;
}

/*
** bicubic_patch: POV-Ray's subdivision into flat-enough cells of two
** triangles each, with the patch's own normals (geometry/bicubic.c).
*/
static const char *src_bicubic(const iris_object *o, struct tri_src *s)
{
    int nt = 0;
    vec3 *p = NULL, *n = NULL;
    iris_vec2 *uv = NULL;
    const char *why = geom_bicubic_tessellate(o, &nt, &p, &n, &uv);
    if (why)
        return why;
    s->nv = 3 * nt;
    s->nt = nt;
    s->vbuf = p;
    s->v = p;
    s->cn = n;
    s->cuv = uv;
    s->ix = iris_malloc(3 * (size_t)(nt ? nt : 1) * sizeof *s->ix);
    if (!s->ix)
        return "out of memory";
    for (int i = 0; i < 3 * nt; i++)
        s->ix[i] = i;
    return NULL;
}

const char *amesh_build(struct anode *n, RTCDevice dev, bool private_scene)
{
    const iris_object *o = n->obj;
    struct amesh *m = iris_calloc(1, sizeof *m);
    if (!m)
        return "out of memory";
    n->mesh = m;
    struct tri_src s;
    memset(&s, 0, sizeof s);
    const char *why = o->kind == IRIS_OBJ_TRIANGLE ? src_triangle(o, &s)
                      : o->kind == IRIS_OBJ_MESH   ? src_mesh(o, &s)
                      : o->kind == IRIS_OBJ_BICUBIC_PATCH
                          ? src_bicubic(o, &s)
                          : src_height_field(o, m, &s);
    if (why) {
        tri_src_free(&s);
        return why;
    }

    /* World-space vertices */
    const xform *xf = o->has_transform ? &o->transform : NULL;
    m->n_verts = s.nv;
    m->verts = iris_malloc((3 * (size_t)s.nv + 1) * sizeof *m->verts);
    m->idx = iris_malloc(3 * (size_t)(s.nt ? s.nt : 1) * sizeof *m->idx);
    if (s.cn)
        m->cn = iris_malloc(3 * (size_t)(s.nt ? s.nt : 1) * sizeof *m->cn);
    if (s.cuv)
        m->cuv = iris_malloc(3 * (size_t)(s.nt ? s.nt : 1) * sizeof *m->cuv);
    if (s.tex)
        m->tex = iris_malloc((size_t)(s.nt ? s.nt : 1) * sizeof *m->tex);
    if (!m->verts || !m->idx || (s.cn && !m->cn) || (s.cuv && !m->cuv) ||
        (s.tex && !m->tex)) {
        tri_src_free(&s);
        return "out of memory";
    }
    for (int i = 0; i < s.nv; i++) {
        vec3 p = xf ? xf_point(xf, s.v[i]) : s.v[i];
        m->verts[3 * i] = (float)p.x;
        m->verts[3 * i + 1] = (float)p.y;
        m->verts[3 * i + 2] = (float)p.z;
    }
    m->verts[3 * (size_t)s.nv] = 0;

    if (m->hf_vn)
        for (size_t k = 0; k < (size_t)m->hf_w * m->hf_h; k++) {
            vec3 nn = xf ? xf_normal(xf, m->hf_vn[k]) : m->hf_vn[k];
            m->hf_vn[k] = isfinite(v3_len2(nn)) && v3_len2(nn) > 0
                              ? v3_norm(nn) : v3(0, 1, 0);
        }

    /* Keep the valid, non-degenerate triangles */
    int kept = 0;
    for (int i = 0; i < s.nt; i++) {
        const int32_t *ix = s.ix + 3 * (size_t)i;
        if (ix[0] < 0 || ix[1] < 0 || ix[2] < 0 || ix[0] >= s.nv ||
            ix[1] >= s.nv || ix[2] >= s.nv)
            continue;
        vec3 p0 = vert(m, (unsigned)ix[0]), p1 = vert(m, (unsigned)ix[1]);
        vec3 p2 = vert(m, (unsigned)ix[2]);
        vec3 e1 = v3_sub(p1, p0), e2 = v3_sub(p2, p0), e3 = v3_sub(p2, p1);
        double area2 = v3_len(v3_cross(e1, e2));
        double emax2 = fmax(v3_len2(e1), fmax(v3_len2(e2), v3_len2(e3)));
        if (!isfinite(area2) || !isfinite(emax2) || !(area2 > 1e-12 * emax2))
            continue;
        for (int k = 0; k < 3; k++) {
            m->idx[3 * kept + k] = (unsigned)ix[k];
            if (m->cn) {
                vec3 nn = s.cn[3 * i + k];
                nn = xf ? xf_normal(xf, nn) : nn;
                m->cn[3 * kept + k] = isfinite(v3_len2(nn)) ? v3_norm(nn)
                                                            : v3(0, 0, 0);
            }
            if (m->cuv)
                m->cuv[3 * kept + k] = s.cuv[3 * i + k];
        }
        if (m->tex)
            m->tex[kept] = s.tex[i];
        kept++;
    }
    m->n_tris = kept;
    tri_src_free(&s);
    if (kept == 0)
        return "mesh has no usable triangles";

    if (o->kind == IRIS_OBJ_MESH) {
        vec3 iv = o->u.mesh.inside_vector;
        if (v3_len2(iv) > 0) {
            iv = xf ? xf_dir(xf, iv) : iv;
            m->inside_dir = v3_norm(iv);
        }
    }

    m->geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
    if (!m->geom)
        return "Embree cannot create the triangles";
    rtcSetSharedGeometryBuffer(m->geom, RTC_BUFFER_TYPE_VERTEX, 0,
                               RTC_FORMAT_FLOAT3, m->verts, 0,
                               3 * sizeof(float), (size_t)m->n_verts);
    rtcSetSharedGeometryBuffer(m->geom, RTC_BUFFER_TYPE_INDEX, 0,
                               RTC_FORMAT_UINT3, m->idx, 0,
                               3 * sizeof(unsigned), (size_t)m->n_tris);
    rtcSetGeometryIntersectFilterFunction(m->geom, filter);
    rtcSetGeometryUserData(m->geom, n);
    rtcCommitGeometry(m->geom);

    if (private_scene || v3_len2(m->inside_dir) > 0) {
        m->priv = rtcNewScene(dev);
        if (!m->priv)
            return "Embree cannot create a scene";
        rtcSetSceneFlags(m->priv, RTC_SCENE_FLAG_ROBUST);
        rtcAttachGeometry(m->priv, m->geom);
        rtcCommitScene(m->priv);
    }
    return NULL;
}

bool amesh_attach(struct anode *n, RTCDevice dev, RTCScene scene)
{
    (void)dev;
    if (!n->mesh || !n->mesh->geom)
        return false;
    rtcAttachGeometry(scene, n->mesh->geom);
    return true;
}
