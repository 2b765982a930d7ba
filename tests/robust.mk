## tests/robust.mk: robustness (issue 7). The per-hit ray offset of
## src/accel (a cmocka test), scenes at the numerical edges
## (tests/stability) and malformed or hostile input (tests/badinput).
## stability.sh also uses tests/cli/imgtool (cli.mk) for PSNR.
check_PROGRAMS += tests/stability/imgcheck tests/stability/test_hit_epsilon
TESTS += tests/stability/test_hit_epsilon tests/stability/stability.sh \
	tests/badinput/badinput.sh
tests_stability_imgcheck_SOURCES = tests/stability/imgcheck.c
tests_stability_imgcheck_LDADD = libiris_core.la $(IRIS_LIBS)
tests_stability_test_hit_epsilon_SOURCES = tests/stability/test_hit_epsilon.c \
	tests/testutil.h
tests_stability_test_hit_epsilon_CFLAGS = $(TEST_CFLAGS)
tests_stability_test_hit_epsilon_LDADD = $(TEST_LDADD)
EXTRA_DIST += tests/stability/stability.sh tests/stability/scenes \
	tests/stability/caustic_mc.py \
	tests/badinput/badinput.sh tests/badinput/cases
