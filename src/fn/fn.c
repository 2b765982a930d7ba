/* SPDX-License-Identifier: MIT */
/*
** fn.c: the evaluator of compiled SDL functions (fn.h) and the internal
** functions of functions.inc.
**
** A plain stack machine over doubles; every result is made finite (a
** domain error or a division by zero gives 0, as fn.h promises), the
** stack and the call depth are bounded, and nothing is allocated, so
** evaluation is reentrant and thread-safe. The internal functions are in
** fnintern.c; pattern and pigment functions are evaluated by the pattern
** code of src/material (mat_pattern_at, mat_pigment_at).
**
** Depends on: material/material.h (pattern evaluation).
*/
#include "config.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "fn/fnimages.h"
#include "iris/fn.h"
#include "iris/scene.h"
#include "material/material.h"

static inline double finite_or_0(double v)
{
    /* (false for NaN too; cheaper than isfinite() where it is a call) */
    return fabs(v) <= DBL_MAX ? v : 0.0;
}

/* A double as an integer without undefined conversions. */
static long long to_ll(double v)
{
    if (!(v > -9.0e18 && v < 9.0e18))
        return 0;
    return (long long)v;
}

static double builtin(int b, const double *a, int n)
{
    switch (b) {
    case IRIS_FB_ABS: return fabs(a[0]);
    case IRIS_FB_ACOS: return acos(a[0]);
    case IRIS_FB_ACOSH: return acosh(a[0]);
    case IRIS_FB_ASIN: return asin(a[0]);
    case IRIS_FB_ASINH: return asinh(a[0]);
    case IRIS_FB_ATAN: return atan(a[0]);
    case IRIS_FB_ATAN2: return n >= 2 ? atan2(a[0], a[1]) : 0;
    case IRIS_FB_ATANH: return atanh(a[0]);
    case IRIS_FB_CEIL: return ceil(a[0]);
    case IRIS_FB_COS: return cos(a[0]);
    case IRIS_FB_COSH: return cosh(a[0]);
    case IRIS_FB_DEGREES: return a[0] * 180.0 / M_PI;
    case IRIS_FB_DIV: return n >= 2 && a[1] != 0 ? trunc(a[0] / a[1]) : 0;
    case IRIS_FB_EXP: return exp(a[0]);
    case IRIS_FB_FLOOR: return floor(a[0]);
    case IRIS_FB_INT: return trunc(a[0]);
    case IRIS_FB_LN: return log(a[0]);
    case IRIS_FB_LOG: return log10(a[0]);
    case IRIS_FB_MAX: case IRIS_FB_MIN: {
        double r = a[0];
        for (int i = 1; i < n; i++)
            r = b == IRIS_FB_MAX ? fmax(r, a[i]) : fmin(r, a[i]);
        return r;
    }
    case IRIS_FB_MOD: return n >= 2 && a[1] != 0 ? fmod(a[0], a[1]) : 0;
    case IRIS_FB_POW: return n >= 2 ? pow(a[0], a[1]) : 0;
    case IRIS_FB_RADIANS: return a[0] * M_PI / 180.0;
    case IRIS_FB_SIN: return sin(a[0]);
    case IRIS_FB_SINH: return sinh(a[0]);
    case IRIS_FB_SQRT: return sqrt(a[0]);
    case IRIS_FB_TAN: return tan(a[0]);
    case IRIS_FB_TANH: return tanh(a[0]);
    case IRIS_FB_SQR: return a[0] * a[0];
    case IRIS_FB_CBRT: return cbrt(a[0]);
    case IRIS_FB_PROD: case IRIS_FB_SUM: {
        double r = b == IRIS_FB_PROD ? 1 : 0;
        for (int i = 0; i < n; i++)
            r = b == IRIS_FB_PROD ? r * a[i] : r + a[i];
        return r;
    }
    case IRIS_FB_BITWISE_AND: case IRIS_FB_BITWISE_OR:
    case IRIS_FB_BITWISE_XOR: {
        long long r = to_ll(a[0]);
        for (int i = 1; i < n; i++) {
            long long x = to_ll(a[i]);
            r = b == IRIS_FB_BITWISE_AND ? (r & x) :
                b == IRIS_FB_BITWISE_OR ? (r | x) : (r ^ x);
        }
        return (double)r;
    }
    default: return 0;
    }
}

/* A pattern function's value, a pigment function's component, a spline's
** component at t = p[0], or a transformed point's component, at the point
** given by the first three of 'p' (missing ones are 0). */
static double point_value(const iris_fn_insn *in, const double *p, int n)
{
    double x = n > 0 ? p[0] : 0, y = n > 1 ? p[1] : 0, z = n > 2 ? p[2] : 0;
    int k = in->arg;
    if (in->op == IRIS_FN_SPLINE) {
        double v[5];
        iris_fn_spline_eval(in->spline, x, v);
        return fn_pigment_component(v, k); /* .gray/.hf weigh x, y, z */
    }
    if (in->op == IRIS_FN_TRANSFORM) {
        if (!in->xform || k < 0 || k > 2)
            return 0;
        const double *m = in->xform->m[k];
        return m[0] * x + m[1] * y + m[2] * z + m[3];
    }
    if (in->images) /* it reads images: evaluated with them loaded */
        return fn_images_value(in, x, y, z);
    if (in->pigment) {
        double c[5];
        mat_pigment_at(in->pigment, x, y, z, c);
        return fn_pigment_component(c, in->arg);
    }
    return in->pattern ? mat_pattern_at(in->pattern, x, y, z) : 0;
}

static double eval(const iris_fn *fn, const double *args, int n_args,
                   int depth);

/* sum()/prod(): the body called for i = a, a+1, ..., b (POV-Ray's bounds
** are inclusive). Past SUM_MAX_TERMS terms the loop stops: a render must
** not hang on a huge bound. */
#define SUM_MAX_TERMS 1000000
#define SUM_MAX_ARGS 64

static double sum_loop(const iris_fn_insn *in, const double *args,
                       int n_args, double a, double b, int depth)
{
    double buf[SUM_MAX_ARGS + 1];
    int slot = in->nargs;
    if (slot < 0 || slot > SUM_MAX_ARGS || !(a <= b) || !isfinite(a))
        return in->arg ? 1 : 0;
    for (int k = 0; k < slot; k++)
        buf[k] = args && k < n_args ? finite_or_0(args[k]) : 0;
    double r = in->arg ? 1 : 0;
    long n = 0;
    for (double i = a; i <= b && n < SUM_MAX_TERMS; i += 1, n++) {
        buf[slot] = i;
        double v = eval(in->callee, buf, slot + 1, depth + 1);
        r = in->arg ? r * v : r + v;
    }
    return r;
}

static double eval(const iris_fn *fn, const double *args, int n_args,
                   int depth)
{
    double st[IRIS_FN_MAX_STACK];
    int sp = 0;
    if (!fn || depth > IRIS_FN_MAX_DEPTH || fn->max_stack > IRIS_FN_MAX_STACK)
        return 0;
    if (!args || n_args < 0)
        n_args = 0;
    /* (a parameter is one unsigned comparison: users' function meshes
    ** run millions of these at parse time) */
    const unsigned n_par = (unsigned)n_args;
    const iris_fn_insn *const end = fn->code + fn->n_code;
    for (const iris_fn_insn *in = fn->code; in < end; in++) {
        double r;
        int pop = 0;
        switch (in->op) {
        case IRIS_FN_CONST: r = in->value; break;
        case IRIS_FN_PARAM:
            if ((unsigned)in->arg < n_par) {
                /* arguments reach here finite (iris_fn_eval's callers
                ** and the pushes below), except the top level's */
                r = args[in->arg];
                if (sp >= IRIS_FN_MAX_STACK)
                    return 0;
                st[sp++] = depth ? r : finite_or_0(r);
                continue;
            }
            r = 0;
            break;
        /* two operands, one result: the stack shrinks, so no bound to
        ** test; each operator its own case (one dispatch, not two) */
#define BINARY(OP, EXPR)                                                  \
        case OP: {                                                        \
            if (sp < 2)                                                   \
                return 0;                                                 \
            double a = st[sp - 2], b = st[sp - 1];                        \
            sp--;                                                         \
            st[sp - 1] = (EXPR);                                          \
            continue;                                                     \
        }
        BINARY(IRIS_FN_ADD, finite_or_0(a + b))
        BINARY(IRIS_FN_SUB, finite_or_0(a - b))
        BINARY(IRIS_FN_MUL, finite_or_0(a * b))
        BINARY(IRIS_FN_DIV, b != 0 ? finite_or_0(a / b) : 0)
        BINARY(IRIS_FN_POW, finite_or_0(pow(a, b)))
        BINARY(IRIS_FN_LT, a < b)
        BINARY(IRIS_FN_LE, a <= b)
        BINARY(IRIS_FN_GT, a > b)
        BINARY(IRIS_FN_GE, a >= b)
        BINARY(IRIS_FN_EQ, a == b)
        BINARY(IRIS_FN_NE, a != b)
        BINARY(IRIS_FN_AND, a != 0 && b != 0)
        BINARY(IRIS_FN_OR, a != 0 || b != 0)
#undef BINARY
        case IRIS_FN_NEG: case IRIS_FN_NOT:
            if (sp < 1)
                return 0;
            r = in->op == IRIS_FN_NEG ? -st[sp - 1] : st[sp - 1] == 0;
            pop = 1;
            break;
        case IRIS_FN_SELECT3: case IRIS_FN_SELECT4: {
            int k = in->op == IRIS_FN_SELECT3 ? 3 : 4;
            if (sp < k)
                return 0;
            const double *a = &st[sp - k];
            if (k == 3)
                r = a[0] < 0 ? a[1] : a[2];
            else
                r = a[0] < 0 ? a[1] : a[0] == 0 ? a[2] : a[3];
            pop = k;
            break;
        }
        case IRIS_FN_BRANCH: case IRIS_FN_BRANCH_ZERO: {
            if (sp < 1)
                return 0;
            double a = st[--sp];
            int to = in->op == IRIS_FN_BRANCH_ZERO ? (a == 0 ? in->arg : -1)
                     : a < 0 ? -1 : a == 0 ? in->arg : in->nargs;
            if (to < 0)
                continue;
            /* forward only, so that every function ends */
            if (to <= in - fn->code || to > fn->n_code)
                return 0;
            in = fn->code + to - 1;
            continue;
        }
        case IRIS_FN_JUMP:
            if (in->arg <= in - fn->code || in->arg > fn->n_code)
                return 0;
            in = fn->code + in->arg - 1;
            continue;
        case IRIS_FN_COND:
            if (sp < 3)
                return 0;
            r = st[sp - 3] != 0 ? st[sp - 2] : st[sp - 1];
            pop = 3;
            break;
        case IRIS_FN_BUILTIN:
            if (in->nargs < 1 || sp < in->nargs)
                return 0;
            r = builtin(in->arg, &st[sp - in->nargs], in->nargs);
            pop = in->nargs;
            break;
        case IRIS_FN_CALL:
            if (in->nargs < 0 || sp < in->nargs)
                return 0;
            r = eval(in->callee, &st[sp - in->nargs], in->nargs, depth + 1);
            pop = in->nargs;
            break;
        case IRIS_FN_INTERNAL:
            if (in->nargs > 0) {
                if (sp < in->nargs)
                    return 0;
                r = iris_fn_internal(in->arg, &st[sp - in->nargs], in->nargs);
                pop = in->nargs;
            } else {
                /* nargs 0: the function's own arguments pass through */
                r = iris_fn_internal(in->arg, args, args ? n_args : 0);
            }
            break;
        case IRIS_FN_SUM:
            if (sp < 2)
                return 0;
            r = sum_loop(in, args, n_args, st[sp - 2], st[sp - 1], depth);
            pop = 2;
            break;
        case IRIS_FN_PATTERN: case IRIS_FN_SPLINE: case IRIS_FN_TRANSFORM: {
            /* the point is the function's own arguments, or popped */
            const double *p = args;
            int np = args ? n_args : 0;
            if (in->nargs > 0) {
                if (sp < in->nargs)
                    return 0;
                p = &st[sp - in->nargs];
                np = in->nargs;
                pop = in->nargs;
            }
            r = point_value(in, p, np);
            break;
        }
        default:
            return 0;
        }
        sp -= pop;
        if (sp >= IRIS_FN_MAX_STACK)
            return 0;
        st[sp++] = finite_or_0(r);
    }
    return sp > 0 ? st[sp - 1] : 0;
}

double iris_fn_eval(const iris_fn *fn, const double *args, int n_args)
{
    return finite_or_0(eval(fn, args, n_args, 0));
}
