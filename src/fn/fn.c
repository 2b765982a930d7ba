/* SPDX-License-Identifier: MIT */
/*
** fn.c: the evaluator of compiled SDL functions (fn.h) and the internal
** functions of functions.inc.
**
** A plain stack machine over doubles; every result is made finite (a
** domain error or a division by zero gives 0, as fn.h promises), the
** stack and the call depth are bounded, and nothing is allocated, so
** evaluation is reentrant and thread-safe.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "iris/fn.h"

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
        case IRIS_FN_PATTERN:
            /* Patterns are evaluated by the renderer's pattern code. */
            r = 0;
            break;
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

/* Argument i, or 'def' when the caller passed fewer. */
static double A(const double *a, int n, int i, double def)
{
    return i < n && a ? a[i] : def;
}

/* Clamps to [-10, 10] as POV-Ray's algebraic-surface functions do. */
static double clamp10(double v)
{
    return fmin(10.0, fmax(v, -10.0));
}

/*
** The internal functions of functions.inc that are implemented, with the
** definitions of POV-Ray 3.7's vm/fnintern.cpp (checked against it; the
** numbers are the internal(N) indices of functions.inc). Arguments: x, y,
** z, then the parameters functions.inc documents for each. The others
** return 0; see the list in the povparse report.
*/
double iris_fn_internal(int n, const double *a, int na)
{
    double x = A(a, na, 0, 0), y = A(a, na, 1, 0), z = A(a, na, 2, 0);
    double p0 = A(a, na, 3, 0), p1 = A(a, na, 4, 0), p2 = A(a, na, 5, 0);
    double p3 = A(a, na, 6, 0);
    double r = 0;
    switch (n) {
    case 17: /* f_ellipsoid(x,y,z, A, B, C) */
        r = sqrt(x * x * p0 * p0 + y * y * p1 * p1 + z * z * p2 * p2);
        break;
    case 45: /* f_paraboloid(x,y,z, field strength) */
        r = clamp10(p0 * -(x * x - y + z * z));
        break;
    case 47: /* f_ph: polar angle measured from +y */
        r = atan2(sqrt(x * x + z * z), y);
        break;
    case 57: /* f_r: distance from the origin */
        r = sqrt(x * x + y * y + z * z);
        break;
    case 60: { /* f_rounded_box(x,y,z, radius, half sizes x, y, z) */
        double dx = fmax(fabs(x) - (p1 - p0), 0);
        double dy = fmax(fabs(y) - (p2 - p0), 0);
        double dz = fmax(fabs(z) - (p3 - p0), 0);
        r = sqrt(dx * dx + dy * dy + dz * dz) - p0 - 1e-6;
        break;
    }
    case 61: /* f_sphere(x,y,z, radius) */
        r = sqrt(x * x + y * y + z * z) - p0;
        break;
    case 68: { /* f_superellipsoid(x,y,z, east-west e, north-south n) */
        if (p0 <= 0 || p1 <= 0)
            return 0;
        double e = 2 / p0, nn = 1 / p1;
        double xy = pow(pow(fabs(x), e) + pow(fabs(y), e), p0 * nn);
        r = 1 - pow(xy + pow(fabs(z), 2 * nn), p1 * 0.5);
        break;
    }
    case 69: /* f_th: azimuth around y, from +z towards +x */
        r = atan2(x, z);
        break;
    case 70: { /* f_torus(x,y,z, major, minor) */
        double d = sqrt(x * x + z * z) - p0;
        r = sqrt(d * d + y * y) - p1;
        break;
    }
    case 71: { /* f_torus2(x,y,z, field strength, major, minor) */
        double x2 = x * x, y2 = y * y, z2 = z * z;
        double ph = p1 * p1, th = p2 * p2;
        double q = x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 +
                   2 * y2 * z2 - 2 * (ph + th) * x2 + 2 * (ph - th) * y2 -
                   2 * (ph + th) * z2 + (ph - th) * (ph - th);
        r = clamp10(-p0 * q);
        break;
    }
    default:
        /* f_noise3d (76) and f_noise_generator (78) need the noise of the
        ** pattern code; the rest are not written yet */
        r = 0;
        break;
    }
    return finite_or_0(r);
}
