## tests/progressive.mk: progressive photon mapping (issue 6) end to end:
## determinism, checkpoint/resume, interruption, the error log.
check_PROGRAMS += tests/progressive/imgdiff
tests_progressive_imgdiff_SOURCES = tests/progressive/imgdiff.c
tests_progressive_imgdiff_LDADD = libiris_core.la $(IRIS_LIBS)
check_PROGRAMS += tests/progressive/imgstat
tests_progressive_imgstat_SOURCES = tests/progressive/imgstat.c
tests_progressive_imgstat_LDADD = libiris_core.la $(IRIS_LIBS)
TESTS += tests/progressive/progressive.sh tests/progressive/radiosity.sh
EXTRA_DIST += tests/progressive/progressive.sh tests/progressive/ball.pov \
	tests/progressive/radiosity.sh tests/progressive/furnace.pov
