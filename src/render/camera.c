/* SPDX-License-Identifier: MIT */
/*
** camera.c: POV-Ray's camera types (CreateCameraRay of tracepixel.cpp):
** perspective, orthographic, fisheye and panoramic. The scene's camera
** vectors are final (look_at, sky, angle and transforms resolved by the
** parser), so this is only the per-pixel mapping.
*/
#include "config.h"

#include <math.h>

#include "render/camera.h"

bool camera_ray(const iris_camera *cam, int width, int height, double x,
                double y, ray *r)
{
    double w = width > 0 ? width : 1, h = height > 0 ? height : 1;
    /* POV-Ray shifts to the pixel's corner first, then maps to [-.5, .5]. */
    x += 0.5;
    y -= 0.5;
    double x0 = x / w - 0.5;
    double y0 = ((h - 1) - y) / h - 0.5;
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
        d = v3_add(v3_add(v3_scale(cam->right, cos(px)),
                          v3_scale(cam->up, ty)),
                   v3_scale(cam->direction, sin(px)));
        break;
    }
    default: /* perspective, and the types not implemented */
        d = v3_add(v3_add(cam->direction, v3_scale(cam->right, x0)),
                   v3_scale(cam->up, y0));
        break;
    }
    double len = v3_len(d);
    if (!(len > 0) || !isfinite(len))
        return false;
    r->d = v3_scale(d, 1.0 / len);
    return true;
}
