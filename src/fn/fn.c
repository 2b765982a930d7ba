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

#include <math.h>
#include <string.h>

#include "fn/fnimages.h"
#include "iris/fn.h"
#include "iris/scene.h"
#include "material/material.h"

static double finite_or_0(double v)
{
    return isfinite(v) ? v : 0.0;
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
        buf[k] = args && k < n_args ? args[k] : 0;
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
    for (int pc = 0; pc < fn->n_code; pc++) {
        const iris_fn_insn *in = &fn->code[pc];
        double r = 0;
        int pop = 0;
        switch (in->op) {
        case IRIS_FN_CONST: r = in->value; break;
        case IRIS_FN_PARAM:
            r = in->arg >= 0 && in->arg < n_args && args ? args[in->arg] : 0;
            break;
        case IRIS_FN_ADD: case IRIS_FN_SUB: case IRIS_FN_MUL: case IRIS_FN_DIV:
        case IRIS_FN_POW: case IRIS_FN_LT: case IRIS_FN_LE: case IRIS_FN_GT:
        case IRIS_FN_GE: case IRIS_FN_EQ: case IRIS_FN_NE: case IRIS_FN_AND:
        case IRIS_FN_OR: {
            if (sp < 2)
                return 0;
            double a = st[sp - 2], b = st[sp - 1];
            pop = 2;
            switch (in->op) {
            case IRIS_FN_ADD: r = a + b; break;
            case IRIS_FN_SUB: r = a - b; break;
            case IRIS_FN_MUL: r = a * b; break;
            case IRIS_FN_DIV: r = b != 0 ? a / b : 0; break;
            case IRIS_FN_POW: r = pow(a, b); break;
            case IRIS_FN_LT: r = a < b; break;
            case IRIS_FN_LE: r = a <= b; break;
            case IRIS_FN_GT: r = a > b; break;
            case IRIS_FN_GE: r = a >= b; break;
            case IRIS_FN_EQ: r = a == b; break;
            case IRIS_FN_NE: r = a != b; break;
            case IRIS_FN_AND: r = a != 0 && b != 0; break;
            default: r = a != 0 || b != 0; break;
            }
            break;
        }
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
