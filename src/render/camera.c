/* SPDX-License-Identifier: MIT */
/*
** camera.c: POV-Ray's camera types (CreateCameraRay of tracepixel.cpp):
** perspective, orthographic, fisheye, panoramic, ultra_wide_angle,
** cylinder 1-4, omnimax and spherical. The scene's camera
** vectors are final (look_at, sky, angle and transforms resolved by the
** parser), so this is only the per-pixel mapping.
*/
#include "config.h"

#include <math.h>

#include "material/material.h"
#include "render/camera.h"
#include "render/camray.h"
#include "render/meshcam.h"

/* The unit vector 'v', or 'v' itself when it has no length. */
static vec3 unit_or_self(vec3 v)
{
    double l = v3_len(v);
    return l > 0 ? v3_scale(v, 1.0 / l) : v;
}

/* 'p' rotated by 'angle' radians about the unit 'axis' (POV-Ray's
** Compute_Axis_Rotation_Transform: p cos + (axis x p) sin + axis (axis.p)
** (1 - cos)). */
static vec3 rotate_about(vec3 p, vec3 axis, double angle)
{
    double c = cos(angle), s = sin(angle);
    return v3_add(v3_add(v3_scale(p, c), v3_scale(v3_cross(axis, p), s)),
                  v3_scale(axis, v3_dot(axis, p) * (1.0 - c)));
}

/*
** The cameras that map the image to angles (ultra_wide_angle, cylinder
** 1-4, omnimax, spherical) from the image position u in [0, 1) to the
** right and v in [0, 1) upwards. They work with unit right, up and
** direction vectors; the lengths only set the aspect ratio.
*/
void camera_axes(const iris_camera *cam, struct cam_axes *a)
{
    a->lr = v3_len(cam->right);
    a->lu = v3_len(cam->up);
    a->R = unit_or_self(cam->right);
    a->U = unit_or_self(cam->up);
    a->D = unit_or_self(cam->direction);
}

static bool angular_ray(const iris_camera *cam, const struct cam_axes *ax,
                        double u, double v, ray *r, double np[2])
{
    const double lr = ax->lr, lu = ax->lu;
    const vec3 R = ax->R, U = ax->U, D = ax->D;
    double x0 = u - 0.5, y0 = v - 0.5;
    double deg = M_PI / 180.0;
    vec3 d;
    switch (cam->kind) {
    case IRIS_CAM_ULTRA_WIDE: {
        double angle = cam->angle > 0 ? cam->angle : 180.0;
        double aspect = lr > 0 ? lu / lr : 1.0;
        x0 *= angle * deg;
        y0 *= angle * aspect * deg;
        d = v3_add(v3_add(v3_scale(R, sin(x0)), v3_scale(U, sin(y0))),
                   v3_scale(D, cos(x0) * cos(y0)));
        break;
    }
    case IRIS_CAM_CYLINDER: {
        double angle = cam->angle > 0 ? cam->angle : 90.0;
        int type = cam->cylinder_type >= 1 && cam->cylinder_type <= 4
                       ? cam->cylinder_type : 1;
        double aspect = (type == 1 || type == 3) ? lu : lr;
        if (type == 1 || type == 3) {
            x0 *= angle * deg;
            y0 *= aspect;
            if (type == 1) {
                d = v3_add(v3_add(v3_scale(R, sin(x0)), v3_scale(U, y0)),
                           v3_scale(D, cos(x0)));
            } else {
                d = v3_add(v3_scale(R, sin(x0)), v3_scale(D, cos(x0)));
                r->o = v3_madd(cam->location, U, y0);
            }
        } else {
            y0 *= angle * deg;
            x0 *= aspect;
            if (type == 2) {
                d = v3_add(v3_add(v3_scale(R, x0), v3_scale(U, sin(y0))),
                           v3_scale(D, cos(y0)));
            } else {
                d = v3_add(v3_scale(U, sin(y0)), v3_scale(D, cos(y0)));
                r->o = v3_madd(cam->location, R, x0);
            }
        }
        break;
    }
    case IRIS_CAM_OMNIMAX: {
        double aspect = lu > 0 ? lr / lu : 1.0;
        x0 *= 2.0;
        y0 *= 2.0;
        if (aspect > 1.0) {
            if (aspect > 1.283458) {
                x0 *= aspect / 1.283458;
                y0 = (y0 - 1.0) / 1.283458 + 1.0;
            } else {
                y0 = (y0 - 1.0) / aspect + 1.0;
            }
        } else if (aspect > 0) {
            y0 /= aspect;
        }
        double rad = sqrt(x0 * x0 + y0 * y0);
        if (rad > 1.0)
            return false;
        double phi = rad == 0.0 ? 0.0
                   : x0 < 0.0 ? M_PI - asin(y0 / rad) : asin(y0 / rad);
        double th = 1.411269 * rad - 0.09439 * rad * rad * rad +
                    0.25674 * pow(rad, 5);
        x0 = phi;
        y0 = th;
        double sx = sin(phi), sy = sin(th), cy = cos(th);
        /* nothing below 45 degrees under the projection axis */
        if (sx * sy < tan(135.0 * deg) * cy)
            return false;
        d = v3_add(v3_add(v3_scale(R, cos(phi) * sy), v3_scale(U, sx * sy)),
                   v3_scale(D, cy));
        break;
    }
    default: { /* spherical: angle = horizontal field, half of it vertical */
        double ha = cam->angle > 0 ? cam->angle : 360.0;
        double va = cam->v_angle > 0 ? cam->v_angle : ha * 0.5;
        y0 *= va * deg;
        x0 *= ha * deg;
        d = rotate_about(rotate_about(D, R, -y0), U, x0);
        break;
    }
    }
    /* where a camera normal{} is evaluated: POV-Ray's x0, y0 as the
    ** projection left them (angles, or polar coordinates for omnimax) */
    np[0] = x0;
    np[1] = y0;
    double len = v3_len(d);
    if (!(len > 0) || !isfinite(len))
        return false;
    r->d = v3_scale(d, 1.0 / len);
    return true;
}

bool camera_ray(const iris_camera *cam, int width, int height, double x,
                double y, ray *r)
{
    vec3 raw;
    return camera_ray_raw(cam, width, height, x, y, r, &raw);
}

/*
** The camera's normal{} (POV-Ray's CreateCameraRay end): the unit ray
** direction perturbed as a surface normal would be, by the pattern
** evaluated at the point <x0, y0, 0> (base_ray's 'np': in [-0.5, 0.5]
** across the image, angles, or 0 for the mesh camera), then normalised
** again. The normal's own transforms place it on that plane; the
** camera's do not reach it. No material context: the pattern uses the
** default noise generator and an image bump_map would read nothing.
*/
static void perturb_ray(const iris_camera *cam, double x0, double y0, ray *r,
                        vec3 *raw)
{
    if (!cam->normal)
        return;
    struct mat_point pt = { .p = v3(x0, y0, 0.0), .n = r->d, .d = r->d };
    vec3 d = mat_perturb_normal(NULL, cam->normal, &pt, r->d);
    double len = v3_len(d);
    if (!(len > 0) || !isfinite(len))
        return;
    double raw_len = v3_len(*raw);
    r->d = v3_scale(d, 1.0 / len);
    /* focal blur aims 'raw' at its focal plane: keep its length */
    *raw = v3_scale(r->d, raw_len > 0 ? raw_len : 1.0);
}

static bool base_ray(const iris_camera *cam, const struct cam_axes *ax,
                     int width, int height, double x, double y, ray *r,
                     vec3 *raw, double np[2]);

bool camera_ray_raw(const iris_camera *cam, int width, int height, double x,
                    double y, ray *r, vec3 *raw)
{
    return camera_ray_axes(cam, NULL, width, height, x, y, r, raw);
}

bool camera_ray_axes(const iris_camera *cam, const struct cam_axes *ax,
                     int width, int height, double x, double y, ray *r,
                     vec3 *raw)
{
    double np[2] = { 0.0, 0.0 };
    if (!base_ray(cam, ax, width, height, x, y, r, raw, np))
        return false;
    /* the mesh camera leaves np at <0, 0>: POV-Ray's x0 and y0 keep
    ** their initial 0 there, so its normal{} moves every ray alike */
    if (cam->normal)
        perturb_ray(cam, np[0], np[1], r, raw);
    return true;
}

/* The ray before the camera's normal{}; 'np' gets the point of the
** image plane where POV-Ray evaluates that normal: x0 and y0 as its
** CreateCameraRay leaves them, i.e. in [-0.5, 0.5] for the perspective
** and orthographic cameras, scaled to angles by the angular ones. */
static bool base_ray(const iris_camera *cam, const struct cam_axes *ax,
                     int width, int height, double x, double y, ray *r,
                     vec3 *raw, double np[2])
{
    if (cam->kind == IRIS_CAM_MESH) {
        if (!meshcam_ray(cam, width, height, x, y, 0, r))
            return false;
        *raw = r->d;
        return true;
    }
    double w = width > 0 ? width : 1, h = height > 0 ? height : 1;
    double x0, y0;
    cam_plane_point(w, h, &x, &y, &x0, &y0);
    np[0] = x0;
    np[1] = y0;
    vec3 d;
    r->o = cam->location;
    switch (cam->kind) {
    case IRIS_CAM_ORTHOGRAPHIC:
        r->o = v3_madd(v3_madd(cam->location, cam->right, x0), cam->up, y0);
        d = cam->direction;
        break;
    case IRIS_CAM_FISHEYE: {
        double fx = 2.0 * x / w - 1.0, fy = 2.0 * ((h - 1) - y) / h - 1.0;
        fx *= v3_len(cam->right);
        fy *= v3_len(cam->up);
        double rad = sqrt(fx * fx + fy * fy);
        if (rad > 1.0)
            return false;
        double phi = rad == 0.0 ? 0.0
                   : fx < 0.0 ? M_PI - asin(fy / rad) : asin(fy / rad);
        double angle = cam->angle > 0 ? cam->angle : 180.0;
        double th = rad * angle * M_PI / 360.0;
        np[0] = phi;
        np[1] = th;
        vec3 rn = v3_norm(cam->right), un = v3_norm(cam->up),
             dn = v3_norm(cam->direction);
        d = v3_add(v3_add(v3_scale(rn, cos(phi) * sin(th)),
                          v3_scale(un, sin(phi) * sin(th))),
                   v3_scale(dn, cos(th)));
        break;
    }
    case IRIS_CAM_PANORAMIC: {
        double px = (1.0 - x / w) * M_PI;
        double py = M_PI_2 * (2.0 * ((h - 1) - y) / h - 1.0);
        double ty = fabs(M_PI_2 - fabs(py)) < 1e-10 ? copysign(1e10, py)
                                                     : tan(py);
        np[0] = px;
        np[1] = py;
        d = v3_add(v3_add(v3_scale(cam->right, cos(px)),
                          v3_scale(cam->up, ty)),
                   v3_scale(cam->direction, sin(px)));
        break;
    }
    case IRIS_CAM_ULTRA_WIDE:
    case IRIS_CAM_CYLINDER:
    case IRIS_CAM_OMNIMAX:
    case IRIS_CAM_SPHERICAL: {
        struct cam_axes own;  /* camera_ray_raw(): worked out here */
        if (!ax) {
            camera_axes(cam, &own);
            ax = &own;
        }
        if (!angular_ray(cam, ax, x / w, ((h - 1) - y) / h, r, np))
            return false;
        *raw = r->d;
        return true;
    }
    default: { /* perspective */
        struct cam_pinhole p = { cam->location, cam->direction, cam->right,
                                 cam->up, w, h };
        return cam_pinhole_dir(&p, x0, y0, r, raw);
    }
    }
    double len = v3_len(d);
    if (!(len > 0) || !isfinite(len))
        return false;
    *raw = d;
    r->d = v3_scale(d, 1.0 / len);
    return true;
}

bool camera_ray_numbered(const iris_camera *cam, int width, int height,
                         double x, double y, int ray_number, ray *r,
                         vec3 *raw)
{
    if (cam->kind != IRIS_CAM_MESH)
        return camera_ray_raw(cam, width, height, x, y, r, raw);
    if (!meshcam_ray(cam, width, height, x, y, ray_number, r))
        return false;
    *raw = r->d;
    /* at <0, 0, 0>, as in camera_ray_raw() */
    if (cam->normal)
        perturb_ray(cam, 0.0, 0.0, r, raw);
    return true;
}
