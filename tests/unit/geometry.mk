## tests/unit/geometry.mk: unit tests of this area.
check_PROGRAMS += tests/unit/test_geom tests/unit/test_accel \
	tests/unit/test_accel_pov
TESTS += tests/unit/test_geom tests/unit/test_accel \
	tests/unit/test_accel_pov
check_PROGRAMS += tests/unit/test_geom_shapes
TESTS += tests/unit/test_geom_shapes
tests_unit_test_geom_shapes_SOURCES = tests/unit/test_geom_shapes.c \
	tests/testutil.h
tests_unit_test_geom_shapes_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_geom_shapes_LDADD = $(TEST_LDADD)
tests_unit_test_geom_SOURCES = tests/unit/test_geom.c tests/testutil.h
tests_unit_test_geom_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_geom_LDADD = $(TEST_LDADD)
tests_unit_test_accel_SOURCES = tests/unit/test_accel.c tests/testutil.h
tests_unit_test_accel_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_accel_LDADD = $(TEST_LDADD)
tests_unit_test_accel_pov_SOURCES = tests/unit/test_accel_pov.c tests/testutil.h
tests_unit_test_accel_pov_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_accel_pov_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_julia_hcx
TESTS += tests/unit/test_julia_hcx
tests_unit_test_julia_hcx_SOURCES = tests/unit/test_julia_hcx.c \
	tests/testutil.h
tests_unit_test_julia_hcx_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_julia_hcx_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_csgbox
TESTS += tests/unit/test_csgbox
tests_unit_test_csgbox_SOURCES = tests/unit/test_csgbox.c tests/testutil.h
tests_unit_test_csgbox_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_csgbox_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_roots_cubic tests/unit/test_geom_bound
TESTS += tests/unit/test_roots_cubic tests/unit/test_geom_bound
tests_unit_test_roots_cubic_SOURCES = tests/unit/test_roots_cubic.c \
	tests/testutil.h
tests_unit_test_roots_cubic_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_roots_cubic_LDADD = $(TEST_LDADD)
tests_unit_test_geom_bound_SOURCES = tests/unit/test_geom_bound.c \
	tests/testutil.h
tests_unit_test_geom_bound_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_geom_bound_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_geom_runs
TESTS += tests/unit/test_geom_runs
tests_unit_test_geom_runs_SOURCES = tests/unit/test_geom_runs.c \
	tests/testutil.h
tests_unit_test_geom_runs_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_geom_runs_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_accel_prim
TESTS += tests/unit/test_accel_prim
tests_unit_test_accel_prim_SOURCES = tests/unit/test_accel_prim.c \
	tests/testutil.h tests/scene_builder.h
tests_unit_test_accel_prim_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_accel_prim_LDADD = $(TEST_LDADD)
