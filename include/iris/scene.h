/* SPDX-License-Identifier: MIT */
/*
** scene.h: the plain-data scene description.
**
** This is what povparse builds from SDL text and what the renderer reads.
** It holds no rays, no spectra and no acceleration structures: only
** numbers, strings and pointers between nodes, every node carrying the
** file:line:col it came from. All nodes, strings and arrays live in the
** scene's arena and are freed together by iris_scene_destroy(); nodes are
** never freed one by one and may be shared (two objects pointing at one
** texture is normal).
**
** Conventions the parser resolves so that the renderer need not:
**  - Coordinates are POV-Ray's: left-handed, +y up.
**  - Every object's 'transform' maps its own space to world space in full
**    (the transforms of enclosing CSG nodes are already folded in).
**  - Every pigment, normal and texture pattern carries its own full
**    world-to-pattern transform, built as POV-Ray builds it (object
**    transforms written after a texture apply to the texture too).
**  - Texture and interior inheritance are resolved: every leaf object has
**    a non-NULL texture (the #default texture when none was given), and
**    CSG children without an interior get their parent's.
**  - The camera is resolved: the vectors are the final ones after
**    look_at, sky, angle and transforms, in POV-Ray's parse order.
**  - Colours are linear in the working space (assumed_gamma 1); 'srgb'
**    keywords and legacy gamma are already decoded.
*/
#ifndef IRIS_SCENE_H
#define IRIS_SCENE_H

#include <stdbool.h>
#include <stdint.h>

#include "iris/common.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct iris_fn iris_fn; /* a compiled SDL function, see fn.h */

/* A point or direction. */
typedef struct iris_vec3 {
    double x, y, z;
} iris_vec3;

/* A 2-D point (uv coordinates, prism and lathe profiles). */
typedef struct iris_vec2 {
    double u, v;
} iris_vec2;

/* A POV-Ray colour: linear rgb plus filter and transmit. */
typedef struct iris_colour {
    double r, g, b, f, t;
} iris_colour;

/*
** An affine transform. 'm' maps local to world: p' = m[0..2][0..2]·p +
** m[0..2][3]; 'inv' is its inverse. Directions use the 3x3 part, normals
** the transpose of inv's 3x3 part.
*/
typedef struct iris_transform {
    double m[3][4];
    double inv[3][4];
} iris_transform;

/* Where a node came from. 'file' indexes iris_scene.files; 0 = unknown. */
typedef struct iris_loc {
    uint32_t file;
    uint32_t line; /* 1-based */
    uint32_t col;  /* 1-based, bytes */
} iris_loc;

/* A tri-state flag: POV-Ray distinguishes "not given" from on and off. */
enum iris_tristate { IRIS_UNSET = 0, IRIS_ON = 1, IRIS_OFF = 2 };

/* ------------------------------------------------------------------ */
/* Patterns (shared by pigments, normals and texture maps)              */
/* ------------------------------------------------------------------ */

enum iris_pattern_kind {
    IRIS_PAT_NONE = 0, /* solid colour / plain texture */
    IRIS_PAT_AGATE, IRIS_PAT_AVERAGE, IRIS_PAT_BOXED, IRIS_PAT_BOZO,
    IRIS_PAT_BRICK, IRIS_PAT_BUMPS, IRIS_PAT_CELLS, IRIS_PAT_CHECKER,
    IRIS_PAT_CRACKLE, IRIS_PAT_CYLINDRICAL, IRIS_PAT_DENTS,
    IRIS_PAT_FUNCTION, IRIS_PAT_GRADIENT, IRIS_PAT_GRANITE,
    IRIS_PAT_HEXAGON, IRIS_PAT_IMAGE_MAP, IRIS_PAT_IMAGE_PATTERN,
    IRIS_PAT_JULIA, IRIS_PAT_LEOPARD, IRIS_PAT_MANDEL, IRIS_PAT_MARBLE,
    IRIS_PAT_ONION, IRIS_PAT_PLANAR, IRIS_PAT_QUILTED, IRIS_PAT_RADIAL,
    IRIS_PAT_RIPPLES, IRIS_PAT_SLOPE, IRIS_PAT_SPHERICAL, IRIS_PAT_SPIRAL1,
    IRIS_PAT_SPIRAL2, IRIS_PAT_SPOTTED, IRIS_PAT_WAVES, IRIS_PAT_WOOD,
    IRIS_PAT_WRINKLES,
    IRIS_PAT_OBJECT, IRIS_PAT_TILING, IRIS_PAT_PAVEMENT,
    IRIS_PAT_SQUARE, IRIS_PAT_TRIANGULAR, IRIS_PAT_FACETS,
    IRIS_PAT_DENSITY_FILE,     /* image->path the .df3, ->interpolate */
    IRIS_PAT_FACE_BLEND,       /* a texture map of the three textures of
                                  a mesh face, blended across it (POV-Ray's
                                  Mesh::Determine_Textures): the corners
                                  are 'vector' and params[0..5] */
    IRIS_PAT_CUBIC,            /* 6 entries on the pyramids around +-x,
                                  +-y, +-z (POV-Ray 3.7's cubic pattern) */
    IRIS_PAT_COUNT
};

/* How a pattern value in [0,1] is shaped before the map lookup. */
enum iris_wave { IRIS_WAVE_RAMP = 0, IRIS_WAVE_SINE, IRIS_WAVE_TRIANGLE,
                 IRIS_WAVE_SCALLOP, IRIS_WAVE_CUBIC, IRIS_WAVE_POLY };

enum iris_warp_kind { IRIS_WARP_TURBULENCE = 0, IRIS_WARP_REPEAT,
                      IRIS_WARP_BLACK_HOLE, IRIS_WARP_TRANSFORM,
                      IRIS_WARP_PLANAR, IRIS_WARP_SPHERICAL,
                      IRIS_WARP_CYLINDRICAL, IRIS_WARP_TOROIDAL };

/* One warp{} block, or the classic turbulence of a pattern. */
typedef struct iris_warp {
    enum iris_warp_kind kind;
    iris_vec3 turbulence;      /* TURBULENCE */
    int octaves;               /* default 6 */
    double omega, lambda;      /* default 0.5, 2 */
    iris_vec3 repeat, offset, flip; /* REPEAT */
    iris_vec3 centre;          /* BLACK_HOLE */
    double radius, strength, falloff; int inverse;
    iris_transform transform;  /* TRANSFORM: world-to-warped, as 'inv' */
    iris_vec3 orientation; double dist_exp; double major_radius;
} iris_warp;

/* An image referenced by image_map, bump_map or height_field. */
typedef struct iris_image_ref {
    const char *path;      /* resolved path; the renderer loads it */
    /* image_map { function W, H { ... } }: the image the parser computed,
    ** W x H linear RGBA floats, top row first; 'path' only names it */
    const float *pixels;
    int pixels_w, pixels_h;
    int map_type;          /* 0 planar, 1 spherical, 2 cylindrical, 5 torus */
    int interpolate;       /* 0 none, 2 bilinear, 4 normalised distance */
    bool once;
    double gamma;          /* 0 = the file's own */
    double filter_all, transmit_all;
    bool use_alpha;
    /* 'filter N, V' / 'transmit N, V' of a palette image, in order:
    ** palette entry 'index' gets filter (which 0) or transmit (1) 'value' */
    int n_palette_ft;
    struct iris_palette_ft { int index, which; double value; } *palette_ft;
    bool use_index;        /* bump_map use_index: palette indices as heights */
    /* POV-Ray's gamma mode when the image was parsed: 1 = texels as the
    ** file stores them (#version below 3.7 there), -1 = decoded to the
    ** working space, 0 = from the scene's final version */
    signed char as_stored;
} iris_image_ref;

/*
** A pattern: a function from a point to a value in [0,1] (or, for
** checker/hexagon/brick and friends, to a map index).
*/
/* The most iterations a mandel, julia or magnet pattern runs per
** evaluation (3.7 ns each: 0.4 ms); POV-Ray's examples use at most 10000.
** A larger count is kept for the colouring (k / iterations) and warned
** about by the parser; 'mandel 1e9' took 4 s per evaluation. */
#define IRIS_PATTERN_MAX_ITERATIONS 100000

typedef struct iris_pattern {
    enum iris_pattern_kind kind;
    iris_transform transform;  /* world-to-pattern is 'inv' */
    bool has_transform;

    /* Value shaping */
    enum iris_wave wave;
    double wave_exponent;      /* for IRIS_WAVE_POLY */
    double frequency, phase;   /* default 1, 0 */

    /* Classic turbulence and warp{} blocks, in order of appearance */
    int n_warps;
    iris_warp *warps;

    /* Kind-specific parameters */
    iris_vec3 vector;          /* gradient, planar, slope direction */
    double params[8];          /* brick mortar, crackle metric/offset, ... */
    iris_vec3 brick_size;      /* default <8,3,4.5> */
    double mortar;             /* default 0.5 */
    int noise_generator;       /* 1, 2 or 3 */
    iris_vec2 complex_c;       /* julia */
    int iterations;            /* mandel, julia (evaluated with at most
                                  IRIS_PATTERN_MAX_ITERATIONS) */
    iris_fn *fn;               /* FUNCTION */
    iris_image_ref *image;     /* IMAGE_MAP, IMAGE_PATTERN */
    struct iris_object *object; /* OBJECT */
    int n_average;             /* AVERAGE: entries come from the map */
    bool uv_mapping;           /* evaluated at the surface's <u, v, 0> */
} iris_pattern;

struct iris_pigment;
struct iris_normal;
struct iris_texture;

/* One entry of a colour_map, pigment_map, normal_map or texture_map. */
typedef struct iris_map_entry {
    double value;              /* position in [0,1] (or weight for average) */
    iris_colour colour;        /* colour_map */
    struct iris_pigment *pigment;  /* pigment_map / list pattern */
    struct iris_normal *normal;    /* normal_map */
    struct iris_texture *texture;  /* texture_map */
    double slope, height;      /* slope_map */
} iris_map_entry;

/*
** The most pigments, normals or textures one map tree may hold, counted
** as a tree. Maps whose entries are maps sharing one declared map double
** at each level ('#declare P = pigment { checker P P }' in a loop):
** every walk over such a tree, and POV-Ray's evaluation of a blend in it,
** takes time in proportion to this count, so the parser refuses it
** rather than hang.
*/
#define IRIS_MAX_MAP_TREE (1u << 18)

/* A pigment: a solid colour, or a pattern with a map. */
typedef struct iris_pigment {
    iris_loc loc;
    iris_pattern pattern;      /* kind NONE = solid 'colour' */
    iris_colour colour;
    int n_entries;             /* colour_map or pigment_map entries */
    iris_map_entry *entries;   /* sorted by value; colour or pigment set */
    bool is_pigment_map;       /* entries hold pigments, not colours */
    iris_colour quick_colour;
    /* Transforms of this pigment that its pigment entries have not got:
    ** they are evaluated at the point moved back by them (NULL: none).
    ** The parser shares a transformed pigment's entries instead of
    ** copying its map tree per transform (POV-Ray shares blend maps). */
    const iris_transform *entry_xf;
    /* The size of the map tree under this one, counted as a tree (an
    ** entry shared by several maps counts each time it occurs; this one
    ** included; 0 = not counted), and whether a pigment under the entries
    ** reads the uv point or the world point (uv_mapping, slope), so that
    ** they cannot share an entry transform. Set by the parser
    ** (povparse/maptree.c), which refuses a tree past IRIS_MAX_MAP_TREE. */
    uint32_t map_tree;
    bool map_tree_pointwise;
} iris_pigment;

/* A normal{} perturbation. */
typedef struct iris_normal {
    iris_loc loc;
    iris_pattern pattern;
    double amount;             /* bump_size / the pattern's strength */
    double accuracy;           /* default 0.02 */
    int n_entries;             /* normal_map or slope_map */
    iris_map_entry *entries;
    bool is_slope_map;
    /* 'no_bump_scale': the normal is not normalised on its way to and
    ** from pattern space (POV-Ray's DONT_SCALE_BUMPS_FLAG), so the
    ** pattern's scale changes the bumps' strength; normal_map entries
    ** inherit it */
    bool no_bump_scale;
    iris_image_ref *bump_map;
    /* As iris_pigment.entry_xf, for a normal_map's entries: they are
    ** perturbed at the point moved back by it, the normal taken to its
    ** space and back (NULL: none). */
    const iris_transform *entry_xf;
    /* As iris_pigment's, over the normal_map's normals. */
    uint32_t map_tree;
    bool map_tree_pointwise;
} iris_normal;

/* A finish{} with POV-Ray's defaults (scene.c: iris_finish_defaults). */
typedef struct iris_finish {
    iris_loc loc;
    iris_colour ambient;       /* 0.1 */
    iris_colour emission;      /* 0 */
    double diffuse;            /* 0.6 */
    double diffuse_back;       /* 0 */
    /* 'diffuse albedo D' multiplied diffuse and diffuse_back by
    ** (brilliance + 1) / 2, this factor; 0 when not. Radiosity and
    ** subsurface take the diffuse as written (POV-Ray's RawDiffuse):
    ** iris_finish_raw_diffuse() */
    double albedo_scale;
    double brilliance;         /* 1 */
    double phong, phong_size;  /* 0, 40 */
    double specular, roughness;/* 0, 0.05 */
    double metallic;           /* 0 (bare keyword: 1) */
    iris_colour reflection_min, reflection_max; /* 0, 0 */
    double reflection_falloff; /* 1 */
    double reflection_exponent;/* 1 */
    double reflection_metallic;/* 0 */
    bool reflection_fresnel;
    bool conserve_energy;
    double crand;
    double irid, irid_thickness; iris_vec3 irid_turbulence;
    double legacy_ior;         /* finish{ior} of old scenes, 0 = unset */
    double legacy_refraction;  /* finish{refraction}, 1 */
    /* subsurface { translucency C }: POV-Ray 3.7's BSSRDF in place of the
    ** diffuse term where global_settings has subsurface{} (render/
    ** subsurface.h); C is the mean free path in mm, 1/sigma'_s */
    bool subsurface;
    iris_colour translucency;  /* 0 */
} iris_finish;

/* The diffuse of 'f' before 'diffuse albedo' scaled it. */
static inline double iris_finish_raw_diffuse(const iris_finish *f)
{
    return f->albedo_scale > 0 ? f->diffuse / f->albedo_scale : f->diffuse;
}

/*
** A wavelength-dependent index of refraction (iris extensions, see
** DESIGN.md). POV is POV-Ray's own law from 'ior' and 'dispersion'.
*/
enum iris_ior_model { IRIS_IOR_POV = 0, IRIS_IOR_SELLMEIER,
                      IRIS_IOR_CAUCHY, IRIS_IOR_ABBE, IRIS_IOR_DECAY };

typedef struct iris_ior_spec {
    enum iris_ior_model model;
    const char *glass_name;    /* glass "N-BK7": SELLMEIER from catalogue */
    double b[4], c[4];         /* SELLMEIER, lambda in um, C in um^2 */
    double cauchy_a, cauchy_b; /* CAUCHY */
    double abbe_nd, abbe_vd;   /* ABBE */
    double decay_n1, decay_n2, decay_spread; /* DECAY */
    iris_loc loc;
} iris_ior_spec;

/*
** A media{} block (POV-Ray 3.7's Media, docs/media.md). Coefficients are
** per unit length, scaled at each point by the product of the densities'
** colours (no density: 1 everywhere). Extinction = absorption +
** sc_ext * scattering.
*/
enum iris_scattering { IRIS_SCATTER_ISOTROPIC = 1, IRIS_SCATTER_MIE_HAZY,
                       IRIS_SCATTER_MIE_MURKY, IRIS_SCATTER_RAYLEIGH,
                       IRIS_SCATTER_HENYEY_GREENSTEIN };

typedef struct iris_media {
    iris_loc loc;
    int method;                /* 1, 2 or 3 (3 from #version 3.5 on) */
    int intervals;             /* 1 (10 before 3.5) */
    int min_samples, max_samples; /* 10, 10 (1, 1 before 3.5) */
    double jitter;             /* 0 */
    double aa_threshold;       /* 0.1 */
    int aa_level;              /* 3 */
    double confidence;         /* 0.9 */
    double variance;           /* 1/128 */
    double ratio;              /* 0.9 */
    bool ignore_photons;       /* collect off */
    iris_colour absorption, emission, scattering; /* rgb used, 0 */
    int scattering_type;       /* enum iris_scattering, 1 */
    double eccentricity;       /* Henyey-Greenstein g, 0 */
    double sc_ext;             /* scattering{ extinction }, 1 */
    int n_densities;           /* multiplied together */
    iris_pigment **densities;  /* each with its world-to-pattern transform */
} iris_media;

/* An interior{} block. */
typedef struct iris_interior {
    iris_loc loc;
    double ior;                /* 0 = unset (POV-Ray: becomes 1) */
    double dispersion;         /* 1 */
    int dispersion_samples;    /* 7 */
    double caustics;           /* fake caustics k as written, 0 (the
                                  renderer uses k*45, as POV-Ray stores) */
    double fade_distance;      /* 0 */
    double fade_power;         /* 0 */
    iris_colour fade_colour;   /* 0 */
    bool has_media;            /* n_media > 0 */
    iris_ior_spec *spectral_ior; /* iris extension, NULL = POV law */
    int n_media;               /* media{} blocks in order */
    iris_media **media;
} iris_interior;

/* One texture layer, or a texture_map/material_map. */
typedef struct iris_texture {
    iris_loc loc;
    struct iris_texture *next; /* the layer below this one, or NULL */
    iris_pigment *pigment;     /* never NULL on a plain texture */
    iris_normal *normal;       /* NULL = none */
    iris_finish *finish;       /* never NULL on a plain texture */
    /* texture_map: pattern with entries holding textures; a material_map
    ** is kind IMAGE_MAP, its entries the textures numbered 0, 1, ... */
    iris_pattern map_pattern;  /* kind NONE = plain texture */
    int n_entries;
    iris_map_entry *entries;
    /* As iris_pigment's: this texture, its pigment's and normal's
    ** trees and its texture_map entries' (not the layers below). */
    uint32_t map_tree;
} iris_texture;

/* ------------------------------------------------------------------ */
/* Objects                                                              */
/* ------------------------------------------------------------------ */

enum iris_object_kind {
    IRIS_OBJ_SPHERE = 0, IRIS_OBJ_BOX, IRIS_OBJ_PLANE, IRIS_OBJ_CYLINDER,
    IRIS_OBJ_CONE, IRIS_OBJ_TORUS, IRIS_OBJ_DISC, IRIS_OBJ_TRIANGLE,
    IRIS_OBJ_MESH, IRIS_OBJ_POLYGON, IRIS_OBJ_PRISM, IRIS_OBJ_LATHE,
    IRIS_OBJ_SOR, IRIS_OBJ_SUPERELLIPSOID, IRIS_OBJ_BLOB,
    IRIS_OBJ_HEIGHT_FIELD, IRIS_OBJ_TEXT, IRIS_OBJ_ISOSURFACE,
    IRIS_OBJ_QUADRIC, IRIS_OBJ_POLY, IRIS_OBJ_JULIA_FRACTAL,
    IRIS_OBJ_BICUBIC_PATCH, IRIS_OBJ_PARAMETRIC, IRIS_OBJ_SPHERE_SWEEP,
    IRIS_OBJ_OVUS, IRIS_OBJ_LEMON,
    /* CSG */
    IRIS_OBJ_UNION, IRIS_OBJ_MERGE, IRIS_OBJ_INTERSECTION,
    IRIS_OBJ_DIFFERENCE,
    IRIS_OBJ_LIGHT_GROUP,
    IRIS_OBJ_KIND_COUNT
};

/* A triangle mesh (mesh, mesh2, and smooth_triangle/triangle alone). */
typedef struct iris_mesh_data {
    int n_vertices, n_normals, n_uvs, n_triangles;
    iris_vec3 *vertices;
    iris_vec3 *normals;        /* may be NULL */
    iris_vec2 *uvs;            /* may be NULL */
    int32_t *tri_vertices;     /* 3 per triangle */
    int32_t *tri_normals;      /* 3 per triangle, or NULL (flat) */
    int32_t *tri_uvs;          /* 3 per triangle, or NULL */
    int32_t *tri_texture;      /* per-triangle texture index, or NULL */
    int n_textures;
    struct iris_texture **textures;
    iris_vec3 inside_vector;   /* for inside tests; zero = none */
} iris_mesh_data;

/* prism, lathe and sor profiles. */
enum iris_spline { IRIS_SPLINE_LINEAR = 0, IRIS_SPLINE_QUADRATIC,
                   IRIS_SPLINE_CUBIC, IRIS_SPLINE_BEZIER };

/* The iteration function of a julia_fractal (quaternion: sqr, cube). */
enum iris_julia_fn { IRIS_JULIA_SQR = 0, IRIS_JULIA_CUBE, IRIS_JULIA_EXP,
                     IRIS_JULIA_RECIPROCAL, IRIS_JULIA_SIN, IRIS_JULIA_ASIN,
                     IRIS_JULIA_SINH, IRIS_JULIA_ASINH, IRIS_JULIA_COS,
                     IRIS_JULIA_ACOS, IRIS_JULIA_COSH, IRIS_JULIA_ACOSH,
                     IRIS_JULIA_TAN, IRIS_JULIA_ATAN, IRIS_JULIA_TANH,
                     IRIS_JULIA_ATANH, IRIS_JULIA_LN, IRIS_JULIA_PWR };

typedef struct iris_blob_component {
    int kind;                  /* 0 sphere, 1 cylinder */
    iris_vec3 a, b;            /* centre, or the cylinder's ends */
    double radius, strength;
    iris_transform transform; bool has_transform;
    struct iris_texture *texture;
} iris_blob_component;

typedef struct iris_object iris_object;

/* One object; 'kind' says which member of the union is valid. */
struct iris_object {
    enum iris_object_kind kind;
    iris_loc loc;

    iris_transform transform;  /* object to world, complete */
    bool has_transform;        /* false: identity */

    iris_texture *texture;     /* resolved; NULL only on CSG nodes */
    iris_texture *interior_texture; /* NULL = same as texture */
    iris_interior *interior;   /* NULL = none (air) */

    /* Modifiers */
    bool inverse, hollow, no_shadow, no_image, no_reflection;
    bool double_illuminate, sturm, open, no_radiosity;
    int n_clipped_by;
    iris_object **clipped_by;  /* each in world space */
    iris_object *bounded_by;   /* tested before the object (POV-Ray's
                                  Ray_In_Bound), also on CSG */

    /* Photons */
    bool photon_target;
    double photon_density;     /* spacing multiplier, 1 */
    iris_loc photon_target_loc; /* its 'target' keyword (line 0: none) */
    enum iris_tristate photon_refraction, photon_reflection;
    bool photon_collect;       /* true unless 'collect off' */
    bool photon_pass_through;
    bool split_union;          /* true unless 'split_union off' */
    /* light_group (POV-Ray's LLights): an object in a group is lit by
    ** scene->group_lights[light_group_first .. +light_group_count) and,
    ** unless no_global_lights, by the scene's lights */
    int light_group_first, light_group_count;
    bool no_global_lights;
    /* radiosity { importance F }: the share of a radiosity sample's rays
    ** that shade it, (0, 1]; 0 = not given: the #default's (CSG children
    ** take their parent's, povparse/obj.c finalize) */
    double radiosity_importance;

    union {
        struct { iris_vec3 centre; double radius; } sphere;
        struct { iris_vec3 lo, hi; } box;
        struct { iris_vec3 normal; double distance; } plane;
        struct { iris_vec3 base, cap; double radius; } cylinder;
        struct { iris_vec3 base, cap; double base_radius, cap_radius; } cone;
        struct { double major, minor; } torus;
        struct { iris_vec3 centre, normal; double radius, hole_radius; } disc;
        struct { iris_vec3 p[3], n[3]; bool smooth; iris_vec2 uv[3];
                 bool has_uv; } triangle;
        iris_mesh_data mesh;
        struct { int n_points; iris_vec3 *points; } polygon;
        struct { enum iris_spline spline; int sweep; /* 0 linear,1 conic */
                 double height1, height2; int n_points; iris_vec2 *points;
               } prism;
        struct { enum iris_spline spline; int n_points; iris_vec2 *points;
               } lathe;        /* also SOR (spline ignored) */
        struct { double e, n; } superellipsoid;
        struct { double threshold; int n_components;
                 iris_blob_component *components; } blob;
        struct { iris_image_ref *image; iris_fn *fn; int fn_res_x, fn_res_y;
                 bool smooth; double water_level; } height_field;
        struct { const char *font; const char *string; double thickness;
                 iris_vec3 offset; } text;
        struct { iris_fn *fn; double threshold, accuracy, max_gradient;
                 int contained_kind; /* 0 box, 1 sphere */
                 iris_vec3 lo, hi; iris_vec3 centre; double radius;
                 int max_trace; bool all_intersections; } isosurface;
        struct { int order; int n_coeffs; double *coeffs; } poly;
               /* QUADRIC stored as order-2 POLY, its 10 coefficients
                  as written: A..J of quadric {<A,B,C>,<D,E,F>,<G,H,I>,J}
                  (x²,y²,z²,xy,xz,yz,x,y,z,1); POLY/cubic/quartic in
                  POV-Ray's poly term order */
        struct { double data[16]; int type; int iterations;
                 double precision; iris_vec3 slice; double distance;
                 int fn; /* enum iris_julia_fn; data[0..3] = the
                            parameter, data[5] = slice w, data[6..7] =
                            pwr(x, y)'s exponent */ } julia;
        struct { int type; double flatness; int u_steps, v_steps;
                 iris_vec3 points[16]; } bicubic;
        struct { iris_fn *fx, *fy, *fz; iris_vec2 uv_lo, uv_hi;
                 iris_vec3 lo, hi;
                 int contained_kind; /* 0 box lo..hi, 1 sphere */
                 iris_vec3 centre; double radius;
                 double accuracy, max_gradient; /* 0 = POV-Ray's
                                                   0.001 and 1 */
                 /* 'precompute D x,y,z': depth 1..20 (0 = none) and the
                 ** functions named, bit 0 x, 1 y, 2 z */
                 int precompute_depth, precompute_axes; } parametric;
        struct { int spline; int n_spheres; iris_vec3 *centres;
                 double *radii; } sphere_sweep;
        struct { double r1, r2; } ovus;
        struct { iris_vec3 base, cap; double base_radius, cap_radius,
                 inner_radius; } lemon;
        struct { int n_children; iris_object **children; } csg;
    } u;
};

/* ------------------------------------------------------------------ */
/* Lights, camera, atmosphere, settings                                  */
/* ------------------------------------------------------------------ */

enum iris_light_kind { IRIS_LIGHT_POINT = 0, IRIS_LIGHT_SPOT,
                       IRIS_LIGHT_CYLINDER };

/* Emission spectrum shapes (iris extension; DESIGN.md). */
enum iris_light_spectrum { IRIS_SPEC_D65 = 0, IRIS_SPEC_A,
                           IRIS_SPEC_F1, /* F1..F12 follow in order */
                           IRIS_SPEC_F12 = IRIS_SPEC_F1 + 11,
                           IRIS_SPEC_BLACKBODY };

/* The most sub-lights (size1 x size2) an area light may have: each trace
** context keeps a shadow-ray table of that many entries (render/trace.c
** tracer_init); a larger area light is rendered as a point light at its
** centre and the parser says so. POV-Ray has no such limit. */
#define IRIS_AREA_LIGHT_MAX_GRID (1024 * 1024)

typedef struct iris_light {
    iris_loc loc;
    enum iris_light_kind kind;
    iris_vec3 location;        /* after transforms */
    iris_vec3 point_at;        /* spot, cylinder, parallel; default <0,0,1> */
    iris_colour colour;
    bool parallel;
    double radius, falloff, tightness; /* degrees for spot (30, 45, 0);
                                          lengths for cylinder (.75, 1, 0) */
    /* area_light */
    bool area;
    iris_vec3 axis1, axis2;
    int size1, size2;          /* above IRIS_AREA_LIGHT_MAX_GRID sub-lights
                                  in all the light is a point light */
    int adaptive;              /* default 100 (area lights) */
    bool jitter, circular, orient, area_illumination;
    bool shadowless;
    double fade_distance, fade_power; /* 0 = none */
    bool media_interaction, media_attenuation;
    iris_object *looks_like;   /* NULL = none; already no_shadow */
    iris_object *projected_through;
    /* photons { refraction reflection area_light } */
    enum iris_tristate photon_refraction, photon_reflection;
    bool photon_area_light;
    /* iris extension */
    enum iris_light_spectrum spectrum;
    double blackbody_kelvin;
} iris_light;

enum iris_camera_kind { IRIS_CAM_PERSPECTIVE = 0, IRIS_CAM_ORTHOGRAPHIC,
                        IRIS_CAM_FISHEYE, IRIS_CAM_PANORAMIC,
                        IRIS_CAM_ULTRA_WIDE, IRIS_CAM_OMNIMAX,
                        IRIS_CAM_CYLINDER, IRIS_CAM_SPHERICAL,
                        IRIS_CAM_MESH };

/*
** The resolved camera. A primary ray for pixel (x, y) of W x H is, for the
** perspective camera, origin 'location' and direction
** normalize(direction + x0·right + y0·up), x0 = (x+.5)/W - .5,
** y0 = .5 - (y+.5)/H (povray-3.7-semantics.md §3.8).
*/
typedef struct iris_camera {
    iris_loc loc;
    enum iris_camera_kind kind;
    int cylinder_type;         /* 1..4 for IRIS_CAM_CYLINDER */
    iris_vec3 location, direction, right, up, sky, look_at;
    double angle;              /* degrees, as given (0 = none) */
    double v_angle;            /* spherical: vertical field in degrees,
                                  'angle H, V' (0 = H/2, POV-Ray's default) */
    /* focal blur: aperture 0 = none; blur_samples is the maximum and
    ** blur_samples_min the minimum before the confidence test may stop
    ** (0: none, as `blur_samples N` alone); focal_distance is resolved by
    ** the parser as POV-Ray does: |focal_point - location| when a
    ** focal_point was given, else the length of direction (0 becomes 1);
    ** -1 until resolved */
    double aperture; int blur_samples, blur_samples_min;
    iris_vec3 focal_point;
    double focal_distance;
    double confidence, variance;
    /* mesh_camera { rays_per_pixel, distribution [max_distance] meshes
    ** [smooth] } (IRIS_CAM_MESH, src/render/meshcam.c): the meshes are
    ** IRIS_OBJ_MESH objects not in the scene's object list */
    int mesh_rays_per_pixel;   /* >= 1 */
    int mesh_distribution;     /* 0..3 */
    double mesh_max_distance;  /* 0 = none; parsed, warned, not used */
    bool mesh_smooth;          /* distribution 3: interpolated normals */
    int n_meshes;
    iris_object **meshes;
    struct iris_normal *normal; /* normal{}: perturbs every ray's direction
                                   (src/render/camera.c), NULL = none */
} iris_camera;

/*
** A rainbow{} (POV-Ray's RAINBOW, resolved as Parse_Rainbow leaves it):
** angles in radians, 'angle' already lowered by half the width, the arc
** and falloff angles halved; antisolar, up and right unit and mutually
** perpendicular. Applied by src/render/rainbow.c.
*/
typedef struct iris_rainbow {
    iris_loc loc;
    double angle, width;       /* the colour map spans [angle, angle+width] */
    double distance;           /* attenuation distance, 1e7 */
    double jitter;             /* parsed; iris does not jitter */
    double arc_angle, falloff_angle, falloff_width;
    iris_vec3 antisolar, up, right;
    struct iris_pigment *pigment; /* gradient x over the colour_map; NULL:
                                     no colour_map, the rainbow is off */
} iris_rainbow;

enum iris_fog_kind { IRIS_FOG_CONSTANT = 1, IRIS_FOG_GROUND = 2 };

typedef struct iris_fog {
    iris_loc loc;
    enum iris_fog_kind kind;
    double distance;
    iris_colour colour;
    iris_vec3 turbulence; double turb_depth; int octaves;
    double omega, lambda;
    double offset, alt;
    iris_vec3 up;              /* default y */
    iris_transform transform; bool has_transform;
} iris_fog;

typedef struct iris_sky_sphere {
    iris_loc loc;
    int n_pigments;            /* first = outermost as written */
    iris_pigment **pigments;
    double emission;           /* 3.7: default 1 */
    iris_transform transform; bool has_transform;
} iris_sky_sphere;

/* global_settings { photons { } } */
typedef struct iris_photon_settings {
    bool enabled;              /* the block is present and gather max > 0 */
    double spacing;            /* 1 (only count given: derived) */
    int count;                 /* 0 = use spacing */
    int gather_min, gather_max;/* 20, 100 */
    double radius, radius_mul; /* -1 = auto, 1 */
    double jitter;             /* 0.4 */
    int max_trace_level;       /* -1 = the scene's */
    double adc_bailout;        /* -1 = the scene's */
    double autostop;           /* 0.5 */
    double expand_tol; int expand_min; /* 0.2, 35 */
    int media_max_steps; double media_factor;
    const char *save_file, *load_file;
    iris_loc file_loc;         /* the save_file or load_file keyword */
    iris_loc loc;              /* the 'spacing' or 'count' keyword (else
                                  the photons block); line 0 = unknown */
} iris_photon_settings;

/* radiosity {} (POV-Ray 3.7's parameters and defaults, set when the block
** is present); src/render/gather.c uses them for its final gather. */
typedef struct iris_radiosity_settings {
    int count;                 /* 35: gather rays per cached sample */
    double brightness;         /* 1 */
    int recursion_limit;       /* 2 (>= 2: gather hits see the global map) */
    double error_bound;        /* 1.8 */
    double low_error_factor;   /* 0.5: error_bound's factor in pretrace */
    double minimum_reuse;      /* 0.015 (of the distance to the camera) */
    double maximum_reuse;      /* 0.2 */
    int nearest_count;         /* 5 */
    double pretrace_start;     /* 0.08 (of the image size) */
    double pretrace_end;       /* 0.04 */
    double gray_threshold;     /* 0 */
    double max_sample;         /* -1 = no cap */
    double adc_bailout;        /* 0.01 */
    bool always_sample;        /* false */
    bool media;                /* false: gather rays ignore media */
    bool normal;               /* false: gather about the unperturbed
                                  normal; true: the layer's (gather.c) */
} iris_radiosity_settings;

typedef struct iris_global_settings {
    double assumed_gamma;      /* 0 = not given */
    int max_trace_level;       /* 5 */
    double adc_bailout;        /* 1/255 */
    iris_colour ambient_light; /* 1 */
    iris_vec3 irid_wavelength; /* 0.70, 0.52, 0.48 */
    int number_of_waves;       /* 10 */
    int noise_generator;       /* 2 */
    bool radiosity;            /* a radiosity{} block was given */
    iris_radiosity_settings rad; /* valid when 'radiosity' */
    iris_photon_settings photons;
    /* mm_per_unit and subsurface {} (render/subsurface.h) */
    double mm_per_unit;        /* 10 */
    bool subsurface;           /* a subsurface{} block was given */
    int sss_samples_diffuse;   /* samples A, B: 50, 50 */
    int sss_samples_single;
    bool sss_radiosity;        /* radiosity BOOL: false */
    /* #default { radiosity { importance F } }: 0 = not given (1) */
    double rad_default_importance;
    bool rad_importance_used;  /* some importance below 1 was given */
} iris_global_settings;

/* A warning found while parsing or building, kept for the caller. */
typedef struct iris_scene_warning {
    iris_loc loc;
    const char *message;
} iris_scene_warning;

typedef struct iris_arena iris_arena;

/* The whole scene. */
/* What iris_scene_destroy() frees besides the arena: data a scene refers
** to that lives outside it (a function's loaded images, src/fn). */
typedef struct iris_scene_cleanup {
    struct iris_scene_cleanup *next;
    void (*free)(void *data);
    void *data;
} iris_scene_cleanup;

typedef struct iris_scene {
    iris_arena *arena;         /* owns everything below */
    iris_scene_cleanup *cleanups; /* run by iris_scene_destroy, in order */
    double version;            /* the last #version; 3.62 if none ran
                                  (POV-Ray 3.7 EffectiveLanguageVersion) */

    int n_files;               /* files[0] is "" (unknown) */
    const char **files;

    iris_camera camera;
    bool has_camera;

    int n_objects;             /* top-level objects in parse order */
    iris_object **objects;

    int n_lights;
    iris_light **lights;
    int n_group_lights;        /* the lights of light_groups: they light */
    iris_light **group_lights; /* only their groups' objects (above) */

    iris_colour background;    /* default black, transmit 1 */
    bool has_background;
    iris_sky_sphere *sky_sphere;
    int n_fogs;
    iris_fog **fogs;
    int n_rainbows;
    iris_rainbow **rainbows;
    int n_media;               /* atmospheric media{} blocks */
    iris_media **media;

    iris_global_settings settings;

    /* Width/height the scene was parsed for (image_width, image_height) */
    int image_width, image_height;
} iris_scene;

/* Frees a scene and everything in its arena. NULL does nothing. */
void iris_scene_destroy(iris_scene *scene);

/* Fills 'f' with POV-Ray's finish defaults (semantics §3.1). */
void iris_finish_defaults(iris_finish *f);

/* Fills 'i' with POV-Ray's interior defaults. */
void iris_interior_defaults(iris_interior *i);

/* Fills 'm' with POV-Ray's media defaults for a scene of #version
** 'version' (method 3, 1 interval, 10 samples from 3.5 on). */
void iris_media_defaults(iris_media *m, double version);

/* Fills 'g' with POV-Ray's global_settings defaults. */
void iris_global_defaults(iris_global_settings *g);

/* Fills 'l' with POV-Ray's light defaults (colour 1, point_at z, ...). */
void iris_light_defaults(iris_light *l);

/* Fills 'c' with POV-Ray's default camera (semantics §3.8). */
void iris_camera_defaults(iris_camera *c);

/* Sets 't' to the identity. */
void iris_transform_identity(iris_transform *t);

#ifdef __cplusplus
}
#endif

#endif
