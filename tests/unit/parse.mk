## tests/unit/parse.mk: tests of povparse, src/scene and src/fn.
# parsedump prints a scene dump or the diagnostics: the golden tests of
# tests/parse/run.sh compare its output with tests/parse/cases/*.expect.
check_PROGRAMS += tests/parse/parsedump
tests_parse_parsedump_SOURCES = tests/parse/parsedump.c
tests_parse_parsedump_LDADD = libiris_core.la $(IRIS_LIBS)
TESTS += tests/parse/run.sh
EXTRA_DIST += tests/parse/cases tests/parse/run.sh
