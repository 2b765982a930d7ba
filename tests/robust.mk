## tests/robust.mk: robustness (issue 7). Scenes at the numerical edges
## (tests/stability) and malformed or hostile input (tests/badinput).
check_PROGRAMS += tests/stability/imgcheck
tests_stability_imgcheck_SOURCES = tests/stability/imgcheck.c
tests_stability_imgcheck_LDADD = libiris_core.la $(IRIS_LIBS)
TESTS += tests/stability/stability.sh tests/badinput/badinput.sh
EXTRA_DIST += tests/stability/stability.sh tests/stability/scenes \
	tests/badinput/badinput.sh tests/badinput/cases
check_PROGRAMS += tests/stability/test_hit_epsilon
TESTS += tests/stability/test_hit_epsilon
tests_stability_test_hit_epsilon_SOURCES = tests/stability/test_hit_epsilon.c \
	tests/testutil.h
tests_stability_test_hit_epsilon_CFLAGS = $(TEST_CFLAGS)
tests_stability_test_hit_epsilon_LDADD = $(TEST_LDADD)
