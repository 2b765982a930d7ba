/* SPDX-License-Identifier: MIT */
/*
** geom.h: analytic shapes in their own object space.
**
** Each analytic shape (sphere, box, torus, blob, ...) answers three
** questions about a ray or point already transformed into object space:
** every crossing of the ray with the surface, whether a point is inside,
** and a bounding box. Meshes are not here (accel hands them to Embree);
** CSG is not here either (accel combines the children's answers). All work
** is in double precision; tolerances are relative to the shape's own size
** so that scaling a scene does not change which surfaces are found.
**
** Depends on: math, util. Used by: accel.
*/
#ifndef IRIS_GEOMETRY_GEOM_H
#define IRIS_GEOMETRY_GEOM_H

#include <math.h>
#include <stdbool.h>
#include <stdio.h>

#include "iris/scene.h"
#include "math/vec3.h"

/* One crossing of a ray with a surface, in object space. */
struct geom_isect {
    double t;        /* ray parameter: the same in object and world space */
    vec3 n;          /* outward normal in object space, any length > 0 */
    iris_vec2 uv;    /* surface uv where the shape defines one, else 0 */
    int part;        /* blob: the component contributing most, else -1 */
};

/*
** A growable list of crossings. The first 'GEOM_INLINE' entries live in
** the struct itself so that the common case never calls malloc.
*/
#define GEOM_INLINE 16
struct isect_list {
    struct geom_isect *v;
    int n, cap;
    bool overflow;   /* an allocation failed: some crossings were dropped */
    /* the caller keeps only the nearest crossing: a marching shape
    ** (julia_fractal) may stop at its first, as POV-Ray's does */
    bool first_only;
    struct geom_isect inline_buf[GEOM_INLINE];
};

void isect_list_init(struct isect_list *l);
void isect_list_fini(struct isect_list *l);
/* Appends a crossing unless 't' or 'n' is not finite or n is zero. */
void isect_push(struct isect_list *l, double t, vec3 n, double u, double v);

/* Whether 'kind' is handled here (analytic user geometry). */
bool geom_is_analytic(enum iris_object_kind kind);

/* Grows the 2-D box [*lo, *hi] to hold [l, h]; the first box (*have
** false) is taken as it is. */
static inline void geom_box2_add(iris_vec2 *lo, iris_vec2 *hi, bool *have,
                                 iris_vec2 l, iris_vec2 h)
{
    if (!*have) {
        *lo = l;
        *hi = h;
        *have = true;
        return;
    }
    lo->u = fmin(lo->u, l.u);
    lo->v = fmin(lo->v, l.v);
    hi->u = fmax(hi->u, h.u);
    hi->v = fmax(hi->v, h.v);
}

/*
** A 2-D outline made of straight segments: the flattened spline of a
** prism or lathe, or the glyph outlines of a text object. Segments are
** grouped (one group per glyph or sub-polygon) with a 2-D box each, so a
** ray skips the groups it cannot meet. Owned by the caller of
** geom_prepare(), freed by geom_profile_free().
*/
struct geom_profile {
    int n_seg;
    iris_vec2 *a, *b;          /* segment i runs from a[i] to b[i] */
    iris_vec2 *ta, *tb;        /* curve tangents at a[i] and b[i] (spline
                                  profiles, for smooth normals), or NULL */
    signed char *side;         /* +1: the outside is to the right of a->b */
    int cap;                   /* allocated segments */
    int n_groups;
    int *group_first, *group_count;
    iris_vec2 *group_lo, *group_hi;
    iris_vec2 lo, hi;          /* box of every segment */
    /* text only (pov_box set): POV-Ray's box of the glyphs, each glyph's
    ** control box (off-curve points included) at its place, an empty
    ** glyph (a space) its pen point; min_extent/max_extent report it */
    bool pov_box;
    iris_vec2 pov_lo, pov_hi;
    /*
    ** Runs of at most PROFILE_RUN consecutive segments of one group, each
    ** with its 2-D box, so that a ray or an inside test skips the runs it
    ** cannot meet: a glyph's contour has hundreds of pieces, and testing
    ** them all was 3/4 of a text scene's time. Run k holds segments
    ** run_first[k] .. run_first[k + 1] - 1; group g's runs are
    ** group_run[g] .. group_run[g + 1] - 1. NULL (n_runs 0) when not
    ** built: every segment is then tested. run_pad: 1e-9 of the
    ** profile's size, by which the tests widen the boxes so that a
    ** crossing rounding puts a hair outside still counts.
    ** group_closed[g]: group g is one chain of segments, each starting
    ** exactly where the one before ends and the last ending where the
    ** first starts (a glyph contour), so that a line crosses it an even
    ** number of times.
    */
    int n_runs;
    int *run_first, *group_run;
    unsigned char *group_closed;
    iris_vec2 *run_lo, *run_hi;
    double run_pad;
    double h1, h2;             /* extrusion range (prism: y, text: z) */
    bool conic;                /* prism conic_sweep */
    bool open;                 /* prism 'open': no caps */
    /*
    ** The exact curve a straight segment stands in for (lathe and sor),
    ** so that a crossing found on the segment can be moved onto the
    ** curve: curve[i] indexes curves[] (-1: the segment is exact), and
    ** the segment spans the curve's parameter cs0[i] .. cs1[i].
    */
    int *curve;
    double *cs0, *cs1;
    struct geom_curve *curves;
    int n_curves, cap_curves;
    /*
    ** The shape's bounded_by, resolved once by geom_prepare() (bound.c)
    ** instead of for every ray: whether the bound's world box is the
    ** smaller one and so cuts the shape, and that box. Any shape with a
    ** bounded_by gets a profile for this, with no segments when it has
    ** no outline.
    */
    struct geom_bound_cut {
        bool ready;            /* filled in; else bound.c computes per ray */
        bool box_cuts;         /* the ray must meet lo..hi */
        vec3 lo, hi;           /* the bound's world box */
    } bound;
    /*
    ** A parametric's 'precompute' (parametric.c): the bounds of function
    ** k on the cells of its subdivision tree numbered as POV-Ray numbers
    ** them (1 the whole uv rectangle, 2n and 2n + 1 the halves of n),
    ** par_lo[k][n] .. par_hi[k][n] for n < 1 << par_depth; NULL for a
    ** function not precomputed.
    */
    double *par_lo[3], *par_hi[3];
    int par_depth;
};

/*
** One spline segment of a profile. GEOM_CURVE_POLY: the point
** (u, v)(s) = c[0] s³ + c[1] s² + c[2] s + c[3] for s in [0, 1] (lathe).
** GEOM_CURVE_SOR: r² = c[0].u h³ + c[1].u h² + c[2].u h + c[3].u with
** h = (y - y0) / dy in [0, 1] (sor); 's' is h.
*/
enum { GEOM_CURVE_POLY, GEOM_CURVE_SOR };
struct geom_curve {
    int kind;
    iris_vec2 c[4];
    double y0, dy;
    int first, n;     /* its pieces first .. first+n-1 (profile_finish) */
    double vlo, vhi;  /* heights and largest |radius| of those pieces */
    double umax;
    /* GEOM_CURVE_POLY: the Bezier control points of the same cubic
    ** (profile.c); the curve over s in [0, 1] lies in their convex hull,
    ** so a line they all lie on one side of cannot meet it (sweep.c).
    ** 'ext' is their largest coordinate magnitude, for tolerances. */
    iris_vec2 bz[4];
    double ext;
};

/*
** Prepares what 'obj' needs beyond its plain data: the flattened profile
** of prism, lathe and text objects, and for any shape with a bounded_by
** the bound's box (NULL for every other shape). Returns NULL and sets
** '*why' when the object cannot be built ("font not found", or
** geom_validate()'s reason for a shape with a bounded_by).
*/
struct geom_profile *geom_prepare(const iris_object *obj, const char **why);
void geom_profile_free(struct geom_profile *p);

/*
** Appends every crossing with tmin < t < tmax of the object-space ray
** o + t·d ('d' need not have unit length) with the surface of 'obj',
** ignoring its transform, inverse and clipped_by. Unordered.
*/
void geom_intersect(const iris_object *obj, const struct geom_profile *prof,
                    vec3 o, vec3 d, double tmin, double tmax,
                    struct isect_list *out);

/* Whether POV-Ray tests shape 'obj' for the object-space ray o + t·d at
** all: false when its bounded_by cuts the ray off (bound.c). */
bool geom_bound_admits(const iris_object *obj, const struct geom_profile *prof,
                       vec3 o, vec3 d);
/* Whether POV-Ray tests CSG 'obj' (its bounded_by in world space) for
** the world ray o + t·d: Ray_In_Bound, the ray meets the bound or starts
** inside it (bound.c). True without a bound. */
bool geom_csg_bound_admits(const iris_object *obj, vec3 o, vec3 d);
/* Fills prof->bound for shape 'obj' (geom_prepare(); 'prof' is the
** shape's own profile, possibly with no segments). */
void geom_bound_prepare(const iris_object *obj, struct geom_profile *prof);

/* Whether object-space point 'p' is inside 'obj' (not inverted). */
bool geom_inside(const iris_object *obj, const struct geom_profile *prof,
                 vec3 p);

/* Object-space bounding box; false when the shape is unbounded. */
bool geom_bounds(const iris_object *obj, const struct geom_profile *prof,
                 vec3 *lo, vec3 *hi);

/*
** Checks the parameters of 'obj' and prepares what it needs. Returns NULL
** when it can be rendered, else a short reason ("radius is not positive")
** that the caller reports with the object's location.
*/
const char *geom_validate(const iris_object *obj);

/* Per-shape entry points, called by geom.c's dispatch. */
void geom_sphere_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                      double t1, struct isect_list *out);
/* A sphere's uv at object-space point 'p' on it. geom_sphere_hits()
** leaves uv 0: the caller asks for the crossing it keeps. */
iris_vec2 geom_sphere_uv(const iris_object *o, vec3 p);
void geom_plane_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out);
void geom_box_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                   double t1, struct isect_list *out);
/* A crossing of a box: its t, the axis of its face and the side of
** that face (-1 low, +1 high) */
struct geom_box_cross {
    double t;
    int axis;
    double side;
};
/* geom_box_hits() in parts, for a caller that wants only the nearest
** crossing (accel/node.c): the crossings in (t0, t1), entering first,
** into c[] (their count, 0-2); the object-space unit normal of one;
** its uv, as geom_box_hits() gives it (0 where not finite). */
int geom_box_crossings(const iris_object *o, vec3 ro, vec3 rd, double t0,
                       double t1, struct geom_box_cross c[2]);
vec3 geom_box_normal(const struct geom_box_cross *c);
iris_vec2 geom_box_uv(const iris_object *o, vec3 ro, vec3 rd,
                      const struct geom_box_cross *c);
void geom_cone_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out);
/* A crossing of a cylinder or cone: its t, its object-space normal
** (finite, not zero: those geom_cone_hits() keeps), and for one on the
** side what its uv is computed from */
struct geom_cone_cross {
    double t;
    vec3 n;
    bool side;
    double x, y, z, len;
};
/* geom_cone_hits() in parts, for a caller that wants only the nearest
** crossing (accel/node.c): the crossings it would push, in its order,
** into c[] (their count, 0-4), and the uv of one (its atan2 asked only
** for the crossing kept), as geom_cone_hits() gives it. */
int geom_cone_crossings(const iris_object *o, vec3 ro, vec3 rd, double t0,
                        double t1, struct geom_cone_cross c[4]);
iris_vec2 geom_cone_uv(const struct geom_cone_cross *c);
/* The cone's (or cylinder's) frame: base 'a', unit axis 'w' and the
** basis u, v about it, length 'len'; the radii ra (base), rb (cap) are
** signed, 'empty' when there is none. A function of the object alone,
** so a caller may take it once (accel/node.h 'cone'); the crossings
** from it are geom_cone_crossings()' to the bit. */
struct geom_cone_frame {
    vec3 a, u, v, w;
    double len, ra, rb;
    bool empty;
};
void geom_cone_frame(const iris_object *o, struct geom_cone_frame *f);
int geom_cone_crossings_in(const iris_object *o,
                           const struct geom_cone_frame *f, vec3 ro,
                           vec3 rd, double t0, double t1,
                           struct geom_cone_cross c[4]);
void geom_disc_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out);
bool geom_cone_inside(const iris_object *o, vec3 p);
/*
** Roots of the torus quartic (|q|^2 + R^2 - r^2)^2 = 4 R^2 (x^2 + z^2)
** about the y axis along q = o + t d (d unit) for t in (t0, t1): written
** to u[] as offsets from the ray's closest approach to the centre,
** *p_out = o + s d with s in *s_out (so t = s + u); the count is returned.
** torus.c, and ovus.c's spindle (where R is below r).
*/
int geom_torus_roots(double R, double r, vec3 o, vec3 d, double t0,
                     double t1, double *s_out, vec3 *p_out, double u[4]);
/*
** geom_torus_hits() in parts, for a caller that wants only the nearest
** crossing (accel/node.c): geom_torus_first() solves for the first root
** only (the same value as the whole solve's first) and returns 1 with
** its crossing in *c (t, normal as geom_torus_hits() pushes it), 0 when
** there is no root, or -1 when that crossing is one isect_push() would
** drop (the caller then takes geom_torus_hits(), which sees the next);
** geom_torus_uv() is its uv, as pushed (its two atan2 only for the
** crossing kept, and only when a texture reads it).
*/
struct geom_torus_cross {
    double t;
    vec3 n;
    vec3 q;
    double rxz, R;
};
int geom_torus_first(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct geom_torus_cross *c);
iris_vec2 geom_torus_uv(const struct geom_torus_cross *c);
void geom_torus_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out);
void geom_poly_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out);
double geom_poly_eval(const iris_object *o, vec3 p);
void geom_polygon_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                       double t1, struct isect_list *out);
void geom_superellipsoid_hits(const iris_object *o, vec3 ro, vec3 rd,
                              double t0, double t1, struct isect_list *out);
double geom_superellipsoid_eval(const iris_object *o, vec3 p);
void geom_blob_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out);
double geom_blob_density(const iris_object *o, vec3 p);
bool geom_blob_bounds(const iris_object *o, vec3 *lo, vec3 *hi);
/* geom_blob_hits() with the box geom_blob_bounds() gave, computed once
** by the caller: over every component, it cost more than the crossings */
void geom_blob_hits_in_box(const iris_object *o, vec3 blo, vec3 bhi,
                           vec3 ro, vec3 rd, double t0, double t1,
                           struct isect_list *out);
/* Lathe and sor: the profile (r, y) revolved about the y axis. */
void geom_lathe_hits(const struct geom_profile *p, vec3 ro, vec3 rd,
                     double t0, double t1, struct isect_list *out);
bool geom_lathe_inside(const struct geom_profile *p, vec3 q);
void geom_lathe_bounds(const struct geom_profile *p, vec3 *lo, vec3 *hi);
/* Prism and text: the profile extruded along 'axis' (1 = y, 2 = z). */
void geom_extrude_hits(const struct geom_profile *p, int axis, vec3 ro,
                       vec3 rd, double t0, double t1, struct isect_list *out);
bool geom_extrude_inside(const struct geom_profile *p, int axis, vec3 q);
void geom_extrude_bounds(const struct geom_profile *p, int axis, vec3 *lo,
                         vec3 *hi);
/* Profiles from splines and fonts (profile.c, text.c). */
struct geom_profile *geom_profile_new(int n_seg_cap);
bool geom_profile_add(struct geom_profile *p, iris_vec2 a, iris_vec2 b);
/* Like geom_profile_add, with the curve's tangents at both ends. */
bool geom_profile_add_curved(struct geom_profile *p, iris_vec2 a, iris_vec2 b,
                             iris_vec2 ta, iris_vec2 tb);
/* Ends the current group; false when out of memory. */
bool geom_profile_close_group(struct geom_profile *p);
/* Computes the boxes and each segment's outward side; call once at the
** end. 'inside2d' decides the side with the even-odd rule. */
void geom_profile_finish(struct geom_profile *p);
/* Even-odd test of 2-D point (u, v) against the profile. */
bool geom_profile_inside2d(const struct geom_profile *p, double u, double v);
struct geom_profile *geom_text_profile(const iris_object *o,
                                       const char **why);
void geom_isosurface_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                          double t1, struct isect_list *out);
bool geom_isosurface_inside(const iris_object *o, vec3 p);


/* julia_fractal (quaternion and hypercomplex). */
bool geom_julia_ok(const iris_object *o);
bool geom_julia_inside(const iris_object *o, vec3 p);
double geom_julia_radius(const iris_object *o);
void geom_julia_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out);

/* ovus, sphere_sweep, parametric, lemon (ovus.c, sphere_sweep.c,
** parametric.c, lemon.c):
** hits, inside, bounds, and the parameter check (NULL when renderable). */
void geom_ovus_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                    double t1, struct isect_list *out);
bool geom_ovus_inside(const iris_object *o, vec3 p);
void geom_ovus_bounds(const iris_object *o, vec3 *lo, vec3 *hi);
const char *geom_ovus_check(const iris_object *o);
void geom_sphere_sweep_hits(const iris_object *o, vec3 ro, vec3 rd,
                            double t0, double t1, struct isect_list *out);
bool geom_sphere_sweep_inside(const iris_object *o, vec3 p);
bool geom_sphere_sweep_bounds(const iris_object *o, vec3 *lo, vec3 *hi);
const char *geom_sphere_sweep_check(const iris_object *o);
bool geom_parametric_precompute(const iris_object *o,
                                struct geom_profile *p);
void geom_parametric_hits(const iris_object *o,
                          const struct geom_profile *prof, vec3 ro, vec3 rd,
                          double t0,
                          double t1, struct isect_list *out);
void geom_parametric_bounds(const iris_object *o, vec3 *lo, vec3 *hi);
const char *geom_parametric_check(const iris_object *o);
void geom_lemon_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out);
bool geom_lemon_inside(const iris_object *o, vec3 p);
void geom_lemon_bounds(const iris_object *o, vec3 *lo, vec3 *hi);
const char *geom_lemon_check(const iris_object *o);
/* bicubic_patch as POV-Ray tessellates it (bicubic.c): 3·n_tris corners
** 'p' with normals 'n' and uv, owned by the caller (iris_free); NULL, or
** the reason it cannot be built. */
const char *geom_bicubic_tessellate(const iris_object *o, int *n_tris,
                                    vec3 **p, vec3 **n, iris_vec2 **uv);
/* The inner ("lemon") part of the spindle torus about the y axis centred
** at (0, yc, 0) whose tube circle, radius C, has its centre H > 0 beyond
** the axis; hits with ylo < y < yhi (ovus.c; used by ovus and lemon). */
void geom_spindle_hits(double H, double C, double yc, double ylo,
                       double yhi, vec3 ro, vec3 rd, double t0, double t1,
                       struct isect_list *out);

/* Whether the box lo..hi is hit by o + t·d for some t in [t0, t1];
** narrows [t0, t1] to the part inside the box. */
bool geom_clip_box(vec3 lo, vec3 hi, vec3 o, vec3 d, double *t0, double *t1);

#endif
