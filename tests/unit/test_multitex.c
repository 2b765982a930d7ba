/* SPDX-License-Identifier: MIT */
/*
** test_multitex.c: the textures of objects that carry several
** (src/material/multitex.c), against values worked out by hand.
**
** - A mesh face's three textures weigh 1 - Calculate_Smooth_T from each
**   corner (POV-Ray's Mesh::Determine_Textures), which on the face is
**   its barycentric coordinate of the point: a point built from known
**   barycentric coordinates must give them back. The tolerance, 1e-12,
**   allows the rounding of a few products of numbers of order 1.
** - A blob's component textures weigh |strength·(1 - r²/R²)²| at the
**   point, normalised (Blob::Determine_Textures); a component without a
**   texture adds to the blob's own. The expected values are computed in
**   the test from the field formula (POV-Ray's documentation), with the
**   same 1e-12 tolerance.
** - mat_eval_texture() on such a blob gives one stack per texture,
**   weighted as above and carrying that texture's pigment.
*/
#include "config.h"

#include <string.h>

#include "testutil.h"

#include "material/mat_internal.h"
#include "material/material.h"
#include "math/transform.h"

/* A FACE_BLEND pattern with corners a, b, c. */
static iris_pattern face(vec3 a, vec3 b, vec3 c)
{
    iris_pattern p;
    memset(&p, 0, sizeof p);
    p.kind = IRIS_PAT_FACE_BLEND;
    p.vector = a;
    p.params[0] = b.x; p.params[1] = b.y; p.params[2] = b.z;
    p.params[3] = c.x; p.params[4] = c.y; p.params[5] = c.z;
    return p;
}

static vec3 bary(vec3 a, vec3 b, vec3 c, double l0, double l1, double l2)
{
    return v3_add(v3_add(v3_scale(a, l0), v3_scale(b, l1)), v3_scale(c, l2));
}

static void check_face(vec3 a, vec3 b, vec3 c)
{
    iris_pattern p = face(a, b, c);
    const double l[][3] = { { 0.2, 0.3, 0.5 }, { 1, 0, 0 }, { 0, 1, 0 },
                            { 0, 0, 1 }, { 0.5, 0.5, 0 }, { 0.1, 0.1, 0.8 },
                            { 1.0 / 3, 1.0 / 3, 1.0 / 3 } };
    for (size_t i = 0; i < sizeof l / sizeof l[0]; i++) {
        double w[3];
        vec3 q = bary(a, b, c, l[i][0], l[i][1], l[i][2]);
        assert_near(mat_face_weights(NULL, &p, q, w), 1.0, 0);
        for (int k = 0; k < 3; k++)
            assert_near(w[k], l[i][k], 1e-12);
    }
}

static void test_face_weights(void **state)
{
    (void)state;
    /* in the xy plane: POV-Ray's first pair of axes */
    check_face(v3(0, 0, 0), v3(2, 0, 0), v3(0, 3, 0));
    /* tilted in 3-D */
    check_face(v3(-1, 0.5, 2), v3(1.5, -0.2, 0.3), v3(0.2, 2, -1));
    /* in a plane x = const: the xy and xz determinants vanish, the
    ** yz pair is used */
    check_face(v3(1, 0, 0), v3(1, 2, 0.5), v3(1, -0.5, 1.5));
}

/* The pattern's transform moves the face: the weights are taken in
** pattern space (the mesh's, after the parser's transforms). */
static void test_face_weights_transformed(void **state)
{
    (void)state;
    vec3 a = v3(0, 0, 0), b = v3(2, 0, 0), c = v3(0, 3, 0);
    iris_pattern p = face(a, b, c);
    xf_translate(&p.transform, v3(5, -1, 2));
    p.has_transform = true;
    double w[3];
    vec3 q = v3_add(bary(a, b, c, 0.6, 0.1, 0.3), v3(5, -1, 2));
    mat_face_weights(NULL, &p, q, w);
    assert_near(w[0], 0.6, 1e-12);
    assert_near(w[1], 0.1, 1e-12);
    assert_near(w[2], 0.3, 1e-12);
}

/* strength·(1 - r²/R²)² inside radius R, 0 outside. */
static double field(double s, double R, double r)
{
    if (r >= R)
        return 0.0;
    double u = 1 - r * r / (R * R);
    return s * u * u;
}

static void test_blob_weights(void **state)
{
    (void)state;
    iris_texture own, ta, tb;
    memset(&own, 0, sizeof own);
    memset(&ta, 0, sizeof ta);
    memset(&tb, 0, sizeof tb);
    iris_blob_component c[4];
    memset(c, 0, sizeof c);
    /* sphere at the origin, R 1.5, strength 1, texture A */
    c[0].kind = 0; c[0].a = v3(0, 0, 0); c[0].radius = 1.5;
    c[0].strength = 1; c[0].texture = &ta;
    /* negative sphere at (1, 0, 0), R 1, strength -0.5, no texture */
    c[1].kind = 0; c[1].a = v3(1, 0, 0); c[1].radius = 1;
    c[1].strength = -0.5;
    /* cylinder from (0, 1, 0) to (0, 3, 0), R 1, strength 2, texture B */
    c[2].kind = 1; c[2].a = v3(0, 1, 0); c[2].b = v3(0, 3, 0);
    c[2].radius = 1; c[2].strength = 2; c[2].texture = &tb;
    /* far away: contributes nothing, texture B */
    c[3].kind = 0; c[3].a = v3(10, 0, 0); c[3].radius = 1;
    c[3].strength = 1; c[3].texture = &tb;
    iris_object o;
    memset(&o, 0, sizeof o);
    o.kind = IRIS_OBJ_BLOB;
    o.texture = &own;
    o.u.blob.threshold = 0.5;
    o.u.blob.n_components = 4;
    o.u.blob.components = c;
    /* blob moved by (0, 0, 4): world point (0.6, 0.7, 4) is blob point
    ** (0.6, 0.7, 0) */
    xf_translate(&o.transform, v3(0, 0, 4));
    o.has_transform = true;
    vec3 p = v3(0.6, 0.7, 4);
    double fa = fabs(field(1, 1.5, sqrt(0.36 + 0.49)));
    double fo = fabs(field(-0.5, 1, sqrt(0.16 + 0.49)));
    /* below the cylinder's base: the distance to its end (0, 1, 0) */
    double fb = fabs(field(2, 1, sqrt(0.36 + 0.09)));
    double sum = fa + fo + fb;
    assert_true(fa > 0 && fo > 0 && fb > 0);
    const iris_texture *tex[4];
    double w[4];
    int n = mat_blob_textures(&o, p, tex, w, 4);
    assert_int_equal(n, 3);
    for (int i = 0; i < n; i++) {
        if (tex[i] == &ta)
            assert_near(w[i], fa / sum, 1e-12);
        else if (tex[i] == &own)
            assert_near(w[i], fo / sum, 1e-12);
        else if (tex[i] == &tb)
            assert_near(w[i], fb / sum, 1e-12);
        else
            fail_msg("unexpected texture %d", i);
    }
    /* beyond the cylinder's cap: the hemisphere at (0, 3, 0) */
    p = v3(0.3, 3.4, 4);
    n = mat_blob_textures(&o, p, tex, w, 4);
    assert_int_equal(n, 1);
    assert_ptr_equal(tex[0], &tb);
    assert_near(w[0], 1.0, 1e-15);
    /* outside every component */
    assert_int_equal(mat_blob_textures(&o, v3(5, 5, 4), tex, w, 4), 0);
}

static void test_blob_stacks(void **state)
{
    (void)state;
    iris_finish f;
    memset(&f, 0, sizeof f);
    f.diffuse = 0.6;
    iris_pigment pa, pb;
    memset(&pa, 0, sizeof pa);
    memset(&pb, 0, sizeof pb);
    pa.colour.r = 1;
    pb.colour.b = 1;
    iris_texture ta, tb;
    memset(&ta, 0, sizeof ta);
    memset(&tb, 0, sizeof tb);
    ta.pigment = &pa; ta.finish = &f;
    tb.pigment = &pb; tb.finish = &f;
    iris_blob_component c[2];
    memset(c, 0, sizeof c);
    c[0].a = v3(-0.5, 0, 0); c[0].radius = 1; c[0].strength = 1;
    c[0].texture = &ta;
    c[1].a = v3(0.5, 0, 0); c[1].radius = 1; c[1].strength = 1;
    c[1].texture = &tb;
    iris_object o;
    memset(&o, 0, sizeof o);
    o.kind = IRIS_OBJ_BLOB;
    o.texture = &ta;
    o.u.blob.n_components = 2;
    o.u.blob.components = c;
    assert_true(mat_texture_blended(&o));
    struct mat_point pt;
    memset(&pt, 0, sizeof pt);
    pt.p = v3(0.2, 0, 0); /* 0.7 from A's centre, 0.3 from B's */
    pt.n = v3(0, 1, 0);
    pt.d = v3(0, -1, 0);
    pt.obj = &o;
    struct mat_eval ev;
    mat_eval_texture(NULL, &tb, &pt, &ev);
    double wa = field(1, 1, 0.7), wb = field(1, 1, 0.3);
    assert_int_equal(ev.n_stacks, 2);
    for (int s = 0; s < 2; s++) {
        const struct mat_layer *l = &ev.layers[ev.stacks[s].first];
        assert_int_equal(ev.stacks[s].n, 1);
        if (l->pigment.r == 1)
            assert_near(ev.stacks[s].weight, wa / (wa + wb), 1e-12);
        else
            assert_near(ev.stacks[s].weight, wb / (wa + wb), 1e-12);
    }
    /* the same texture on an object that is not a blob: one stack */
    iris_object plain;
    memset(&plain, 0, sizeof plain);
    plain.kind = IRIS_OBJ_SPHERE;
    plain.texture = &tb;
    pt.obj = &plain;
    assert_false(mat_texture_blended(&plain));
    mat_eval_texture(NULL, &tb, &pt, &ev);
    assert_int_equal(ev.n_stacks, 1);
    assert_near(ev.layers[0].pigment.b, 1, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_face_weights),
        cmocka_unit_test(test_face_weights_transformed),
        cmocka_unit_test(test_blob_weights),
        cmocka_unit_test(test_blob_stacks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
