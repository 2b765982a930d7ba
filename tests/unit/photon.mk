## tests/unit/photon.mk: unit tests of the photon map (src/photon), run
## against an analytic test double of the ray queries (photon_world.c).
check_PROGRAMS += tests/unit/test_photon
TESTS += tests/unit/test_photon
tests_unit_test_photon_SOURCES = tests/unit/test_photon.c \
	tests/unit/photon_world.c tests/unit/photon_world.h tests/testutil.h
tests_unit_test_photon_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_photon_LDADD = $(TEST_LDADD)
