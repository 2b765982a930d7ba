/* SPDX-License-Identifier: MIT */
/*
** test_camray.c: the eye pass's inline perspective ray (camray.h). It
** replaces camera_ray_raw() (camera.c) for a perspective camera without
** normal{}, so it must give the same ray to the bit: origin, unit
** direction and the unnormalised direction focal blur aims with. The
** independent check is the geometry: the ray through the image centre is
** the camera's direction, and through a pixel D + x0 R + y0 U with
** x0 = (x + 0.5)/W - 0.5, y0 = 0.5 - (y + 0.5)/H (camera.h), normalised.
** Also the angular cameras' axes worked out once (camera_ray_axes).
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

/*
** The angular cameras (ultra_wide_angle, cylinder 1-4, omnimax,
** spherical) in the eye pass take their unit axes from camera_axes(),
** worked out once per render (camera.h): camera_ray_axes() must give
** camera_ray_raw()'s ray to the bit at every pixel centre and at jittered
** positions; and the geometry: the image centre looks along the unit
** direction from the location (each projection maps it to angle 0 and
** offset 0; not omnimax's, which POV-Ray moves up in an image wider
** than 1.28:1), within a few roundings (1e-15).
*/
static void test_angular_axes(void **state)
{
    (void)state;
    struct { enum iris_camera_kind kind; int type; double angle; } k[] = {
        { IRIS_CAM_ULTRA_WIDE, 0, 170 }, { IRIS_CAM_CYLINDER, 1, 200 },
        { IRIS_CAM_CYLINDER, 2, 120 }, { IRIS_CAM_CYLINDER, 3, 90 },
        { IRIS_CAM_CYLINDER, 4, 0 }, { IRIS_CAM_OMNIMAX, 0, 0 },
        { IRIS_CAM_SPHERICAL, 0, 300 } };
    rng r;
    rng_seed(&r, 12, 0, 0);
    for (size_t i = 0; i < sizeof k / sizeof k[0]; i++) {
        iris_camera cam = tilted();
        cam.kind = k[i].kind;
        cam.cylinder_type = k[i].type;
        cam.angle = k[i].angle;
        struct cam_axes ax;
        camera_axes(&cam, &ax);
        int n_ok = 0;
        for (int j = 0; j < W * H + 4000; j++) {
            double x = j < W * H ? j % W : rng_uniform(&r) * (W + 2) - 1.5;
            double y = j < W * H ? j / W : rng_uniform(&r) * (H + 2) - 1.5;
            ray want, got;
            vec3 raw_want, raw_got;
            memset(&want, 0, sizeof want);
            memset(&got, 0, sizeof got);
            bool ok_want = camera_ray_raw(&cam, W, H, x, y, &want, &raw_want);
            bool ok_got = camera_ray_axes(&cam, &ax, W, H, x, y, &got,
                                          &raw_got);
            assert_int_equal(ok_want, ok_got);
            if (!ok_want)
                continue;
            n_ok++;
            assert_memory_equal(&want.o, &got.o, sizeof want.o);
            assert_memory_equal(&want.d, &got.d, sizeof want.d);
            assert_memory_equal(&raw_want, &raw_got, sizeof raw_want);
        }
        assert_true(n_ok > W * H / 2); /* most positions have a ray */
        if (k[i].kind == IRIS_CAM_OMNIMAX)
            continue;          /* its centre moves up in a wide image */
        ray c;
        vec3 raw;
        assert_true(camera_ray_axes(&cam, &ax, W, H, W / 2 - 0.5, H / 2 - 0.5,
                                    &c, &raw));
        vec3 d = v3_norm(cam.direction);
        assert_near(c.d.x, d.x, 1e-15);
        assert_near(c.d.y, d.y, 1e-15);
        assert_near(c.d.z, d.z, 1e-15);
        assert_near(c.o.x, 1.0, 1e-15);
        assert_near(c.o.y, 2.0, 1e-15);
        assert_near(c.o.z, -3.0, 1e-15);
        if (k[i].kind != IRIS_CAM_CYLINDER || k[i].type != 1)
            continue;
        /* cylinder 1 (POV-Ray: angle across x, |up| high): pixel column
        ** 0 turns by (0.5/W - 0.5) x 200 degrees about up, row 0 rises
        ** to (0.5 - 0.5/H) |up| along the unit up */
        vec3 R = v3_norm(cam.right), U = v3_norm(cam.up);
        double a = (0.5 / W - 0.5) * 200.0 * M_PI / 180.0;
        vec3 e = v3_norm(v3_add(v3_scale(R, sin(a)), v3_scale(d, cos(a))));
        assert_true(camera_ray_axes(&cam, &ax, W, H, 0.0, H / 2 - 0.5, &c,
                                    &raw));
        assert_near(c.d.x, e.x, 1e-14);
        assert_near(c.d.y, e.y, 1e-14);
        assert_near(c.d.z, e.z, 1e-14);
        e = v3_norm(v3_add(v3_scale(U, (0.5 - 0.5 / H) * v3_len(cam.up)), d));
        assert_true(camera_ray_axes(&cam, &ax, W, H, W / 2 - 0.5, 0.0, &c,
                                    &raw));
        assert_near(c.d.x, e.x, 1e-14);
        assert_near(c.d.y, e.y, 1e-14);
        assert_near(c.d.z, e.z, 1e-14);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_same_bits),
        cmocka_unit_test(test_geometry),
        cmocka_unit_test(test_setup_refuses),
        cmocka_unit_test(test_angular_axes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
