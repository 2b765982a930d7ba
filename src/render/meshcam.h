/* SPDX-License-Identifier: MIT */
/*
** meshcam.h: primary rays of POV-Ray's mesh_camera (IRIS_CAM_MESH):
** rays leave mesh faces along their normals, the face chosen from the
** pixel by the camera's distribution type (see meshcam.c).
**
** Depends on: math. Used by: camera.
*/
#ifndef IRIS_RENDER_MESHCAM_H
#define IRIS_RENDER_MESHCAM_H

#include <stdbool.h>

#include "accel/accel.h"
#include "iris/scene.h"

/* Sets '*r' to ray 'ray_number' (0 .. rays_per_pixel - 1) of pixel
** (x, y) of a width x height image. False where POV-Ray traces no ray
** (no face for that pixel): the ray is then left out of the pixel's
** average, and a pixel with none is transparent black. */
bool meshcam_ray(const iris_camera *cam, int width, int height, double x,
                 double y, int ray_number, ray *r);

/* The box holding the origin of every ray meshcam_ray() can give: each
** camera mesh's vertex box grown by the origins' offset along the face
** normal (|location.z|), transformed. False without such a box. */
bool meshcam_origin_box(const iris_camera *cam, vec3 *lo, vec3 *hi);

#endif
