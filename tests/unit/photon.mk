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
	tests/unit/parse_util.h tests/unit/pmap_same.h tests/testutil.h
tests_unit_test_pfast_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_pfast_LDADD = $(TEST_LDADD)
# photons in media (src/photon/pmedia.c): extinction, media photons
check_PROGRAMS += tests/unit/test_pmedia
TESTS += tests/unit/test_pmedia
tests_unit_test_pmedia_SOURCES = tests/unit/test_pmedia.c \
	tests/unit/photon_world.c tests/unit/photon_world.h tests/testutil.h
tests_unit_test_pmedia_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_pmedia_LDADD = $(TEST_LDADD)
check_PROGRAMS += tests/unit/test_ptexcache
TESTS += tests/unit/test_ptexcache
tests_unit_test_ptexcache_SOURCES = tests/unit/test_ptexcache.c \
	tests/unit/parse_util.h tests/unit/pmap_same.h tests/testutil.h
tests_unit_test_ptexcache_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_ptexcache_LDADD = $(TEST_LDADD)
# photons through filtering surfaces without an interior (trace.c)
check_PROGRAMS += tests/unit/test_pfilter
TESTS += tests/unit/test_pfilter
tests_unit_test_pfilter_SOURCES = tests/unit/test_pfilter.c \
	tests/unit/photon_world.c tests/unit/photon_world.h tests/testutil.h
tests_unit_test_pfilter_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_pfilter_LDADD = $(TEST_LDADD)
# sibling wavelengths on paths that do not depend on lambda (trace.h)
check_PROGRAMS += tests/unit/test_psib
TESTS += tests/unit/test_psib
tests_unit_test_psib_SOURCES = tests/unit/test_psib.c \
	tests/unit/photon_world.c tests/unit/photon_world.h tests/testutil.h
tests_unit_test_psib_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_psib_LDADD = $(TEST_LDADD)
# the wavefront photon tracer against the scalar one (wavefront.h)
check_PROGRAMS += tests/unit/test_pwave
TESTS += tests/unit/test_pwave
tests_unit_test_pwave_SOURCES = tests/unit/test_pwave.c \
	tests/unit/parse_util.h tests/unit/scene_world.h tests/testutil.h
tests_unit_test_pwave_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_pwave_LDADD = $(TEST_LDADD)
# the wavefront lanes kept between passes (shoot.c), own program
check_PROGRAMS += tests/unit/test_wflanes
TESTS += tests/unit/test_wflanes
tests_unit_test_wflanes_SOURCES = tests/unit/test_wflanes.c \
	tests/unit/parse_util.h tests/unit/scene_world.h tests/testutil.h
tests_unit_test_wflanes_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_wflanes_LDADD = $(TEST_LDADD)
