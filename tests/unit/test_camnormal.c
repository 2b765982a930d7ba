/* SPDX-License-Identifier: MIT */
/*
** test_camnormal.c: a camera's normal{} on every camera type, at the
** point of POV-Ray 3.7's CreateCameraRay (tracepixel.cpp).
**
** POV-Ray perturbs the unit ray direction with the camera's normal
** evaluated at <x0, y0, 0>, where x0 and y0 are what the camera's
** projection left in those variables: the image position in [-0.5, 0.5]
** for the perspective camera, scaled to radians by the angular cameras
** (ultra_wide_angle, cylinder, spherical), the polar angle and the
** off-axis angle for fisheye, and the longitude and latitude for
** panoramic. The expected point below is computed from those formulas
** (with x shifted by +0.5 and y by -0.5 first, as POV-Ray does), the
** expected direction as the camera's ray without the normal perturbed
** there by mat_perturb_normal() and normalised. Both sides do the same
** few floating-point operations, so the tolerance is 1e-12. With the
** normal at the perspective point for every camera (iris before), the
** bumps differ by far more than that.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "parse_util.h"
#include "material/material.h"
#include "render/camera.h"

#define W 80
#define H 60

/* POV-Ray's x0, y0 for pixel position (x, y) of camera 'c'. */
static void pov_point(const iris_camera *c, double x, double y, double *px,
                      double *py)
{
    x += 0.5;
    y -= 0.5;
    double lr = v3_len(c->right), lu = v3_len(c->up);
    double x0 = x / W - 0.5, y0 = ((H - 1) - y) / H - 0.5;
    double deg = M_PI / 180.0;
    switch (c->kind) {
    case IRIS_CAM_ULTRA_WIDE:
        x0 *= c->angle * deg;
        y0 *= c->angle * (lu / lr) * deg;
        break;
    case IRIS_CAM_CYLINDER:
        if (c->cylinder_type == 1 || c->cylinder_type == 3) {
            x0 *= c->angle * deg;
            y0 *= lu;
        } else {
            y0 *= c->angle * deg;
            x0 *= lr;
        }
        break;
    case IRIS_CAM_SPHERICAL:
        y0 *= c->v_angle * deg;
        x0 *= c->angle * deg;
        break;
    case IRIS_CAM_FISHEYE: {
        double fx = (2.0 * x / W - 1.0) * lr, fy = (2.0 * ((H - 1) - y) / H
                                                    - 1.0) * lu;
        double rad = sqrt(fx * fx + fy * fy);
        x0 = rad == 0.0 ? 0.0
           : fx < 0.0 ? M_PI - asin(fy / rad) : asin(fy / rad);
        y0 = rad * c->angle * M_PI / 360.0;
        break;
    }
    case IRIS_CAM_PANORAMIC:
        x0 = (1.0 - x / W) * M_PI;
        y0 = M_PI_2 * (2.0 * ((H - 1) - y) / H - 1.0);
        break;
    default:
        break;
    }
    *px = x0;
    *py = y0;
}

static void check_camera(const char *cam_sdl)
{
    char sdl[512];
    snprintf(sdl, sizeof sdl,
             "camera { %s location <0, 1, -4> look_at <0, 0.5, 0> "
             "normal { bumps 0.6 scale 0.08 } }\n"
             "sphere { 0, 1 pigment { rgb 1 } }\n", cam_sdl);
    iris_scene *sc = pt_scene_with(sdl, NULL);
    const iris_camera *cam = &sc->camera;
    assert_non_null(cam->normal);
    iris_camera plain = *cam;
    plain.normal = NULL;
    /* pixels near the corners, the middle and between (the fisheye's
    ** circle holds them all at these sizes) */
    const double px[][2] = { { 30, 20 }, { 40, 30 }, { 52.25, 41.75 },
                             { 25.5, 35 }, { 47, 22.5 } };
    for (size_t i = 0; i < sizeof px / sizeof px[0]; i++) {
        ray base, got;
        assert_true(camera_ray(&plain, W, H, px[i][0], px[i][1], &base));
        assert_true(camera_ray(cam, W, H, px[i][0], px[i][1], &got));
        double x0, y0;
        pov_point(cam, px[i][0], px[i][1], &x0, &y0);
        struct mat_point pt = { .p = v3(x0, y0, 0.0), .n = base.d,
                                .d = base.d };
        vec3 e = v3_norm(mat_perturb_normal(NULL, cam->normal, &pt,
                                            base.d));
        assert_near(got.d.x, e.x, 1e-12);
        assert_near(got.d.y, e.y, 1e-12);
        assert_near(got.d.z, e.z, 1e-12);
        /* the normal does move the ray (the test would pass vacuously
        ** otherwise) */
        assert_true(v3_len(v3_sub(got.d, base.d)) > 1e-3);
    }
    iris_scene_destroy(sc);
}

static void test_perspective(void **state)
{
    (void)state;
    check_camera("");
}

static void test_ultra_wide(void **state)
{
    (void)state;
    check_camera("ultra_wide_angle angle 160");
}

static void test_cylinders(void **state)
{
    (void)state;
    check_camera("cylinder 1 angle 120");
    check_camera("cylinder 2 angle 100");
}

static void test_spherical(void **state)
{
    (void)state;
    check_camera("spherical angle 200 90");
}

static void test_fisheye(void **state)
{
    (void)state;
    check_camera("fisheye angle 170");
}

static void test_panoramic(void **state)
{
    (void)state;
    check_camera("panoramic");
}

/* The mesh camera sets neither x0 nor y0 (its case of CreateCameraRay
** leaves their initial 0), so POV-Ray evaluates the normal at <0, 0, 0>
** for every pixel: each face's unit ray turned by the same bump vector.
** Distribution 0 with three faces: pixels (0, 0), (1, 0) and (2, 0) are
** faces 0, 1 and 2. iris followed no mesh camera normal before, which the
** 1e-3 check below catches; the tolerance is 1e-12 as above (the same
** operations on both sides). */
static void test_mesh(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        "camera { mesh_camera { 1 0 mesh {\n"
        "  triangle { <0, 0, 0>, <0, 0.1, 0>, <0.1, 0, 0> }\n"
        "  triangle { <1, 0, 0>, <1, 0.1, 0.05>, <1.1, 0, 0> }\n"
        "  triangle { <2, 0, 0>, <2, 0.1, 0>, <2.1, 0, -0.08> } } }\n"
        "  location <0, 0, 0.1> normal { bumps 0.6 scale 0.08 } }\n"
        "sphere { 0, 1 pigment { rgb 1 } }\n", NULL);
    const iris_camera *cam = &sc->camera;
    assert_int_equal(cam->kind, IRIS_CAM_MESH);
    assert_non_null(cam->normal);
    iris_camera plain = *cam;
    plain.normal = NULL;
    for (int f = 0; f < 3; f++) {
        ray base, got, numbered;
        vec3 raw;
        assert_true(camera_ray(&plain, W, H, f, 0, &base));
        assert_true(camera_ray(cam, W, H, f, 0, &got));
        assert_true(camera_ray_numbered(cam, W, H, f, 0, 0, &numbered,
                                        &raw));
        struct mat_point pt = { .p = v3(0.0, 0.0, 0.0), .n = base.d,
                                .d = base.d };
        vec3 e = v3_norm(mat_perturb_normal(NULL, cam->normal, &pt,
                                            base.d));
        assert_near(got.d.x, e.x, 1e-12);
        assert_near(got.d.y, e.y, 1e-12);
        assert_near(got.d.z, e.z, 1e-12);
        assert_near(numbered.d.x, e.x, 1e-12);
        assert_near(numbered.d.y, e.y, 1e-12);
        assert_near(numbered.d.z, e.z, 1e-12);
        /* the origin is the face's, untouched by the normal */
        assert_near(got.o.x, base.o.x, 1e-12);
        assert_near(got.o.y, base.o.y, 1e-12);
        assert_near(got.o.z, base.o.z, 1e-12);
        assert_true(v3_len(v3_sub(got.d, base.d)) > 1e-3);
    }
    iris_scene_destroy(sc);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_perspective),
        cmocka_unit_test(test_ultra_wide),
        cmocka_unit_test(test_cylinders),
        cmocka_unit_test(test_spherical),
        cmocka_unit_test(test_fisheye),
        cmocka_unit_test(test_panoramic),
        cmocka_unit_test(test_mesh),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
