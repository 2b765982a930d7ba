## tests/unit/render.mk: unit tests of src/material and src/render, and
## the POV-Ray parity suite (tests/render).
check_PROGRAMS += tests/unit/test_material
TESTS += tests/unit/test_material
tests_unit_test_material_SOURCES = tests/unit/test_material.c tests/testutil.h
tests_unit_test_material_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_material_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_noise_exact
TESTS += tests/unit/test_noise_exact
tests_unit_test_noise_exact_SOURCES = tests/unit/test_noise_exact.c \
	tests/testutil.h
tests_unit_test_noise_exact_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_noise_exact_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_df3
TESTS += tests/unit/test_df3
tests_unit_test_df3_SOURCES = tests/unit/test_df3.c tests/testutil.h
tests_unit_test_df3_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_df3_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_tiling
TESTS += tests/unit/test_tiling
tests_unit_test_tiling_SOURCES = tests/unit/test_tiling.c tests/testutil.h
tests_unit_test_tiling_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_tiling_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_objpattern
TESTS += tests/unit/test_objpattern
tests_unit_test_objpattern_SOURCES = tests/unit/test_objpattern.c \
	tests/scene_builder.h tests/testutil.h
tests_unit_test_objpattern_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_objpattern_LDADD = $(TEST_LDADD)

check_PROGRAMS += tests/unit/test_render
TESTS += tests/unit/test_render
tests_unit_test_render_SOURCES = tests/unit/test_render.c \
	tests/unit/render_double.c tests/unit/render_double.h tests/testutil.h
tests_unit_test_render_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_render_LDADD = $(TEST_LDADD)

check_PROGRAMS += tests/unit/test_meshcam
TESTS += tests/unit/test_meshcam
tests_unit_test_meshcam_SOURCES = tests/unit/test_meshcam.c \
	tests/unit/parse_util.h tests/testutil.h
tests_unit_test_meshcam_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_meshcam_LDADD = $(TEST_LDADD)

check_PROGRAMS += tests/unit/test_media
TESTS += tests/unit/test_media
tests_unit_test_media_SOURCES = tests/unit/test_media.c \
	tests/unit/render_double.c tests/unit/render_double.h tests/testutil.h
tests_unit_test_media_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_media_LDADD = $(TEST_LDADD)

check_PROGRAMS += tests/unit/test_gather_sources
TESTS += tests/unit/test_gather_sources
tests_unit_test_gather_sources_SOURCES = tests/unit/test_gather_sources.c \
	tests/unit/parse_util.h tests/testutil.h
tests_unit_test_gather_sources_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_gather_sources_LDADD = $(TEST_LDADD)

# The POV-Ray parity suite: iris against POV-Ray, scene by scene.
check_PROGRAMS += tests/render/psnr
tests_render_psnr_SOURCES = tests/render/psnr.c
tests_render_psnr_LDADD = libiris_core.la $(IRIS_LIBS)
TESTS += tests/render/parity.sh
EXTRA_DIST += tests/render/parity.sh tests/render/scenes
# radiosity's final gather against analytic values (tests/render/gather.sh)
TESTS += tests/render/gather.sh
EXTRA_DIST += tests/render/gather.sh tests/render/gather
# +UA output against POV-Ray's (tests/render/alpha.sh)
TESTS += tests/render/alpha.sh
EXTRA_DIST += tests/render/alpha.sh tests/render/alpha
# the magnet patterns (src/material/fractal_pattern.c)
check_PROGRAMS += tests/unit/test_fractal_pattern
TESTS += tests/unit/test_fractal_pattern
tests_unit_test_fractal_pattern_SOURCES = tests/unit/test_fractal_pattern.c \
	tests/testutil.h tests/unit/parse_util.h
tests_unit_test_fractal_pattern_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_fractal_pattern_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_srgb8
TESTS += tests/unit/test_srgb8
tests_unit_test_srgb8_SOURCES = tests/unit/test_srgb8.c tests/testutil.h
tests_unit_test_srgb8_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_srgb8_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_eyesrgb
TESTS += tests/unit/test_eyesrgb
tests_unit_test_eyesrgb_SOURCES = tests/unit/test_eyesrgb.c tests/testutil.h
tests_unit_test_eyesrgb_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_eyesrgb_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_multitex
TESTS += tests/unit/test_multitex
tests_unit_test_multitex_SOURCES = tests/unit/test_multitex.c tests/testutil.h
tests_unit_test_multitex_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_multitex_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_camnormal
TESTS += tests/unit/test_camnormal
tests_unit_test_camnormal_SOURCES = tests/unit/test_camnormal.c \
	tests/unit/parse_util.h tests/testutil.h
tests_unit_test_camnormal_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_camnormal_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_camray
TESTS += tests/unit/test_camray
tests_unit_test_camray_SOURCES = tests/unit/test_camray.c tests/testutil.h
tests_unit_test_camray_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_camray_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_subsurface
TESTS += tests/unit/test_subsurface
tests_unit_test_subsurface_SOURCES = tests/unit/test_subsurface.c tests/testutil.h
tests_unit_test_subsurface_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_subsurface_LDADD = $(TEST_LDADD)
# the iteration cap of mandel/julia/magnet patterns (IRIS_PATTERN_MAX_ITERATIONS)
check_PROGRAMS += tests/unit/test_fractal_cap
TESTS += tests/unit/test_fractal_cap
tests_unit_test_fractal_cap_SOURCES = tests/unit/test_fractal_cap.c tests/testutil.h \
	tests/unit/parse_util.h
tests_unit_test_fractal_cap_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_fractal_cap_LDADD = $(TEST_LDADD)
# iris's ray counts against POV-Ray's render statistics (tests/render/raycounts.sh)
TESTS += tests/render/raycounts.sh
EXTRA_DIST += tests/render/raycounts.sh
check_PROGRAMS += tests/unit/test_texelmemo
TESTS += tests/unit/test_texelmemo
tests_unit_test_texelmemo_SOURCES = tests/unit/test_texelmemo.c \
	tests/testutil.h tests/unit/parse_util.h
tests_unit_test_texelmemo_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_texelmemo_LDADD = $(TEST_LDADD)
# pattern.c's and pigment.c's short cuts (fmod, long colour maps) give POV-Ray's formulas' bits
check_PROGRAMS += tests/unit/test_pattern_paths
TESTS += tests/unit/test_pattern_paths
tests_unit_test_pattern_paths_SOURCES = tests/unit/test_pattern_paths.c \
	tests/testutil.h tests/unit/parse_util.h
tests_unit_test_pattern_paths_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_pattern_paths_LDADD = $(TEST_LDADD)
