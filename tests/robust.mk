## tests/robust.mk: robustness (issue 7). The per-hit ray offset of
## src/accel (a cmocka test), scenes at the numerical edges
## (tests/stability) and malformed or hostile input (tests/badinput).
## stability.sh also uses tests/cli/imgtool (cli.mk) for PSNR.
check_PROGRAMS += tests/stability/imgcheck tests/stability/test_hit_epsilon
TESTS += tests/stability/test_hit_epsilon tests/stability/stability.sh \
	tests/badinput/badinput.sh tests/stability/area_light_cap.sh
tests_stability_imgcheck_SOURCES = tests/stability/imgcheck.c
tests_stability_imgcheck_LDADD = libiris_core.la $(IRIS_LIBS)
tests_stability_test_hit_epsilon_SOURCES = tests/stability/test_hit_epsilon.c \
	tests/testutil.h
tests_stability_test_hit_epsilon_CFLAGS = $(TEST_CFLAGS)
tests_stability_test_hit_epsilon_LDADD = $(TEST_LDADD)
EXTRA_DIST += tests/stability/stability.sh tests/stability/scenes \
	tests/stability/caustic_mc.py \
	tests/stability/area_light_cap.sh \
	tests/badinput/badinput.sh tests/badinput/cases

## Stages scripts/run-tests runs after make check (issue 7); each can be
## run alone:
##   make check-fuzz       the fuzz regression (tests/fuzz/regress.sh:
##                         clang + libFuzzer, ~1 minute)
##   make check-sanitized  in a tree configured with --enable-sanitizers:
##                         the compiled (unit) tests and SAN_SHELL_TESTS,
##                         the parse, bad-input and stability tests; not
##                         the POV-Ray parity renders (tests/render,
##                         test_accel_pov), which take long and test
##                         pixels, not memory.
## Tests that bound time or memory read IRIS_SANITIZED (non-empty in a
## sanitised build) and relax themselves.
AM_TESTS_ENVIRONMENT += export IRIS_SANITIZED='$(SAN_FLAGS)';
## intercept_tls_get_addr=0: up to GCC 13 and LLVM 16 the sanitizer
## runtime's __tls_get_addr interceptor takes a dynamic TLS block that
## happens to start 16 bytes past a page boundary for a pre-2.25 glibc
## header and reads a bogus range from the words before it; LeakSanitizer's
## tracer then dies at exit ("Tracer caught signal 11 ... LeakSanitizer has
## encountered a fatal error") after every test passed. Embree's threads
## make it likely: test_accel alone died in 6 of 50 runs, two at once with
## a busy core in 239 of 300, and 0 of 300 with this option (session 9).
## The libFuzzer targets (clang 14) get it too.
AM_TESTS_ENVIRONMENT += export ASAN_OPTIONS="intercept_tls_get_addr=0$${ASAN_OPTIONS:+:$$ASAN_OPTIONS}";
SAN_SHELL_TESTS = tests/parse/run.sh tests/badinput/badinput.sh \
	tests/stability/stability.sh
EXTRA_DIST += tests/valgrind.supp \
	tests/fuzz/build.sh tests/fuzz/seed.sh tests/fuzz/regress.sh \
	tests/fuzz/fuzz_parse.c tests/fuzz/fuzz_plan.c tests/fuzz/fuzz_render.c \
	tests/fuzz/fuzz_common.h \
	tests/fuzz/corpus
check-fuzz:
	$(MAKE) $(AM_MAKEFLAGS) check-TESTS check_PROGRAMS= TESTS='tests/fuzz/regress.sh' \
	    TEST_SUITE_LOG=fuzz-suite.log
# Builds only what the subset runs (not the POV-Ray comparison tools),
# then runs it with check_PROGRAMS emptied so that nothing else is built.
check-sanitized:
	@test -n '$(SAN_FLAGS)' || { echo 'check-sanitized: configure this tree with --enable-sanitizers'; exit 1; }
	@tests=''; for t in $(TESTS); do \
	    case $$t in *.sh|tests/unit/test_accel_pov) ;; *) tests="$$tests $$t" ;; esac; \
	done; \
	$(MAKE) $(AM_MAKEFLAGS) iris$(EXEEXT) iris-oiio.la \
	    tests/parse/parsedump$(EXEEXT) tests/stability/imgcheck$(EXEEXT) \
	    tests/cli/imgtool$(EXEEXT) $$tests || exit 1; \
	echo "$(MAKE) check-TESTS TESTS='$$tests $(SAN_SHELL_TESTS)'"; \
	ulimit -s 65536 2>/dev/null || true; \
	$(MAKE) $(AM_MAKEFLAGS) check-TESTS check_PROGRAMS= \
	    TESTS="$$tests $(SAN_SHELL_TESTS)" TEST_SUITE_LOG=sanitized-suite.log
.PHONY: check-fuzz check-sanitized
CLEANFILES += fuzz-suite.log sanitized-suite.log
