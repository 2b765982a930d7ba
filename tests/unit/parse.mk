## tests/unit/parse.mk: tests of povparse, src/scene and src/fn.
# parsedump prints a scene dump or the diagnostics: the golden tests of
# tests/parse/run.sh compare its output with tests/parse/cases/*.expect.
check_PROGRAMS += tests/parse/parsedump
tests_parse_parsedump_SOURCES = tests/parse/parsedump.c src/cli/geomq.c \
	src/cli/geomq.h
tests_parse_parsedump_LDADD = libiris_core.la $(IRIS_LIBS)
TESTS += tests/parse/run.sh
EXTRA_DIST += tests/parse/cases tests/parse/run.sh
check_PROGRAMS += tests/unit/test_parse tests/unit/test_fn
TESTS += tests/unit/test_parse tests/unit/test_fn
tests_unit_test_parse_SOURCES = tests/unit/test_parse.c tests/testutil.h \
	tests/unit/parse_util.h
tests_unit_test_parse_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)
tests_unit_test_parse_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_parse_LDADD = $(TEST_LDADD)
tests_unit_test_fn_SOURCES = tests/unit/test_fn.c tests/testutil.h
tests_unit_test_fn_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_fn_LDADD = $(TEST_LDADD)
# The libFuzzer target is built by tests/fuzz/build.sh (clang), not here.
EXTRA_DIST += tests/fuzz/fuzz_parse.c tests/fuzz/build.sh
# Parser fixes found against POV-Ray's example scenes (issue 3).
check_PROGRAMS += tests/unit/test_parse_parity
TESTS += tests/unit/test_parse_parity
# (with the CLI's geometry queries, which the test uses as the CLI does)
tests_unit_test_parse_parity_SOURCES = tests/unit/test_parse_parity.c \
	tests/testutil.h tests/unit/parse_util.h src/cli/geomq.c src/cli/geomq.h
tests_unit_test_parse_parity_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)
tests_unit_test_parse_parity_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_parse_parity_LDADD = $(TEST_LDADD)
# The media{} grammar (povparse/media.c, docs/media.md).
check_PROGRAMS += tests/unit/test_parse_media
TESTS += tests/unit/test_parse_media
tests_unit_test_parse_media_SOURCES = tests/unit/test_parse_media.c \
	tests/testutil.h tests/unit/parse_util.h
tests_unit_test_parse_media_CPPFLAGS = $(AM_CPPFLAGS) -I$(top_srcdir)
tests_unit_test_parse_media_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_parse_media_LDADD = $(TEST_LDADD)
