/* SPDX-License-Identifier: MIT */
/*
** julia.c: POV-Ray's julia_fractal: quaternion (sqr, cube) and
** hypercomplex (sqr, cube, reciprocal and the complex functions, whose
** algebra is in julia_hcx.c).
**
** A 3-D point p is lifted to the quaternion (x, y, z, w) on the slice
** hyperplane slice·q = distance, and iterated q <- q² + c (or q³ + c). It
** is inside while |q|² stays below the exit value for 'max_iteration'
** steps. A ray marches from the bounding sphere with POV-Ray's distance
** estimate (never shorter than 1/precision) until inside/outside flips;
** the crossing is then bisected to 1e-12 of the bounding radius (POV-Ray
** stops at 1e-7, which a secondary ray started accel_epsilon() away would
** find again). Normals are the gradient of |q_n|² through the Jacobian
** of all the iterations at the inside end of the crossing, as POV-Ray
** computes them. A caller that keeps only the
** nearest crossing (isect_list.first_only) gets the first one and the
** march stops there, as POV-Ray's does for an object outside CSG.
**
** Hypercomplex sets follow POV-Ray's hcmplx.cpp: bounding radius 4, exit
** value 16, a step |q|²/(2 |n·d|) from the normal n along the ray d when
** it lies between 1 and 30 minimum steps (the minimum otherwise), and
** normals from POV-Ray's derivative product (julia_hcx.h), taken at the
** inside end of the crossing as POV-Ray takes them.
*/
#include "config.h"

#include "geometry/geom.h"
#include "geometry/julia_hcx.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Steps one ray may take: a bad precision cannot stall a render */
#define MAX_STEPS 100000
/*
** Iterations of the map one ray may spend in all, marching and bisecting
** (issue 7: bounded time). A heavy POV-Ray setting (max_iteration 50,
** precision 1000, radius 2) needs about 2e5; max_iteration 1e6 with
** precision 1e9 would need 1e11 and stall the render for hours. Past the
** budget the march stops and the rest of the ray is treated as missing
** the set: about 5 ms of work per ray at most.
*/
#define MAX_WORK 1000000L

struct jset {
    double c[4], s[4], sdist;
    double exit2, radius, step_min;
    int iters;
    bool cube;
    bool hcx;    /* hypercomplex algebra */
    int fn;      /* enum iris_julia_fn */
    double e[2]; /* pwr's exponent */
};

static bool setup(const iris_object *o, struct jset *j)
{
    const double *d = o->u.julia.data;
    for (int k = 0; k < 4; k++)
        j->c[k] = d[k];
    j->s[0] = o->u.julia.slice.x;
    j->s[1] = o->u.julia.slice.y;
    j->s[2] = o->u.julia.slice.z;
    j->s[3] = d[5];
    if (j->s[0] == 0 && j->s[1] == 0 && j->s[2] == 0 && j->s[3] == 0)
        j->s[3] = 1; /* POV-Ray's default slice <0,0,0,1>, 0 */
    double len = sqrt(j->s[0] * j->s[0] + j->s[1] * j->s[1] +
                      j->s[2] * j->s[2] + j->s[3] * j->s[3]);
    if (!(len > 0) || !isfinite(len))
        return false;
    for (int k = 0; k < 4; k++)
        j->s[k] /= len;
    j->sdist = o->u.julia.distance;
    /* The slice must cross the w axis: w is solved for below */
    if (fabs(j->s[3]) < 1e-10)
        return false;
    double cn = sqrt(j->c[0] * j->c[0] + j->c[1] * j->c[1] +
                     j->c[2] * j->c[2] + j->c[3] * j->c[3]);
    j->hcx = o->u.julia.type == 1;
    j->fn = o->u.julia.fn;
    j->e[0] = d[6];
    j->e[1] = d[7];
    if (j->hcx) {
        /* POV-Ray: a fixed radius 4 and exit value 16 */
        j->radius = 4;
        j->exit2 = 16;
    } else {
        /* POV-Ray: radius 1 + |c| capped at 2, with a 1e-7 margin */
        j->radius = fmin(2, 1 + cn + 1e-7);
        j->exit2 = j->radius * j->radius + 1e-7;
    }
    j->iters = o->u.julia.iterations > 0 ? o->u.julia.iterations : 20;
    /* One inside point (and its normal) costs 'iters' iterations, counted
    ** only afterwards: past the ray's whole budget, max_iteration 1e9 took
    ** minutes per ray. A point still bounded after MAX_WORK iterations
    ** counts as inside (issue 7: bounded time). */
    if (j->iters > MAX_WORK)
        j->iters = (int)MAX_WORK;
    j->step_min = o->u.julia.precision > 0 ? 1 / o->u.julia.precision
                                           : 1.0 / 20;
    j->cube = o->u.julia.fn == IRIS_JULIA_CUBE;
    return isfinite(cn) && isfinite(j->sdist);
}

static void lift(const struct jset *j, vec3 p, double q[4])
{
    q[0] = p.x;
    q[1] = p.y;
    q[2] = p.z;
    q[3] = (j->sdist - j->s[0] * p.x - j->s[1] * p.y - j->s[2] * p.z) /
           j->s[3];
}

/* Inline: the quaternion normal calls it 7 times per iteration. */
static inline void qmul(const double a[4], const double b[4], double r[4])
{
    double t[4] = {
        a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
        a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
        a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
        a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]
    };
    for (int k = 0; k < 4; k++)
        r[k] = t[k];
}

static bool hcx_run(const struct jset *j, vec3 p, vec3 d, double *dist,
                    double (*z)[4], long *work);

/* 2^n exactly, as ldexp(1, n), without the libm call for small n (the
** hypercomplex march asks for it at every step) */
static double pow2(int n)
{
    return n >= 0 && n < 63 ? (double)((uint64_t)1 << n) : ldexp(1, n);
}

/*
** One step q <- q² + c or q³ + c, from the closed forms of a quaternion
** (a, v) squared, (a² - |v|², 2a v), and cubed, (a(a² - 3|v|²),
** (3a² - |v|²) v), as POV-Ray's quaternion iteration writes them: a
** quarter of the products of qmul().
*/
static void quat_step(const struct jset *j, double q[4])
{
    double a = q[0], v2 = q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    double s, k;
    if (j->cube) {
        double a2 = a * a;
        s = a * (a2 - 3 * v2);
        k = 3 * a2 - v2;
    } else {
        s = a * a - v2;
        k = 2 * a;
    }
    q[0] = s + j->c[0];
    q[1] = k * q[1] + j->c[1];
    q[2] = k * q[2] + j->c[2];
    q[3] = k * q[3] + j->c[3];
}

/*
** The quaternion iteration from 'p'. Returns whether the orbit stays
** bounded; '*dist' (when not NULL) receives POV-Ray's lower bound on the
** distance to the set for escaping orbits (the minimum step otherwise).
** '*work' (when not NULL) grows by the iterations spent. Always inlined
** into the march and the bisection of geom_julia_hits(), which call it
** once a step (143_julia_quaternion_normal: 10 % of its instructions
** were the calls).
*/
static inline __attribute__((always_inline)) bool
quat_iter(const struct jset *j, vec3 p, double *dist, long *work)
{
    double q[4], normp = 1;
    lift(j, p, q);
    double pw = 1;
    for (int i = 1; i <= j->iters; i++) {
        double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (dist)
            normp *= sqrt(n2);  /* only the distance estimate reads it */
        if (n2 > j->exit2) {
            if (work)
                *work += i;
            if (dist) {
                /* Pow · sqrt(Norm) / |q_0 q_1 ... q_i| · log(Norm),
                ** POV-Ray's estimator (quatern.cpp); the norm of the
                ** quaternion product is the product of the norms */
                double de = pw / (j->cube ? 3 : 2) * sqrt(n2) / normp *
                            log(n2);
                *dist = isfinite(de) && de > 0 ? de : j->step_min;
            }
            return false;
        }
        pw /= j->cube ? 3 : 2;
        quat_step(j, q);
    }
    if (work)
        *work += j->iters;
    if (dist)
        *dist = j->step_min;
    return true;
}

/*
** Iterates from 'p', in either algebra: quat_iter() or hcx_run(), where
** hypercomplex sets step along the unit direction 'd'.
*/
static bool iterate(const struct jset *j, vec3 p, vec3 d, double *dist,
                    long *work)
{
    if (j->hcx)
        return hcx_run(j, p, d, dist, NULL, work);
    return quat_iter(j, p, dist, work);
}

/*
** POV-Ray's iteration stack z_0 .. z_iters. POV-Ray keeps one per thread
** and its normal reads all of it, also rows an early escape left from
** earlier calls; for 3.7's function typo (hcx_run) that decides the
** normal, so each ray replays POV-Ray's sequence of calls on a stack of
** its own. It starts zeroed, not with the previous ray's rows as
** POV-Ray's does: renders stay independent of thread order (a test render
** of a hypercomplex exp set came out identical either way).
*/
#define HSTACK_ROWS 65

struct hstack {
    double (*z)[4];
    double rows[HSTACK_ROWS][4];
};

static bool hstack_init(struct hstack *s, int iters)
{
    /* Rows past 'iters' are never read or written: only z_0 .. z_iters
    ** start zeroed (a ray clears 10 rows, not 65, at max_iteration 9) */
    if (iters < HSTACK_ROWS) {
        s->z = s->rows;
        memset(s->rows, 0, ((size_t)iters + 1) * sizeof *s->rows);
    } else {
        s->z = calloc((size_t)iters + 1, sizeof *s->z);
    }
    return s->z != NULL;
}

static void hstack_fini(struct hstack *s)
{
    if (s->z != s->rows)
        free(s->z);
}

/*
** POV-Ray's hypercomplex normal from the stack: the derivative product
** z_0 · factor(z_1) ... factor(z_(nmax-1)) against z_nmax · pw.
*/
static inline vec3 hcx_stack_normal(const struct jset *j, double (*z)[4],
                                    int nmax, double pw)
{
    double dp[4], n[4], g[3];
    for (int k = 0; k < 4; k++) {
        dp[k] = z[0][k];
        n[k] = z[nmax][k] * pw;
    }
    /* sqr and cube: the factor is z_i itself (hcx_normal_factor), used
    ** in place here, with no call per row */
    if (j->fn == IRIS_JULIA_SQR || j->fn == IRIS_JULIA_CUBE)
        for (int i = 1; i < nmax; i++)
            hcx_mul(dp, z[i], dp);
    else
        for (int i = 1; i < nmax; i++) {
            double f[4];
            hcx_normal_factor(j->fn, j->e, z[i], f);
            hcx_mul(dp, f, dp);
        }
    hcx_normal(dp, n, g);
    return v3(g[0], g[1], g[2]);
}

/*
** The hypercomplex iteration from 'p' into the stack 'z', as iterate()
** above. With 'dist' it is POV-Ray's stepping iteration: '*dist' gets the
** step |q|²/(2|n·d|) along the unit direction 'd' when that lies between
** 1 and 30 minimum steps. Always inlined: the march (hcx_hits) calls it
** once a step, of about 2.5 iterations on 92_julia_hypercomplex, where
** the call (its saved registers, the vectors passed on the stack) cost
** 16 % of the scene's instructions. hcx_run() is the same out of line.
*/
static inline __attribute__((always_inline)) bool
hcx_iter(const struct jset *j, vec3 p, vec3 d, double *dist, double (*z)[4],
         long *work)
{
    /*
    ** POV-Ray 3.7's plain iteration for the complex functions (its inside
    ** test, bisection and normal; not the stepping one) starts from
    ** z = y, a typo fixed only in 3.8 (Iteration_HCompl_Func): iris
    ** renders 3.7's surfaces and normals.
    */
    bool square = j->fn == IRIS_JULIA_SQR || j->fn == IRIS_JULIA_CUBE;
    bool fn = !square && j->fn != IRIS_JULIA_RECIPROCAL;
    if (fn && !dist)
        p.z = p.y;
    /*
    ** z_(i-1) is carried in four scalars (u: its j part), the stack only
    ** written here: reloading a row, 8 bytes from each 16-byte store GCC
    ** made of it, defeated the store forwarding (92_julia_hypercomplex's
    ** CPU time 0.81 -> 0.72 s without it, at the same instructions).
    */
    lift(j, p, z[0]);
    double x = z[0][0], y = z[0][1], u = z[0][2], w = z[0][3];
    for (int i = 1; i <= j->iters; i++) {
        double n2 = x * x + y * y + u * u + w * w;
        if (n2 > j->exit2) {
            if (work)
                *work += i;
            if (dist) {
                /* sqr's normal carries POV-Ray's 2^n: it scales the step */
                double pw = j->fn == IRIS_JULIA_SQR
                                ? pow2(i > 1 ? i - 1 : 1) : 1;
                vec3 g = hcx_stack_normal(j, z, i - 1, pw);
                double step = v3_dot(g, d);
                *dist = j->step_min;
                if (step < -1e-8) {
                    step *= -2;
                    if (n2 > j->step_min * step &&
                        n2 < 30 * j->step_min * step)
                        *dist = n2 / step;
                }
            }
            return false;
        }
        double r[4];
        if (square) {
            const double q[4] = { x, y, u, w };
            hcx_mul(q, q, r); /* hcx_map's sqr and cube, inline */
        } else {
            hcx_map(j->fn, j->e, z[i - 1], r);
        }
        x = z[i][0] = r[0] + j->c[0];
        y = z[i][1] = r[1] + j->c[1];
        u = z[i][2] = r[2] + j->c[2];
        w = z[i][3] = r[3] + j->c[3];
    }
    if (work)
        *work += j->iters;
    if (dist)
        *dist = j->step_min;
    return true;
}

/* hcx_iter() out of line, on a stack of its own when 'z' is NULL (the
** inside test) */
static bool hcx_run(const struct jset *j, vec3 p, vec3 d, double *dist,
                    double (*z)[4], long *work)
{
    if (z)
        return hcx_iter(j, p, d, dist, z, work);
    struct hstack own;
    if (!hstack_init(&own, j->iters))
        return false;
    bool in = hcx_iter(j, p, d, dist, own.z, work);
    hstack_fini(&own);
    return in;
}

/*
** A ray through a hypercomplex set, as POV-Ray's Fractal::All_Intersections
** traces it: step until inside/outside flips, bisect to 1e-7, take the
** normal from the stack the last plain iteration left, and start a ray
** that begins inside 2e-7 further on. 'a'..'b' is the span inside the
** bounding sphere along the unit direction 'd' ('dl' = |rd|).
*/
static void hcx_hits(const struct jset *j, vec3 ro, vec3 d, double dl,
                     double a, double b, double t0, double t1,
                     struct isect_list *out)
{
    const double tol = 1e-7;
    struct hstack st;
    if (b < tol || !hstack_init(&st, j->iters))
        return;
    long work = 0;
    double depth = fmax(a, tol), dist, dist_next = 0;
    vec3 next = v3_madd(ro, d, depth);
    bool cur = hcx_run(j, next, d, &dist, st.z, &work), nxt, last = false;
    if (cur) {
        next = v3_madd(next, d, 2 * tol);
        depth += 2 * tol;
        cur = hcx_run(j, next, d, &dist, st.z, &work);
    }
    while (depth < b && work < MAX_WORK) {
        vec3 ip;
        for (;;) {
            /* fmax(dist, step_min) without the libm call: a NaN
            ** step gives step_min as fmax does */
            dist = dist > j->step_min ? dist : j->step_min;
            depth += dist;
            if (depth > b || work >= MAX_WORK)
                goto done;
            ip = next;
            next = v3_madd(next, d, dist);
            nxt = hcx_iter(j, next, d, &dist_next, st.z, &work);
            if (nxt != cur) {
                depth -= dist;
                break;
            }
            dist = dist_next;
        }
        while (dist > tol) {
            dist *= 0.5;
            vec3 mid = v3_madd(ip, d, dist);
            last = hcx_iter(j, mid, d, NULL, st.z, &work);
            if (last == cur) {
                ip = mid;
                depth += dist;
                if (depth > b)
                    goto done;
            }
        }
        if (!cur) {
            ip = v3_madd(ip, d, dist);
            depth += dist;
            hcx_run(j, ip, d, NULL, st.z, &work);
        } else if (last != cur) {
            hcx_run(j, ip, d, NULL, st.z, &work);
        }
        vec3 n = hcx_stack_normal(j, st.z, j->iters, 1);
        if (!(v3_len2(n) > 0) || !isfinite(v3_len2(n)))
            n = v3_scale(d, -1); /* degenerate: face the ray */
        if (depth > t0 * dl && depth < t1 * dl) {
            int had = out->n;
            isect_push(out, depth / dl, n, 0, 0);
            if (out->first_only && out->n > had)
                break;         /* POV-Ray's exit outside CSG */
        }
        /* POV-Ray carries on from the step's far end */
        dist = dist_next;
        cur = nxt;
    }
done:
    hstack_fini(&st);
}

/*
** POV-Ray's quaternion normal (quatern.cpp's CalcNormal): the gradient of
** |q_n|² through the Jacobian of all max_iteration steps, taken at the
** inside end of the crossing (where every step is defined), with the
** Jacobian starting at the identity on (x, y, z): the slice's dependence
** of w on x, y, z is left out, as POV-Ray leaves it out. Taking the
** gradient at the outside end up to the escaping step instead gave
** objects/fractal1 29.4 dB diffuse-only against POV-Ray.
*/
static vec3 julia_normal(const struct jset *j, vec3 p)
{
    double q[4], J[3][4];
    lift(j, p, q);
    for (int a = 0; a < 3; a++)
        for (int k = 0; k < 4; k++)
            J[a][k] = a == k ? 1 : 0;
    for (int i = 1; i <= j->iters; i++) {
        double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        /* Not reached from an inside point; guards against overflow */
        if (!(n2 < 1e150))
            break;
        double q2[4];
        qmul(q, q, q2);
        for (int a = 0; a < 3; a++) {
            double t1[4], t2[4], t3[4];
            if (!j->cube) {
                /* d(q²) = q dq + dq q */
                qmul(q, J[a], t1);
                qmul(J[a], q, t2);
                for (int k = 0; k < 4; k++)
                    J[a][k] = t1[k] + t2[k];
            } else {
                /* d(q³) = dq q² + q dq q + q² dq */
                double m[4];
                qmul(J[a], q2, t1);
                qmul(q, J[a], m);
                qmul(m, q, t2);
                qmul(q2, J[a], t3);
                for (int k = 0; k < 4; k++)
                    J[a][k] = t1[k] + t2[k] + t3[k];
            }
        }
        double r[4];
        if (j->cube)
            qmul(q2, q, r);
        else
            for (int k = 0; k < 4; k++)
                r[k] = q2[k];
        for (int k = 0; k < 4; k++)
            q[k] = r[k] + j->c[k];
    }
    vec3 n = v3(0, 0, 0);
    for (int k = 0; k < 4; k++) {
        n.x += J[0][k] * q[k];
        n.y += J[1][k] * q[k];
        n.z += J[2][k] * q[k];
    }
    return n;
}

bool geom_julia_ok(const iris_object *o)
{
    struct jset j;
    /* POV-Ray rejects quaternion functions other than sqr and cube */
    bool quat_fn = o->u.julia.fn == IRIS_JULIA_SQR ||
                   o->u.julia.fn == IRIS_JULIA_CUBE;
    bool fn_ok = o->u.julia.fn >= IRIS_JULIA_SQR &&
                 o->u.julia.fn <= IRIS_JULIA_PWR;
    return ((o->u.julia.type == 0 && quat_fn) ||
            (o->u.julia.type == 1 && fn_ok)) &&
           setup(o, &j);
}

bool geom_julia_inside(const iris_object *o, vec3 p)
{
    struct jset j;
    if (!setup(o, &j) || v3_len2(p) > j.radius * j.radius)
        return false;
    return iterate(&j, p, v3(0, 0, 0), NULL, NULL);
}

double geom_julia_radius(const iris_object *o)
{
    struct jset j;
    return setup(o, &j) ? j.radius : 0;
}

void geom_julia_hits(const iris_object *o, vec3 ro, vec3 rd, double t0,
                     double t1, struct isect_list *out)
{
    struct jset j;
    double dl = v3_len(rd);
    if (!setup(o, &j) || !(dl > 0))
        return;
    /* March in units of length along a unit direction */
    vec3 d = v3_scale(rd, 1.0 / dl);
    double tc = -v3_dot(ro, d);
    double h2 = j.radius * j.radius - v3_len2(v3_madd(ro, d, tc));
    if (!(h2 > 0))
        return;
    double a = fmax(tc - sqrt(h2), t0 * dl), b = fmin(tc + sqrt(h2), t1 * dl);
    if (!(a < b))
        return;
    if (j.hcx) {
        hcx_hits(&j, ro, d, dl, a, b, t0, t1, out);
        return;
    }
    double t = a, dist;
    long work = 0;
    bool in = iterate(&j, v3_madd(ro, d, t), d, &dist, &work);
    for (int step = 0; step < MAX_STEPS && t < b && work < MAX_WORK;
         step++) {
        /* fmin(t + fmax(dist, step_min), b) without the libm calls
        ** (the same values: a NaN dist steps by step_min) */
        double adv = t + (dist > j.step_min ? dist : j.step_min);
        double tn = adv < b ? adv : b, dn;
        bool inn = quat_iter(&j, v3_madd(ro, d, tn), &dn, &work);
        if (inn != in) {
            /* Bisect to 1e-12 of the set's radius, a thousandth of the
            ** offset a secondary ray starts at (hit_epsilon, 1e-9 of
            ** the object), or to adjacent doubles far from the origin */
            double lo = t, hi = tn;
            double tol = fmax(1e-12 * j.radius,
                              2e-16 * fmax(fabs(lo), fabs(hi)));
            for (int k = 0; k < 80 && hi - lo > tol; k++) {
                double m = 0.5 * (lo + hi);
                if (quat_iter(&j, v3_madd(ro, d, m), NULL, &work) == in)
                    lo = m;
                else
                    hi = m;
            }
            /* The normal is taken on the inside of the crossing */
            vec3 n = julia_normal(&j, v3_madd(ro, d, in ? lo : hi));
            double th = 0.5 * (lo + hi);
            if (th > t0 * dl && th < t1 * dl) {
                int had = out->n;
                isect_push(out, th / dl, n, 0, 0);
                if (out->first_only && out->n > had)
                    return;    /* POV-Ray's exit outside CSG */
            }
        }
        t = tn;
        dist = dn;
        in = inn;
    }
}
