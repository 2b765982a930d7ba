## tests/cli.mk: the iris command and image files.
check_PROGRAMS += tests/cli/test_options tests/cli/image_roundtrip
TESTS += tests/cli/test_options tests/cli/image_roundtrip tests/cli/cli.sh
tests_cli_test_options_SOURCES = tests/cli/test_options.c src/cli/options.c
tests_cli_test_options_CFLAGS = $(TEST_CFLAGS)
tests_cli_test_options_LDADD = $(TEST_LDADD)
tests_cli_image_roundtrip_SOURCES = tests/cli/image_roundtrip.c
tests_cli_image_roundtrip_CFLAGS = $(TEST_CFLAGS)
tests_cli_image_roundtrip_LDADD = $(TEST_LDADD)
EXTRA_DIST += tests/cli/cli.sh tests/cli/scenes
check_PROGRAMS += tests/cli/imgtool
tests_cli_imgtool_SOURCES = tests/cli/imgtool.c
tests_cli_imgtool_LDADD = libiris_core.la $(IRIS_LIBS)
# the command line misused: every option's bad values, files, conflicts
TESTS += tests/cli/misuse.sh
EXTRA_DIST += tests/cli/misuse.sh
# the render window +SR +ER +SC +EC, fractions included, against POV-Ray
TESTS += tests/cli/window.sh
EXTRA_DIST += tests/cli/window.sh
# the shipped scenes (scenes/) render in iris and in POV-Ray
TESTS += tests/cli/shipped_scenes.sh
EXTRA_DIST += tests/cli/shipped_scenes.sh
