/* SPDX-License-Identifier: MIT */
/*
** transform.c: affine transforms, kept with their inverses.
*/
#include "config.h"

#include "math/transform.h"

#include <math.h>
#include <string.h>

void iris_transform_identity(iris_transform *t)
{
    memset(t, 0, sizeof *t);
    for (int i = 0; i < 3; i++)
        t->m[i][i] = t->inv[i][i] = 1.0;
}

void xf_identity(xform *t)
{
    iris_transform_identity(t);
}

void xf_translate(xform *t, vec3 v)
{
    xf_identity(t);
    t->m[0][3] = v.x; t->m[1][3] = v.y; t->m[2][3] = v.z;
    t->inv[0][3] = -v.x; t->inv[1][3] = -v.y; t->inv[2][3] = -v.z;
}

void xf_scale(xform *t, vec3 v)
{
    xf_identity(t);
    double s[3] = { v.x, v.y, v.z };
    for (int i = 0; i < 3; i++) {
        if (s[i] == 0.0)
            s[i] = 1.0; /* POV-Ray: "Illegal scale 0, changed to 1" */
        t->m[i][i] = s[i];
        t->inv[i][i] = 1.0 / s[i];
    }
}

/* Sets the 3x3 part of m to 'r' and of inv to its transpose. */
static void set_rotation(xform *t, const double r[3][3])
{
    xf_identity(t);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            t->m[i][j] = r[i][j];
            t->inv[j][i] = r[i][j];
        }
}

static void mul3(double out[3][3], const double a[3][3], const double b[3][3])
{
    double r[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r[i][j] = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
    memcpy(out, r, sizeof r);
}

void xf_rotate(xform *t, vec3 deg)
{
    /* Column-vector matrices; x first, then y, then z: R = Rz Ry Rx.
    ** POV-Ray's rotations are left-handed in appearance because its
    ** coordinate system is; the matrices are the usual ones. */
    double ax = deg.x * M_PI / 180, ay = deg.y * M_PI / 180, az = deg.z * M_PI / 180;
    double cx = cos(ax), sx = sin(ax), cy = cos(ay), sy = sin(ay);
    double cz = cos(az), sz = sin(az);
    double rx[3][3] = { { 1, 0, 0 }, { 0, cx, -sx }, { 0, sx, cx } };
    double ry[3][3] = { { cy, 0, sy }, { 0, 1, 0 }, { -sy, 0, cy } };
    double rz[3][3] = { { cz, -sz, 0 }, { sz, cz, 0 }, { 0, 0, 1 } };
    double r[3][3];
    mul3(r, ry, rx);
    mul3(r, rz, r);
    set_rotation(t, r);
}

void xf_axis_rotate(xform *t, vec3 axis, double degrees)
{
    vec3 a = v3_norm(axis);
    double ang = degrees * M_PI / 180, c = cos(ang), s = sin(ang), k = 1 - c;
    double r[3][3] = {
        { c + a.x * a.x * k, a.x * a.y * k - a.z * s, a.x * a.z * k + a.y * s },
        { a.y * a.x * k + a.z * s, c + a.y * a.y * k, a.y * a.z * k - a.x * s },
        { a.z * a.x * k - a.y * s, a.z * a.y * k + a.x * s, c + a.z * a.z * k },
    };
    set_rotation(t, r);
}

/* Inverts the affine map 'm' into 'inv'; false when singular. */
static bool invert_affine(double inv[3][4], const double m[3][4])
{
    double a = m[0][0], b = m[0][1], c = m[0][2];
    double d = m[1][0], e = m[1][1], f = m[1][2];
    double g = m[2][0], h = m[2][1], i = m[2][2];
    double A = e * i - f * h, B = -(d * i - f * g), C = d * h - e * g;
    double det = a * A + b * B + c * C;
    if (!(fabs(det) > 1e-300) || !isfinite(det))
        return false;
    double r[3][3] = {
        { A / det, -(b * i - c * h) / det, (b * f - c * e) / det },
        { B / det, (a * i - c * g) / det, -(a * f - c * d) / det },
        { C / det, -(a * h - b * g) / det, (a * e - b * d) / det },
    };
    for (int k = 0; k < 3; k++) {
        for (int j = 0; j < 3; j++)
            inv[k][j] = r[k][j];
        inv[k][3] = -(r[k][0] * m[0][3] + r[k][1] * m[1][3] + r[k][2] * m[2][3]);
    }
    return true;
}

bool xf_matrix(xform *t, const double v[12])
{
    /* POV-Ray: p' = p·M with rows (v0 v1 v2), (v3 v4 v5), (v6 v7 v8) and
    ** translation (v9 v10 v11); as a column-vector matrix that is the
    ** transpose. */
    xform r;
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++)
            r.m[i][j] = v[j * 3 + i];
        r.m[i][3] = v[9 + i];
    }
    if (!invert_affine(r.inv, r.m)) {
        xf_identity(t);
        return false;
    }
    *t = r;
    return true;
}

void xf_inverse(xform *out, const xform *t)
{
    xform r;
    memcpy(r.m, t->inv, sizeof r.m);
    memcpy(r.inv, t->m, sizeof r.inv);
    *out = r;
}

/* out = b ∘ a as 3x4 affine maps. */
static void mul_affine(double out[3][4], const double b[3][4], const double a[3][4])
{
    double r[3][4];
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 4; j++) {
            r[i][j] = b[i][0] * a[0][j] + b[i][1] * a[1][j] + b[i][2] * a[2][j];
        }
        r[i][3] += b[i][3];
    }
    memcpy(out, r, sizeof r);
}

void xf_compose(xform *out, const xform *a, const xform *b)
{
    xform r;
    mul_affine(r.m, b->m, a->m);
    mul_affine(r.inv, a->inv, b->inv);
    *out = r;
}

/* The affine map of the 3x4 part of 'm' applied to a point (with the
** translation) and to a direction (without it). */
static inline vec3 affine_point(const double (*m)[4], vec3 p)
{
    return v3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
              m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
              m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

static inline vec3 affine_dir(const double (*m)[4], vec3 d)
{
    return v3(m[0][0] * d.x + m[0][1] * d.y + m[0][2] * d.z,
              m[1][0] * d.x + m[1][1] * d.y + m[1][2] * d.z,
              m[2][0] * d.x + m[2][1] * d.y + m[2][2] * d.z);
}

vec3 xf_point(const xform *t, vec3 p)
{
    return affine_point(t->m, p);
}

vec3 xf_dir(const xform *t, vec3 d)
{
    return affine_dir(t->m, d);
}

vec3 xf_inv_point(const xform *t, vec3 p)
{
    return affine_point(t->inv, p);
}

vec3 xf_inv_dir(const xform *t, vec3 d)
{
    return affine_dir(t->inv, d);
}

vec3 xf_normal(const xform *t, vec3 n)
{
    const double (*m)[4] = t->inv; /* transpose of the inverse */
    return v3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,
              m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
              m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z);
}

void xf_axis_frame(vec3 d, vec3 e[3])
{
    e[0] = v3(1, 0, 0);
    e[1] = v3(0, 1, 0);
    e[2] = v3(0, 0, 1);
    if (fabs(d.z) > 1 - 1e-10) {
        if (d.z < 0) {
            e[1] = v3(0, -1, 0);
            e[2] = v3(0, 0, -1);
        }
        return;
    }
    /* Rodrigues: each axis turned about k by the angle of cosine d.z */
    double kl = sqrt(d.x * d.x + d.y * d.y);
    vec3 k = v3(-d.y / kl, d.x / kl, 0);
    double c = d.z, sn = kl;
    for (int i = 0; i < 3; i++) {
        vec3 v = e[i];
        e[i] = v3_add(v3_add(v3_scale(v, c), v3_scale(v3_cross(k, v), sn)),
                      v3_scale(k, v3_dot(k, v) * (1 - c)));
    }
}
