/* SPDX-License-Identifier: MIT */
/*
** test_accel_pov.c: silhouettes and depths against POV-Ray's output.
**
** Each case describes one shape twice: as SDL for POV-Ray and as the
** iris_object the parser would build. POV-Ray renders all cases white on
** black in one image, each in its own 64x64 tile of an orthographic view
** (no antialiasing); the same rays go through accel_intersect(). The hit masks must agree except along
** the outline: at most 0.5% of the pixels (20 of 4096; an outline 64
** pixels wide has ~200 edge pixels, where flattened splines and float
** rounding may flip a few) and the object must cover at least 150
** pixels. The per-case count goes to stderr. Skipped when $POVRAY is not
** set (make check sets it).
*/
#include "config.h"

#include "testutil.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "accel/accel.h"
#include "iris/fn.h"
#include "math/transform.h"
#include "util/arena.h"

#define W 64
#define H 64

static iris_texture tex;

struct pov_case {
    const char *name;
    const char *sdl;               /* the object, POV-Ray syntax */
    iris_object *(*make)(iris_arena *ar);
};

static iris_object *new_obj(iris_arena *ar, enum iris_object_kind k)
{
    iris_object *o = arena_alloc(ar, sizeof *o);
    o->kind = k;
    o->texture = &tex;
    iris_transform_identity(&o->transform);
    return o;
}

static void then(iris_object *o, const xform *x)
{
    xf_compose(&o->transform, &o->transform, x);
    o->has_transform = true;
}

static void then_rotate(iris_object *o, vec3 deg)
{
    xform x;
    xf_rotate(&x, deg);
    then(o, &x);
}

static iris_object *make_torus(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_TORUS);
    o->u.torus.major = 1.2;
    o->u.torus.minor = 0.35;
    then_rotate(o, v3(-60, 20, 0));
    return o;
}

static iris_vec2 *pts(iris_arena *ar, const double *xy, int n)
{
    iris_vec2 *p = arena_array(ar, (size_t)n, sizeof *p);
    for (int i = 0; i < n; i++) {
        p[i].u = xy[2 * i];
        p[i].v = xy[2 * i + 1];
    }
    return p;
}

static const double lathe_pts[] = { 0, -1.5, 1.2, -1.2, 0.4, 0, 1.1, 1.2,
                                    0, 1.5, 0.2, 1.8 };
static iris_object *make_lathe(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_LATHE);
    o->u.lathe.spline = IRIS_SPLINE_CUBIC;
    o->u.lathe.n_points = 6;
    o->u.lathe.points = pts(ar, lathe_pts, 6);
    then_rotate(o, v3(-30, 0, 0));
    return o;
}

static const double prism_pts[] = { -1, 0.5, 1, 0, 0.5, 1, -1, 0.8,
                                     -1.2, -1, 1, 0, 0.5, 1 };
static iris_object *make_prism(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_PRISM);
    o->u.prism.spline = IRIS_SPLINE_CUBIC;
    o->u.prism.height1 = -0.3;
    o->u.prism.height2 = 0.3;
    o->u.prism.n_points = 7;
    o->u.prism.points = pts(ar, prism_pts, 7);
    then_rotate(o, v3(-70, 0, 0));
    return o;
}

static const double sor_pts[] = { 0.5, -2, 0.6, -1.2, 1.3, -0.5, 0.4, 0.6,
                                  1.0, 1.3, 1.2, 2 };
static iris_object *make_sor(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_SOR);
    o->u.lathe.n_points = 6;
    o->u.lathe.points = pts(ar, sor_pts, 6);
    then_rotate(o, v3(-25, 0, 0));
    return o;
}

static iris_object *make_superellipsoid(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_SUPERELLIPSOID);
    o->u.superellipsoid.e = 0.3;
    o->u.superellipsoid.n = 2.2;
    xform x;
    xf_scale(&x, v3(1.4, 1.2, 1));
    then(o, &x);
    then_rotate(o, v3(30, 40, 0));
    return o;
}

static iris_object *make_blob(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_BLOB);
    iris_blob_component *c = arena_array(ar, 3, sizeof *c);
    c[0].kind = 0;
    c[0].a = v3(-0.6, 0, 0);
    c[0].radius = 1.2;
    c[0].strength = 1;
    c[1].kind = 0;
    c[1].a = v3(0.7, 0.3, 0);
    c[1].radius = 1;
    c[1].strength = 1;
    c[2].kind = 1;
    c[2].a = v3(-1, -1, 0);
    c[2].b = v3(1, -1.2, 0.5);
    c[2].radius = 0.6;
    c[2].strength = 1.5;
    o->u.blob.threshold = 0.4;
    o->u.blob.n_components = 3;
    o->u.blob.components = c;
    return o;
}

static iris_object *make_text(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_TEXT);
    o->u.text.font = "timrom.ttf";
    o->u.text.string = "Iris";
    o->u.text.thickness = 0.5;
    xform x;
    xf_translate(&x, v3(-0.8, -0.3, 0));
    then(o, &x);
    xf_scale(&x, v3(2, 2, 2));
    then(o, &x);
    then_rotate(o, v3(0, 25, 0));
    return o;
}

static iris_object *make_csg(iris_arena *ar)
{
    iris_object *b = new_obj(ar, IRIS_OBJ_BOX);
    b->u.box.lo = v3(-1.2, -1.2, -1.2);
    b->u.box.hi = v3(1.2, 1.2, 1.2);
    iris_object *s = new_obj(ar, IRIS_OBJ_SPHERE);
    s->u.sphere.radius = 1.5;
    iris_object *c = new_obj(ar, IRIS_OBJ_CYLINDER);
    c->u.cylinder.base = v3(0, 0, -2);
    c->u.cylinder.cap = v3(0, 0, 2);
    c->u.cylinder.radius = 0.6;
    iris_object *i = new_obj(ar, IRIS_OBJ_INTERSECTION);
    i->texture = NULL;
    i->u.csg.n_children = 2;
    i->u.csg.children = arena_array(ar, 2, sizeof(iris_object *));
    i->u.csg.children[0] = b;
    i->u.csg.children[1] = s;
    iris_object *d = new_obj(ar, IRIS_OBJ_DIFFERENCE);
    d->texture = NULL;
    d->u.csg.n_children = 2;
    d->u.csg.children = arena_array(ar, 2, sizeof(iris_object *));
    d->u.csg.children[0] = i;
    d->u.csg.children[1] = c;
    iris_object *pl = new_obj(ar, IRIS_OBJ_PLANE);
    pl->u.plane.normal = v3(1, 1, 0);
    pl->u.plane.distance = 0.8;
    d->n_clipped_by = 1;
    d->clipped_by = arena_array(ar, 1, sizeof(iris_object *));
    d->clipped_by[0] = pl;
    /* The parser folds the CSG's transform into every child */
    iris_object *all[5] = { b, s, c, i, d };
    for (int k = 0; k < 5; k++)
        then_rotate(all[k], v3(25, 35, 0));
    then_rotate(pl, v3(25, 35, 0));
    return d;
}

static iris_object *make_cone(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_CONE);
    o->u.cone.base = v3(-1, -1, 0);
    o->u.cone.cap = v3(1, 1.2, 0.5);
    o->u.cone.base_radius = 1;
    o->u.cone.cap_radius = 0.3;
    return o;
}

/* x² - y² + z² + 0.5xy + 0.3y = 0.5 (quadric order: x², y², z², xy, xz,
** yz, x, y, z, 1) clipped by a box. */
static iris_object *make_quadric(iris_arena *ar)
{
    static double q[10] = { 1, -1, 1, 0.5, 0, 0, 0, 0.3, 0, -0.5 };
    iris_object *o = new_obj(ar, IRIS_OBJ_QUADRIC);
    o->u.poly.order = 2;
    o->u.poly.n_coeffs = 10;
    o->u.poly.coeffs = q;
    iris_object *b = new_obj(ar, IRIS_OBJ_BOX);
    b->u.box.lo = v3(-1.5, -1.5, -1.5);
    b->u.box.hi = v3(1.5, 1.5, 1.5);
    o->n_clipped_by = 1;
    o->clipped_by = arena_array(ar, 1, sizeof(iris_object *));
    o->clipped_by[0] = b;
    then_rotate(o, v3(-30, 0, 20));
    then_rotate(b, v3(-30, 0, 20));
    return o;
}

/* x*x + 2*y*y + z*z - 1.5 as fn.h stack code. */
static iris_object *make_isosurface(iris_arena *ar)
{
    static const enum iris_fn_op ops[] = {
        IRIS_FN_PARAM, IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_CONST,
        IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_ADD,
        IRIS_FN_PARAM, IRIS_FN_PARAM, IRIS_FN_MUL, IRIS_FN_ADD, IRIS_FN_CONST,
        IRIS_FN_SUB
    };
    static const int args[] = { 0, 0, 0, 0, 1, 0, 1, 0, 0, 2, 2, 0, 0, 0, 0 };
    int n = (int)(sizeof ops / sizeof ops[0]);
    iris_fn *f = arena_alloc(ar, sizeof *f);
    f->n_params = 3;
    f->n_code = n;
    f->code = arena_array(ar, (size_t)n, sizeof *f->code);
    for (int i = 0; i < n; i++) {
        f->code[i].op = ops[i];
        f->code[i].arg = args[i];
    }
    f->code[3].value = 2;
    f->code[13].value = 1.5;
    f->max_stack = 8;
    f->n_results = 1;
    iris_object *o = new_obj(ar, IRIS_OBJ_ISOSURFACE);
    o->u.isosurface.fn = f;
    o->u.isosurface.lo = v3(-1.4, -1.4, -1.4);
    o->u.isosurface.hi = v3(1.4, 1.4, 1.4);
    o->u.isosurface.threshold = 0;
    o->u.isosurface.accuracy = 1e-3;
    o->u.isosurface.max_gradient = 6;
    o->u.isosurface.max_trace = 1;
    then_rotate(o, v3(0, 0, 30));
    return o;
}

static iris_object *make_polygon(iris_arena *ar)
{
    static const vec3 p[10] = { { -1.5, -1.5, 0 }, { 1.5, -1.5, 0 },
                                { 0, 1.5, 0 }, { -1.5, -1.5, 0 },
                                { -0.5, -0.8, 0 }, { 0.5, -0.8, 0 },
                                { 0, 0.3, 0 }, { -0.5, -0.8, 0 } };
    iris_object *o = new_obj(ar, IRIS_OBJ_POLYGON);
    o->u.polygon.n_points = 8;
    o->u.polygon.points = arena_array(ar, 8, sizeof(vec3));
    memcpy(o->u.polygon.points, p, 8 * sizeof(vec3));
    then_rotate(o, v3(30, 30, 0));
    return o;
}

static iris_object *make_disc(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_DISC);
    o->u.disc.centre = v3(0.2, 0, 0);
    o->u.disc.normal = v3(0.3, 0.4, -1);
    o->u.disc.radius = 1.6;
    o->u.disc.hole_radius = 0.7;
    return o;
}

static iris_object *make_bicubic(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_BICUBIC_PATCH);
    o->u.bicubic.type = 1;
    o->u.bicubic.u_steps = 3;
    o->u.bicubic.v_steps = 3;
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            o->u.bicubic.points[4 * r + c] =
                v3(c - 1.5, r - 1.5, (r == 1 || r == 2) && (c == 1 || c == 2)
                                         ? 2.5 : 0);
    then_rotate(o, v3(-60, 10, 0));
    return o;
}

static iris_object *make_julia(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_JULIA_FRACTAL);
    const double c[4] = { -0.083, 0.0, -0.83, -0.025 };
    for (int k = 0; k < 4; k++)
        o->u.julia.data[k] = c[k];
    o->u.julia.type = 0;
    o->u.julia.fn = IRIS_JULIA_SQR;
    o->u.julia.iterations = 8;
    o->u.julia.precision = 15;
    xform x;
    xf_scale(&x, v3(1.3, 1.3, 1.3));
    then(o, &x);
    then_rotate(o, v3(-35, 30, 0));
    return o;
}

static iris_object *make_julia_cube(iris_arena *ar)
{
    iris_object *o = make_julia(ar);
    o->u.julia.fn = IRIS_JULIA_CUBE;
    o->u.julia.data[0] = -0.2;
    o->u.julia.data[2] = 0.5;
    o->u.julia.slice = v3(0, 0.3, 0);
    o->u.julia.data[5] = 1;
    o->u.julia.distance = 0.1;
    return o;
}

/* The directory POV-Ray runs in, where the height field image is. */
static char work_dir[64];

/* A 16x16 grey image: a smooth bump, 0 at the rim, 255 in the middle. */
static bool write_bump(const char *path)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return false;
    fprintf(f, "P5\n16 16\n255\n");
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            double dx = (x - 7.5) / 7.5, dy = (y - 5.5) / 7.5;
            double v = fmax(0, 1 - dx * dx - dy * dy);
            fputc((int)lround(255 * v), f);
        }
    return fclose(f) == 0;
}

static iris_object *make_height_field(iris_arena *ar)
{
    iris_object *o = new_obj(ar, IRIS_OBJ_HEIGHT_FIELD);
    iris_image_ref *ref = arena_alloc(ar, sizeof *ref);
    char path[128];
    snprintf(path, sizeof path, "%s/hf.pgm", work_dir);
    ref->path = arena_strdup(ar, path);
    o->u.height_field.image = ref;
    xform x;
    xf_translate(&x, v3(-0.5, 0, -0.5));
    then(o, &x);
    xf_scale(&x, v3(3, 1.5, 3));
    then(o, &x);
    then_rotate(o, v3(-50, 20, 0));
    return o;
}

/* A box and a sphere (merged or united), cut open by clipped_by so that
** the inner surfaces face the camera: the union shows the sphere inside
** the box, the merge does not. */
static iris_object *make_cut(iris_arena *ar, enum iris_object_kind kind)
{
    iris_object *b = new_obj(ar, IRIS_OBJ_BOX);
    b->u.box.lo = v3(-1.2, -1.2, -1.2);
    b->u.box.hi = v3(1.2, 1.2, 1.2);
    iris_object *s = new_obj(ar, IRIS_OBJ_SPHERE);
    s->u.sphere.centre = v3(0.5, 0.5, 0);
    s->u.sphere.radius = 1;
    iris_object *u = new_obj(ar, kind);
    u->texture = NULL;
    u->u.csg.n_children = 2;
    u->u.csg.children = arena_array(ar, 2, sizeof(iris_object *));
    u->u.csg.children[0] = b;
    u->u.csg.children[1] = s;
    iris_object *pl = new_obj(ar, IRIS_OBJ_PLANE);
    pl->u.plane.normal = v3(0, 0, -1);
    pl->u.plane.distance = 0.2;
    u->n_clipped_by = 1;
    u->clipped_by = arena_array(ar, 1, sizeof(iris_object *));
    u->clipped_by[0] = pl;
    iris_object *all[4] = { b, s, u, pl };
    for (int k = 0; k < 4; k++)
        then_rotate(all[k], v3(15, -20, 0));
    return u;
}

static iris_object *make_cut_union(iris_arena *ar)
{
    return make_cut(ar, IRIS_OBJ_UNION);
}

static iris_object *make_cut_merge(iris_arena *ar)
{
    return make_cut(ar, IRIS_OBJ_MERGE);
}

/* intersection with an inverted sphere: a bite out of a sphere's front. */
static iris_object *make_bite(iris_arena *ar)
{
    iris_object *a = new_obj(ar, IRIS_OBJ_SPHERE);
    a->u.sphere.radius = 1.8;
    iris_object *b = new_obj(ar, IRIS_OBJ_SPHERE);
    b->u.sphere.centre = v3(0.3, 0.2, -1.2);
    b->u.sphere.radius = 1.1;
    b->inverse = true;
    iris_object *i = new_obj(ar, IRIS_OBJ_INTERSECTION);
    i->texture = NULL;
    i->u.csg.n_children = 2;
    i->u.csg.children = arena_array(ar, 2, sizeof(iris_object *));
    i->u.csg.children[0] = a;
    i->u.csg.children[1] = b;
    return i;
}

static const struct pov_case cases[] = {
    { "torus", "torus { 1.2, 0.35 rotate <-60, 20, 0> }", make_torus },
    { "lathe", "lathe { cubic_spline 6, <0,-1.5>, <1.2,-1.2>, <0.4,0>, "
               "<1.1,1.2>, <0,1.5>, <0.2,1.8> rotate -30*x }", make_lathe },
    { "prism", "prism { cubic_spline -0.3, 0.3, 7, <-1,0.5>, <1,0>, "
               "<0.5,1>, <-1,0.8>, <-1.2,-1>, <1,0>, <0.5,1> "
               "rotate -70*x }", make_prism },
    { "sor", "sor { 6, <0.5,-2>, <0.6,-1.2>, <1.3,-0.5>, <0.4,0.6>, "
             "<1.0,1.3>, <1.2,2> rotate -25*x }", make_sor },
    { "superellipsoid", "superellipsoid { <0.3, 2.2> scale <1.4,1.2,1> "
                        "rotate <30,40,0> }", make_superellipsoid },
    { "blob", "blob { threshold 0.4 sphere { <-0.6,0,0>, 1.2, 1 } "
              "sphere { <0.7,0.3,0>, 1, 1 } "
              "cylinder { <-1,-1,0>, <1,-1.2,0.5>, 0.6, 1.5 } }",
      make_blob },
    { "text", "text { ttf \"timrom.ttf\" \"Iris\" 0.5, 0 "
              "translate <-0.8,-0.3,0> scale 2 rotate 25*y }", make_text },
    { "csg", "difference { intersection { box { -1.2, 1.2 } sphere { 0, 1.5 } }"
             " cylinder { -2*z, 2*z, 0.6 } "
             "clipped_by { plane { <1,1,0>, 0.8 } } rotate <25,35,0> }",
      make_csg },
    { "cone", "cone { <-1,-1,0>, 1, <1,1.2,0.5>, 0.3 }", make_cone },
    { "quadric", "quadric { <1,-1,1>, <0.5,0,0>, <0,0.3,0>, -0.5 "
                 "clipped_by { box { -1.5, 1.5 } } rotate <-30,0,20> }",
      make_quadric },
    { "isosurface", "isosurface { function { x*x + 2*y*y + z*z - 1.5 } "
                    "contained_by { box { -1.4, 1.4 } } max_gradient 6 "
                    "rotate 30*z }", make_isosurface },
    { "polygon", "polygon { 8, <-1.5,-1.5>, <1.5,-1.5>, <0,1.5>, "
                 "<-1.5,-1.5>, <-0.5,-0.8>, <0.5,-0.8>, <0,0.3>, "
                 "<-0.5,-0.8> rotate <30,30,0> }", make_polygon },
    { "disc", "disc { <0.2,0,0>, <0.3,0.4,-1>, 1.6, 0.7 }", make_disc },
    { "bicubic_patch", "bicubic_patch { type 1 flatness 0 u_steps 3 "
                       "v_steps 3 <-1.5,-1.5,0>, <-0.5,-1.5,0>, "
                       "<0.5,-1.5,0>, <1.5,-1.5,0>, <-1.5,-0.5,0>, "
                       "<-0.5,-0.5,2.5>, <0.5,-0.5,2.5>, <1.5,-0.5,0>, "
                       "<-1.5,0.5,0>, <-0.5,0.5,2.5>, <0.5,0.5,2.5>, "
                       "<1.5,0.5,0>, <-1.5,1.5,0>, <-0.5,1.5,0>, "
                       "<0.5,1.5,0>, <1.5,1.5,0> rotate <-60,10,0> }",
      make_bicubic },
    { "julia", "julia_fractal { <-0.083,0.0,-0.83,-0.025> quaternion sqr "
               "max_iteration 8 precision 15 scale 1.3 rotate <-35,30,0> }",
      make_julia },
    { "julia_cube", "julia_fractal { <-0.2,0.0,0.5,-0.025> quaternion cube "
                    "max_iteration 8 precision 15 slice <0,0.3,0,1>, 0.1 "
                    "scale 1.3 rotate <-35,30,0> }", make_julia_cube },
    { "height_field", "height_field { pgm \"hf.pgm\" translate <-0.5,0,-0.5> "
                      "scale <3,1.5,3> rotate <-50,20,0> }",
      make_height_field },
    { "cut_union", "union { box { -1.2, 1.2 } sphere { <0.5,0.5,0>, 1 } "
                   "clipped_by { plane { -z, 0.2 } } rotate <15,-20,0> }",
      make_cut_union },
    { "cut_merge", "merge { box { -1.2, 1.2 } sphere { <0.5,0.5,0>, 1 } "
                   "clipped_by { plane { -z, 0.2 } } rotate <15,-20,0> }",
      make_cut_merge },
    { "bite", "intersection { sphere { 0, 1.8 } "
              "sphere { <0.3,0.2,-1.2>, 1.1 inverse } }", make_bite },
};

#define N_CASES ((int)(sizeof cases / sizeof cases[0]))

/* The cases are laid out on a grid of TILES x TILES tiles of 4x4 units
** (W x H pixels each) and rendered as one image: POV-Ray's start-up then
** costs once, not once per case. */
#define TILES 5
#define IW (TILES * W)
#define IH (TILES * H)

/* Centre of the tile of case 'c' in the big image. */
static vec3 tile_centre(int c)
{
    return v3(4.0 * (c % TILES) - 2.0 * (TILES - 1),
              2.0 * (TILES - 1) - 4.0 * (c / TILES), 0);
}

/* What POV-Ray saw in one pixel: whether it hit, and the depth (z). */
struct pov_px {
    bool hit;
    double z;
};

/*
** Reads an IW x IH binary PPM into per-case pixels. Red marks a hit;
** green is the depth, written linearly (File_Gamma=1) as (z + 5) / 10.
*/
static bool read_masks(const char *path, struct pov_px masks[][W * H])
{
    FILE *f = fopen(path, "rb");
    if (!f)
        return false;
    /* P6 with '#' comment lines, then width, height, maxval */
    char line[256];
    int vals[3], nv = 0;
    while (nv < 3 && fgets(line, sizeof line, f)) {
        if (line[0] == '#' || line[0] == 'P')
            continue;
        char *p = line;
        while (nv < 3) {
            char *end;
            long v = strtol(p, &end, 10);
            if (end == p)
                break;
            vals[nv++] = (int)v;
            p = end;
        }
    }
    static unsigned char px[IW * IH * 3];
    bool ok = nv == 3 && vals[0] == IW && vals[1] == IH &&
              fread(px, 1, sizeof px, f) == sizeof px;
    fclose(f);
    for (int c = 0; ok && c < N_CASES; c++) {
        int x0 = (c % TILES) * W, y0 = (c / TILES) * H;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++)
            {
                const unsigned char *q = px + 3 * ((size_t)(y0 + y) * IW +
                                                   x0 + x);
                masks[c][y * W + x].hit = q[0] > 128;
                masks[c][y * W + x].z = 10.0 * q[1] / 255.0 - 5;
            }
    }
    return ok;
}

/* Renders every case, each moved to its tile, with one POV-Ray run. */
static bool pov_masks(const char *povray, struct pov_px masks[][W * H])
{
    const char *dir = work_dir;
    char pov[256], out[256], cmd[1024];
    snprintf(pov, sizeof pov, "%s/s.pov", dir);
    snprintf(out, sizeof out, "%s/s.ppm", dir);
    FILE *f = fopen(pov, "w");
    if (!f)
        return false;
    fprintf(f, "#version 3.7;\nglobal_settings { assumed_gamma 1 }\n"
               "camera { orthographic location <0,0,-10> look_at 0 "
               "right %d*x up %d*y }\n"
               "background { rgb 0 }\n"
               "#declare Depth = texture { pigment { gradient z "
               "color_map { [0 rgb <1,0,0>] [1 rgb <1,1,0>] } "
               "scale 10 translate -5*z } finish { ambient 1 diffuse 0 } }\n",
            4 * TILES, 4 * TILES);
    for (int c = 0; c < N_CASES; c++) {
        vec3 t = tile_centre(c);
        /* The texture comes after the case's own transforms, so the
        ** depth gradient stays along z; clipping keeps a case in its tile */
        fprintf(f, "object { %s texture { Depth } translate <%g,%g,0> "
                   "clipped_by { box { <%g,%g,-100>, <%g,%g,100> } } }\n",
                cases[c].sdl, t.x, t.y, t.x - 2, t.y - 2, t.x + 2, t.y + 2);
    }
    fclose(f);
    snprintf(cmd, sizeof cmd,
             "cd %s && '%s' +Is.pov +Os.ppm +W%d +H%d -D -V -A +FP -GA "
             "File_Gamma=1.0 +L'%s' >/dev/null 2>&1", dir, povray, IW, IH,
             POVRAY_INCLUDE_DIR);
    bool ok = system(cmd) == 0 && read_masks(out, masks);
    remove(out);
    remove(pov);
    return ok;
}

static void test_pov_images(void **state)
{
    (void)state;
    const char *povray = getenv("POVRAY");
    if (!povray || !*povray)
        skip();
    static struct pov_px masks[N_CASES][W * H];
    snprintf(work_dir, sizeof work_dir, "/tmp/iris-pov-XXXXXX");
    if (!mkdtemp(work_dir))
        fail_msg("cannot make a temporary directory");
    char hf[128];
    snprintf(hf, sizeof hf, "%s/hf.pgm", work_dir);
    bool ok = write_bump(hf) && pov_masks(povray, masks);
    if (!ok) {
        remove(hf);
        rmdir(work_dir);
        fail_msg("POV-Ray could not render the cases");
    }
    for (int c = 0; c < N_CASES; c++) {
        const struct pov_px *want = masks[c];
        iris_arena *ar = arena_create(0);
        iris_scene sc;
        memset(&sc, 0, sizeof sc);
        sc.arena = ar;
        iris_object *o = cases[c].make(ar);
        sc.objects = &o;
        sc.n_objects = 1;
        struct accel *a = NULL;
        char err[128];
        assert_int_equal(accel_build(&sc, &a, stderr, err, sizeof err),
                         IRIS_OK);
        int diff = 0, cover = 0, deep = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                double x0 = (x + 0.5) / W - 0.5, y0 = 0.5 - (y + 0.5) / H;
                ray r = { v3(4 * x0, 4 * y0, -10), v3(0, 0, 1) };
                struct hit h;
                bool got = accel_intersect(a, &r, 0, INFINITY, 0, &h);
                const struct pov_px *w = &want[y * W + x];
                cover += w->hit;
                diff += got != w->hit;
                /* Same surface first: depth within 0.1 (the 8-bit depth
                ** steps by 10/255 = 0.04) */
                deep += got && w->hit && fabs(h.p.z - w->z) > 0.1;
            }
        fprintf(stderr, "# %s: %d px differ, %d deeper, cover %d\n",
                cases[c].name, diff, deep, cover);
        if (diff + deep > W * H * 5 / 1000 || cover < 150)
            fail_msg("case '%s': %d pixels differ from POV-Ray, %d at "
                     "another depth (cover %d)", cases[c].name, diff, deep,
                     cover);
        accel_destroy(a);
        arena_destroy(ar);
    }
    remove(hf);
    rmdir(work_dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pov_images),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
