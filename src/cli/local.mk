## src/cli: see the file headers. Appends to the core library.
bin_PROGRAMS += iris
iris_SOURCES = %reldir%/main.c %reldir%/options.c %reldir%/options.h \
	%reldir%/report.c %reldir%/report.h %reldir%/passlog.c %reldir%/passlog.h \
	%reldir%/geomq.c %reldir%/geomq.h
iris_LDADD = libiris_core.la $(IRIS_LIBS)
