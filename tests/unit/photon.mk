## tests/unit/photon.mk: unit tests of the photon map (src/photon), run
## against an analytic test double of the ray queries (photon_world.c).
check_PROGRAMS += tests/unit/test_photon tests/unit/test_pfast
TESTS += tests/unit/test_photon tests/unit/test_pfast
check_PROGRAMS += tests/unit/test_membudget
TESTS += tests/unit/test_membudget
tests_unit_test_membudget_SOURCES = tests/unit/test_membudget.c tests/testutil.h
tests_unit_test_membudget_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_membudget_LDADD = $(TEST_LDADD)
tests_unit_test_photon_SOURCES = tests/unit/test_photon.c \
	tests/unit/photon_world.c tests/unit/photon_world.h tests/testutil.h
tests_unit_test_photon_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_photon_LDADD = $(TEST_LDADD)
tests_unit_test_pfast_SOURCES = tests/unit/test_pfast.c \
	tests/unit/parse_util.h tests/testutil.h
tests_unit_test_pfast_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_pfast_LDADD = $(TEST_LDADD)
