/* SPDX-License-Identifier: MIT */
/*
** julia.c: POV-Ray's quaternion julia_fractal (sqr and cube).
**
** A 3-D point p is lifted to the quaternion (x, y, z, w) on the slice
** hyperplane slice·q = distance, and iterated q <- q² + c (or q³ + c). It
** is inside while |q|² stays below the exit value for 'max_iteration'
** steps. A ray marches from the bounding sphere with POV-Ray's distance
** estimate (never shorter than 1/precision) until inside/outside flips;
** the crossing is then bisected to double precision (POV-Ray stops at
** 1e-7, which a secondary ray started accel_epsilon() away would find
** again). Normals are the gradient of |q_n|² through the iteration's
** Jacobian, as POV-Ray computes them.
*/
#include "config.h"

#include "geometry/geom.h"

#include <math.h>

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
    /* POV-Ray: radius 1 + |c| capped at 2, with a 1e-7 margin */
    j->radius = fmin(2, 1 + cn + 1e-7);
    j->exit2 = j->radius * j->radius + 1e-7;
    j->iters = o->u.julia.iterations > 0 ? o->u.julia.iterations : 20;
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

static void qmul(const double a[4], const double b[4], double r[4])
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

/*
** Iterates from 'p'. Returns whether the orbit stays bounded; '*dist'
** (when not NULL) receives POV-Ray's lower bound on the distance to the
** set for escaping orbits (the minimum step otherwise). '*work' (when not
** NULL) grows by the iterations spent.
*/
static bool iterate(const struct jset *j, vec3 p, double *dist, long *work)
{
    double q[4], normp = 1;
    lift(j, p, q);
    double pw = 1;
    for (int i = 1; i <= j->iters; i++) {
        double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        normp *= sqrt(n2);
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
        double r[4];
        qmul(q, q, r);
        if (j->cube)
            qmul(r, q, r);
        for (int k = 0; k < 4; k++)
            q[k] = r[k] + j->c[k];
    }
    if (work)
        *work += j->iters;
    if (dist)
        *dist = j->step_min;
    return true;
}

/* Gradient of |q_n|² with respect to p, through the Jacobian of the map. */
static vec3 julia_normal(const struct jset *j, vec3 p)
{
    double q[4], J[3][4];
    lift(j, p, q);
    for (int a = 0; a < 3; a++) {
        for (int k = 0; k < 4; k++)
            J[a][k] = a == k ? 1 : 0;
        J[a][3] = -j->s[a] / j->s[3];
    }
    for (int i = 1; i <= j->iters; i++) {
        double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
        if (n2 > j->exit2)
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
    return o->u.julia.type == 0 &&
           (o->u.julia.fn == IRIS_JULIA_SQR ||
            o->u.julia.fn == IRIS_JULIA_CUBE) &&
           setup(o, &j);
}

bool geom_julia_inside(const iris_object *o, vec3 p)
{
    struct jset j;
    if (!setup(o, &j) || v3_len2(p) > j.radius * j.radius)
        return false;
    return iterate(&j, p, NULL, NULL);
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
    double t = a, dist;
    long work = 0;
    bool in = iterate(&j, v3_madd(ro, d, t), &dist, &work);
    for (int step = 0; step < MAX_STEPS && t < b && work < MAX_WORK;
         step++) {
        double tn = fmin(t + fmax(dist, j.step_min), b), dn;
        bool inn = iterate(&j, v3_madd(ro, d, tn), &dn, &work);
        if (inn != in) {
            /* Bisect to adjacent doubles (at most ~60 halvings) */
            double lo = t, hi = tn;
            for (int k = 0; k < 80 && hi - lo > 2e-16 * fmax(fabs(lo),
                                                           fabs(hi)); k++) {
                double m = 0.5 * (lo + hi);
                if (iterate(&j, v3_madd(ro, d, m), NULL, &work) == in)
                    lo = m;
                else
                    hi = m;
            }
            /* The normal is taken on the outside of the crossing */
            vec3 n = julia_normal(&j, v3_madd(ro, d, in ? hi : lo));
            double th = 0.5 * (lo + hi);
            if (th > t0 * dl && th < t1 * dl)
                isect_push(out, th / dl, n, 0, 0);
        }
        t = tn;
        dist = dn;
        in = inn;
    }
}
