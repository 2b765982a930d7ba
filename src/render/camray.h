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
** Used by: render/eyepass.c.
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

/* camera_ray_raw() of the camera of 'p' through image point (x, y):
** POV-Ray's corner shift, x0 = (x + 0.5)/w - 0.5, y0 = (h - 1 - (y -
** 0.5))/h - 0.5, the direction D + x0 R + y0 U added in that order, and
** its length; false where it has none. */
static inline bool cam_pinhole_ray(const struct cam_pinhole *p, double x,
                                   double y, ray *r, vec3 *raw)
{
    x += 0.5;
    y -= 0.5;
    double x0 = x / p->w - 0.5;
    double y0 = ((p->h - 1) - y) / p->h - 0.5;
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

#endif
