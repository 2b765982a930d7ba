/* SPDX-License-Identifier: MIT */
/*
** pp.h: the private interface of povparse, shared by its .c files.
**
** The parser works as POV-Ray's does: the scanner (input.c) hands out
** tokens after executing the directives (#declare, #if, #while, #macro,
** #include, ...) it meets, and the grammar functions (expr.c, mat.c,
** obj.c, scene.c) pull tokens from it. Macro bodies and loop bodies are
** re-read from the source text, which stays in memory for the whole parse.
** Every error goes through pp_error(), which longjmps to the single setjmp
** in parse.c; all memory is in arenas or in tables parse.c frees.
**
** Depends on: the public headers in include/iris, src/util and src/math.
*/
#ifndef IRIS_POVPARSE_PP_H
#define IRIS_POVPARSE_PP_H

#include <math.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "iris/fn.h"
#include "iris/parse.h"
#include "iris/scene.h"
#include "math/transform.h"
#include "util/arena.h"

/* Tokens: punctuation first, then every keyword of tokens.def. */
enum pp_tok {
    T_EOF = 0, T_IDENT, T_NUMBER, T_STRING,
    T_LBRACE, T_RBRACE, T_LPAREN, T_RPAREN, T_LBRACKET, T_RBRACKET,
    T_LT, T_GT, T_LE, T_GE, T_EQUALS, T_NE, T_COMMA, T_SEMI, T_PLUS,
    T_MINUS, T_STAR, T_SLASH, T_HASH, T_QUESTION, T_COLON, T_AMP, T_BAR,
    T_BANG, T_DOT, T_OTHER,
    T_KW_FIRST,
#define TOK(name, word) T_##name,
#define ALIAS(name, word)
#include "tokens.def"
#undef TOK
#undef ALIAS
    T_NUM_TOKENS
};


/* A source file held in memory with its line map. */
typedef struct pp_file {
    const char *path;      /* as opened */
    const char *dir;       /* its directory, for #include search */
    const char *text;
    size_t len;
    uint32_t *line_start;  /* offsets of line starts, built on demand */
    uint32_t n_lines;
} pp_file;

/* Value kinds of identifiers and expressions. */
enum pp_vkind {
    V_NONE = 0, V_FLOAT, V_VECTOR, V_COLOUR, V_STRING, V_OBJECT, V_LIGHT,
    V_TEXTURE, V_PIGMENT, V_NORMAL, V_FINISH, V_INTERIOR, V_MATERIAL,
    V_TRANSFORM, V_CAMERA, V_FUNCTION, V_ARRAY, V_COLOUR_MAP,
    V_PIGMENT_MAP, V_NORMAL_MAP, V_TEXTURE_MAP, V_SLOPE_MAP, V_DENSITY_MAP,
    V_FOG, V_SKY_SPHERE, V_RAINBOW, V_SPLINE, V_MEDIA, V_DENSITY, V_FILE,
    V_MACRO, V_TEXTURE_LIST, V_UNSUPPORTED, V_KIND_COUNT
};

struct pp_array;
struct pp_macro;
struct pp_spline;
struct pp_material;
struct pp_map;
struct pp_fileh;

/* A value: numbers inline (dim 1 = float, 2..5 = vector; colours are 5),
** everything else by pointer into an arena. */
typedef struct pp_value {
    int kind;
    int dim;
    double v[5];
    /* a float made by the period operator (V.y): v[1..4] still hold the
    ** vector's other components, which POV-Ray's Parse_Vector reads as
    ** they are (vlength(V.x) is vlength(V)), while an operator with a
    ** vector operand promotes v[0] as for any float */
    bool leftover;
    union {
        const char *str;
        iris_object *obj;
        iris_light *light;
        iris_texture *tex;
        iris_pigment *pig;
        iris_normal *nor;
        iris_finish *fin;
        iris_interior *inter;
        struct pp_material *mat;
        iris_transform *xf;
        iris_camera *cam;
        iris_fn *fn;
        struct pp_array *arr;
        struct pp_map *map;
        iris_fog *fog;
        iris_sky_sphere *sky;
        struct pp_spline *spline;
        struct pp_macro *macro;
        struct pp_fileh *fh;
        void *ptr;
    } u;
} pp_value;

struct pp_sym;

/* One token: where it is (file, byte offset, length) and its value. */
typedef struct pp_token {
    int kind;
    uint32_t file;
    uint32_t off, len;
    double num;            /* T_NUMBER */
    const char *str;       /* T_STRING contents (scratch arena) */
    struct pp_sym *sym;    /* T_IDENT: the symbol, valid only until the
                              next token (a macro may end and free it) */
    pp_value val;          /* T_IDENT: a copy of the symbol's value */
} pp_token;

/* An array of 1 to 5 dimensions; unset elements have kind V_NONE. */
typedef struct pp_array {
    int ndim;
    int dims[5];
    long n;
    pp_value *items;
    /* POV-Ray's array Type: set by the first element stored, which every
    ** later one must match (pp_array_type; 0: none stored yet) */
    int elem_type;
} pp_array;


/* A macro: name, parameters and where its body starts in the source. */
typedef struct pp_macro {
    const char *name;
    int n_params;
    const char **params;
    uint32_t file;
    uint32_t body_off;     /* just after the ')' of the parameter list */
    uint32_t def_off;
} pp_macro;

/* material { texture interior } */
typedef struct pp_material {
    iris_texture *tex;
    iris_texture *interior_tex;
    iris_interior *inter;
} pp_material;

/* A colour/pigment/normal/texture/slope map. */
typedef struct pp_map {
    int kind;              /* V_COLOUR_MAP ... */
    int n;
    iris_map_entry *e;
} pp_map;

/* A spline{} (linear, quadratic, cubic, natural: evaluated by src/fn's
** iris_fn_spline_eval, POV-Ray's definitions). */
typedef struct pp_spline {
    int type;              /* enum iris_fn_spline_type */
    int n, dim;
    double *t;
    double (*p)[5];
    double (*coeff)[5];    /* natural splines: from iris_fn_spline_coeffs */
} pp_spline;

/* A file a scene wrote while writes are refused (memfile.c): kept for
** the rest of the parse so that the scene reads back what it wrote. */
typedef struct pp_memfile {
    struct pp_memfile *next;
    const char *path;      /* normalised directory/name */
    char *buf;             /* scratch arena; len bytes and a NUL */
    size_t len, cap;
} pp_memfile;

/* A file opened by #fopen. */
typedef struct pp_fileh {
    FILE *fp;
    pp_memfile *mem;       /* a refused write goes here instead of fp */
    bool write;
    const char *path;
} pp_fileh;

/* A symbol: a name bound to a value, or an alias of a caller's symbol
** (a macro parameter passed an identifier: POV-Ray's by-reference rule). */
typedef struct pp_sym {
    const char *name;
    size_t name_len;
    char name_buf[48];     /* short names live here */
    struct pp_sym *ref;
    pp_value val;
    struct pp_sym *next;   /* hash chain */
} pp_sym;

/* One symbol table: the global one, one per #include file, one per
** macro call. */
typedef struct pp_scope {
    pp_sym **buckets;
    unsigned n_buckets, n_syms;
} pp_scope;


/* Input frames: the file being read, and the #include files and macro
** calls that led to it. */
enum pp_frame_kind { FR_FILE = 0, FR_INCLUDE, FR_MACRO, FR_STRING };

typedef struct pp_frame {
    int kind;
    uint32_t file;
    uint32_t pos;          /* where the next token starts */
    uint32_t call_file, call_off; /* the #include or macro call */
    const pp_macro *macro;
    int cond_base;         /* cond stack depth when the frame started */
    int scope;             /* its symbol table index */
    /* macro parameters passed an array element (Swap(A[i], A[j])): their
    ** values go back to the elements when the macro returns */
    int n_elem_params;
    pp_sym **elem_params;
    int *elem_index;       /* which parameter of 'macro' each one is */
    pp_value **elem_slots;
} pp_frame;

/* Conditional/loop stack entries (#if, #while, #for, #switch, macro). */
enum pp_cond_kind { C_IF = 0, C_ELSE, C_WHILE, C_FOR, C_SWITCH, C_MACRO };

typedef struct pp_cond {
    int kind;
    uint32_t file, off;    /* the directive, for "missing #end" */
    uint32_t loop_pos;     /* WHILE/FOR: where the body starts */
    uint32_t cond_pos;     /* WHILE: where the condition starts */
    double switch_val;     /* SWITCH */
    bool matched;          /* SWITCH: a case ran */
    pp_sym *for_sym;       /* FOR */
    double for_end, for_step;
    long iterations;
} pp_cond;

typedef struct pp_state pp_state;

/* Per-object data the parser keeps beside the public node. */
typedef struct pp_light_node {
    iris_light *light;
    struct pp_light_node *next;
} pp_light_node;

typedef struct pp_obj {
    iris_object o;         /* first: (pp_obj *)obj is valid */
    pp_light_node *lights; /* light_sources inside a CSG */
    bool is_light_group;
    bool global_lights;    /* light_group: global_lights on */
    bool uv_mapping;       /* object { uv_mapping ... }: its textures are
                           ** evaluated at <u, v, 0> (POV-Ray's UV_FLAG) */
    bool cutaway;          /* cutaway_textures (CUTAWAY_TEXTURES_FLAG) */
    /* A CSG's bounding box as POV-Ray keeps it for min_extent/max_extent:
    ** made from its children's when they are read (Compute_CSG_BBox),
    ** then every later transform moves its eight corners (the box of a
    ** rotated union is the box of the rotated box, not of the rotated
    ** children) */
    bool has_box;
    iris_vec3 box_lo, box_hi;
    /* a sphere that POV-Ray gives a Trans (Sphere::Transform: after a
    ** matrix, a transform or an uneven scale): its box is then the
    ** transformed box, no longer the tight one */
    bool sphere_trans;
    /* a CSG copy's children are still the original's (pp_object_copy):
    ** own_children() copies them before anything changes them */
    bool shared_children;
} pp_obj;

struct pp_state {
    iris_scene *scene;
    iris_arena *A;         /* scene arena */
    iris_arena *S;         /* scratch arena (values, arrays, tokens) */
    iris_parse_options opt;
    iris_diag_list *diags;
    jmp_buf jb;
    enum iris_status fail_status;
    unsigned poll_count;   /* tokens since opt.interrupt was last read */

    /* Sources */
    pp_file *files;
    int n_files, cap_files;
    pp_frame *frames;
    int n_frames, cap_frames;
    pp_cond *conds;
    int n_conds, cap_conds;
    int include_depth, macro_depth;
    /* The frame and condition depths (n_frames, n_conds) at which a
    ** directive's own parameters are being read (#if (...), #case (...),
    ** #for (...)), 0 when none: no directive runs in the middle of those
    ** (expr.c's next_directive_closes_if), as '#if (X) #else' must not
    ** take the #else for an enclosing #if. */
    int header_frames, header_conds;

    /* Tokens: up to four tokens of look-ahead can be pushed back */
    pp_token tok;          /* the current token */
    int n_unget;
    pp_token unget[4];
    int no_expand;         /* > 0: identifiers are not expanded as macros */

    /* Keyword table (built per parse; tokens.def) */
    const char **kw_name;
    int *kw_hash;          /* open addressing: token kinds */
    unsigned kw_mask;

    /* Symbol tables */
    pp_scope *scopes;
    int n_scopes, cap_scopes;
    pp_sym *free_syms;     /* recycled symbols */

    /* Defaults set by #default */
    iris_texture *default_tex;
    iris_finish *default_finish;
    iris_pigment *default_pigment;

    /* Growing scene lists */
    int cap_objects, cap_lights, cap_fogs, cap_group_lights;

    /* Once-per-keyword warnings */
    unsigned char *warned;

    /* rand(): seed() streams */
    uint64_t *rng;
    int n_rng, cap_rng;

    pp_fileh *open_files[32];
    int n_open_files;
    pp_memfile *memfiles;  /* refused writes, newest first */
    int n_function_images; /* image_map { function ... }: their names */
    /* The array element an identifier with indices last stood for
    ** (input.c resolve_element): its slot and source extent */
    pp_value *elem_slot;
    uint32_t elem_file, elem_start, elem_end;

    /* Resolved directories reads may use (access.c); [0] = the scene's */
    const char **io_roots;
    int n_io_roots;

    double version;
    bool in_vector;        /* inside <..>: '>' closes, is no operator */
    /* POV-Ray's Terms where the next factor is read: 3 at the top of a
    ** vector parameter (Parse_Vector), the left operand's for the right
    ** one, else 1 (0 counts as 1). A float's '.y' needs Terms > 1. */
    int dot_terms;
    bool gamma_given;
    /* a #version directive has run (the scene's or an include file's):
    ** until then POV-Ray 3.7's EffectiveLanguageVersion() is 3.62, though
    ** 'version' reads 3.7 (pp_effective_version) */
    bool version_set;
    /* global_settings gave noise_generator: #version no longer sets it */
    bool noise_explicit;
    bool srgb_warned;      /* "sRGB colour before assumed_gamma" once */
    int depth;             /* nesting of the grammar's recursion */
    uintptr_t stack_base;  /* frame address where the parse started */
    size_t stack_limit;    /* bytes of C stack the grammar may use */
    uint32_t outer_file, outer_off, outer_len; /* where depth 1 began */
    int lex_peek;          /* > 0: strings are not decoded (look-ahead) */
    int in_density;        /* > 0: a media density{} is parsed (density_map
                              and density identifiers are allowed) */

    /* Finished copies of declared objects handed to the geometry
    ** queries (pp_query_object), so that one object keeps one pointer */
#define PP_QUERY_CACHE 8
    const iris_object *query_src[PP_QUERY_CACHE];
    const iris_object *query_obj[PP_QUERY_CACHE];
    unsigned query_next;
};

/* ---- diag.c ------------------------------------------------------- */
_Noreturn void pp_error(pp_state *ps, const pp_token *at, const char *fmt,
                        ...) IRIS_PRINTF(3, 4);
_Noreturn void pp_error_at(pp_state *ps, uint32_t file, uint32_t off,
                           uint32_t len, const char *fmt, ...)
    IRIS_PRINTF(5, 6);
void pp_warning(pp_state *ps, const pp_token *at, const char *fmt, ...)
    IRIS_PRINTF(3, 4);
/* Warns once per token kind 'kw' that a feature is parsed but ignored. */
void pp_warn_once(pp_state *ps, const pp_token *at, int kw, const char *what);
_Noreturn void pp_nomem(pp_state *ps);
/* Room for the first diagnostics, reserved before the parse starts. */
void pp_diags_reserve(pp_state *ps);
/* A located error with IRIS_EINTR when opt.interrupt is set (SIGINT). */
void pp_check_interrupt(pp_state *ps);
/* pp_check_interrupt every 4096 calls: cheap enough for every token. */
static inline void pp_poll_interrupt(pp_state *ps)
{
    if ((++ps->poll_count & 4095) == 0)
        pp_check_interrupt(ps);
}
/* Guards the C stack: nesting deeper than PP_MAX_DEPTH, or using more
** than stack_limit bytes of stack (sanitizer builds have large frames),
** is an error. */
#define PP_MAX_DEPTH 1000
void pp_enter(pp_state *ps, const pp_token *at);
static inline void pp_leave(pp_state *ps) { ps->depth--; }
/* "unexpected X in 'where'", or "undeclared identifier". */
_Noreturn void pp_unexpected(pp_state *ps, const pp_token *at,
                             const char *where);
iris_loc pp_loc(pp_state *ps, const pp_token *t);
void pp_line_col(pp_state *ps, uint32_t file, uint32_t off,
                 unsigned *line, unsigned *col);
const char *pp_tok_name(pp_state *ps, const pp_token *t, char *buf,
                        size_t n);
const char *pp_kind_name(int kind);

/* ---- access.c: the file access policy (issue 7) ------------------ */
/* True when 'path' may be read under opt.read_policy. */
bool pp_read_allowed(pp_state *ps, const char *path);
/* A located error at 'at' when 'path' may not be read. */
void pp_check_read(pp_state *ps, const pp_token *at, const char *path);
/* True when writes are allowed and 'path' lies in the scene's tree. */
bool pp_write_allowed(pp_state *ps, const char *path);

/* ---- memfile.c: refused writes kept in memory -------------------- */
pp_memfile *pp_memfile_open(pp_state *ps, const char *path, bool append);
void pp_memfile_write(pp_state *ps, pp_memfile *m, const char *s, size_t n);
pp_memfile *pp_memfile_find(pp_state *ps, const char *path);

/* ---- lex.c -------------------------------------------------------- */
void lex_init_keywords(pp_state *ps);
/* Scans the token at 'pos' of file 'f'; returns the offset after it. */
uint32_t lex_scan(pp_state *ps, uint32_t f, uint32_t pos, pp_token *t);
/* The same for a look-ahead: string contents are not decoded. */
uint32_t lex_peek(pp_state *ps, uint32_t f, uint32_t pos, pp_token *t);
const char *lex_keyword_name(int kind);

/* ---- input.c: tokens with directives executed --------------------- */
void pp_next(pp_state *ps);           /* advances ps->tok */
void pp_unget(pp_state *ps);          /* pushes ps->tok back */
/* Runs the directives that come next, as POV-Ray's Get_Token does
** wherever it reads on: only where the construct being read is not
** complete (a list before its ')', a function body before its '}'). */
void pp_run_directives(pp_state *ps);
/* pp_accept after the directives that come next have run: for the
** end of a list, which POV-Ray reads with Get_Token ('concat("a"
** #if (C) , "b" #end)'). */
bool pp_accept_in_list(pp_state *ps, int kind);
bool pp_accept(pp_state *ps, int kind);
void pp_expect(pp_state *ps, int kind, const char *what);
void pp_open_file(pp_state *ps, const char *path, bool is_include,
                  const pp_token *at);
uint32_t pp_add_text(pp_state *ps, const char *name, const char *text,
                     size_t len);
/* True when the next raw token starts a directive (an expression ends). */
bool pp_next_is_directive(pp_state *ps);
void pp_skip_block(pp_state *ps);     /* after '{': up to its '}' */
/* After 'radiosity' (object modifier or #default): '{' [importance F]
** '}'; returns F, or 0 when not given. */
double pp_radiosity_block(pp_state *ps);
void pp_close_files(pp_state *ps);
/* Raw skipping of a false branch: returns the directive it stopped at
** (T_ELSE, T_ELSEIF, T_END, T_CASE, T_RANGE, T_BREAK) at depth 0. */
enum { SKIP_IF = 0, SKIP_END, SKIP_SWITCH };
int pp_skip(pp_state *ps, int mode, const pp_cond *opener);
void pp_push_cond(pp_state *ps, int kind, const pp_token *at);
void pp_push_frame(pp_state *ps, int kind, uint32_t file, uint32_t pos,
                   const pp_token *call);
void pp_pop_frame(pp_state *ps);
/* The raw next token of the current frame (no directives, no macros). */
void pp_raw(pp_state *ps, pp_token *t);
/* Runs the directive whose keyword follows '#' (directive.c). */
void pp_directive(pp_state *ps, const pp_token *hash);
/* 'declare', 'include' or 'version' without '#' at a scene's top level
** ('kw', just read): runs it with a warning, as POV-Ray does; false for
** any other token. */
bool pp_bare_directive(pp_state *ps, const pp_token *kw);
void pp_call_macro(pp_state *ps, const pp_macro *m, const pp_token *call);
void pp_default_block(pp_state *ps);   /* after #default or default */

/* ---- symtab.c ----------------------------------------------------- */
void sym_push_scope(pp_state *ps);
void sym_pop_scope(pp_state *ps);
void sym_free_all(pp_state *ps);
pp_sym *sym_lookup(pp_state *ps, const char *name, size_t len);
pp_sym *sym_define(pp_state *ps, int scope, const char *name, size_t len);
pp_sym *sym_resolve(pp_sym *s);       /* follows by-reference aliases */
/* Whether 's' is still a symbol of an open scope (not recycled). */
bool sym_is_live(pp_state *ps, const pp_sym *s);
bool sym_undef(pp_state *ps, const char *name, size_t len);
/* The identifier text of token 't' (not NUL-terminated). */
const char *pp_tok_text(pp_state *ps, const pp_token *t);

/* ---- expr.c ------------------------------------------------------- */
pp_value pp_expr(pp_state *ps);
/* The expression of a #declare value, a macro argument or an array
** element: sums and products only (POV-Ray's Parse_RValue reads
** Parse_Rel_Factor; a comparison, '&', '|' or '?:' needs parentheses). */
pp_value pp_expr_sum(pp_state *ps);
/* rgb, rgbft, srgb..., color, red ... transmit: a colour's first word */
bool pp_is_colour_keyword(int kind);       /* numeric or string expression */
/* The noise generator POV-Ray takes by default under #version v: 1
** (the original Perlin noise) before 3.5, 2 from 3.5 on. */
static inline int pp_version_noise(double v)
{
    /* compared as a double: a huge or odd #version must not overflow an
    ** int conversion (the fuzzer's '#version 30000000') */
    return v * 100 + 0.5 < 350.0 ? 1 : 2;
}
/* '(' float ')' and no more, as POV-Ray's Parse_Float_Param: the
** condition of #if, #elseif, #while and #switch. */
double pp_paren_float(pp_state *ps);
double pp_float(pp_state *ps);        /* POV-Ray's Parse_Float: no <, = */
int pp_int(pp_state *ps);             /* a float in the int range */
long pp_clamp_long(double v);
double pp_full_float(pp_state *ps);         /* a full expression as a float */
iris_vec3 pp_vector(pp_state *ps);
/* pp_vector, an infinite component taken as +-bound: a box's corners
** ('Count / clock' at clock 0), which POV-Ray's box takes as they are,
** its intersection then stopping at BOUND_HUGE. */
iris_vec3 pp_vector_clamped(pp_state *ps, double bound);
/* Where an infinite box corner is put: POV-Ray's MAX_DISTANCE
** (configcore.h), far beyond any scene's objects. Not POV-Ray's
** BOUND_HUGE (2e10): iris's box and shadow arithmetic lose precision
** there (tests/render/scenes/253: 1e7 gives 65 dB to inf against POV-Ray,
** 1e9 32 dB, 2e10 25 dB). */
#define POV_MAX_DISTANCE 1.0e7
iris_vec2 pp_vector2(pp_state *ps);
void pp_vector4(pp_state *ps, double out[4]);
iris_colour pp_colour(pp_state *ps);
const char *pp_string(pp_state *ps);
bool pp_bool_opt(pp_state *ps);       /* optional on/off after a flag */
/* Parses the value of #declare X = ...; (any kind). */
pp_value pp_rvalue(pp_state *ps);
/* spline { ... } after 'spline' (rvalue.c); scratch arena. */
/* Prepares a spline for evaluation once its type and keys are set (a
** natural spline's coefficients). */
void pp_spline_finish(pp_state *ps, pp_spline *s);
pp_spline *pp_spline_block(pp_state *ps);
/* The public view of a spline, for iris_fn_spline_eval. */
iris_fn_spline pp_spline_view(const pp_spline *s);
void pp_value_promote(pp_value *v, int dim);
/* POV-Ray's truth of a number (its FTRUE): further than its EPSILON,
** 1e-10, from zero. #if, #while, ?:, !, & and | all test this, so
** '#if (1e-11)' is false as in POV-Ray. */
#define PP_EPSILON 1e-10
static inline bool pp_true(double x) { return fabs(x) > PP_EPSILON; }
/* True when the current token can start a float/vector expression. */
bool pp_starts_expr(pp_state *ps);
/* Whether the next token starts a float expression (not '<'), without
** consuming it: POV-Ray's Allow_Float test for an optional float. */
bool pp_float_follows(pp_state *ps);
iris_colour pp_value_colour(const pp_value *v);
/* The element A[i]...: the indices follow. */
pp_value pp_array_element(pp_state *ps, const pp_token *at, pp_array *arr);
/* A copy of 'arr' and of the arrays it holds (#declare B = A copies). */
/* Stores 'v' into 'slot' of 'arr' (at: for the error), refusing a value
** of another type than the array's, as POV-Ray's Test_Redefine does. */
void pp_array_store(pp_state *ps, pp_array *arr, pp_value *slot,
                    const pp_value *v, const pp_token *at);
pp_array *pp_array_copy(pp_state *ps, const pp_array *arr);
/* min_extent/max_extent's box of 'o' as POV-Ray computes it; false (and
** the box +-1e10) when the parser cannot bound 'o' itself (expr.c). */
bool pp_object_bounds(const iris_object *o, iris_vec3 *lo, iris_vec3 *hi);
pp_value pp_string_rvalue(pp_state *ps);
/* One factor with its .x/.red suffixes, no operators after it. */
pp_value pp_factor_value(pp_state *ps);

/* ---- fnc.c: function { } compiler --------------------------------- */
iris_fn *pp_function(pp_state *ps);
/* The number of arguments a call of 'fn' takes, as POV-Ray counts them:
** 1 for a spline function, functions.inc's for internal(N), else its
** parameters (fnc.c). */
int pp_fn_arity(const iris_fn *fn);
/* '(' Name ')' of #ifdef/#ifndef and defined(): whether Name (or an array
** element Name[i]) has a value (directive.c). */
bool pp_is_defined(pp_state *ps);   /* after 'function' */
/* The function pattern of pigment_pattern { pg }: pg's grey level. */
iris_fn *pp_pigment_grey_fn(pp_state *ps, iris_pigment *pg);

/* ---- mat.c: textures ---------------------------------------------- */
iris_pigment *pp_pigment(pp_state *ps, const iris_pigment *base);
iris_normal *pp_normal(pp_state *ps, const iris_normal *base);
iris_finish *pp_finish(pp_state *ps, const iris_finish *base);
iris_texture *pp_texture(pp_state *ps);           /* after 'texture' */
iris_interior *pp_interior(pp_state *ps, const iris_interior *base);
pp_material *pp_material_block(pp_state *ps);
pp_map *pp_map_block(pp_state *ps, int kind);      /* after x_map */
iris_texture *pp_default_texture(pp_state *ps);
iris_transform *pp_transform_block(pp_state *ps);  /* after 'transform' */
/* Parses one transform keyword (translate/rotate/scale/matrix/transform)
** at the current token into 'out'; false if the token is none. */
bool pp_transform_item(pp_state *ps, iris_transform *out);
/* A copy of texture 't' (its layers, texture_map patterns and entries)
** evaluated at the surface's <u, v, 0>: an object's uv_mapping. */
iris_texture *pp_tex_uv_mapped(pp_state *ps, const iris_texture *t);
/* Composes 'xf' into every pattern of a copied texture/pigment/normal. */
iris_texture *pp_tex_transform(pp_state *ps, const iris_texture *t,
                               const iris_transform *xf);
iris_pigment *pp_pig_transform(pp_state *ps, const iris_pigment *p,
                               const iris_transform *xf);
iris_normal *pp_nor_transform(pp_state *ps, const iris_normal *n,
                              const iris_transform *xf);
/* Count a completed pigment's, normal's or texture's map tree
** (maptree.c); an error at 'at' past IRIS_MAX_MAP_TREE. */
void pp_pig_map_tree(pp_state *ps, iris_pigment *p, const pp_token *at);
void pp_nor_map_tree(pp_state *ps, iris_normal *n, const pp_token *at);
void pp_tex_map_tree(pp_state *ps, iris_texture *t, const pp_token *at);
/* Whether a pigment's (normal's) map entries, or any map entry under
** them, read the uv point or the world point (uv_mapping, slope): from
** the entries' flags, one level down; also while 'p' is being parsed. */
bool pp_pig_entries_pointwise(const iris_pigment *p);
bool pp_nor_entries_pointwise(const iris_normal *n);
iris_texture *pp_texture_new(pp_state *ps, const pp_token *at);
iris_pigment *pp_pigment_new(pp_state *ps, const pp_token *at);
iris_fog *pp_fog(pp_state *ps);
void pp_rainbow(pp_state *ps); /* rainbow { ... }, appended to the scene */
iris_rainbow *pp_rainbow_block(pp_state *ps); /* a declared rainbow */
iris_sky_sphere *pp_sky_sphere(pp_state *ps, const iris_sky_sphere *b);
void pp_pattern_init(iris_pattern *p);
/* A file resolved along the search path (scene arena); one found nowhere
** keeps its name, with a located warning (density_file, not rendered). */
const char *pp_find_file(pp_state *ps, const pp_token *at, const char *name);
/* A file the scene cannot do without (an image, a font), also trying
** name+ext for each of the NULL-ended 'exts' (may be NULL) in POV-Ray's
** order (a font "cyrvetic" is found as cyrvetic.ttf); not finding it is a
** located error, as it is fatal in POV-Ray ("Cannot find image file",
** "Cannot open font file"). 'what' names the kind of file. */
/* The extensions POV-Ray tries for image type token 'kind' (T_PNG...),
** NULL-ended; NULL for any other token. */
const char *const *pp_image_exts(int kind);
const char *pp_require_file(pp_state *ps, const pp_token *at,
                            const char *name, const char *const *exts,
                            const char *what);

/* density { [DENSITY_ID] pigment items, density_map } (mat.c) after
** 'density': a pigment, as POV-Ray keeps densities. */
iris_pigment *pp_density_block(pp_state *ps, const iris_pigment *base);

/* ---- media.c: media{} --------------------------------------------- */
iris_media *pp_media(pp_state *ps);               /* at 'media' */
void pp_interior_add_media(pp_state *ps, iris_interior *in, iris_media *m);
iris_interior *pp_interior_transform(pp_state *ps, const iris_interior *in,
                                     const iris_transform *xf);
void pp_add_atmosphere_media(pp_state *ps, iris_media *m);

/* POV-Ray 3.7's EffectiveLanguageVersion(): the last #version, or 3.62
** while none has run (the renderer's compatibility switches). */
static inline double pp_effective_version(const pp_state *ps)
{
    return ps->version_set ? ps->version : 3.62;
}

/* An image's POV-Ray gamma mode, fixed when the image is parsed
** (iris_image_ref.as_stored): each #version sets POV-Ray's gammaMode
** anew (tokenize.cpp), 3.6's modes (None, AssumedGamma36) below 3.7,
** which read the texels as stored; 3.7's decode them. An image parsed
** before the scene's #version 3.7 (in an include file) keeps 3.6's. */
static inline signed char pp_image_as_stored(const pp_state *ps)
{
    return pp_effective_version(ps) < 3.7 ? 1 : -1;
}

/* ---- obj.c: objects ----------------------------------------------- */
/* Parses an object if the current token starts one (a shape, CSG,
** object {}, or a bare object or light identifier); NULL otherwise. */
iris_object *pp_object(pp_state *ps);
bool pp_starts_object(pp_state *ps);
iris_object *pp_object_copy(pp_state *ps, const iris_object *o);
void pp_object_transform(pp_state *ps, iris_object *o,
                         const iris_transform *xf);
iris_light *pp_light(pp_state *ps);               /* after light_source */
void pp_light_transform(iris_light *l, const iris_transform *xf);
/* Resolves inheritance of a finished top-level object. */
void pp_finalize_object(pp_state *ps, iris_object *o);
/* 'o' as the renderer sees a scene object (textures resolved, no lights
** added to the scene): what trace()/inside()/extents hand to
** opt.geometry. The same 'o' gives the same copy (a small cache). */
const iris_object *pp_query_object(pp_state *ps, const iris_object *o);

/* ---- scene.c: top level ------------------------------------------- */
void pp_scene_items(pp_state *ps);     /* until EOF */
iris_camera *pp_camera(pp_state *ps, const iris_camera *base);
void pp_add_object(pp_state *ps, iris_object *o);
void pp_add_light(pp_state *ps, iris_light *l);
/* Appends 'l' to the scene's light_group lights; returns its index. */
int pp_add_group_light(pp_state *ps, iris_light *l);

/* ---- gamma.c ------------------------------------------------------ */
double pp_srgb_decode(double c);     /* sRGB-encoded -> linear light */
/* An srgb colour channel in the working space of assumed_gamma. */
double pp_srgb_to_working(pp_state *ps, const pp_token *at, double c);

/* ---- memory ------------------------------------------------------- */
void *pp_alloc(pp_state *ps, size_t n);          /* scene arena, zeroed */
void *pp_salloc(pp_state *ps, size_t n);         /* scratch arena */
char *pp_strdup(pp_state *ps, const char *s, size_t n);

#endif
