/* SPDX-License-Identifier: MIT */
/*
** test_meshcam.c: mesh_camera (povparse/scene.c, src/render/meshcam.c)
** against the rays POV-Ray 3.7's CreateCameraRay builds, worked out by
** hand from its MESH_CAMERA code for small meshes, and the parse errors
** of its Parse_Mesh_Camera, each with its line and column.
**
** Image positions are iris's (camera.h); POV-Ray 3.7 sees (x + 0.5,
** y - 0.5), so pixel (i, j) of a W-wide image reads face
** max(j - 1, 0) W + i. The expected values are sums and quotients of
** small binary fractions and thirds: a tolerance of 1e-12 covers their
** rounding. POV-Ray 3.7 holds a mesh's vertices in single precision and
** sums a face's corners and divides by 3 in single precision (methods
** 0-2), so a centroid's third is the float nearest it (third() below):
** 1e-8 from the double, which the tolerance tells apart.
*/
#include "config.h"

#include <math.h>
#include <string.h>

#include "parse_util.h"
#include "render/camera.h"

#define TOL 1e-12

/* A centroid coordinate whose corners sum to 'sum', as POV-Ray's
** MESH_CAMERA computes it: single-precision sum over 3. */
static double third(float sum)
{
    return (double)(sum / 3.0f);
}

/* The one triangle T: (P3 - P1) x (P2 - P1) = y x x = -z, centroid
** (1/3, 1/3, 0); U the same moved to x + 2 (centroid x 7/3). */
#define TRIS "#declare T = mesh { triangle { 0, x, y } " \
             "triangle { <2, 0, 0>, <3, 0, 0>, <2, 1, 0> } }\n"

static void expect_ray(const iris_camera *c, int w, int h, double x,
                       double y, int nr, vec3 o, vec3 d)
{
    ray r;
    vec3 raw;
    assert_true(camera_ray_numbered(c, w, h, x, y, nr, &r, &raw));
    assert_near(r.o.x, o.x, TOL);
    assert_near(r.o.y, o.y, TOL);
    assert_near(r.o.z, o.z, TOL);
    assert_near(r.d.x, d.x, TOL);
    assert_near(r.d.y, d.y, TOL);
    assert_near(r.d.z, d.z, TOL);
}

/* Distribution 0: face index from the pixel, origin the centroid moved
** location.z along the normal, direction reversed by direction.z < 0,
** then the mesh's transform. */
static void test_distribution0(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        TRIS "camera { mesh_camera { 1 0 mesh { T translate <0, 0, 5> } }"
        " location <0, 0, 0.5> direction <0, 0, -1> }\n", NULL);
    const iris_camera *c = &sc->camera;
    assert_int_equal(c->kind, IRIS_CAM_MESH);
    /* pixel (0, 0) and (0, 1): face 0; origin (1/3, 1/3, -0.5) + 5 z */
    expect_ray(c, 2, 2, 0, 0, 0, v3(third(1), third(1), 4.5), v3(0, 0, 1));
    expect_ray(c, 2, 2, 0, 1, 0, v3(third(1), third(1), 4.5), v3(0, 0, 1));
    /* pixel (1, 0): face 1 */
    expect_ray(c, 2, 2, 1, 0, 0, v3(third(7), third(1), 4.5), v3(0, 0, 1));
    /* a 1-wide image: pixel (0, 2) reads row 1, face 1 */
    expect_ray(c, 1, 3, 0, 2, 0, v3(third(7), third(1), 4.5), v3(0, 0, 1));
    /* face 2 does not exist: no ray */
    ray r;
    vec3 raw;
    assert_false(camera_ray_numbered(c, 1, 4, 0, 3, 0, &r, &raw));
    iris_scene_destroy(sc);
}

/* Distribution 1: ray n of a pixel reads face index + n F over the
** meshes' faces counted together (F = 3 here: T then one more). */
static void test_distribution1(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        TRIS "#declare V = mesh { triangle { <0, 0, 1>, <0, 1, 1>, "
        "<1, 0, 1> } }\n"
        "camera { mesh_camera { 2 1 mesh { T } mesh { V } } }\n", NULL);
    const iris_camera *c = &sc->camera;
    /* pixel (2, 0) of a 3-wide image: face 2, the first of V; its normal
    ** (P3 - P1) x (P2 - P1) = x x y = +z; centroid (1/3, 1/3, 1) */
    expect_ray(c, 3, 1, 2, 0, 0, v3(third(1), third(1), 1), v3(0, 0, 1));
    /* its ray 1 reads face 5: none */
    ray r;
    vec3 raw;
    assert_false(camera_ray_numbered(c, 3, 1, 2, 0, 1, &r, &raw));
    iris_scene_destroy(sc);
}

/* Distribution 2: columns of W / M pixels per mesh, face y (W / M) + x
** with x from the image's left edge. */
static void test_distribution2(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        TRIS "camera { mesh_camera { 1 2 mesh { T } "
        "mesh { T translate <0, 10, 0> } } }\n", NULL);
    const iris_camera *c = &sc->camera;
    /* 2-wide image, two meshes: pixel 0 is mesh 0 face 0, pixel 1 is
    ** mesh 1 face 1 */
    expect_ray(c, 2, 1, 0, 0, 0, v3(third(1), third(1), 0), v3(0, 0, -1));
    expect_ray(c, 2, 1, 1, 0, 0, v3(third(7), 10 + third(1), 0), v3(0, 0, -1));
    iris_scene_destroy(sc);
}

/* Distribution 3: the uv point (x / W, 1 - y / H) in iris's terms, found
** in the mesh's uv map; smooth blends the unit vertex normals. */
static void test_distribution3(void **state)
{
    (void)state;
    iris_scene *sc = pt_scene_with(
        "#declare Q = mesh2 { vertex_vectors { 3, <0, 0, 0>, <4, 0, 0>, "
        "<0, 4, 0> } normal_vectors { 3, <0, 0, 2>, <0, 0, 2>, <0, 3, 0> } "
        "uv_vectors { 3, <0, 0>, <1, 0>, <0, 1> } "
        "face_indices { 1, <0, 1, 2> } }\n"
        "camera { mesh_camera { 1 3 mesh { Q } smooth } }\n", NULL);
    const iris_camera *c = &sc->camera;
    /* pixel (1, 2) of 4x4: u = 1/4, v = 1 - 2/4 = 1/2; barycentric
    ** (1/4, 1/4, 1/2): origin (1, 2, 0); normal z/4 + z/4 + y/2 */
    double s = 1.0 / sqrt(0.5);
    expect_ray(c, 4, 4, 1, 2, 0, v3(1, 2, 0), v3(0, 0.5 * s, 0.5 * s));
    /* u = 3/4, v = 3/4 lies outside the triangle: no ray */
    ray r;
    vec3 raw;
    assert_false(camera_ray_numbered(c, 4, 4, 3, 1, 0, &r, &raw));
    iris_scene_destroy(sc);
}

/* The first error's position, or line 0 when the scene parsed. */
static iris_diag first_error(const char *sdl)
{
    iris_scene *sc = NULL;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = iris_parse_string("t.pov", sdl, strlen(sdl), NULL,
                                            &sc, &d);
    iris_diag e;
    memset(&e, 0, sizeof e);
    assert_int_not_equal(st, IRIS_OK);
    for (int i = 0; i < d.n; i++)
        if (d.items[i].sev == IRIS_SEV_ERROR) {
            e = d.items[i];
            break;
        }
    iris_diag_list_fini(&d);
    if (sc)
        iris_scene_destroy(sc);
    return e;
}

/* Parse_Mesh_Camera's errors, located at 'mesh_camera' (line 2 col 10)
** or at the offending token. */
static void test_errors(void **state)
{
    (void)state;
    static const char *const bad[] = {
        "camera { mesh_camera { 0 0 mesh { T } } }",       /* rays 0 */
        "camera { mesh_camera { 1 4 mesh { T } } }",       /* type 4 */
        "camera { mesh_camera { 2 2 mesh { T } mesh { T } } }",
        "camera { mesh_camera { 2 0 mesh { T } } }",       /* 2 > 1 mesh */
        "camera { mesh_camera { 1 0 } }",                  /* no mesh */
        "camera { mesh_camera { 1 3 mesh { T } } }",       /* no uv */
        "camera { mesh_camera { 1 0 mesh { T } smooth } }",
        "camera { mesh_camera { 1 0 sphere { 0, 1 } } }",
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char sdl[512];
        snprintf(sdl, sizeof sdl, "%s%s\n", TRIS, bad[i]);
        iris_diag e = first_error(sdl);
        assert_int_equal(e.line, 2);
        assert_true(e.col >= 10);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_distribution0),
        cmocka_unit_test(test_distribution1),
        cmocka_unit_test(test_distribution2),
        cmocka_unit_test(test_distribution3),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
