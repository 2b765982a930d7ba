## tests/optics.mk: independent optics (issue 5) end to end: scenes
## rendered by the iris command, images measured by imgprobe, numbers
## compared with predictions the test computes itself (docs/optics.md).
check_PROGRAMS += tests/optics/imgprobe
tests_optics_imgprobe_SOURCES = tests/optics/imgprobe.c
tests_optics_imgprobe_LDADD = libiris_core.la $(IRIS_LIBS)
TESTS += tests/optics/optics.sh tests/optics/targets.sh
EXTRA_DIST += tests/optics/optics.sh tests/optics/optics.awk tests/optics/scenes \
	tests/optics/targets.sh
