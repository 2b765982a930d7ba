/* SPDX-License-Identifier: MIT */
/*
** test_camray.c: the eye pass's inline perspective ray (camray.h). It
** replaces camera_ray_raw() (camera.c) for a perspective camera without
** normal{}, so it must give the same ray to the bit: origin, unit
** direction and the unnormalised direction focal blur aims with. The
** independent check is the geometry: the ray through the image centre is
** the camera's direction, and through a pixel D + x0 R + y0 U with
** x0 = (x + 0.5)/W - 0.5, y0 = 0.5 - (y + 0.5)/H (camera.h), normalised.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "testutil.h"

#include "render/camera.h"
#include "render/camray.h"
#include "util/rng.h"

enum { W = 160, H = 120 };

/* A camera as the parser resolves 'location <1, 2, -3> look_at <0.3,
** 0.5, 1> angle 50' in a 4:3 image: unit-free right and up, a direction
** whose length sets the field, none on an axis (every product rounds). */
static iris_camera tilted(void)
{
    iris_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.kind = IRIS_CAM_PERSPECTIVE;
    cam.location = v3(1.0, 2.0, -3.0);
    cam.direction = v3(-0.25915491652, -0.55522451781, 1.4302346897);
    cam.right = v3(1.2986891366, 0.0, 0.2353192931);
    cam.up = v3(-0.12903227, 0.93055215, 0.07121209);
    return cam;
}

static void expect_same(const iris_camera *cam, const struct cam_pinhole *p,
                        double x, double y)
{
    ray want, got;
    vec3 raw_want, raw_got;
    memset(&want, 0, sizeof want);
    memset(&got, 0, sizeof got);
    bool ok_want = camera_ray_raw(cam, W, H, x, y, &want, &raw_want);
    bool ok_got = cam_pinhole_ray(p, x, y, &got, &raw_got);
    assert_int_equal(ok_want, ok_got);
    if (!ok_want)
        return;
    /* bitwise: the image may not change by a bit */
    if (memcmp(&want.o, &got.o, sizeof want.o) != 0 ||
        memcmp(&want.d, &got.d, sizeof want.d) != 0 ||
        memcmp(&raw_want, &raw_got, sizeof raw_want) != 0) {
        print_error("(%.17g, %.17g): d %.17g %.17g %.17g, camera.c "
                    "%.17g %.17g %.17g\n", x, y, got.d.x, got.d.y, got.d.z,
                    want.d.x, want.d.y, want.d.z);
        fail();
    }
}

/* Every pixel centre, and 20000 jittered sample positions, some outside
** the image (AA subsamples near the border, the edge of a render
** window): the same bits as camera_ray_raw(). */
static void test_same_bits(void **state)
{
    (void)state;
    iris_camera cam = tilted();
    struct cam_pinhole p;
    assert_true(cam_pinhole_setup(&p, &cam, W, H));
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            expect_same(&cam, &p, x, y);
    rng r;
    rng_seed(&r, 11, 0, 0);
    for (int i = 0; i < 20000; i++)
        expect_same(&cam, &p, rng_uniform(&r) * (W + 2) - 1.5,
                    rng_uniform(&r) * (H + 2) - 1.5);
}

/* The geometry itself: the image centre (W/2 - 0.5, H/2 - 0.5) looks
** along the direction, a corner along D + x0 R + y0 U. Tolerance 1e-15:
** a few roundings of unit-sized values (a double's epsilon is 2.2e-16). */
static void test_geometry(void **state)
{
    (void)state;
    iris_camera cam = tilted();
    struct cam_pinhole p;
    assert_true(cam_pinhole_setup(&p, &cam, W, H));
    ray r;
    vec3 raw;
    assert_true(cam_pinhole_ray(&p, W / 2 - 0.5, H / 2 - 0.5, &r, &raw));
    vec3 d = v3_norm(cam.direction);
    assert_near(r.d.x, d.x, 1e-15);
    assert_near(r.d.y, d.y, 1e-15);
    assert_near(r.d.z, d.z, 1e-15);
    assert_near(r.o.x, 1.0, 0.0);
    assert_near(r.o.z, -3.0, 0.0);
    /* pixel (0, 0): x0 = 0.5/W - 0.5, y0 = 0.5 - 0.5/H */
    assert_true(cam_pinhole_ray(&p, 0.0, 0.0, &r, &raw));
    double x0 = 0.5 / W - 0.5, y0 = 0.5 - 0.5 / H;
    vec3 e = v3_norm(v3_add(v3_add(cam.direction, v3_scale(cam.right, x0)),
                            v3_scale(cam.up, y0)));
    assert_near(r.d.x, e.x, 1e-15);
    assert_near(r.d.y, e.y, 1e-15);
    assert_near(r.d.z, e.z, 1e-15);
    assert_near(v3_len(r.d), 1.0, 1e-15);
}

/* Other cameras and a camera normal{} keep camera_ray_raw(). */
static void test_setup_refuses(void **state)
{
    (void)state;
    struct cam_pinhole p;
    iris_camera cam = tilted();
    cam.kind = IRIS_CAM_ORTHOGRAPHIC;
    assert_false(cam_pinhole_setup(&p, &cam, W, H));
    cam.kind = IRIS_CAM_FISHEYE;
    assert_false(cam_pinhole_setup(&p, &cam, W, H));
    cam = tilted();
    iris_normal nrm;
    memset(&nrm, 0, sizeof nrm);
    cam.normal = &nrm;
    assert_false(cam_pinhole_setup(&p, &cam, W, H));
    /* a degenerate camera: no direction at the centre, as camera.c says */
    cam = tilted();
    cam.direction = v3(0, 0, 0);
    cam.right = v3(0, 0, 0);
    cam.up = v3(0, 0, 0);
    assert_true(cam_pinhole_setup(&p, &cam, W, H));
    expect_same(&cam, &p, 3.0, 4.0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_bits),
        cmocka_unit_test(test_geometry),
        cmocka_unit_test(test_setup_refuses),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
