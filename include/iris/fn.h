/* SPDX-License-Identifier: MIT */
/*
** fn.h: compiled SDL functions (function { ... }).
**
** The parser compiles a function body into a small stack program that both
** the parser (for '#declare V = F(1,2,3);') and the renderer (isosurfaces,
** function patterns) evaluate with iris_fn_eval(). The program is plain
** data in the scene arena; evaluation is reentrant and thread-safe.
*/
#ifndef IRIS_FN_H
#define IRIS_FN_H

#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Opcodes of the stack machine. */
enum iris_fn_op {
    IRIS_FN_CONST = 0, /* push 'value' */
    IRIS_FN_PARAM,     /* push parameter 'arg' (0 = x, 1 = y, 2 = z, ...) */
    IRIS_FN_ADD, IRIS_FN_SUB, IRIS_FN_MUL, IRIS_FN_DIV, IRIS_FN_NEG,
    IRIS_FN_POW,
    IRIS_FN_LT, IRIS_FN_LE, IRIS_FN_GT, IRIS_FN_GE, IRIS_FN_EQ, IRIS_FN_NE,
    IRIS_FN_AND, IRIS_FN_OR, IRIS_FN_NOT,
    IRIS_FN_SELECT3,   /* select(a, b, c): a < 0 ? b : c */
    IRIS_FN_SELECT4,   /* select(a, b, c, d): a < 0 ? b : a == 0 ? c : d */
    IRIS_FN_COND,      /* a ? b : c */
    IRIS_FN_BUILTIN,   /* 'arg' = enum iris_fn_builtin, pops its arity */
    IRIS_FN_CALL,      /* call 'callee' with 'arg' arguments */
    IRIS_FN_INTERNAL,  /* functions.inc internal('arg'), pops 'nargs' */
    IRIS_FN_PATTERN,   /* a pattern function: 'pattern' at (x,y,z), or
                          component 'arg' (0..4 = r,g,b,f,t; 5 = gray) of
                          'pigment'; (x,y,z) are the function's own
                          arguments when 'nargs' is 0, else 3 popped */
    IRIS_FN_SUM,       /* sum/prod(i, a, b, body): pops a and b; 'callee'
                          is the body, called with the function's own
                          arguments then i = a, a+1, ..., b at index
                          'nargs'; 'arg' 0 = sum, 1 = product */
    IRIS_FN_SPLINE,    /* component 'arg' of 'spline' at t = the first
                          argument (nargs 0) or 1 popped (nargs 1) */
    IRIS_FN_TRANSFORM, /* component 'arg' of 'xform' applied to (x,y,z):
                          the arguments (nargs 0) or 3 popped (nargs 3) */
    /* select() and a ? b : c, lazily as POV-Ray compiles them (only the
    ** arm chosen is evaluated: users' functions put costly calls in every
    ** arm). Targets are insn indices after the branch, at most n_code. */
    IRIS_FN_BRANCH,    /* pops a: a < 0 goes on, a == 0 jumps to 'arg',
                          a > 0 to 'nargs' */
    IRIS_FN_BRANCH_ZERO, /* pops a: jumps to 'arg' when a == 0 */
    IRIS_FN_JUMP,      /* jumps to 'arg' */
    IRIS_FN_OP_COUNT
};

/* Built-in maths functions callable inside a function body. */
enum iris_fn_builtin {
    IRIS_FB_ABS = 0, IRIS_FB_ACOS, IRIS_FB_ACOSH, IRIS_FB_ASIN,
    IRIS_FB_ASINH, IRIS_FB_ATAN, IRIS_FB_ATAN2, IRIS_FB_ATANH,
    IRIS_FB_CEIL, IRIS_FB_COS, IRIS_FB_COSH, IRIS_FB_DEGREES, IRIS_FB_DIV,
    IRIS_FB_EXP, IRIS_FB_FLOOR, IRIS_FB_INT, IRIS_FB_LN, IRIS_FB_LOG,
    IRIS_FB_MAX, IRIS_FB_MIN, IRIS_FB_MOD, IRIS_FB_POW, IRIS_FB_RADIANS,
    IRIS_FB_SIN, IRIS_FB_SINH, IRIS_FB_SQRT, IRIS_FB_TAN, IRIS_FB_TANH,
    IRIS_FB_PROD, IRIS_FB_SUM, IRIS_FB_BITWISE_AND, IRIS_FB_BITWISE_OR,
    IRIS_FB_BITWISE_XOR, IRIS_FB_SQR, IRIS_FB_CBRT, IRIS_FB_COUNT
};

typedef struct iris_fn iris_fn;
struct iris_pattern;
struct iris_pigment;
struct iris_transform;

/* An SDL spline{} (keys t[i], increasing, with values p[i][0..dim-1]),
** evaluated as POV-Ray 3.7's splines.cpp does: outside the keys the end
** value; cubic_spline is Catmull-Rom between the second and next-to-last
** keys; natural_spline needs 'coeff' (n rows) from iris_fn_spline_coeffs. */
enum iris_fn_spline_type { IRIS_FN_SPLINE_LINEAR = 0,
                           IRIS_FN_SPLINE_QUADRATIC, IRIS_FN_SPLINE_CUBIC,
                           IRIS_FN_SPLINE_NATURAL };
typedef struct iris_fn_spline {
    int type;              /* enum iris_fn_spline_type */
    int n, dim;
    const double *t;
    const double (*p)[5];
    const double (*coeff)[5];
} iris_fn_spline;

/* The natural spline's second derivatives at the keys, into 'out' (n
** rows); false when out of memory (then 'out' is zero: linear). */
bool iris_fn_spline_coeffs(const iris_fn_spline *s, double (*out)[5]);
/* The spline's value at 't' (all 5 components; zeros when empty). */
void iris_fn_spline_eval(const iris_fn_spline *s, double t, double out[5]);

/* One instruction. */
typedef struct iris_fn_insn {
    enum iris_fn_op op;
    int arg;               /* parameter index, builtin, internal number */
    int nargs;             /* for CALL, BUILTIN with variable arity */
    double value;          /* CONST */
    const iris_fn *callee; /* CALL */
    const struct iris_pattern *pattern; /* PATTERN */
    const struct iris_pigment *pigment; /* PATTERN of a pigment function */
    const iris_fn_spline *spline;       /* SPLINE */
    const struct iris_transform *xform; /* TRANSFORM */
    /* PATTERN whose pattern or pigment reads images (image_map,
    ** image_pattern, density_file) or objects: what it reads, loaded by
    ** iris_fn_load_images(); NULL = nothing to load */
    const void *images;
} iris_fn_insn;

/* A compiled function: 'n_params' named parameters, 'n_code' insns. */
struct iris_fn {
    int n_params;          /* x, y, z by default */
    const char **param_names;
    int n_code;
    iris_fn_insn *code;
    int max_stack;         /* computed by the compiler */
    int n_results;         /* 1, or 3/5 for vector/colour functions */
};

/* Limits the evaluator enforces; past them it returns 0. */
#define IRIS_FN_MAX_STACK 256
#define IRIS_FN_MAX_DEPTH 64

/*
** Evaluates 'fn' with 'n_args' arguments. Missing arguments are 0. A
** division by zero or a domain error gives 0, never NaN or Inf, as POV-Ray's
** VM does not crash either. Thread-safe.
*/
double iris_fn_eval(const iris_fn *fn, const double *args, int n_args);

/*
** Loads what the PATTERN insn 'in' reads (images, density files, objects
** of an object pattern) into in->images, so that the function sees them
** as a render's textures do; nothing when it reads none. 'assumed_gamma'
** and 'version' are the scene's, for the images' colours (0: none given).
** Free with iris_fn_free_images(in->images). False when out of memory.
*/
bool iris_fn_load_images(iris_fn_insn *in, double assumed_gamma,
                         double version);
void iris_fn_free_images(void *images);

/* Evaluates internal function 'n' of functions.inc (f_sphere, f_noise3d,
** ...). Returns 0 for numbers it does not implement. */
double iris_fn_internal(int n, const double *args, int n_args);

/* SDL's vturbulence(lambda, omega, octaves, <p>): POV-Ray's DTurbulence
** with its noise, octaves clamped to 1..10 as POV-Ray does; the parser
** calls it through here, since the noise lives in the core. */
void iris_fn_vturbulence(double lambda, double omega, double octaves,
                         const double p[3], double out[3]);

#ifdef __cplusplus
}
#endif

#endif
