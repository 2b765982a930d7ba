## tests/unit/spectrum.mk: unit tests of src/spectrum (colour, light
## spectra, Burns' curves, IOR models).
check_PROGRAMS += tests/unit/test_spectrum
TESTS += tests/unit/test_spectrum
tests_unit_test_spectrum_SOURCES = tests/unit/test_spectrum.c tests/testutil.h
tests_unit_test_spectrum_CFLAGS = $(TEST_CFLAGS)
tests_unit_test_spectrum_LDADD = $(TEST_LDADD)
