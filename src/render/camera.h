/* SPDX-License-Identifier: MIT */
/*
** camera.h: primary rays from the resolved camera (semantics §3.8).
**
** Pixel coordinates are POV-Ray's: (x, y) with x to the right and y down,
** the centre of pixel (i, j) at (i, j); AA samples use fractional values.
** The perspective ray through (x, y) of a W x H image has direction
** D + x0 R + y0 U with x0 = (x + 0.5)/W - 0.5, y0 = 0.5 - (y + 0.5)/H.
**
** Depends on: math. Used by: render.
*/
#ifndef IRIS_RENDER_CAMERA_H
#define IRIS_RENDER_CAMERA_H

#include <stdbool.h>

#include "accel/accel.h"
#include "iris/scene.h"

/*
** Sets '*r' to the camera ray through image point (x, y). Returns false
** where the camera has no ray (outside a fisheye's circle): the sample
** is then background-free black, as POV-Ray leaves it.
*/
bool camera_ray(const iris_camera *cam, int width, int height, double x,
                double y, ray *r);

/* camera_ray() that also gives the direction before normalisation (for
** the perspective camera D + x0 R + y0 U), which focal blur scales to
** the focal plane as POV-Ray does. */
bool camera_ray_raw(const iris_camera *cam, int width, int height, double x,
                    double y, ray *r, vec3 *raw);

/* camera_ray_raw() for ray 'ray_number' of the pixel: the mesh camera
** (meshcam.h) traces rays_per_pixel rays per pixel, each from its own
** face; the other cameras ignore the number. */
bool camera_ray_numbered(const iris_camera *cam, int width, int height,
                         double x, double y, int ray_number, ray *r,
                         vec3 *raw);

/* What the angular cameras (ultra_wide_angle, cylinder, omnimax,
** spherical) take of the camera's vectors: right, up and direction made
** unit, and the lengths of right and up (their aspect ratio).
** camera_ray_raw() works them out per ray; the eye pass once per render
** (camera_axes()) and passes them to camera_ray_axes(), which gives the
** same ray to the bit (the same numbers, computed once; they were a
** third of such a camera's ray). camera_ray_axes() with 'ax' NULL is
** camera_ray_raw(); neither is for the mesh camera's numbered rays. */
struct cam_axes {
    vec3 R, U, D;
    double lr, lu;
};
void camera_axes(const iris_camera *cam, struct cam_axes *a);
bool camera_ray_axes(const iris_camera *cam, const struct cam_axes *ax,
                     int width, int height, double x, double y, ray *r,
                     vec3 *raw);

#endif
