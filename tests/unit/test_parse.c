/* SPDX-License-Identifier: MIT */
/*
** test_parse.c: expressions, directives, macros, arrays, strings and the
** scene the parser builds (camera, transforms, inheritance), checked
** against values worked out by hand from POV-Ray's rules (and, for the
** expression values, against POV-Ray 3.7's own #debug output of the same
** SDL). Values are read back through the pp_test_value() hook.
*/
#include "config.h"

#include "parse_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "iris/parse.h"
#include "povparse/pp_test.h"
#include "src/spectrum/ior.h"

/* The tolerance of float results: every value below is exact in binary
** or a short decimal, so only rounding of one or two operations is left. */
#define TOL 1e-12

/* Parses 'sdl' and returns the value of 'name'; fails on a parse error. */
static pp_test_result value_of(const char *sdl, const char *name)
{
    pp_test_result r;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = pp_test_value(sdl, name, NULL, &r, &d);
    if (st != IRIS_OK) {
        for (int i = 0; i < d.n; i++)
            iris_diag_format(&d.items[i], stderr);
        iris_diag_list_fini(&d);
        fail_msg("parse failed: %s", sdl);
    }
    iris_diag_list_fini(&d);
    return r;
}

static double fval(const char *sdl, const char *name)
{
    pp_test_result r = value_of(sdl, name);
    if (r.kind != 1)
        fail_msg("'%s' is not a float (kind %d) after: %s", name, r.kind, sdl);
    return r.v[0];
}

/* Parses 'sdl' expecting an error; returns the first error. */
static iris_diag first_error(const char *sdl, const iris_parse_options *o,
                             enum iris_status want)
{
    pp_test_result r;
    iris_diag_list d;
    iris_diag_list_init(&d);
    enum iris_status st = pp_test_value(sdl, "X", o, &r, &d);
    assert_int_equal(st, want);
    iris_diag e;
    memset(&e, 0, sizeof e);
    for (int i = 0; i < d.n; i++)
        if (d.items[i].sev == IRIS_SEV_ERROR) {
            e = d.items[i];
            break;
        }
    iris_diag_list_fini(&d);
    assert_int_equal(e.sev, IRIS_SEV_ERROR);
    return e;
}

/* Precedence and associativity as POV-Ray: * / before + -, left to
** right; comparisons and logic inside parentheses; ?: lowest. */
static void test_precedence(void **state)
{
    (void)state;
    assert_near(fval("#declare A = 1 + 2 * 3 - 4 / 2;", "A"), 5, TOL);
    assert_near(fval("#declare A = 8 / 4 / 2;", "A"), 1, TOL);
    assert_near(fval("#declare A = -2 * -3;", "A"), 6, TOL);
    assert_near(fval("#declare A = 2 - -3 + +1;", "A"), 6, TOL);
    /* a #declare value is a sum (POV-Ray's Parse_RValue): comparisons,
    ** & | and ?: go in parentheses */
    assert_near(fval("#declare A = ((1 < 2) & (3 > 2));", "A"), 1, TOL);
    assert_near(fval("#declare A = ((1 = 2) | !(2 != 2));", "A"), 1, TOL);
    assert_near(fval("#declare A = ((2 >= 3) ? 10 : 20);", "A"), 20, TOL);
    assert_near(fval("#declare A = (1 < 2 ? 10 : 20);", "A"), 10, TOL);
    assert_near(fval("#declare A = 1.5e2 + .5;", "A"), 150.5, TOL);
}

/* Float-to-vector promotion, dot items, vector built-ins. */
static void test_vectors(void **state)
{
    (void)state;
    pp_test_result r = value_of("#declare V = <1,2,3> * 2 + 1;", "V");
    assert_int_equal(r.kind, 2);
    assert_int_equal(r.dim, 3);
    assert_near(r.v[0], 3, TOL);
    assert_near(r.v[1], 5, TOL);
    assert_near(r.v[2], 7, TOL);
    assert_near(fval("#declare A = (x + y*2).y;", "A"), 2, TOL);
    assert_near(fval("#declare A = <4 5 6>.z;", "A"), 6, TOL);
    assert_near(fval("#declare A = vlength(<3,4,0>);", "A"), 5, TOL);
    assert_near(fval("#declare A = vdot(<1,2,3>, <4,5,6>);", "A"), 32, TOL);
    r = value_of("#declare V = vcross(x, y);", "V");
    assert_near(r.v[2], 1, TOL);
    /* POV-Ray: vrotate(x, 90*z) = y (rotation about z by +90 degrees) */
    r = value_of("#declare V = vrotate(x, <0,0,90>);", "V");
    assert_near(r.v[0], 0, 1e-12);
    assert_near(r.v[1], 1, 1e-12);
    r = value_of("#declare V = vnormalize(<0,3,4>);", "V");
    assert_near(r.v[1], 0.6, TOL);
    assert_near(r.v[2], 0.8, TOL);
    r = value_of("#declare V = vaxis_rotate(x, y, 90);", "V");
    assert_near(r.v[0], 0, 1e-12);
    assert_near(fabs(r.v[2]), 1, 1e-12);
    r = value_of("#declare V = <1,2>;", "V");
    assert_int_equal(r.dim, 2);
}

/* Colour keywords: rgb/rgbf/rgbt, components, srgb decoding. */
static void test_colours(void **state)
{
    (void)state;
    pp_test_result r = value_of("#declare C = rgb <1, 0.5, 0.25>;", "C");
    assert_int_equal(r.kind, 3);
    assert_near(r.v[1], 0.5, TOL);
    assert_near(r.v[3], 0, TOL);
    r = value_of("#declare C = rgbt <1, 1, 1, 0.5>;", "C");
    assert_near(r.v[3], 0, TOL);
    assert_near(r.v[4], 0.5, TOL);
    r = value_of("#declare C = color red 1 green 0.5 filter 0.25;", "C");
    assert_near(r.v[0], 1, TOL);
    assert_near(r.v[1], 0.5, TOL);
    assert_near(r.v[2], 0, TOL);
    assert_near(r.v[3], 0.25, TOL);
    /* sRGB 0.5 -> ((0.5 + 0.055) / 1.055)^2.4 = 0.2140411... */
    r = value_of("#declare C = srgb 0.5;", "C");
    assert_near(r.v[0], pow(0.555 / 1.055, 2.4), 1e-12);
    assert_near(fval("#declare A = (rgb <1,1,1> * 0.5).green;", "A"), 0.5,
                TOL);
    /* gray = 0.297 r + 0.589 g + 0.114 b */
    assert_near(fval("#declare A = (rgb <1,0,0>).gray;", "A"), 0.297, TOL);
}

static void test_builtins(void **state)
{
    (void)state;
    assert_near(fval("#declare A = abs(-3) + mod(7,3) + div(7,2);", "A"), 7,
                TOL);
    assert_near(fval("#declare A = int(-2.5) + floor(-2.5) + ceil(2.1);", "A"),
                -2, TOL);
    assert_near(fval("#declare A = pow(2,10) + sqrt(16);", "A"), 1028, TOL);
    assert_near(fval("#declare A = degrees(pi);", "A"), 180, 1e-12);
    assert_near(fval("#declare A = atan2(1,1);", "A"), M_PI / 4, 1e-15);
    assert_near(fval("#declare A = min(3,1,2) + max(3,1,2);", "A"), 4, TOL);
    assert_near(fval("#declare A = select(-1, 1, 2);", "A"), 1, TOL);
    assert_near(fval("#declare A = select(0, 1, 2, 3);", "A"), 2, TOL);
    assert_near(fval("#declare A = exp(ln(5));", "A"), 5, 1e-12);
    assert_near(fval("#declare A = log(1000);", "A"), 3, 1e-12);
    assert_near(fval("#declare A = radians(180) - pi;", "A"), 0, 1e-15);
    assert_near(fval("#declare A = true + yes + on - off;", "A"), 3, TOL);
    assert_near(fval("#declare A = bitwise_and(12, 10);", "A"), 8, TOL);
    assert_near(fval("#declare A = iris_version;", "A"), 0.1, TOL);
    /* rand: same seed, same stream, values in [0,1) */
    pp_test_result r = value_of("#declare S1 = seed(7); #declare S2 = seed(7);"
                                "#declare A = rand(S1) - rand(S2);", "A");
    assert_near(r.v[0], 0, 0);
    double u = fval("#declare S = seed(3); #declare A = rand(S);", "A");
    assert_true(u >= 0 && u < 1);
}

static void expect_str(const char *sdl, const char *want)
{
    pp_test_result r = value_of(sdl, "S");
    assert_int_equal(r.kind, 4);
    assert_string_equal(r.str, want);
}

static void test_strings(void **state)
{
    (void)state;
    expect_str("#declare S = concat(\"a\", \"bc\", \"d\");", "abcd");
    expect_str("#declare S = str(3.14159, 0, 2);", "3.14");
    expect_str("#declare S = str(5, -3, 0);", "005");
    expect_str("#declare S = substr(\"hello\", 2, 3);", "ell");
    expect_str("#declare S = strupr(\"abC\");", "ABC");
    expect_str("#declare S = strlwr(\"AbC\");", "abc");
    expect_str("#declare S = chr(65);", "A");
    expect_str("#declare S = vstr(3, <1,2,3>, \",\", 0, 1);", "1.0,2.0,3.0");
    expect_str("#declare S = \"tab\\tq\\\"\";", "tab\tq\"");
    assert_near(fval("#declare A = strlen(\"abc\") + val(\"2.5\");", "A"),
                5.5, TOL);
    assert_near(fval("#declare A = asc(\"A\");", "A"), 65, TOL);
    assert_near(fval("#declare A = strcmp(\"a\", \"b\");", "A"), -1, TOL);
    assert_near(fval("#declare A = (\"ab\" = \"ab\");", "A"), 1, TOL);
}

static void test_conditionals(void **state)
{
    (void)state;
    assert_near(fval("#declare A = 2; #if (A = 1) #declare X = 10;"
                     "#elseif (A = 2) #declare X = 20; #else #declare X = 30;"
                     "#end", "X"), 20, TOL);
    assert_near(fval("#if (0) #if (1) #declare X = 1; #else #declare X = 2;"
                     "#end #else #declare X = 3; #end", "X"), 3, TOL);
    assert_near(fval("#declare Q = 1; #ifdef (Q) #declare X = 1; #else "
                     "#declare X = 0; #end", "X"), 1, TOL);
    assert_near(fval("#ifndef (Nope) #declare X = 4; #end", "X"), 4, TOL);
    assert_near(fval("#declare Q = 1; #undef Q #ifdef (Q) #declare X = 1;"
                     "#else #declare X = 2; #end", "X"), 2, TOL);
    /* switch: the matching #range runs, #break leaves */
    assert_near(fval("#switch (5) #case (1) #declare X = 1; #break "
                     "#range (4, 6) #declare X = 5; #break "
                     "#else #declare X = 9; #end", "X"), 5, TOL);
    assert_near(fval("#switch (7) #case (1) #declare X = 1; #break "
                     "#else #declare X = 9; #end", "X"), 9, TOL);
    /* POV-Ray 3.7: a reserved word such as pi is not defined */
    assert_near(fval("#declare Q = 1; #declare A = defined(Q) * 2 + "
                     "defined(pi);", "A"), 2, TOL);
}

static void test_loops(void **state)
{
    (void)state;
    /* 1 + 2 + ... + 100 = 5050 */
    assert_near(fval("#declare X = 0; #declare I = 1; #while (I <= 100) "
                     "#declare X = X + I; #declare I = I + 1; #end", "X"),
                5050, TOL);
    assert_near(fval("#declare X = 0; #for (I, 1, 10, 3) #declare X = X + I;"
                     "#end", "X"), 1 + 4 + 7 + 10, TOL);
    assert_near(fval("#declare X = 0; #for (I, 3, 1, -1) #declare X = X*10 + I;"
                     "#end", "X"), 321, TOL);
    /* #break leaves the innermost loop */
    assert_near(fval("#declare X = 0; #while (1) #declare X = X + 1;"
                     "#if (X = 7) #break #end #end", "X"), 7, TOL);
    /* nested loops with a skipped inner body */
    assert_near(fval("#declare X = 0; #for (I, 1, 3) #for (J, 1, I) "
                     "#declare X = X + 1; #end #end", "X"), 6, TOL);
}

static void test_macros(void **state)
{
    (void)state;
    /* recursion: 10! = 3628800 */
    assert_near(fval("#macro F(N) #if (N <= 1) 1 #else N * F(N - 1) #end #end"
                     "#declare X = F(10);", "X"), 3628800, 1e-6);
    /* by-reference identifier arguments (POV-Ray's rule) */
    assert_near(fval("#macro Inc(V) #declare V = V + 1; #end "
                     "#declare X = 5; Inc(X) Inc(X)", "X"), 7, TOL);
    /* an expression argument is a copy */
    assert_near(fval("#macro Inc(V) #declare V = V + 1; #end "
                     "#declare X = 5; Inc(X + 0)", "X"), 5, TOL);
    /* #local stays inside the macro */
    pp_test_result r = value_of("#macro M() #local L = 3; #end M()", "L");
    assert_int_equal(r.kind, 0);
    /* a macro result followed by more expression */
    assert_near(fval("#macro Two() 2 #end #declare X = Two() * 3 + 1;", "X"),
                7, TOL);
    /* macro returning an object used by object{} */
    assert_near(fval("#macro S(R) sphere { 0, R } #end #declare O = S(2);"
                     "#declare X = max_extent(O).x;", "X"), 2, TOL);
}

static void test_arrays(void **state)
{
    (void)state;
    assert_near(fval("#declare A = array[3] {1, 2, 3};"
                     "#declare X = A[0] + A[1] * A[2];", "X"), 7, TOL);
    assert_near(fval("#declare A = array[2][3] {{1,2,3},{4,5,6}};"
                     "#declare X = A[1][2] + dimension_size(A, 2) * 10 + "
                     "dimensions(A) * 100;", "X"), 236, TOL);
    assert_near(fval("#declare A = array[2]; #declare A[1] = 4;"
                     "#declare X = A[1]; ", "X"), 4, TOL);
    /* elements without commas, vectors */
    assert_near(fval("#declare A = array[2] { <1,2> <3,4> };"
                     "#declare X = A[1].v;", "X"), 4, TOL);
    pp_test_result r = value_of("#declare A = array[4][5];", "A");
    assert_int_equal(r.kind, 16);
    assert_int_equal(r.n, 20);
}

static void test_functions(void **state)
{
    (void)state;
    assert_near(fval("#declare F = function(a, b) { a * b + 1 };"
                     "#declare X = F(3, 4);", "X"), 13, TOL);
    assert_near(fval("#declare F = function { x*x + y*y + z*z };"
                     "#declare X = F(1, 2, 3);", "X"), 14, TOL);
    assert_near(fval("#declare K = 2; #declare F = function { K * x };"
                     "#declare K = 5; #declare X = F(3, 0, 0);", "X"), 6, TOL);
    assert_near(fval("#declare F = function { select(x, -1, 1) };"
                     "#declare X = F(-2, 0, 0) + F(2, 0, 0) * 10;", "X"), 9,
                TOL);
    assert_near(fval("#declare G = function { x + 1 };"
                     "#declare F = function { G(x, y, z) * 2 };"
                     "#declare X = F(4, 0, 0);", "X"), 10, TOL);
    /* f_sphere is internal(61): |p| - r */
    assert_near(fval("#declare f_sphere = function { internal(61) };"
                     "#declare X = f_sphere(3, 0, 4, 1);", "X"), 4, TOL);
}

/* Declare=Name=Value from the command line. */
static void test_declares(void **state)
{
    (void)state;
    iris_declare d[2] = { { "Q", "2*3" }, { "S", "\"txt\"" } };
    iris_parse_options o;
    memset(&o, 0, sizeof o);
    o.declares = d;
    o.n_declares = 2;
    pp_test_result r;
    iris_diag_list dl;
    iris_diag_list_init(&dl);
    assert_int_equal(pp_test_value("#declare X = Q + strlen(S);", "X", &o,
                                   &r, &dl), IRIS_OK);
    assert_near(r.v[0], 9, TOL);
    iris_diag_list_fini(&dl);
}

/* Errors are located; limits stop runaway input with a located error. */
static void test_errors_and_limits(void **state)
{
    (void)state;
    iris_diag e = first_error("#declare A = 1;\n#declare B = A + ;\n", NULL,
                              IRIS_EPARSE);
    assert_int_equal(e.line, 2);
    assert_int_equal(e.col, 18);
    assert_string_equal(e.source_line, "#declare B = A + ;");

    e = first_error("#declare B = Undefined + 1;", NULL, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "undeclared identifier 'Undefined'"));

    iris_parse_options o;
    memset(&o, 0, sizeof o);
    o.max_while_iterations = 1000;
    e = first_error("#declare I = 0;\n#while (1) #declare I = I + 1; #end",
                    &o, IRIS_EPARSE);
    assert_int_equal(e.line, 2);
    assert_non_null(strstr(e.message, "1000"));

    memset(&o, 0, sizeof o);
    o.max_macro_depth = 50;
    e = first_error("#macro R(N) R(N + 1) #end\nR(0)", &o, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "nested more than 50"));
    assert_true(e.n_chain > 0);

    /* 20000 nested parentheses (and unary '!'): an error, not a stack
    ** overflow; the fuzzer found one at ~900 levels under AddressSanitizer,
    ** whose frames are larger. Which limit fires first (depth or stack
    ** bytes) depends on the build, so only "nested" is checked. */
    {
        size_t n = 20000;
        char *deep = malloc(2 * n + 64);
        assert_non_null(deep);
        strcpy(deep, "#declare X = ");
        size_t k = strlen(deep);
        for (size_t i = 0; i < n; i++)
            deep[k++] = i % 7 == 3 ? '!' : '(';
        deep[k++] = '1';
        deep[k] = 0;
        e = first_error(deep, NULL, IRIS_EPARSE);
        assert_non_null(strstr(e.message, "nested"));
        free(deep);
    }

    memset(&o, 0, sizeof o);
    o.max_memory = 1 << 20;
    e = first_error("#declare A = array[1000000];", &o, IRIS_ENOMEM);
    assert_non_null(strstr(e.message, "memory"));

    e = first_error("#if (1)\n#declare A = 1;\n", NULL, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "#end"));
    e = first_error("#declare S = \"abc\n", NULL, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "unterminated string"));
    e = first_error("#declare A = array[2]; #declare X = A[2];", NULL,
                    IRIS_EPARSE);
    assert_non_null(strstr(e.message, "out of range"));
    /* x / 0 is POV-Ray's HUGE_VAL with a warning; only its use in the
    ** scene is an error */
    e = first_error("#declare X = 1 / 0;\nsphere { 0, X }", NULL,
                    IRIS_EPARSE);
    assert_non_null(strstr(e.message, "not a finite number"));
    e = first_error("#error \"stop here\"", NULL, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "stop here"));

    /* NUL bytes and binary input are errors, not crashes */
    const char bin[] = "#declare A = 1;\0\xff\xfe";
    pp_test_result r;
    iris_diag_list dl;
    iris_diag_list_init(&dl);
    iris_scene *sc = NULL;
    assert_int_equal(iris_parse_string("bin", bin, sizeof bin - 1, NULL, &sc,
                                       &dl), IRIS_EPARSE);
    assert_null(sc);
    iris_diag_list_fini(&dl);
    /* deep nesting: 500 parentheses parse, 100000 stop with an error
    ** (the grammar's recursion is bounded, the C stack is safe) */
    static char deep[210000];
    for (int depth = 500; depth <= 100000; depth += 99500) {
        size_t k = (size_t)snprintf(deep, sizeof deep, "#declare X = ");
        for (int i = 0; i < depth; i++)
            deep[k++] = '(';
        deep[k++] = '1';
        for (int i = 0; i < depth; i++)
            deep[k++] = ')';
        deep[k++] = ';';
        deep[k] = 0;
        iris_diag_list_init(&dl);
        enum iris_status st = pp_test_value(deep, "X", NULL, &r, &dl);
        assert_int_equal(st, depth == 500 ? IRIS_OK : IRIS_EPARSE);
        if (st == IRIS_OK)
            assert_near(r.v[0], 1, 0);
        iris_diag_list_fini(&dl);
    }
    /* the same for CSG nested in CSG */
    size_t k = 0;
    for (int i = 0; i < 5000; i++)
        k += (size_t)snprintf(deep + k, sizeof deep - k, "union{");
    deep[k] = 0;
    e = first_error(deep, NULL, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "nested"));
}

/* Parses a scene from a string; fails on error. */
static iris_scene *scene_of(const char *sdl)
{
    return pt_scene_with(sdl, NULL);
}

/* The camera in POV-Ray's fixed order (semantics §3.8). */
static void test_camera(void **state)
{
    (void)state;
    iris_scene *sc = scene_of("camera { look_at <0,0,0> location <0,0,-5> }");
    /* look_at straight ahead: D = z*|z|, R = 1.33 x, U = y */
    assert_near(sc->camera.direction.z, 1, 1e-12);
    assert_near(sc->camera.right.x, 1.33, 1e-12);
    assert_near(sc->camera.up.y, 1, 1e-12);
    iris_scene_destroy(sc);
    /* angle 90 with right x: |D| = 0.5 * 1 / tan(45 deg) = 0.5 */
    sc = scene_of("camera { angle 90 right x location 0 }");
    assert_near(sc->camera.direction.z, 0.5, 1e-12);
    iris_scene_destroy(sc);
    /* looking along +x: R = normalize(y x x) * 1.33 = -z * 1.33 */
    sc = scene_of("camera { location 0 look_at x }");
    assert_near(sc->camera.direction.x, 1, 1e-12);
    assert_near(sc->camera.right.z, -1.33, 1e-12);
    assert_near(sc->camera.up.y, 1, 1e-12);
    iris_scene_destroy(sc);
    /* right-handed setup (right -x): right stays negated after look_at */
    sc = scene_of("camera { right -1.33*x location <0,0,-1> look_at 0 }");
    assert_near(sc->camera.right.x, -1.33, 1e-12);
    assert_near(sc->camera.up.y, 1, 1e-12);
    iris_scene_destroy(sc);
    /* transforms come last */
    sc = scene_of("camera { location 0 look_at z translate <1,2,3> }");
    assert_near(sc->camera.location.x, 1, 1e-12);
    assert_near(sc->camera.location.z, 3, 1e-12);
    iris_scene_destroy(sc);
}

/* Transforms fold into CSG children; texture transforms follow POV-Ray. */
static void test_transforms_and_textures(void **state)
{
    (void)state;
    iris_scene *sc = scene_of(
        "union { sphere { 0, 1 translate x } sphere { 0, 1 pigment { rgb 1 } }"
        " pigment { checker } translate y }\n"
        "sphere { 0, 1 pigment { checker } translate x }\n"
        "sphere { 0, 1 translate x pigment { checker } }\n"
        "sphere { 0, 1 scale <2, 0, 1> }\n");
    assert_int_equal(sc->n_objects, 4);
    const iris_object *u = sc->objects[0];
    assert_int_equal(u->kind, IRIS_OBJ_UNION);
    const iris_object *c0 = u->u.csg.children[0];
    const iris_object *c1 = u->u.csg.children[1];
    /* child 0: translate x, then the union's translate y */
    assert_near(c0->transform.m[0][3], 1, 0);
    assert_near(c0->transform.m[1][3], 1, 0);
    /* child 0 inherits the union's checker, moved by the union's y */
    assert_int_equal(c0->texture->pigment->pattern.kind, IRIS_PAT_CHECKER);
    assert_near(c0->texture->pigment->pattern.transform.m[1][3], 1, 0);
    /* child 1 keeps its own solid pigment */
    assert_int_equal(c1->texture->pigment->pattern.kind, IRIS_PAT_NONE);
    assert_near(c1->texture->pigment->colour.g, 1, 0);
    /* texture before the transform moves with the object... */
    assert_near(sc->objects[1]->texture->pigment->pattern.transform.m[0][3],
                1, 0);
    /* ...after it, it does not */
    assert_near(sc->objects[2]->texture->pigment->pattern.transform.m[0][3],
                0, 0);
    /* scale 0 is taken as 1 (POV-Ray warns and does the same) */
    assert_near(sc->objects[3]->transform.m[1][1], 1, 0);
    assert_near(sc->objects[3]->transform.m[0][0], 2, 0);
    /* leaves always have a texture with a finish */
    assert_non_null(sc->objects[3]->texture);
    assert_non_null(sc->objects[3]->texture->finish);
    assert_near(sc->objects[3]->texture->finish->diffuse, 0.6, 0);
    iris_scene_destroy(sc);
}

/* #default, interior inheritance, finish forms, iris IOR extensions. */
static void test_materials(void **state)
{
    (void)state;
    iris_scene *sc = scene_of(
        "#default { finish { ambient 0.2 } }\n"
        "sphere { 0, 1 }\n"
        "union { sphere { 0, 1 } interior { ior 1.5 dispersion 1.1 } }\n"
        "sphere { 0, 1 finish { reflection 0.3 phong albedo 0.5 } }\n"
        "sphere { 0, 1 finish { reflection { 0.1, 0.9 fresnel on } } }\n"
        "sphere { 0, 1 interior { #ifdef (iris_version) glass \"N-BK7\" #end } }\n"
        "sphere { 0, 1 interior { ior_decay 1.6, 1.5, 120 } }\n"
        "light_source { 0, 1 #ifdef (iris_version) blackbody 3200 #end }\n"
        "light_source { 0, 1 spotlight spectrum \"F11\" }\n");
    assert_near(sc->objects[0]->texture->finish->ambient.r, 0.2, 0);
    const iris_object *child = sc->objects[1]->u.csg.children[0];
    assert_non_null(child->interior);
    assert_near(child->interior->ior, 1.5, 0);
    assert_near(child->interior->dispersion, 1.1, 0);
    const iris_finish *f = sc->objects[2]->texture->finish;
    assert_near(f->reflection_min.r, 0.3, 0);
    assert_near(f->reflection_max.r, 0.3, 0);
    /* phong albedo p = p (phong_size + 1) / 2 = 0.5 * 41 / 2 */
    assert_near(f->phong, 10.25, 1e-12);
    f = sc->objects[3]->texture->finish;
    assert_true(f->reflection_fresnel);
    assert_near(f->reflection_min.r, 0.1, 0);
    assert_near(f->reflection_max.r, 0.9, 0);
    /* a catalogue glass keeps its name; src/spectrum holds the data:
    ** N-BK7's n_d (587.5618 nm) is 1.51680 in SCHOTT's data sheet,
    ** given to 5 decimals */
    const iris_ior_spec *s = sc->objects[4]->interior->spectral_ior;
    assert_non_null(s);
    assert_int_equal(s->model, IRIS_IOR_SELLMEIER);
    assert_string_equal(s->glass_name, "N-BK7");
    assert_near(ior_eval(sc->objects[4]->interior, IOR_LAMBDA_D), 1.5168,
                5e-6);
    s = sc->objects[5]->interior->spectral_ior;
    assert_int_equal(s->model, IRIS_IOR_DECAY);
    assert_near(s->decay_spread, 120, 0);
    assert_int_equal(sc->n_lights, 2);
    assert_int_equal(sc->lights[0]->spectrum, IRIS_SPEC_BLACKBODY);
    assert_near(sc->lights[0]->blackbody_kelvin, 3200, 0);
    assert_int_equal(sc->lights[1]->spectrum, IRIS_SPEC_F1 + 10);
    assert_int_equal(sc->lights[1]->kind, IRIS_LIGHT_SPOT);
    assert_near(sc->lights[1]->radius, 30, 0);
    assert_near(sc->lights[1]->falloff, 45, 0);
    iris_scene_destroy(sc);

    iris_diag e = first_error("sphere { 0, 1 interior { ior_decay 1.6, 1.5, 0 } }",
                              NULL, IRIS_EPARSE);
    assert_non_null(strstr(e.message, "spread"));
    e = first_error("sphere { 0,1 interior { dispersion_samples 1 } }", NULL,
                    IRIS_EPARSE);
    assert_non_null(strstr(e.message, "dispersion_samples"));
    /* an unknown glass name parses: the render build reports it, located
    ** (render/check_ior.c; test_parse_parity checks that) */
    sc = scene_of("sphere { 0,1 interior { glass \"nope\" } }");
    assert_string_equal(sc->objects[0]->interior->spectral_ior->glass_name,
                        "nope");
    iris_scene_destroy(sc);
    e = first_error("sphere { 0,1 interior { glass \"\" } }", NULL,
                    IRIS_EPARSE);
    assert_non_null(strstr(e.message, "glass needs a catalogue name"));
}

/* assumed_gamma 2.2: colours decode as c^2.2, shared pigments once. */
/* assumed_gamma G: POV-Ray 3.7 keeps rgb colours as written (they are
** working-space values; the output applies v^G), and converts srgb
** colours to the working space. The srgb value is POV-Ray 3.7.0.10's own
** #debug of (srgb 0.5).red under assumed_gamma 2.2, printed with six
** decimals: hence the 5e-7 tolerance. */
static void test_gamma(void **state)
{
    (void)state;
    iris_scene *sc = scene_of(
        "global_settings { assumed_gamma 2.2 }\n"
        "#declare P = pigment { rgbf <0.5, 1, 0, 0.5> }\n"
        "sphere { 0, 1 pigment { P } } sphere { 0, 1 pigment { srgb 0.5 } }\n"
        "light_source { 0, rgb 0.25 }\n");
    const iris_colour *c = &sc->objects[0]->texture->pigment->colour;
    assert_near(c->r, 0.5, 0);
    assert_near(c->g, 1, 0);
    assert_near(c->f, 0.5, 0);
    c = &sc->objects[1]->texture->pigment->colour;
    assert_near(c->r, 0.496227, 5e-7);
    assert_near(sc->lights[0]->colour.r, 0.25, 0);
    iris_scene_destroy(sc);
    /* Without assumed_gamma srgb decodes to light: 0.5 -> 0.214041 */
    assert_near(fval("#declare X = (srgb 0.5).red;", "X"), 0.2140412, 1e-7);
}

/* Issue 7: #fopen write needs allow_writes, and then writes only inside
** the scene's directory (a subdirectory is inside; ".." is not). The
** scene lives in a fresh temporary directory so that nothing else is
** touched; what was written is read back from the file system. */
/*
** Map trees are counted as trees when built (maptree.c): a pigment_map
** whose entries share one declared map counts that map each time. A
** doubling chain of L levels over a colour-map leaf holds 2^(L+1) - 1
** pigments: 17 levels (262143) fit under IRIS_MAX_MAP_TREE = 2^18, 18
** levels are refused at the map that passed it. The flag that keeps uv
** entries from sharing a transform is read one level down.
*/
static void test_map_tree(void **state)
{
    (void)state;
    iris_scene *sc = scene_of(
        "#declare P = pigment { checker rgb 0 rgb 1 }\n"
        "#declare Q = pigment { checker P P }\n"
        "sphere { 0, 1 pigment { checker Q Q rotate 30*y } }\n"
        "sphere { 0, 1 pigment { checker pigment { P uv_mapping } Q } }\n"
        "sphere { 0, 1 pigment { checker Q pigment { checker P "
        "pigment { Q uv_mapping } } scale 2 } }\n"
        "sphere { 0, 1 texture { checker texture { pigment { Q } }"
        " texture { pigment { P } } } }\n");
    const iris_texture *t = sc->objects[0]->texture;
    assert_int_equal(t->pigment->map_tree, 7);  /* 1 + 2 (1 + 2) */
    assert_false(t->pigment->map_tree_pointwise);
    /* an uv-mapped entry, one level down and two */
    assert_true(sc->objects[1]->texture->pigment->map_tree_pointwise);
    assert_true(sc->objects[2]->texture->pigment->map_tree_pointwise);
    /* the transform reached the uv entries' map by copy: no entry transform */
    assert_null(sc->objects[2]->texture->pigment->entry_xf);
    assert_int_equal(sc->objects[2]->texture->pigment->map_tree,
                     1 + 3 + (1 + 1 + 3));
    /* a texture_map: itself, its (default) pigment, each entry texture
    ** and its pigment's tree */
    assert_int_equal(sc->objects[3]->texture->map_tree,
                     1 + 1 + (1 + 3) + (1 + 1));
    iris_scene_destroy(sc);

    char sdl[256];
    for (int levels = 17; levels <= 18; levels++) {
        snprintf(sdl, sizeof sdl,
                 "#declare P = pigment { checker rgb 0 rgb 1 }\n"
                 "#for (I, 1, %d)\n"
                 "  #declare P = pigment { checker P P scale 0.5 }\n"
                 "#end\n"
                 "sphere { 0, 1 pigment { P } }\n", levels);
        iris_scene *s2 = NULL;
        iris_diag_list d;
        iris_diag_list_init(&d);
        enum iris_status st = iris_parse_string("t.pov", sdl, strlen(sdl),
                                                NULL, &s2, &d);
        if (levels == 17) {
            assert_int_equal(st, IRIS_OK);
            assert_int_equal(s2->objects[0]->texture->pigment->map_tree,
                             (1u << 18) - 1);
        } else {
            assert_int_equal(st, IRIS_EPARSE);
            assert_true(d.n > 0);
            assert_int_equal(d.items[d.n - 1].line, 3);
            assert_int_equal(d.items[d.n - 1].col, 26);
            assert_non_null(strstr(d.items[d.n - 1].message, "map tree"));
        }
        iris_scene_destroy(s2);
        iris_diag_list_fini(&d);
    }
}

static void test_write_policy(void **state)
{
    (void)state;
    char dir[] = "/tmp/iris-parse-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char sub[64], scene[80], out[96], bad_scene[80], outside[96];
    snprintf(sub, sizeof sub, "%s/s", dir);
    assert_int_equal(mkdir(sub, 0700), 0);
    snprintf(scene, sizeof scene, "%s/w.pov", sub);
    snprintf(out, sizeof out, "%s/out.txt", sub);
    snprintf(bad_scene, sizeof bad_scene, "%s/bad.pov", sub);
    snprintf(outside, sizeof outside, "%s/outside.txt", dir);
    pt_put_file(scene, "#fopen F \"out.txt\" write\n"
                    "#write (F, \"x=\", 7, \"\\n\")\n#fclose F\n");
    pt_put_file(bad_scene, "#fopen F \"../outside.txt\" write\n");

    iris_parse_options o;
    memset(&o, 0, sizeof o);
    struct stat st;
    for (int allow = 0; allow < 2; allow++) {
        o.allow_writes = allow;
        iris_diag_list d;
        iris_diag_list_init(&d);
        iris_scene *sc = NULL;
        assert_int_equal(iris_parse_file(scene, &o, &sc, &d), IRIS_OK);
        /* Refused writes are a warning: the scene still renders */
        assert_int_equal(d.n_warnings, allow ? 0 : 1);
        iris_scene_destroy(sc);
        iris_diag_list_fini(&d);
        assert_int_equal(stat(out, &st) == 0, allow);
    }
    char buf[32] = "";
    FILE *fp = fopen(out, "r");
    assert_non_null(fp);
    assert_non_null(fgets(buf, sizeof buf, fp));
    fclose(fp);
    assert_string_equal(buf, "x=7\n");

    iris_diag_list d;
    iris_diag_list_init(&d);
    iris_scene *sc = NULL;
    assert_int_equal(iris_parse_file(bad_scene, &o, &sc, &d), IRIS_EPARSE);
    assert_null(sc);
    assert_int_equal(d.items[0].line, 1);
    assert_non_null(strstr(d.items[0].message, "refused"));
    iris_diag_list_fini(&d);
    assert_int_not_equal(stat(outside, &st), 0);

    unlink(out);
    unlink(scene);
    unlink(bad_scene);
    rmdir(sub);
    rmdir(dir);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_precedence),
        cmocka_unit_test(test_vectors),
        cmocka_unit_test(test_colours),
        cmocka_unit_test(test_builtins),
        cmocka_unit_test(test_strings),
        cmocka_unit_test(test_conditionals),
        cmocka_unit_test(test_loops),
        cmocka_unit_test(test_macros),
        cmocka_unit_test(test_arrays),
        cmocka_unit_test(test_functions),
        cmocka_unit_test(test_declares),
        cmocka_unit_test(test_errors_and_limits),
        cmocka_unit_test(test_camera),
        cmocka_unit_test(test_transforms_and_textures),
        cmocka_unit_test(test_materials),
        cmocka_unit_test(test_gamma),
        cmocka_unit_test(test_write_policy),
        cmocka_unit_test(test_map_tree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
