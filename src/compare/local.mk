## src/compare: iris-compare, POV-Ray and iris side by side.
bin_PROGRAMS += iris-compare
iris_compare_SOURCES = %reldir%/compare.c
iris_compare_LDADD = libiris_core.la $(IRIS_LIBS)
