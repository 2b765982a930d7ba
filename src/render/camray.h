/* SPDX-License-Identifier: MIT */
/*
** camray.h: the eye pass's perspective camera ray without a call.
**
** camera_ray_numbered() (camera.h) dispatches on the camera kind, tests
** for a mesh camera and a camera normal{} and reads the camera's vectors
** through two calls per sample: about 4 % of a simple scene's eye pass.
** The usual camera, perspective without normal{}, is set up here once per
** render and its ray computed inline, with the same floating-point
** operations in the same order as camera.c's base_ray(), so the ray is
** the same to the bit (tests/unit/test_camray.c compares them over the
** image, at pixel centres and jittered positions).
**
** Depends on: math, include/iris/scene.h.
** Used by: render/eyepass.c, render/camera.c.
*/
#ifndef IRIS_RENDER_CAMRAY_H
#define IRIS_RENDER_CAMRAY_H

#include <math.h>
#include <stdbool.h>

#include "iris/scene.h"
#include "accel/accel.h"
#include "math/vec3.h"

/* A perspective camera's constant part. */
struct cam_pinhole {
    vec3 location, direction, right, up;
    double w, h;               /* the image size, at least 1 */
};

/* Fills 'p' for camera 'cam' of a width x height image. Returns false
** where camera_ray_raw() must be used: another kind, or a normal{}. */
static inline bool cam_pinhole_setup(struct cam_pinhole *p,
                                     const iris_camera *cam, int width,
                                     int height)
{
    if (cam->kind != IRIS_CAM_PERSPECTIVE || cam->normal)
        return false;
    p->location = cam->location;
    p->direction = cam->direction;
    p->right = cam->right;
    p->up = cam->up;
    p->w = width > 0 ? width : 1;
    p->h = height > 0 ? height : 1;
    return true;
}

/* POV-Ray's point of the image plane for image position (x, y): it
** shifts to the pixel's corner first ('x', 'y' are left shifted: the
** angular cameras go on from there), then maps to [-0.5, 0.5]. */
static inline void cam_plane_point(double w, double h, double *x, double *y,
                                   double *x0, double *y0)
{
    *x += 0.5;
    *y -= 0.5;
    *x0 = *x / w - 0.5;
    *y0 = ((h - 1) - *y) / h - 0.5;
}

/* The perspective ray of 'p' through plane point (x0, y0): the direction
** D + x0 R + y0 U added in that order, and its length; false where it has
** none. camera.c's base_ray() takes it too, so both paths agree. */
static inline bool cam_pinhole_dir(const struct cam_pinhole *p, double x0,
                                   double y0, ray *r, vec3 *raw)
{
    vec3 d = v3_add(v3_add(p->direction, v3_scale(p->right, x0)),
                    v3_scale(p->up, y0));
    double len = v3_len(d);
    if (!(len > 0) || !isfinite(len))
        return false;
    r->o = p->location;
    *raw = d;
    r->d = v3_scale(d, 1.0 / len);
    return true;
}

/* camera_ray_raw() of the camera of 'p' through image point (x, y). */
static inline bool cam_pinhole_ray(const struct cam_pinhole *p, double x,
                                   double y, ray *r, vec3 *raw)
{
    double x0, y0;
    cam_plane_point(p->w, p->h, &x, &y, &x0, &y0);
    return cam_pinhole_dir(p, x0, y0, r, raw);
}

#endif
